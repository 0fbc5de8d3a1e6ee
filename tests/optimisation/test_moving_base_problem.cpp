// test_moving_base_problem.cpp: ShapeProblem with a moving base (issue 21): the 12 variables
// x = (w_b, ξ), the cost gradient and every row of dg/dx against central finite differences (the
// error model of optimisation_fixtures.hpp, in the scaled variables: w_b / S, δt / L, δφ), and an
// optimisation that must move the base to reach a target made from a moved clamp.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "optimisation/optimisation_fixtures.hpp"
#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/core/so3.hpp"
#include "rodshape/optimisation/shape_optimiser.hpp"
#include "rodshape/optimisation/shape_problem.hpp"
#include "support/analytic_rods.hpp"
#include "support/eigen_compare.hpp"

namespace rodshape {
namespace test_moving_base_problem {
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

/// The shape of the body-frame wrench wb from a clamp moved 3 cm and turned 0.24 rad from rod's.
RodConfiguration moved_shape(const ClampedRod& rod, const Vector6d& wb) {
  ClampedRod moved = rod;
  moved.clamp.position += Eigen::Vector3d(0.02, -0.015, 0.018);
  moved.clamp.rotation = exp_so3(Eigen::Vector3d(0.1, 0.2, -0.1)) * rod.clamp.rotation;
  return integrate(
      moved, BaseWrench{moved.clamp.rotation * wb.head<3>(), moved.clamp.rotation * wb.tail<3>()});
}

/// The paper's smoothed Σ dist (W1 = 1e-3, W2 = 1), its points `offset` off moved_shape (nodes
/// 0 … 40).
ShapeTarget target_off_moved_shape(const ClampedRod& rod, const Vector6d& wb, double offset) {
  const RodConfiguration truth = moved_shape(rod, wb);
  ShapeTarget target;
  for (int i : {0, 5, 12, 20, 28, 36, 40})
    target.points.push_back(truth.p[i] + offset * truth.R[i].col(i % 2));
  target.energy_weight = 1e-3;
  target.distance_weight = 1.0;
  return target;
}

TEST(MovingBaseProblem, WithoutLoadsThePoseIsEliminatedAndTheOptimumIsThatOfTheTwelveUnknowns) {
  // No distributed load: the shape in the base's frame depends on w_b alone, so without constraint
  // rows IPOPT sees w_b and ξ is the best rigid placement at each w_b (align_base). Its optimum
  // must be stationary in all 12 unknowns and the same as the 12-unknown NLP's (forced here by an
  // inactive base workspace row).
  const ClampedRod rod = tilted_band(ConstitutiveModel::Cosserat, 40, false);
  const Vector6d wb = 0.3 * body_wrench(rod);
  const ShapeTarget target = target_off_moved_shape(rod, wb, 1e-3);
  BaseMotion motion;
  motion.reference = rod.clamp;
  const BaseWrench guess{rod.clamp.rotation * 0.2 * wb.head<3>(),
                         rod.clamp.rotation * 0.2 * wb.tail<3>()};
  ShapeOptimiserOptions options;
  options.max_iterations = 500;

  ShapeProblem projected(rod, target);
  projected.move_base(motion);
  ASSERT_TRUE(projected.rigid_alignment_applies());
  const ShapeResult result = optimise_shape(projected, guess, options);
  ASSERT_TRUE(result.converged()) << result.brief();
  const Pose base{result.configuration.p[0], result.configuration.R[0]};
  Vector12d x;
  x << base.rotation.transpose() * result.base_wrench.force,
      base.rotation.transpose() * result.base_wrench.moment, base.position - rod.clamp.position,
      log_so3(base.rotation * rod.clamp.rotation.transpose());
  projected.evaluate_with_base(x);
  Vector12d scale;
  scale << testing::wrench_scale(rod), Eigen::Vector3d::Constant(rod.properties.length),
      Eigen::Vector3d::Ones();
  const Vector12d gradient = projected.variable_gradient();
  EXPECT_LT(gradient.cwiseProduct(scale).lpNorm<Eigen::Infinity>(), 1e-7) << gradient.transpose();
  // align_base from ξ = 0 at the optimum's w_b finds the optimum's ξ.
  Vector6d xi = Vector6d::Zero();
  ASSERT_TRUE(projected.align_base(x.head<6>(), xi));
  EXPECT_LT((xi - x.tail<6>()).lpNorm<Eigen::Infinity>(), 1e-7) << xi.transpose();

  Workspace far;  // a base workspace row that is never active
  far.box = Workspace::Box{rod.clamp.position - Eigen::Vector3d::Constant(10.0),
                           rod.clamp.position + Eigen::Vector3d::Constant(10.0)};
  motion.workspace = far;
  ShapeProblem twelve(rod, target);
  twelve.move_base(motion);
  ASSERT_GT(twelve.constraint_count(), 0);
  const ShapeResult reference = optimise_shape(twelve, guess, options);
  ASSERT_TRUE(reference.converged()) << reference.brief();
  EXPECT_NEAR(result.cost.cost, reference.cost.cost, 1e-9 * reference.cost.cost);
  EXPECT_LT((result.configuration.p[0] - reference.configuration.p[0]).norm(), 1e-6);
  EXPECT_LT((result.configuration.tip().position - reference.configuration.tip().position).norm(),
            1e-6);
  // The eliminated problem's dense Newton updates its Hessian (SR1 between shortened steps), so
  // it takes more iterations than IPOPT on the 12 unknowns but fewer integrations: the cost.
  EXPECT_LT(projected.integrations(), twelve.integrations())
      << "iterations " << result.ipopt.iterations << " against " << reference.ipopt.iterations;
}

TEST(MovingBaseProblem, TheEliminatedEvaluationInTheBasesFrameIsTheWorldsAtTheAlignment) {
  // With the base pose eliminated, F and ∂F/∂w_b are evaluated on the shape in the base's frame
  // (F is invariant under the rigid placement): they must be the world evaluation's at x = (w_b,
  // ξ*), up to the rounding of integrating the same ODE in two frames (about 1e-13 relative here).
  const ClampedRod rod = tilted_band(ConstitutiveModel::Cosserat, 40, false);
  const Vector6d wb = 0.3 * body_wrench(rod);
  const ShapeTarget target = target_off_moved_shape(rod, wb, 2e-3);
  BaseMotion motion;
  motion.reference = rod.clamp;
  ShapeProblem problem(rod, target);
  problem.move_base(motion);
  ASSERT_TRUE(problem.rigid_alignment_applies());
  const Vector6d units = rod.properties.bending_wrench_units();
  for (double scale : {0.5, 1.0, 1.3}) {
    problem.eliminate_base_pose(true);
    problem.evaluate((scale * wb).cwiseQuotient(units));
    const double eliminated_cost = problem.cost();
    const Vector6d eliminated_gradient = problem.cost_gradient().cwiseQuotient(units);  // ∂F/∂w_b
    const Vector12d x = problem.evaluated_variables();
    ASSERT_TRUE(std::isfinite(eliminated_cost));
    EXPECT_GT(x.tail<3>().norm() + x.segment<3>(6).norm(), 1e-3) << "the base did not move";
    problem.eliminate_base_pose(false);
    problem.evaluate_with_base(x);
    EXPECT_NEAR(eliminated_cost, problem.cost(), 1e-12 * problem.cost()) << "scale " << scale;
    const Vector6d world_gradient = problem.variable_gradient().head<6>();
    EXPECT_TRUE(CompareMatrices(eliminated_gradient, world_gradient,
                                1e-9 * world_gradient.lpNorm<Eigen::Infinity>()))
        << "scale " << scale;
  }
}

/// The alignment's problem: a moving base (motion weight 0.3) and points 5–20 mm off moved_shape,
/// one beyond the tip (its closest point is the end), Σ dist (smoothed) or
/// Σ dist².
ShapeProblem alignment_problem(const ClampedRod& rod, const Vector6d& wb, bool squared) {
  const RodConfiguration truth = moved_shape(rod, wb);
  ShapeTarget target;
  const double offsets[] = {0.005, 0.012, 0.02, 0.008, 0.015, 0.01};
  const int nodes[] = {3, 10, 17, 24, 31, 37};
  for (int k = 0; k < 6; ++k)
    target.points.push_back(truth.p[nodes[k]] + offsets[k] * truth.R[nodes[k]].col(k % 2));
  target.points.push_back(truth.p[40] + 0.01 * truth.R[40].col(2) + 0.004 * truth.R[40].col(0));
  target.energy_weight = 1e-3;
  target.distance_weight = 1.0;
  target.squared_distances = squared;
  ShapeProblem problem(rod, target);
  BaseMotion motion;
  motion.reference = rod.clamp;
  motion.motion_weight = 0.3;
  problem.move_base(motion);
  return problem;
}

TEST(MovingBaseProblem, AlignmentGradientAndHessianMatchCentralFiniteDifferences) {
  // align_base() takes Newton steps on alignment_cost's gradient and Hessian in ξ̃ = (δt / L, δφ):
  // both against central differences (of the cost, of the gradient), away from the alignment's
  // optimum and with a turn δφ ≠ 0 (the left Jacobian's own derivative enters), for the smoothed
  // Σ dist and for Σ dist². Points 5–20 mm from the curve, one beyond the tip (its closest point
  // is the end: a point's distance, curved along the tangent too).
  // FD error model: the shape is fixed, so F(ξ̃) is the points' distances to a cubic curve after a
  // rigid motion, smooth where no closest point changes interval. Central differences err by
  // O(η²) (truncation) + O(ε |F| / η) (round-off): the truncation at η/2 is bounded by
  // 2 |FD(η) - FD(η/2)| (Richardson: FD(η/2) errs by a third of their difference, with margin), the
  // round-off by 1e3 ε |F| / (η/2) (a few hundred operations per point). A missing or wrong term of
  // the Hessian (branch elim's, 38cb6b2: errors of 2–12 % of |H|) exceeds both by far.
  const ClampedRod rod = tilted_band(ConstitutiveModel::Cosserat, 40, false);
  const double L = rod.properties.length;
  const Vector6d wb = 0.3 * body_wrench(rod);
  for (const bool squared : {false, true}) {
    ShapeProblem problem = alignment_problem(rod, wb, squared);
    ASSERT_TRUE(problem.rigid_alignment_applies());
    Vector6d xi_optimum = Vector6d::Zero();
    ASSERT_TRUE(problem.align_base(wb, xi_optimum));
    Vector6d offset;
    offset << 0.004, -0.003, 0.005, 0.03, -0.05, 0.04;
    for (const Vector6d& xi : {Vector6d(Vector6d::Zero()), Vector6d(xi_optimum + offset)}) {
      Vector6d gradient;
      Matrix6d hessian;
      const double cost = problem.alignment_cost(wb, xi, &gradient, &hessian);
      ASSERT_TRUE(std::isfinite(cost));
      const auto at = [&](int j, double step) {  // ξ with ξ̃_j moved by step
        Vector6d moved_xi = xi;
        moved_xi[j] += j < 3 ? L * step : step;
        return moved_xi;
      };
      const auto differences = [&](double eta, Vector6d& cost_fd, Matrix6d& gradient_fd) {
        for (int j = 0; j < 6; ++j) {
          Vector6d g_plus, g_minus;
          const double f_plus = problem.alignment_cost(wb, at(j, eta), &g_plus, nullptr);
          const double f_minus = problem.alignment_cost(wb, at(j, -eta), &g_minus, nullptr);
          cost_fd[j] = (f_plus - f_minus) / (2.0 * eta);
          gradient_fd.col(j) = (g_plus - g_minus) / (2.0 * eta);
        }
      };
      constexpr double kEta = 1e-4;
      Vector6d cost_fd, cost_fd_half;
      Matrix6d gradient_fd, gradient_fd_half;
      differences(kEta, cost_fd, gradient_fd);
      differences(0.5 * kEta, cost_fd_half, gradient_fd_half);
      const double round_off =
          1e3 * std::numeric_limits<double>::epsilon() * std::abs(cost) / (0.5 * kEta);
      const double gradient_bound =
          2.0 * (cost_fd - cost_fd_half).lpNorm<Eigen::Infinity>() + round_off;
      const double hessian_bound =
          2.0 * (gradient_fd - gradient_fd_half).lpNorm<Eigen::Infinity>() +
          round_off * std::max(1.0, gradient.lpNorm<Eigen::Infinity>() / std::abs(cost));
      const double gradient_error = (gradient - cost_fd_half).lpNorm<Eigen::Infinity>();
      const double hessian_error = (hessian - gradient_fd_half).lpNorm<Eigen::Infinity>();
      RecordProperty(std::string(squared ? "squared" : "smoothed") + (xi.isZero() ? "_0" : "_off") +
                         "_hessian_error",
                     testing::scientific(hessian_error));
      EXPECT_LE(gradient_error, gradient_bound)
          << "squared " << squared << ", |∇F|∞ " << gradient.lpNorm<Eigen::Infinity>();
      EXPECT_LE(hessian_error, hessian_bound)
          << "squared " << squared << ", |H|∞ " << hessian.lpNorm<Eigen::Infinity>() << "\n"
          << hessian << "\nFD\n"
          << gradient_fd_half;
      // The bounds are meaningful: far below the entries they check.
      EXPECT_LT(hessian_bound, 1e-3 * hessian.lpNorm<Eigen::Infinity>());
      EXPECT_LT(gradient_bound, 1e-3 * gradient.lpNorm<Eigen::Infinity>());
    }
  }
}

TEST(MovingBaseProblem, AlignmentMixedDerivativeMatchesCentralDifferencesInTheWrench) {
  // ∂²F/∂ξ̃∂w_b (the alignment's gradient as the curve moves under the fixed points, the closest
  // points sliding along it) against central differences of alignment_cost's gradient in w_b at
  // fixed ξ, each w_b component stepped by η of its bending unit. The same error model as the
  // test above: the shape is a smooth function of w_b (one integration each, its rounding ε|F|
  // per operation), truncation bounded by Richardson, round-off by 1e3 ε |F| / (η/2).
  const ClampedRod rod = tilted_band(ConstitutiveModel::Cosserat, 40, false);
  const Vector6d units = rod.properties.bending_wrench_units();
  const Vector6d wb = 0.3 * body_wrench(rod);
  for (const bool squared : {false, true}) {
    ShapeProblem problem = alignment_problem(rod, wb, squared);
    Vector6d xi_optimum = Vector6d::Zero();
    ASSERT_TRUE(problem.align_base(wb, xi_optimum));
    Vector6d offset;
    offset << 0.004, -0.003, 0.005, 0.03, -0.05, 0.04;
    for (const Vector6d& xi : {Vector6d(xi_optimum), Vector6d(xi_optimum + offset)}) {
      Vector6d gradient;
      Matrix6d mixed;
      const double cost = problem.alignment_cost(wb, xi, &gradient, nullptr, &mixed);
      ASSERT_TRUE(std::isfinite(cost));
      const auto differences = [&](double eta) {  // in w̃ = w_b / units
        Matrix6d fd;
        for (int j = 0; j < 6; ++j) {
          const Vector6d step = eta * units[j] * Vector6d::Unit(j);
          Vector6d g_plus, g_minus;
          problem.alignment_cost(wb + step, xi, &g_plus, nullptr);
          problem.alignment_cost(wb - step, xi, &g_minus, nullptr);
          fd.col(j) = (g_plus - g_minus) / (2.0 * eta);
        }
        return fd;
      };
      constexpr double kEta = 1e-4;
      const Matrix6d fd = differences(kEta), fd_half = differences(0.5 * kEta);
      const Matrix6d scaled = mixed * units.asDiagonal();  // ∂²F/∂ξ̃∂w̃
      const double round_off = 1e3 * std::numeric_limits<double>::epsilon() *
                               std::max(1.0, gradient.lpNorm<Eigen::Infinity>() / std::abs(cost)) *
                               std::abs(cost) / (0.5 * kEta);
      const double bound = 2.0 * (fd - fd_half).lpNorm<Eigen::Infinity>() + round_off;
      EXPECT_LE((scaled - fd_half).lpNorm<Eigen::Infinity>(), bound)
          << "squared " << squared << "\n"
          << scaled << "\nFD\n"
          << fd_half;
      EXPECT_LT(bound, 1e-3 * scaled.lpNorm<Eigen::Infinity>());  // a bound that can fail
    }
  }
}

TEST(MovingBaseProblem, TheAlignmentsPredictorIsFirstOrderExact) {
  // alignment_sensitivity() = dξ̃*/dw_b: the start ξ̃*(w_b) + S δw for the alignment at w_b + δw
  // errs by O(|δw|²), so halving δw quarters the error (a ratio of 3–5 allows the next order),
  // and the error is far below the change of ξ̃* it predicts.
  const ClampedRod rod = tilted_band(ConstitutiveModel::Cosserat, 40, false);
  const double L = rod.properties.length;
  const Vector6d units = rod.properties.bending_wrench_units();
  const Vector6d wb = 0.3 * body_wrench(rod);
  const auto scaled = [&](const Vector6d& xi) {  // ξ̃ = (δt / L, δφ)
    Vector6d xi_scaled;
    xi_scaled << xi.head<3>() / L, xi.tail<3>();
    return xi_scaled;
  };
  for (const bool squared : {false, true}) {
    ShapeProblem problem = alignment_problem(rod, wb, squared);
    Vector6d xi_star = Vector6d::Zero();
    ASSERT_TRUE(problem.align_base(wb, xi_star));
    ASSERT_TRUE(problem.alignment_sensitivity().has_value());
    const Matrix6d S = *problem.alignment_sensitivity();
    Vector6d direction;
    direction << 0.5, -0.3, 0.2, 0.4, -0.6, 0.3;
    double errors[2], changes[2];
    for (int k = 0; k < 2; ++k) {
      const Vector6d dw = (k == 0 ? 0.02 : 0.01) * direction.cwiseProduct(units);
      Vector6d xi = xi_star;
      ASSERT_TRUE(problem.align_base(wb + dw, xi));
      const Vector6d change = scaled(xi) - scaled(xi_star);
      errors[k] = (change - S * dw).lpNorm<Eigen::Infinity>();
      changes[k] = change.lpNorm<Eigen::Infinity>();
    }
    EXPECT_GT(errors[0] / errors[1], 3.0)
        << "squared " << squared << ": " << errors[0] << ", " << errors[1];
    EXPECT_LT(errors[0] / errors[1], 5.0) << "squared " << squared;
    EXPECT_LT(errors[1], 0.05 * changes[1]) << "squared " << squared;
  }
}

}  // namespace
}  // namespace test_moving_base_problem
}  // namespace rodshape
