// test_secant_start.cpp: what a solve hands to the next continuation substep
// (src/solvers/secant_start.hpp). A solve without a predictor (the first substep) records the
// Euler error of its start, root - (w - J⁻¹ r) with the exact (r, J) at the guess w, so that the
// second substep's predictor is already of second order: the error is ½ w'' h² + O(h³), a quarter
// when the step h is halved.
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <numbers>

#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/samples/rubber_band.hpp"
#include "rodshape/solvers/shooting_residual.hpp"
#include "rodshape/solvers/shooting_solver.hpp"
#include "solvers/secant_start.hpp"
#include "support/analytic_rods.hpp"
#include "support/eigen_compare.hpp"
#include "support/solver_fixtures.hpp"

namespace rodshape {
namespace test_secant_start {
namespace {

using testing::CompareMatrices;
using testing::kEps;

using samples::bent_tip;

/// Euler's point w - J⁻¹ r for `tip` from the exact residual and Jacobian at w.
Vector6d euler_point(const ClampedRod& rod, const TipCondition& tip, const Vector6d& w) {
  RodConfiguration c;
  integrate(rod, Wrench::from_vector(w), c, Derivatives::Tip);
  Vector6d r;
  Matrix6d J;
  shooting_residual(tip, c, r, J);
  return w - Eigen::PartialPivLU<Matrix6d>(J).solve(r);
}

TEST(SecantStart, ASolveWithoutAPredictorRecordsItsStartsEulerErrorOfSecondOrder) {
  const ClampedRod rod = testing::rubber_band();
  ShootingOptions options;
  options.continuation = false;
  const ShootingResult start = solve_equilibrium(rod, ClampedTip{bent_tip()}, {}, options);
  ASSERT_TRUE(start.summary.converged()) << start.brief();
  const Vector6d w = start.base_wrench.to_vector();

  double error_at[2] = {0.0, 0.0};
  for (int k = 0; k < 2; ++k) {
    Pose moved = bent_tip();
    moved.position += Eigen::Vector3d(2e-3, 0.0, -1e-3) / (1 << k);  // h, then h / 2
    const TipCondition tip = ClampedTip{moved};
    detail::SecantStart secant;  // not valid: no predictor, as on a path's first substep
    const ShootingResult solved =
        detail::solve_equilibrium(rod, tip, start.base_wrench, options, &secant);
    ASSERT_TRUE(solved.summary.converged()) << solved.brief();
    ASSERT_TRUE(secant.valid);
    ASSERT_TRUE(secant.euler_error.has_value());
    // The same arithmetic as the solver's first evaluation (Output::Tip's tip derivatives are
    // Output::Full's bit for bit), so equal to round-off of the wrench's size.
    const Vector6d expected = solved.base_wrench.to_vector() - euler_point(rod, tip, w);
    EXPECT_TRUE(CompareMatrices(*secant.euler_error, expected, 4 * kEps * w.norm()));
    error_at[k] = secant.euler_error->norm();
  }
  // Of second order: halving the step quarters it (the O(h³) term and the roots' tolerance,
  // |J⁻¹| 2τ ≈ 1e-7 against errors of 1e-3, move the ratio by about 0.1 %).
  EXPECT_GT(error_at[0], 0.0);
  EXPECT_NEAR(error_at[0] / error_at[1], 4.0, 0.2);
}

}  // namespace
}  // namespace test_secant_start
}  // namespace rodshape
