// test_shape_problem.cpp: ShapeProblem's cost, constraints and their derivatives.
//
// Derivatives are checked against central finite differences of ShapeProblem::evaluate() itself,
// with the error model of optimisation_fixtures.hpp: |FD - ∂f/∂ξ_j| ≤ bound · F, bound ≈ 3.8e-9 for
// N = 20, in the scaled wrench ξ = w/S. The size F of each output (the cost, each row of g) is
// taken as max(|f(w)|, max_j |∂f/∂ξ_j|): outputs that vary by O(1) of themselves over ξ ~ 1. Rows
// are written without cancellation against a large constant (u - ũ from m̄, v_z - ṽ_z from n̄), so
// their round-off is relative to F, as the model assumes.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <ostream>
#include <string>

#include "optimisation/optimisation_fixtures.hpp"
#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/core/so3.hpp"
#include "rodshape/optimisation/shape_problem.hpp"
#include "support/analytic_rods.hpp"
#include "support/eigen_compare.hpp"
#include "support/input_error.hpp"

namespace rodshape {
namespace test_shape_problem {
namespace {

using testing::CompareMatrices;
using testing::CompareScalars;
using testing::input_error_message;

constexpr double kInf = std::numeric_limits<double>::infinity();

ClampedRod loaded_rod(ConstitutiveModel model, int intervals = 20) {
  ClampedRod rod = testing::rubber_band(model, intervals);
  rod.properties.u_rest = Eigen::Vector3d(0.5, -0.3, 1.0);
  rod.load =
      DistributedLoad::gravity(testing::kBandMassPerLength, Eigen::Vector3d(0.0, -9.81, 0.0));
  rod.clamp.position = Eigen::Vector3d(0.1, 0.2, 0.3);
  rod.clamp.rotation = exp_so3(Eigen::Vector3d(0.2, -0.5, 0.3));
  rod.validate();
  return rod;
}

Vector6d base_wrench(const ClampedRod& rod) {
  Vector6d xi;
  xi << 0.6, -0.4, 0.3, 0.7, -0.5, 0.4;  // O(1): genuinely nonlinear
  return xi.cwiseProduct(testing::wrench_scale(rod));
}

/// Every kind of workspace set, each with a non-trivial gradient at the tip (the reach shell's
/// point off the tip, so that its rows depend on R(L)).
Workspace every_kind_of_workspace(const Eigen::Vector3d& tip) {
  Workspace ws;
  ws.reach = Workspace::ReachShell{tip + Eigen::Vector3d(0.3, -0.2, 0.1), 0.1, 0.9,
                                   Eigen::Vector3d(0.05, -0.08, -0.12)};
  ws.box =
      Workspace::Box{tip - Eigen::Vector3d(0.1, 0.2, 0.3), tip + Eigen::Vector3d::Constant(0.1)};
  ws.inside.push_back({tip + Eigen::Vector3d(0.05, -0.1, 0.02), 0.5});
  ws.outside.push_back({tip + Eigen::Vector3d(-0.1, 0.03, 0.04), 0.05});
  ws.half_spaces.push_back({Eigen::Vector3d(1.0, -2.0, 0.5), 1.0});
  return ws;
}

/// Objective points beside the curve (distance ~ 2-4 cm: far from |·|'s kink at 0).
ShapeTarget target_beside(const RodConfiguration& c, bool squared) {
  ShapeTarget target;
  for (int i : {4, 9, 14, 19}) {
    const Eigen::Matrix3d& R = c.R[i];
    target.points.push_back(c.p[i] + 0.03 * R.col(0) - 0.02 * R.col(1));
  }
  target.energy_weight = 0.7;
  target.distance_weight = 3.0;
  target.squared_distances = squared;
  return target;
}

/// One obstacle of each kind beside the rod (1–3 cm off its nodes, none touching it), so that
/// every clearance row is smooth at the configuration: the nearest points are on faces, not edges.
Clearance every_kind_of_obstacle(const RodConfiguration& c) {
  Clearance clearance;
  clearance.scene.rod_radius = 0.002;
  clearance.scene.clearance = 0.005;
  const auto beside = [&](int i, double d) { return Eigen::Vector3d(c.p[i] + d * c.R[i].col(0)); };
  clearance.scene.obstacles = {
      {"ball", SphereObstacle{beside(5, 0.03), 0.01}},
      {"rail", CapsuleObstacle{beside(10, 0.025) - 0.01 * c.R[10].col(2),
                               beside(10, 0.025) + 0.01 * c.R[10].col(2), 0.008}},
      {"crate", BoxObstacle{beside(15, -0.04), Eigen::Vector3d(0.04, 0.03, 0.02), c.R[15]}},
      {"floor", HalfSpaceObstacle{-c.R[0].col(0), 0.05 - c.R[0].col(0).dot(c.p[0])}}};
  clearance.required.assign(4, 0.005);
  return clearance;
}

ShapeProblem make_problem(ConstitutiveModel model, bool squared) {
  const ClampedRod rod = loaded_rod(model);
  const RodConfiguration c = integrate(rod, Wrench::from_vector(base_wrench(rod)));
  Grasp grasp;
  grasp.released = {true, false, false, true, false, false};  // fx, mx
  StrainLimits limits;
  limits.max_curvature = 8.0;
  limits.max_axial_strain = 0.01;
  return ShapeProblem(rod, target_beside(c, squared), every_kind_of_workspace(c.p.back()), grasp,
                      limits, WrenchBounds{}, every_kind_of_obstacle(c));
}

struct Case {
  ConstitutiveModel model;
  bool squared;
};

void PrintTo(const Case& c, std::ostream* out) {
  *out << to_string(c.model) << (c.squared ? ", Σ dist²" : ", Σ dist");
}

class ShapeProblemDerivatives : public ::testing::TestWithParam<Case> {};

TEST_P(ShapeProblemDerivatives, CostGradientAndEveryJacobianRowMatchCentralFiniteDifferences) {
  ShapeProblem problem = make_problem(GetParam().model, GetParam().squared);
  const ClampedRod& rod = problem.rod();
  const int N = rod.intervals;
  const ShapeProblem::RowBlocks& rows = problem.row_blocks();
  EXPECT_EQ(rows.workspace, 7);
  EXPECT_EQ(rows.grasp, 2);
  EXPECT_EQ(rows.curvature, N + 1);
  EXPECT_EQ(rows.axial, GetParam().model == ConstitutiveModel::Cosserat ? N + 1 : 0);
  EXPECT_EQ(rows.clearance, 4 * N);
  ASSERT_EQ(problem.constraint_count(),
            rows.workspace + rows.grasp + rows.curvature + rows.axial + rows.clearance);

  const Vector6d w = base_wrench(rod);
  const Vector6d S = testing::wrench_scale(rod);
  problem.evaluate(w);
  const double cost = problem.cost();
  const Vector6d gradient = problem.cost_gradient();
  const Eigen::VectorXd g = problem.constraints();
  const Eigen::MatrixXd J = problem.constraint_jacobian();
  ASSERT_EQ(J.rows(), problem.constraint_count());
  ASSERT_EQ(J.cols(), 6);
  for (double d : problem.breakdown().distances) ASSERT_GT(d, 0.01);

  const testing::FdModel fd = testing::central_difference_model(N);
  Vector6d fd_gradient;
  Eigen::MatrixXd fd_J(J.rows(), 6);
  for (int j = 0; j < 6; ++j) {
    Vector6d step = Vector6d::Zero();
    step(j) = fd.eta * S(j);
    problem.evaluate(w + step);
    const double cost_plus = problem.cost();
    const Eigen::VectorXd g_plus = problem.constraints();
    problem.evaluate(w - step);
    fd_gradient(j) = (cost_plus - problem.cost()) / (2.0 * step(j));
    fd_J.col(j) = (g_plus - problem.constraints()) / (2.0 * step(j));
  }
  // The clearance rows: distances to obstacles curved at radius ≥ 8 mm (the rail) from nodes that
  // a unit ξ moves by about L: a model with (L / 8 mm)² times the third derivative, its own step.
  const double L = rod.properties.length;
  const testing::FdModel fd_clear =
      testing::central_difference_model(N, 10.0 * std::pow(L / 0.008, 2));
  Eigen::MatrixXd fd_J_clear(J.rows(), 6);
  for (int j = 0; j < 6; ++j) {
    Vector6d step = Vector6d::Zero();
    step(j) = fd_clear.eta * S(j);
    problem.evaluate(w + step);
    const Eigen::VectorXd g_plus = problem.constraints();
    problem.evaluate(w - step);
    fd_J_clear.col(j) = (g_plus - problem.constraints()) / (2.0 * step(j));
  }
  const int first_clearance = problem.constraint_count() - rows.clearance;
  const std::string label = to_string(GetParam().model) + (GetParam().squared ? ", Σd²" : ", Σd");
  // In ξ: ∂f/∂ξ_j = S_j ∂f/∂w_j.
  const Vector6d scaled_gradient = gradient.cwiseProduct(S);
  const double F_cost = std::max(std::abs(cost), scaled_gradient.cwiseAbs().maxCoeff());
  EXPECT_TRUE(CompareMatrices(scaled_gradient, fd_gradient.cwiseProduct(S), fd.bound * F_cost))
      << "cost gradient, " << label;
  for (int r = 0; r < J.rows(); ++r) {
    const Eigen::RowVectorXd scaled = J.row(r).cwiseProduct(S.transpose());
    const double F_row = std::max(std::abs(g(r)), scaled.cwiseAbs().maxCoeff());
    const bool clearance = r >= first_clearance;
    const Eigen::RowVectorXd fd_row = clearance ? fd_J_clear.row(r) : fd_J.row(r);
    const double bound = clearance ? fd_clear.bound : fd.bound;
    EXPECT_TRUE(CompareMatrices(scaled, fd_row.cwiseProduct(S.transpose()), bound * F_row))
        << "row " << r << ", " << label;
  }
}

INSTANTIATE_TEST_SUITE_P(ModelsAndCosts,
                         ShapeProblemDerivatives,
                         ::testing::Values(Case{ConstitutiveModel::Cosserat, false},
                                           Case{ConstitutiveModel::Cosserat, true},
                                           Case{ConstitutiveModel::Kirchhoff, false},
                                           Case{ConstitutiveModel::Kirchhoff, true}),
                         [](const auto& info) {
                           return to_string(info.param.model) +
                                  (info.param.squared ? "Squared" : "Plain");
                         });

TEST(ShapeProblem, RowValuesAndBoundsAreThoseDocumented) {
  ShapeProblem problem = make_problem(ConstitutiveModel::Cosserat, false);
  const Vector6d w = base_wrench(problem.rod());
  problem.evaluate(w);
  const RodConfiguration& c = problem.configuration();
  const Eigen::VectorXd& g = problem.constraints();
  const Eigen::VectorXd& lo = problem.constraint_lower();
  const Eigen::VectorXd& up = problem.constraint_upper();
  const Eigen::Vector3d tip = c.p.back();
  const Workspace& ws = problem.workspace();
  // workspace: box (p itself), inside ball, outside ball, half-space
  EXPECT_TRUE(CompareMatrices(g.head<3>(), tip, 0.0));
  EXPECT_TRUE(CompareMatrices(lo.head<3>(), ws.box->lower, 0.0));
  EXPECT_TRUE(CompareMatrices(up.head<3>(), ws.box->upper, 0.0));
  EXPECT_TRUE(CompareScalars(g(3), (tip - ws.inside[0].center).squaredNorm(), 1e-15));
  EXPECT_EQ(lo(3), -kInf);
  EXPECT_EQ(up(3), 0.25);
  EXPECT_TRUE(CompareScalars(g(4), (tip - ws.outside[0].center).squaredNorm(), 1e-15));
  EXPECT_EQ(lo(4), 0.05 * 0.05);
  EXPECT_EQ(up(4), kInf);
  EXPECT_TRUE(CompareScalars(g(5), ws.half_spaces[0].normal.dot(tip), 1e-15));
  EXPECT_EQ(up(5), 1.0);
  // reach: r_in² ≤ |p(L) + R(L) t - c|² ≤ r_out², one two-sided row
  const Eigen::Matrix3d& R = c.R.back();
  const double reach_squared = (tip + R * ws.reach->tip_point - ws.reach->center).squaredNorm();
  EXPECT_TRUE(CompareScalars(g(6), reach_squared, 1e-15));
  EXPECT_EQ(lo(6), 0.1 * 0.1);
  EXPECT_EQ(up(6), 0.81);
  // grasp: fx and mx of the tip wrench in the tip frame, = 0
  EXPECT_TRUE(CompareScalars(g(7), (R.transpose() * c.n.back()).x(), 1e-15));
  EXPECT_TRUE(CompareScalars(g(8), (R.transpose() * c.m.back()).x(), 1e-15));
  EXPECT_EQ(lo(7), 0.0);
  EXPECT_EQ(up(8), 0.0);
  // curvature |u - ũ|² ≤ κ², axial v_z - ṽ_z ∈ [-ε, ε], node by node
  const int nodes = c.nodes();
  const Eigen::Vector3d& u_rest = problem.rod().properties.u_rest;
  constexpr double eps = std::numeric_limits<double>::epsilon();
  for (int i = 0; i < nodes; ++i) {
    // g is |K⁻¹ m̄|², u - ũ = (K⁻¹ m̄ + ũ) - ũ: the two differ by the round-off of adding and
    // removing ũ, a few ε (|u| + |ũ|) in u - ũ, so 2 |u - ũ| times that in its square.
    const double du = (c.u[i] - u_rest).norm();
    EXPECT_TRUE(CompareScalars(g(9 + i), du * du, 8 * eps * (c.u[i].norm() + u_rest.norm()) * du))
        << i;
    EXPECT_EQ(up(9 + i), 64.0);
    EXPECT_TRUE(CompareScalars(g(9 + nodes + i), c.v[i].z() - 1.0, 1e-15)) << i;
    EXPECT_EQ(lo(9 + nodes + i), -0.01);
    EXPECT_EQ(up(9 + nodes + i), 0.01);
  }
}

TEST(ShapeProblem, EnergyTermIsW1TimesEnergyOverLengthOnAnArc) {
  // Pure end moment M: an exact arc with E = M² L / (2 EI). The energy integrand is constant, so
  // RK4 integrates it exactly: equality to round-off (N steps of a few ε each).
  const ClampedRod rod = testing::rubber_band(ConstitutiveModel::Cosserat, 20);
  const double L = rod.properties.length, EI = rod.properties.K_rot.x(), M = 0.3;
  ShapeTarget target;
  target.points = {{0.0, 0.0, 0.1}};
  target.energy_weight = 2.5;
  target.distance_weight = 0.0;
  ShapeProblem problem(rod, target);
  EXPECT_EQ(problem.constraint_count(), 0);
  Vector6d w;
  w << 0.0, 0.0, 0.0, M, 0.0, 0.0;
  problem.evaluate(w);
  const double E = M * M * L / (2.0 * EI);
  const double tol = 16.0 * rod.intervals * testing::kEps;
  EXPECT_TRUE(CompareScalars(problem.breakdown().energy, E, tol * E));
  EXPECT_TRUE(CompareScalars(problem.breakdown().energy_term, 2.5 * E / L, tol * 2.5 * E / L));
  EXPECT_EQ(problem.breakdown().distance_term, 0.0);
  EXPECT_EQ(problem.cost(), problem.breakdown().energy_term);
  // ∇(W1 E/L) = W1/L dE/dw; on the arc dE/dm_x = M L / EI.
  const double dE = 2.5 / L * M * L / EI;
  EXPECT_TRUE(CompareScalars(problem.cost_gradient()(3), dE, tol * dE));
}

TEST(ShapeProblem, DistanceTermVanishesAtPointsSampledFromTheConfiguration) {
  // Objective points sampled between the coarse nodes of a fine integration (8× the intervals) at
  // the same w. Their distance to the coarse Hermite curve is bounded by the Hermite error
  // h⁴/384 max|p''''| plus the RK4 errors of both integrations. max|p''''| is measured on the fine
  // nodes by fourth differences (their O(h_f²) error and the variation inside a fine interval are
  // covered by a factor 2).
  for (ConstitutiveModel model : {ConstitutiveModel::Cosserat, ConstitutiveModel::Kirchhoff}) {
    const ClampedRod coarse = loaded_rod(model, 20);
    ClampedRod fine = coarse;
    fine.intervals = 160;
    const Vector6d w = base_wrench(coarse);
    const RodConfiguration f = integrate(fine, Wrench::from_vector(w));
    const double hf = fine.step(), h = coarse.step(), L = coarse.properties.length;
    double p4 = 0.0, kappa = 0.0;
    for (int i = 0; i + 4 < f.nodes(); ++i) {
      const Eigen::Vector3d d4 =
          f.p[i] - 4.0 * f.p[i + 1] + 6.0 * f.p[i + 2] - 4.0 * f.p[i + 3] + f.p[i + 4];
      p4 = std::max(p4, d4.norm() / std::pow(hf, 4));
    }
    for (const Eigen::Vector3d& u : f.u) kappa = std::max(kappa, u.norm());
    const double hermite = std::pow(h, 4) / 384.0 * 2.0 * p4;
    const double bound = hermite + testing::rk4_error_bound(L, kappa, coarse.intervals) +
                         testing::rk4_error_bound(L, kappa, fine.intervals);
    ShapeTarget target;
    for (int j = 3; j < fine.intervals; j += 10) target.points.push_back(f.p[j]);  // off-node
    target.distance_smoothing = 0.0;  // the exact Σ dist (the smoothed form has its own test)
    ShapeProblem problem(coarse, target);
    problem.evaluate(w);
    EXPECT_LE(problem.breakdown().max_distance, bound) << to_string(model);
    EXPECT_TRUE(CompareScalars(
        problem.breakdown().distance_term,
        target.distance_weight *
            [&] {
              double sum = 0.0;
              for (double d : problem.breakdown().distances) sum += d;
              return sum;
            }(),
        1e-15));
    RecordProperty(to_string(model) + "_max_distance",
                   testing::scientific(problem.breakdown().max_distance));
    RecordProperty(to_string(model) + "_bound", testing::scientific(bound));
    RecordProperty(to_string(model) + "_hermite_part", testing::scientific(hermite));
  }
}

TEST(ShapeProblem, ASecondCallAtTheSameWrenchReturnsTheSameResults) {
  ShapeProblem problem = make_problem(ConstitutiveModel::Cosserat, false);
  const Vector6d w = base_wrench(problem.rod());
  problem.evaluate(w);
  const Eigen::VectorXd g = problem.constraints();
  const double cost = problem.cost();
  problem.evaluate(w);
  EXPECT_EQ(problem.cost(), cost);
  problem.evaluate(1.1 * w);
  EXPECT_NE(problem.cost(), cost);
  problem.evaluate(w);
  EXPECT_EQ(problem.cost(), cost);
  EXPECT_TRUE(CompareMatrices(problem.constraints(), g, 0.0));
}

TEST(ShapeProblem, BadInputThrowsInputErrorNamingTheField) {
  const ClampedRod rod = testing::rubber_band(ConstitutiveModel::Cosserat, 20);
  ShapeTarget good;
  good.points = {{0.0, 0.05, 0.2}};
  auto with_target = [&](ShapeTarget target) {
    return input_error_message([&] { ShapeProblem problem(rod, target); });
  };
  ShapeTarget t = good;
  t.points.clear();
  EXPECT_NE(with_target(t).find("ShapeTarget.points"), std::string::npos) << with_target(t);
  t = good;
  t.points.push_back({0.0, std::nan(""), 0.1});
  EXPECT_NE(with_target(t).find("ShapeTarget.points[1]"), std::string::npos) << with_target(t);
  t = good;
  t.distance_weight = -0.5;
  EXPECT_NE(with_target(t).find("ShapeTarget.distance_weight"), std::string::npos)
      << with_target(t);
  t = good;
  t.energy_weight = 0.0;
  t.distance_weight = 0.0;
  EXPECT_NE(with_target(t).find("both 0"), std::string::npos) << with_target(t);

  Workspace ws;
  ws.inside.push_back({Eigen::Vector3d::Zero(), -0.2});
  const std::string radius = input_error_message([&] { ShapeProblem problem(rod, good, ws); });
  EXPECT_NE(radius.find("Workspace.inside[0].radius"), std::string::npos) << radius;
  const auto reach_error = [&](double inner, double outer, double x) {
    Workspace shell;
    shell.reach = Workspace::ReachShell{{x, 0.0, 0.0}, inner, outer, Eigen::Vector3d::Zero()};
    return input_error_message([&] { ShapeProblem problem(rod, good, shell); });
  };
  EXPECT_NE(reach_error(0.0, -0.5, 0.0).find("Workspace.reach.outer_radius"), std::string::npos);
  EXPECT_NE(reach_error(-0.1, 0.5, 0.0).find("Workspace.reach.inner_radius"), std::string::npos);
  EXPECT_NE(reach_error(0.6, 0.5, 0.0).find("empty shell"), std::string::npos);
  EXPECT_NE(reach_error(0.1, 0.5, std::nan("")).find("Workspace.reach.center"), std::string::npos);
  for (double bad : {0.0, -1.0}) {
    StrainLimits limits;
    limits.max_curvature = bad;
    const std::string message =
        input_error_message([&] { ShapeProblem problem(rod, good, {}, {}, limits); });
    EXPECT_NE(message.find("StrainLimits.max_curvature"), std::string::npos) << message;
  }
  ClampedRod bad_rod = rod;
  bad_rod.properties.length = -1.0;
  const std::string length = input_error_message([&] { ShapeProblem problem(bad_rod, good); });
  EXPECT_NE(length.find("RodProperties.length"), std::string::npos) << length;
  WrenchBounds bounds;
  bounds.lower(4) = 1.0;
  bounds.upper(4) = -1.0;
  const std::string wrench =
      input_error_message([&] { ShapeProblem problem(rod, good, {}, {}, {}, bounds); });
  EXPECT_NE(wrench.find("WrenchBounds.moment.y"), std::string::npos) << wrench;
}

}  // namespace
}  // namespace test_shape_problem
}  // namespace rodshape

