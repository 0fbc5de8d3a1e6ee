// test_moving_base_problem.cpp: ShapeProblem with a moving base (issue 21): the 12 variables
// x = (w_b, ξ), the cost gradient and every row of dg/dx against central finite differences (the
// error model of optimisation_fixtures.hpp, in the scaled variables: w_b / S, δt / L, δφ), and an
// optimisation that must move the base to reach a target made from a moved clamp.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "optimisation/optimisation_fixtures.hpp"
#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/core/so3.hpp"
#include "rodshape/optimisation/shape_optimiser.hpp"
#include "rodshape/optimisation/shape_problem.hpp"
#include "support/analytic_rods.hpp"
#include "support/eigen_compare.hpp"

namespace rodshape {
namespace {

using testing::CompareMatrices;

ClampedRod tilted_band(ConstitutiveModel model, int intervals = 20, bool gravity = true) {
  ClampedRod rod = testing::rubber_band(model, intervals);
  rod.properties.u_rest = Eigen::Vector3d(0.5, -0.3, 1.0);
  if (gravity)
    rod.load =
        DistributedLoad::gravity(testing::kBandMassPerLength, Eigen::Vector3d(0.0, -9.81, 0.0));
  rod.clamp.position = Eigen::Vector3d(0.1, 0.2, 0.3);
  rod.clamp.rotation = exp_so3(Eigen::Vector3d(0.2, -0.5, 0.3));
  rod.validate();
  return rod;
}

Vector6d body_wrench(const ClampedRod& rod) {
  Vector6d xi;
  xi << 0.6, -0.4, 0.3, 0.7, -0.5, 0.4;
  return xi.cwiseProduct(testing::wrench_scale(rod));
}

/// Objective points 2–4 cm beside the shape of `x`.
ShapeTarget target_beside(const RodConfiguration& c) {
  ShapeTarget target;
  for (int i : {4, 9, 14, 19})
    target.points.push_back(c.p[i] + 0.03 * c.R[i].col(0) - 0.02 * c.R[i].col(1));
  target.energy_weight = 0.7;
  target.distance_weight = 3.0;
  return target;
}

/// A base workspace of every kind, the reach shell's point off the base.
Workspace base_workspace(const Eigen::Vector3d& p0) {
  Workspace ws;
  ws.reach = Workspace::ReachShell{p0 + Eigen::Vector3d(0.3, -0.2, 0.1), 0.1, 0.9,
                                   Eigen::Vector3d(0.05, -0.08, -0.12)};
  ws.box = Workspace::Box{p0 - Eigen::Vector3d(0.1, 0.2, 0.3), p0 + Eigen::Vector3d::Constant(0.1)};
  ws.inside.push_back({p0 + Eigen::Vector3d(0.05, -0.1, 0.02), 0.5});
  ws.half_spaces.push_back({Eigen::Vector3d(1.0, -2.0, 0.5), 1.0});
  return ws;
}

TEST(MovingBaseProblem, CostGradientAndEveryJacobianRowMatchCentralFiniteDifferences) {
  for (ConstitutiveModel model : {ConstitutiveModel::Cosserat, ConstitutiveModel::Kirchhoff}) {
    const ClampedRod rod = tilted_band(model);
    const RodConfiguration c = integrate(rod, Wrench::from_vector(body_wrench(rod)));
    Grasp grasp;
    grasp.released = {true, false, false, true, false, false};
    ShapeProblem problem(rod, target_beside(c), Workspace{}, grasp);
    BaseMotion motion;
    motion.reference = rod.clamp;
    motion.workspace = base_workspace(rod.clamp.position);
    motion.motion_weight = 0.3;
    problem.move_base(motion);
    ASSERT_EQ(problem.variables(), 12);
    ASSERT_EQ(problem.row_blocks().base, 6);  // box 3, inside, half-space, reach

    const double L = rod.properties.length;
    Vector12d x;
    x << body_wrench(rod), 0.01, -0.02, 0.015, 0.1, -0.2, 0.15;
    Vector12d S;
    S << testing::wrench_scale(rod), Eigen::Vector3d::Constant(L), Eigen::Vector3d::Ones();
    problem.evaluate_with_base(x);
    const double cost = problem.cost();
    const Eigen::VectorXd gradient = problem.variable_gradient();
    const Eigen::VectorXd g = problem.constraints();
    const Eigen::MatrixXd J = problem.variable_jacobian();
    ASSERT_EQ(J.cols(), 12);
    // The base pose and world wrench at x are what the variables say.
    EXPECT_TRUE(
        CompareMatrices(problem.configuration().p[0], rod.clamp.position + x.segment<3>(6), 1e-15));
    const Eigen::Matrix3d R0 = exp_so3(x.segment<3>(9)) * rod.clamp.rotation;
    EXPECT_TRUE(CompareMatrices(problem.configuration().n[0], R0 * x.head<3>(), 1e-12));

    const testing::FdModel fd = testing::central_difference_model(rod.intervals);
    Vector12d fd_gradient;
    Eigen::MatrixXd fd_J(J.rows(), 12);
    for (int j = 0; j < 12; ++j) {
      Vector12d step = Vector12d::Zero();
      step(j) = fd.eta * S(j);
      problem.evaluate_with_base(x + step);
      const double cost_plus = problem.cost();
      const Eigen::VectorXd g_plus = problem.constraints();
      problem.evaluate_with_base(x - step);
      fd_gradient(j) = (cost_plus - problem.cost()) / (2.0 * step(j));
      fd_J.col(j) = (g_plus - problem.constraints()) / (2.0 * step(j));
    }
    const Eigen::VectorXd scaled_gradient = gradient.cwiseProduct(S);
    const double F_cost = std::max(std::abs(cost), scaled_gradient.cwiseAbs().maxCoeff());
    EXPECT_TRUE(CompareMatrices(scaled_gradient, fd_gradient.cwiseProduct(S), fd.bound * F_cost))
        << "cost gradient, " << to_string(model);
    for (int r = 0; r < J.rows(); ++r) {
      const Eigen::RowVectorXd scaled = J.row(r).cwiseProduct(S.transpose());
      const double F_row = std::max(std::abs(g(r)), scaled.cwiseAbs().maxCoeff());
      EXPECT_TRUE(
          CompareMatrices(scaled, fd_J.row(r).cwiseProduct(S.transpose()), fd.bound * F_row))
          << "row " << r << ", " << to_string(model);
    }
  }
}

TEST(MovingBaseProblem, OptimiserMovesTheBaseOntoATargetMadeFromAMovedClamp) {
  const ClampedRod rod = tilted_band(ConstitutiveModel::Cosserat, 40);
  // The target: points of the equilibrium of w_b with the clamp moved by 3 cm and 0.25 rad.
  ClampedRod moved = rod;
  moved.clamp.position += Eigen::Vector3d(0.02, -0.015, 0.018);
  moved.clamp.rotation = exp_so3(Eigen::Vector3d(0.1, 0.2, -0.1)) * rod.clamp.rotation;
  const Vector6d wb = 0.3 * body_wrench(rod);
  const BaseWrench w_moved{moved.clamp.rotation * wb.head<3>(),
                           moved.clamp.rotation * wb.tail<3>()};
  const RodConfiguration truth = integrate(moved, w_moved);
  ShapeTarget target;
  for (int i : {0, 2, 5, 12, 20, 28, 36, 40}) target.points.push_back(truth.p[i]);
  target.energy_weight = 1e-9;      // the points decide: the base must move onto them
  target.squared_distances = true;  // smooth where the points are reached
  target.distance_weight = 1.0;
  ShapeProblem problem(rod, target);
  BaseMotion motion;
  motion.reference = rod.clamp;
  motion.motion_weight = 1e-9;
  problem.move_base(motion);
  const BaseWrench guess{rod.clamp.rotation * wb.head<3>(), rod.clamp.rotation * wb.tail<3>()};
  ShapeOptimiserOptions options;
  options.max_iterations = 300;
  const ShapeResult result = optimise_shape(problem, guess, options);
  ASSERT_TRUE(result.converged()) << result.brief();
  EXPECT_LT(result.cost.max_distance, 1e-4) << result.brief();
  // The base found is at the moved clamp (a point is there); the rod's clamp is the optimum's base.
  EXPECT_LT((result.configuration.p[0] - moved.clamp.position).norm(), 1e-4);
  EXPECT_LT((problem.rod().clamp.position - result.configuration.p[0]).norm(), 1e-15);
  // With the clamp fixed at the reference, the same target is out of reach.
  ShapeProblem fixed(rod, target);
  const ShapeResult clamped = optimise_shape(fixed, guess, options);
  EXPECT_GT(clamped.cost.max_distance, 0.01) << clamped.brief();
}

}  // namespace
}  // namespace rodshape
