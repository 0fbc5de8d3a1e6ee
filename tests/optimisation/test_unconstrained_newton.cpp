// test_unconstrained_newton.cpp: the dense Newton iteration that stands in for IPOPT on problems
// without rows or bounds (src/optimisation/unconstrained_newton.hpp). Its promise is IPOPT's
// result: the same optimum to the solver tolerance, the same statuses and stopping test.
//
// Tolerance of the comparison: both solvers stop once s_f |∇F|_∞ ≤ tol. Near a strict minimum,
// ∇F(w) ≈ H (w - w*), so two points that both pass the test lie within
// |w_a - w_b|_2 ≤ (|∇F(w_a)|_2 + |∇F(w_b)|_2) / λ_min(H) of each other, H the Hessian there
// (λ_min from the differenced Hessian; a factor 2 covers the second-order term and the
// differencing error of √ε relative).
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>
#include <optional>
#include <tuple>

#include "optimisation/ipopt_adapter.hpp"
#include "optimisation/unconstrained_newton.hpp"
#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/optimisation/shape_optimiser.hpp"
#include "rodshape/samples/rubber_band.hpp"

namespace rodshape {
namespace test_unconstrained_newton {
namespace {

using detail::IpoptRun;
using detail::IpoptSession;
using detail::unconstrained_newton;
using detail::unconstrained_newton_serves;

/// The paper's experiment's target (bench/bench_plan.cpp): ten points on the band bent in 3D,
/// Σ dist with W1 = 1e-3, W2 = 1, or Σ dist² (smooth at dist = 0) when `squared`.
ShapeTarget paper_target(bool squared) {
  const RodConfiguration fine = integrate(samples::rubber_band(ConstitutiveModel::Cosserat, 200),
                                          {{-0.6, 0.2, 0.0}, {0.02, 0.12, 0.01}});
  ShapeTarget target;
  for (int i = 0; i < 10; ++i) target.points.push_back(fine.p[20 * i + 10]);
  target.energy_weight = 1e-3;
  target.distance_weight = squared ? 100.0 : 1.0;
  target.squared_distances = squared;
  return target;
}

/// λ_min of the symmetrised forward-difference Hessian of F at w.
double least_curvature(ShapeProblem& problem, const Vector6d& w) {
  problem.evaluate(w);
  const Vector6d g = problem.cost_gradient();
  const Vector6d units = problem.rod().properties.bending_wrench_units();
  Matrix6d H;
  for (int j = 0; j < 6; ++j) {
    const double h =
        std::sqrt(std::numeric_limits<double>::epsilon()) * std::max(std::abs(w[j]), units[j]);
    Vector6d shifted = w;
    shifted[j] += h;
    problem.evaluate(shifted);
    H.col(j) = (problem.cost_gradient() - g) / h;
  }
  H = 0.5 * (H + H.transpose()).eval();
  return Eigen::SelfAdjointEigenSolver<Matrix6d>(H).eigenvalues().minCoeff();
}

double gradient_norm(ShapeProblem& problem, const Vector6d& w) {
  problem.evaluate(w);
  return problem.cost_gradient().norm();
}

struct Case {
  bool squared;
  Vector6d start;
};

/// (case, Hessian model): every model reaches IPOPT's optimum.
class UnconstrainedNewton : public ::testing::TestWithParam<std::tuple<int, detail::HessianModel>> {
};

TEST_P(UnconstrainedNewton, ReachesIpoptsOptimumWithinTheStoppingTest) {
  const ClampedRod rod = samples::rubber_band();
  Vector6d near_optimum;
  near_optimum << -0.5, 0.15, 0.0, 0.02, 0.1, 0.0;
  const Case cases[] = {{false, Vector6d::Zero()},
                        {true, Vector6d::Zero()},
                        {false, near_optimum},
                        {true, near_optimum}};
  const Case& c = cases[std::get<0>(GetParam())];
  const detail::HessianModel model = std::get<1>(GetParam());
  ShapeProblem problem(rod, paper_target(c.squared));
  const ShapeOptimiserOptions options;
  ASSERT_TRUE(unconstrained_newton_serves(problem, true));

  IpoptSession session(options, true);
  const int before = problem.integrations();
  const IpoptRun ipopt = session.run(problem, c.start);
  const int by_ipopt = problem.integrations() - before;
  const IpoptRun newton = unconstrained_newton(problem, c.start, options, std::nullopt, model);
  const int by_newton = problem.integrations() - before - by_ipopt;
  ASSERT_EQ(ipopt.status, SolveStatus::Converged) << ipopt.details.application_status_name;
  ASSERT_EQ(newton.status, SolveStatus::Converged) << newton.details.application_status_name;
  EXPECT_EQ(newton.details.solver, "dense Newton");
  EXPECT_EQ(ipopt.details.solver, "IPOPT");

  const double spread = 2.0 * (gradient_norm(problem, ipopt.w) + gradient_norm(problem, newton.w)) /
                        least_curvature(problem, ipopt.w);
  ASSERT_GT(least_curvature(problem, ipopt.w), 0.0) << "not a strict minimum";
  EXPECT_LE((newton.w - ipopt.w).norm(), spread)
      << "IPOPT " << ipopt.w.transpose() << "\nNewton " << newton.w.transpose();
  problem.evaluate(newton.w);
  EXPECT_DOUBLE_EQ(newton.details.objective, problem.cost());
  // IPOPT differences the Hessian at every iteration (7 integrations an iteration); the SR1
  // models difference it once (and after a shortened step), so more iterations (superlinear
  // convergence, not quadratic) but fewer integrations.
  if (model == detail::HessianModel::DifferencedEveryIteration) return;
  EXPECT_LT(by_newton, by_ipopt) << "iterations: IPOPT " << ipopt.details.iterations << ", Newton "
                                 << newton.details.iterations;
}

INSTANTIATE_TEST_SUITE_P(
    PaperTarget,
    UnconstrainedNewton,
    ::testing::Combine(::testing::Range(0, 4),
                       ::testing::Values(detail::HessianModel::Sr1Updated,
                                         detail::HessianModel::Sr1UntilBacktrack,
                                         detail::HessianModel::DifferencedEveryIteration)));

TEST(Sr1Update, SatisfiesTheSecantEquationAndStaysSymmetric) {
  Matrix6d B = Matrix6d::Identity();
  B(0, 1) = B(1, 0) = 0.3;
  Vector6d s, y;
  s << 1.0, -2.0, 0.5, 0.0, 3.0, -1.0;
  y << 2.0, 1.0, -1.0, 4.0, 0.5, 2.0;
  detail::sr1_update(s, y, B);
  EXPECT_LE((B * s - y).norm(), 1e-13 * y.norm());
  EXPECT_EQ(B, B.transpose());
}

TEST(Sr1Update, LeavesTheModelWhenTheUpdateIsUndefined) {
  Matrix6d B = 2.0 * Matrix6d::Identity();
  const Matrix6d unchanged = B;
  Vector6d s = Vector6d::Unit(0), y = 2.0 * Vector6d::Unit(0);
  detail::sr1_update(s, y, B);  // B s = y already: r = 0
  EXPECT_EQ(B, unchanged);
  y += Vector6d::Unit(1);  // r = e_1 is orthogonal to s = e_0: rᵀs = 0
  detail::sr1_update(s, y, B);
  EXPECT_EQ(B, unchanged);
}

TEST(UnconstrainedNewtonServes, OnlyProblemsWithoutRowsOrBounds) {
  const ClampedRod rod = samples::rubber_band();
  const ShapeTarget target = paper_target(false);
  ShapeProblem plain(rod, target);
  EXPECT_TRUE(unconstrained_newton_serves(plain, true));
  EXPECT_FALSE(unconstrained_newton_serves(plain, false));  // the limited-memory Hessian: IPOPT

  Workspace workspace;
  workspace.inside.push_back({Eigen::Vector3d::Zero(), 1.0});
  ShapeProblem with_row(rod, target, workspace);
  ASSERT_GT(with_row.constraint_count(), 0);
  EXPECT_FALSE(unconstrained_newton_serves(with_row, true));

  WrenchBounds bounds;
  bounds.upper(3) = 1.0;
  ShapeProblem bounded(rod, target, {}, {}, {}, bounds);
  ASSERT_EQ(bounded.constraint_count(), 0);
  EXPECT_FALSE(unconstrained_newton_serves(bounded, true));
}

TEST(UnconstrainedNewtonStatus, IterationLimitAsIpoptNamesIt) {
  ShapeProblem problem(samples::rubber_band(), paper_target(false));
  ShapeOptimiserOptions options;
  options.max_iterations = 0;
  const IpoptRun none = unconstrained_newton(problem, Vector6d::Zero(), options);
  EXPECT_EQ(none.status, SolveStatus::IterationLimit);
  EXPECT_EQ(none.details.application_status_name, "Maximum_Iterations_Exceeded");
  EXPECT_EQ(none.details.iterations, 0);
  EXPECT_EQ(none.w, Vector6d::Zero());  // no step taken
}

}  // namespace
}  // namespace test_unconstrained_newton
}  // namespace rodshape