namespace rodshape {
namespace test_shape_problem {
namespace {

// The smoothed sum of distances: ρ(d) = sqrt(d² + δ²) - δ lies within δ of d, below it, and its
// gradient (ρ.(d) ∇d) is checked against finite differences by the cost-gradient tests above.
TEST(ShapeProblem, SmoothedDistanceTermIsWithinDeltaOfTheSum) {
  const ClampedRod rod = testing::rubber_band(ConstitutiveModel::Cosserat, 20);
  const Vector6d w = (Vector6d() << -0.3, 0.1, 0.2, 0.02, 0.05, -0.01).finished();
  ShapeTarget exact;
  exact.points = {{0.05, 0.0, 0.2}, {0.0, 0.03, 0.1}};
  exact.energy_weight = 0.0;
  exact.distance_smoothing = 0.0;
  ShapeTarget smooth = exact;
  smooth.distance_smoothing = 1e-2;  // large, so the difference is far above round-off
  ShapeProblem p_exact(rod, exact), p_smooth(rod, smooth);
  p_exact.evaluate(w);
  p_smooth.evaluate(w);
  double expected = 0.0;
  for (double d : p_exact.breakdown().distances) expected += std::sqrt(d * d + 1e-4) - 1e-2;
  EXPECT_NEAR(p_smooth.breakdown().distance_term, expected, 1e-15);
  EXPECT_LT(p_smooth.breakdown().distance_term, p_exact.breakdown().distance_term);
  EXPECT_GT(p_smooth.breakdown().distance_term,
            p_exact.breakdown().distance_term - 2 * smooth.distance_smoothing);
}

}  // namespace
}  // namespace test_shape_problem
}  // namespace rodshape
