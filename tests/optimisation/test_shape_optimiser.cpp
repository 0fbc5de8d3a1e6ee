// test_shape_optimiser.cpp: optimise_shape() with IPOPT on the paper's rubber band.
//
// The oracle is a known equilibrium: integrate the band at a base wrench w_gen and take objective
// points on it, at s = (i + ½) L / 10 (between the nodes of the optimiser's grid). That shape
// passes through every point at F(w_gen) = W1 E_gen / L, so the optimum must fit the points and
// cannot need more energy. Constraints are then added that cut that optimum off, and the tests
// check that the optimum respects them with the multiplier signs of the KKT conditions.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <string>

#include "optimisation/ipopt_derivative_test.hpp"
#include "optimisation_fixtures.hpp"
#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/error.hpp"
#include "rodshape/optimisation/shape_optimiser.hpp"
#include "support/input_error.hpp"

namespace rodshape {
namespace test_shape_optimiser {
namespace {

using testing::rubber_band;

constexpr int kIntervals = 64;  // s_i = i L / 64: no objective point sits on a node
constexpr int kPoints = 10;

/// A moderate, non-planar base wrench: bending moments of ~2 EI/L and forces of ~0.5 EI/L².
Vector6d generating_wrench() {
  Vector6d w;
  w << 0.20, -0.12, 0.05, 0.09, -0.14, 0.01;
  return w;
}

/// p(s) of the band at `w`, integrated exactly to s on a rod of length s (no interpolation).
Eigen::Vector3d point_at(const ClampedRod& rod, const Vector6d& w, double s) {
  ClampedRod part = rod;
  part.properties.length = s;
  part.intervals = 200;
  return integrate(part, BaseWrench::from_vector(w)).p.back();
}

/// Objective points on the band at `w`, s = (i + ½) L / 10. The distances are squared: with the
/// paper's Σ dist and points the rod can reach exactly, the optimum sits on the kink of |·| at
/// dist = 0, where IPOPT (a smooth NLP solver) gets within round-off of w_gen but cannot certify
/// optimality (it ends at max_iter or Restoration_Failed). Σ dist² is smooth; with W2 = 100 /m²
/// against W1 = 1e-3 the fit dominates: the energy term moves the optimum by ~0.1 mm.
ShapeTarget target_on(const ClampedRod& rod, const Vector6d& w, double W1, double W2) {
  ShapeTarget target;
  const double L = rod.properties.length;
  for (int i = 0; i < kPoints; ++i)
    target.points.push_back(point_at(rod, w, (i + 0.5) * L / kPoints));
  target.squared_distances = true;
  target.energy_weight = W1;
  target.distance_weight = W2;
  return target;
}

/// max over nodes of |u_i - ũ|.
double max_curvature(const ClampedRod& rod, const RodConfiguration& c) {
  double kappa = 0.0;
  for (const Eigen::Vector3d& u : c.u) kappa = std::max(kappa, (u - rod.properties.u_rest).norm());
  return kappa;
}

/// Runs optimise_shape and reports its time and iterations in the test's XML properties.
ShapeResult timed_optimise(ShapeProblem& problem,
                           const Vector6d& guess,
                           ShapeOptimiserOptions options = {}) {
  // RODSHAPE_TEST_IPOPT_PRINT_LEVEL=5 shows IPOPT's iterations when a test needs diagnosing.
  if (const char* level = std::getenv("RODSHAPE_TEST_IPOPT_PRINT_LEVEL"))
    options.print_level = std::atoi(level);
  const auto start = std::chrono::steady_clock::now();
  ShapeResult solution = optimise_shape(problem, BaseWrench::from_vector(guess), options);
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  ::testing::Test::RecordProperty("iterations", solution.ipopt.iterations);
  ::testing::Test::RecordProperty("milliseconds", std::to_string(ms));
  std::printf("    [%s] %s (%.1f ms)\n", to_string(solution.status).c_str(),
              solution.message.c_str(), ms);
  return solution;
}

class ShapeOptimiserTest : public ::testing::Test {
 protected:
  ClampedRod rod = rubber_band(ConstitutiveModel::Cosserat, kIntervals);
  Vector6d w_gen = generating_wrench();
  RodConfiguration generated = integrate(rod, BaseWrench::from_vector(w_gen));
  ShapeTarget target = target_on(rod, w_gen, 1e-3, 100.0);
};

// ---- (a) derivatives --------------------------------------------------------------------------

// IPOPT's derivative checker compares ∇F and dg/dw with forward differences,
// |FD - exact| / max(|FD|, 1) ≥ tol flags an entry. Error model of the forward difference with
// step h: h |f''| / 2 + 2 ε_f |f| / h, ε_f ≈ 64 steps × ε ≈ 1.4e-14 the round-off of one
// evaluation. With h = 1e-7 (w of order 0.1), |f''| ≲ 2e3 (|u|² rows: 2/EI² ≈ 1.3e3 per N·m²) and
// |f| ≲ 30: ≲ 1e-4 + 1e-5 in the worst row, far less in most. tol = 1e-3 keeps a margin of 10 while
// a wrong term (a sign, a missing envelope term, a transposed block) errs by O(1) in relative
// terms.
TEST_F(ShapeOptimiserTest, IpoptDerivativeCheckerFindsNoErrors) {
  Workspace workspace;
  workspace.half_spaces.push_back({Eigen::Vector3d(1.0, 0.0, 0.0), 0.5});
  workspace.inside.push_back({Eigen::Vector3d(0.0, 0.0, 0.1), 0.5});
  workspace.outside.push_back({Eigen::Vector3d(0.3, 0.3, 0.0), 0.05});
  Grasp grasp;
  grasp.released[0] = true;  // n_x
  grasp.released[3] = true;  // m_x
  StrainLimits limits;
  limits.max_curvature = 5.0;
  limits.max_axial_strain = 0.01;
  ShapeProblem problem(rod, target, workspace, grasp, limits);
  ASSERT_GT(problem.constraint_count(), 2 * (kIntervals + 1));

  // Away from w_gen, so that every distance is well above zero (|·| is smooth there).
  Vector6d w = 0.7 * w_gen;
  w(4) += 0.03;
  problem.evaluate(w);
  for (double d : problem.breakdown().distances) ASSERT_GT(d, 1e-4);

  const detail::DerivativeTestReport report =
      detail::run_derivative_test(problem, w, /*tolerance=*/1e-3, /*perturbation=*/1e-7);
  EXPECT_EQ(report.error_count, 0) << report.log;
  EXPECT_TRUE(report.no_errors_line) << report.log;
  // It did check the constraint Jacobian.
  EXPECT_NE(report.log.find("jac_g"), std::string::npos) << report.log;
}

// ---- (b) the known equilibrium ------------------------------------------------------------------

TEST_F(ShapeOptimiserTest, RecoversAKnownEquilibriumFromAZeroGuess) {
  ShapeProblem problem(rod, target);
  const ShapeResult solution = timed_optimise(problem, Vector6d::Zero());
  ASSERT_TRUE(solution.converged()) << solution.message;
  EXPECT_EQ(solution.ipopt.application_status_name.rfind("Solve", 0), 0u);
  for (int i = 0; i < kPoints; ++i) EXPECT_LT(solution.cost.distances[i], 0.5e-3) << "point " << i;

  // F(w*) ≤ F(w_gen) = W1 E_gen / L (all distances zero up to the O(h⁴) Hermite error) if IPOPT
  // found the minimum of w_gen's basin, and the distance term is ≥ 0, so
  // E* ≤ E_gen + (L / W1) (F* - F(w_gen)). At tol = 1e-8 the excess F* - min F ≈ ½ ∇Fᵀ H⁻¹ ∇F is
  // far below 1e-8 (2e-5 of F_gen); that margin allows (L / W1)·1e-8 = 2.9e-6 J, 2e-5 of E_gen.
  problem.evaluate(w_gen);
  const double F_gen = problem.cost();
  const double E_gen = generated.energy;
  EXPECT_LE(solution.cost.cost, F_gen + 1e-8);
  EXPECT_LE(solution.cost.energy, E_gen + (rod.properties.length / 1e-3) * 1e-8)
      << "E* = " << solution.cost.energy << ", E_gen = " << E_gen;
  // The configuration is the one at the returned wrench.
  EXPECT_TRUE(solution.configuration.base_wrench().to_vector().isApprox(
      solution.base_wrench.to_vector(), 1e-12));
  ASSERT_TRUE(solution.stability.has_value());
  EXPECT_EQ(solution.starts_tried, 1);
}

TEST_F(ShapeOptimiserTest, ARunDoesNotChangeTheNext) {
  // The thread's IPOPT session is reused while the options stay the same: a solve after another,
  // different one (constrained, other options in between) is bit for bit a first solve.
  ShapeProblem problem(rod, target);
  const ShapeResult first = optimise_shape(problem, BaseWrench{});
  ShapeOptimiserOptions other;
  other.tolerance = 1e-6;
  StrainLimits limits;
  limits.max_curvature = 5.0;
  ShapeProblem constrained(rod, target, {}, {}, limits);
  (void)optimise_shape(constrained, BaseWrench::from_vector(0.5 * w_gen));
  (void)optimise_shape(constrained, BaseWrench::from_vector(0.5 * w_gen), other);
  (void)optimise_shape(problem, BaseWrench::from_vector(0.5 * w_gen));
  ShapeProblem fresh(rod, target);
  const ShapeResult again = optimise_shape(fresh, BaseWrench{});
  EXPECT_EQ(again.ipopt.iterations, first.ipopt.iterations);
  EXPECT_EQ(again.base_wrench.to_vector(), first.base_wrench.to_vector());
  EXPECT_EQ(again.cost.cost, first.cost.cost);
}

TEST_F(ShapeOptimiserTest, MultiStartKeepsTheBestConvergedStart) {
  ShapeProblem problem(rod, target);
  const Vector6d guess = 0.3 * w_gen;
  ShapeOptimiserOptions single;
  const ShapeResult one = timed_optimise(problem, guess, single);
  ShapeOptimiserOptions multi;
  multi.multi_starts = 3;
  const ShapeResult best = timed_optimise(problem, guess, multi);
  EXPECT_EQ(best.starts_tried, 4);
  ASSERT_TRUE(best.converged()) << best.message;
  // The guess's own run is among the starts (IPOPT is deterministic), so the best is no worse.
  // ... up to pick_best's tie band, 1e-9 max(1, |F|), within which the lower energy wins.
  EXPECT_LE(best.cost.cost, one.cost.cost + 1e-9 * std::max(1.0, std::abs(one.cost.cost)));
}

// ---- (c) an active workspace constraint ---------------------------------------------------------

TEST_F(ShapeOptimiserTest, ActiveHalfSpaceHoldsWithAPositiveMultiplier) {
  // Cut 1 cm off the unconstrained optimum's tip along the clamp-to-tip direction: nᵀ p ≤ offset.
  const Eigen::Vector3d tip = generated.p.back();
  const Eigen::Vector3d normal = tip.normalized();
  const double offset = normal.dot(tip) - 0.01;
  Workspace workspace;
  workspace.half_spaces.push_back({normal, offset});
  ShapeProblem problem(rod, target, workspace);
  ShapeOptimiserOptions options;
  const ShapeResult solution = timed_optimise(problem, Vector6d::Zero(), options);
  ASSERT_TRUE(solution.converged()) << solution.message;

  const double g = normal.dot(solution.configuration.p.back());
  EXPECT_LE(g, offset + options.constraint_tolerance);
  // Active (the optimum lies on the plane) ...
  EXPECT_NEAR(g, offset, 1e-6);
  // ... and the multiplier says the plane holds the tip back: IPOPT's Lagrangian is F + λ g, so an
  // upper bound that is active has λ > 0, and stationarity ∇F = -λ ∇g (no other constraint).
  ASSERT_EQ(solution.ipopt.constraint_multipliers.size(), 1u);
  const double lambda = solution.ipopt.constraint_multipliers[0];
  EXPECT_GT(lambda, 1e-6);
  problem.evaluate(solution.base_wrench.to_vector());
  const Vector6d stationarity =
      problem.cost_gradient() + lambda * problem.constraint_jacobian().row(0).transpose();
  // IPOPT stopped (Solve_Succeeded) with its scaled dual infeasibility ≤ tol·s_d, in the ∞-norm.
  // Its gradient-based scaling leaves F and g unscaled when their gradients at the start are
  // below nlp_scaling_max_gradient = 100, and s_d = max(100, (|λ| + |z|)/(m + n))/100 = 1 for
  // |λ| < 700: so ||∇F + λ ∇g||_∞ ≤ tol here, up to the round-off of recomputing it.
  ASSERT_EQ(solution.ipopt.application_status_name, "Solve_Succeeded");
  ASSERT_LT(lambda, 700.0);
  EXPECT_LE(stationarity.lpNorm<Eigen::Infinity>(), options.tolerance) << stationarity.transpose();
  problem.evaluate(Vector6d::Zero());  // the start: no scaling
  ASSERT_LT(problem.cost_gradient().lpNorm<Eigen::Infinity>(), 100.0);
  ASSERT_LT(problem.constraint_jacobian().row(0).lpNorm<Eigen::Infinity>(), 100.0);
  // The constraint costs something: the fit is worse than without it.
  EXPECT_GT(solution.cost.max_distance, 1e-3);
}

// ---- (d) a grasp that cannot transmit m_x -------------------------------------------------------

TEST_F(ShapeOptimiserTest, GraspWithoutMomentXGivesZeroTipMomentX) {
  // The generating shape has a non-zero tip moment about its own x axis, so the constraint bites.
  const double mx_gen = (generated.R.back().transpose() * generated.m.back()).x();
  ASSERT_GT(std::abs(mx_gen), 1e-2);

  Grasp grasp;
  grasp.released[3] = true;
  ShapeProblem problem(rod, target, {}, grasp);
  ShapeOptimiserOptions options;
  const ShapeResult solution = timed_optimise(problem, Vector6d::Zero(), options);
  ASSERT_TRUE(solution.converged()) << solution.message;
  const RodConfiguration& c = solution.configuration;
  const double mx = (c.R.back().transpose() * c.m.back()).x();
  EXPECT_LE(std::abs(mx), options.constraint_tolerance);
}

// ---- (e) a curvature limit ----------------------------------------------------------------------

TEST_F(ShapeOptimiserTest, CurvatureLimitHoldsAtEveryNode) {
  ShapeProblem free_problem(rod, target);
  const ShapeResult free = timed_optimise(free_problem, Vector6d::Zero());
  ASSERT_TRUE(free.converged()) << free.message;
  const double kappa_free = max_curvature(rod, free.configuration);

  StrainLimits limits;
  limits.max_curvature = 0.8 * kappa_free;
  ShapeProblem problem(rod, target, {}, {}, limits);
  ShapeOptimiserOptions options;
  const ShapeResult solution = timed_optimise(problem, free.base_wrench.to_vector(), options);
  ASSERT_TRUE(solution.converged()) << solution.message;
  const double kappa2 = *limits.max_curvature * *limits.max_curvature;
  double largest = 0.0;
  for (int i = 0; i < solution.configuration.nodes(); ++i) {
    const double du2 = (solution.configuration.u[i] - rod.properties.u_rest).squaredNorm();
    EXPECT_LE(du2, kappa2 + options.constraint_tolerance) << "node " << i;
    largest = std::max(largest, du2);
  }
  EXPECT_NEAR(largest, kappa2, 1e-6 * kappa2);  // the limit is active somewhere
}

// ---- (f) statuses and options -------------------------------------------------------------------

TEST_F(ShapeOptimiserTest, IterationLimitIsReported) {
  ShapeProblem problem(rod, target);
  ShapeOptimiserOptions options;
  options.max_iterations = 2;
  const ShapeResult solution = timed_optimise(problem, Vector6d::Zero(), options);
  EXPECT_EQ(solution.status, SolveStatus::IterationLimit) << solution.message;
  EXPECT_EQ(solution.ipopt.application_status_name, "Maximum_Iterations_Exceeded");
  EXPECT_NE(solution.message.find("Maximum_Iterations_Exceeded"), std::string::npos);
  EXPECT_EQ(solution.ipopt.iterations, 2);
}

TEST_F(ShapeOptimiserTest, UnreachableWorkspaceIsNeverConverged) {
  // The tip must lie in a ball 1 m away: the 0.29 m band cannot reach it.
  Workspace workspace;
  workspace.inside.push_back({Eigen::Vector3d(0.0, 0.0, 1.0), 0.1});
  ShapeProblem problem(rod, target, workspace);
  ShapeOptimiserOptions options;
  options.max_iterations = 50;
  const ShapeResult solution = timed_optimise(problem, Vector6d::Zero(), options);
  EXPECT_NE(solution.status, SolveStatus::Converged) << solution.message;
  EXPECT_GT(solution.max_constraint_violation, options.constraint_tolerance);
  EXPECT_NE(solution.message.find(solution.ipopt.application_status_name), std::string::npos);
}

TEST_F(ShapeOptimiserTest, ConvergedImpliesFeasibleAcrossStartsAndLimits) {
  // A box of ±2 cm around the generating tip and a curvature limit the generating shape nearly
  // meets: feasible, so some runs converge; cut short, others do not. Whatever the outcome,
  // "converged" must mean "feasible to constraint_tolerance", checked here on the returned
  // configuration (optimise_shape's own measure, max_constraint_violation, is what it maps
  // converged runs with, so it cannot disagree with the status).
  Workspace workspace;
  const Eigen::Vector3d tip = generated.p.back();
  workspace.box =
      Workspace::Box{tip - Eigen::Vector3d::Constant(0.02), tip + Eigen::Vector3d::Constant(0.02)};
  StrainLimits limits;
  limits.max_curvature = 0.9 * max_curvature(rod, generated);
  ShapeProblem problem(rod, target, workspace, {}, limits);
  ShapeOptimiserOptions options;
  int converged = 0;
  for (int iterations : {3, 10, 300}) {
    options.max_iterations = iterations;
    const ShapeResult solution = timed_optimise(problem, Vector6d::Zero(), options);
    if (!solution.converged()) continue;
    ++converged;
    const RodConfiguration& c = solution.configuration;
    EXPECT_TRUE(workspace.contains(c.tip(), options.constraint_tolerance))
        << solution.message << "; tip " << c.p.back().transpose();
    const double kappa2 = *limits.max_curvature * *limits.max_curvature;
    for (int i = 0; i < c.nodes(); ++i) {
      EXPECT_LE((c.u[i] - rod.properties.u_rest).squaredNorm(),
                kappa2 + options.constraint_tolerance)
          << solution.message << "; node " << i;
    }
  }
  EXPECT_GE(converged, 1);
}

TEST_F(ShapeOptimiserTest, PrintsNothingAtPrintLevelZero) {
  ShapeProblem problem(rod, target);
  ::testing::internal::CaptureStdout();
  const ShapeResult solution =
      optimise_shape(problem, BaseWrench::from_vector(Vector6d::Zero()), {});
  std::fflush(stdout);
  const std::string printed = ::testing::internal::GetCapturedStdout();
  EXPECT_EQ(printed, "");
}

TEST(ShapeOptimiserOptions, BadOptionsNameTheField) {
  const auto message_of = [](const ShapeOptimiserOptions& options) {
    return testing::input_error_message([&] { options.validate(); });
  };
  ShapeOptimiserOptions options;
  EXPECT_EQ(message_of(options), "");
  options.max_iterations = -1;
  EXPECT_NE(message_of(options).find("ShapeOptimiserOptions.max_iterations"), std::string::npos);
  options = {};
  options.tolerance = 0.0;
  EXPECT_NE(message_of(options).find("ShapeOptimiserOptions.tolerance"), std::string::npos);
  options = {};
  options.constraint_tolerance = std::nan("");
  EXPECT_NE(message_of(options).find("ShapeOptimiserOptions.constraint_tolerance"),
            std::string::npos);
  options = {};
  options.multi_starts = -2;
  EXPECT_NE(message_of(options).find("ShapeOptimiserOptions.multi_starts"), std::string::npos);
  options = {};
  options.print_level = 13;
  EXPECT_NE(message_of(options).find("ShapeOptimiserOptions.print_level"), std::string::npos);

  // optimise_shape validates before touching IPOPT.
  ShapeTarget target;
  target.points = {Eigen::Vector3d(0.0, 0.0, 0.2)};
  ShapeProblem problem(rubber_band(ConstitutiveModel::Cosserat, kIntervals), target);
  options = {};
  options.tolerance = -1.0;
  EXPECT_THROW(optimise_shape(problem, BaseWrench{}, options), InputError);
}

}  // namespace
}  // namespace test_shape_optimiser
}  // namespace rodshape
