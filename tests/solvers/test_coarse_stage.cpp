// The coarse stage (src/solvers/shooting_solver.cpp, CoarseStage): a solve's global phase
// (Levenberg–Marquardt, coarse_phase()) runs on the accuracy check's longer steps, and the chord
// steps are checked on them; the stage's last integration is the check's comparison run.
#include <gtest/gtest.h>

#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/samples/rubber_band.hpp"
#include "rodshape/solvers/integration_error.hpp"
#include "rodshape/solvers/shooting_residual.hpp"
#include "rodshape/solvers/shooting_solver.hpp"
#include "solvers/step_doubling.hpp"
#include "support/solver_fixtures.hpp"

namespace rodshape {
namespace test_coarse_stage {
namespace {

ShootingOptions tip_only_output() {
  ShootingOptions options;
  options.output_derivatives = Derivatives::None;  // the last chord step's integration is output
  return options;
}

// The bench's warm solve: the bent band's tip moved by 1 mm. The solve's estimate is
// integration_error_estimate()'s on the returned configuration, bit for bit, and the solve needs
// fewer integrations of the rod than the 5 chord steps and the check's run without the stage (7
// in all, 1 with derivatives).
TEST(CoarseStage, WarmSolveOnTheStageConvergesWithTheChecksEstimate) {
  const ClampedRod rod = samples::rubber_band(ConstitutiveModel::Cosserat, 100);
  const ShootingOptions options = tip_only_output();
  const ShootingResult solved =
      solve_equilibrium(rod, ClampedTip{samples::bent_tip()}, {}, options);
  ASSERT_TRUE(solved.summary.converged()) << solved.brief();
  Pose moved = samples::bent_tip();
  moved.position += Eigen::Vector3d(1e-3, 0.0, 0.0);
  const ClampedTip tip{moved};
  const ShootingResult warm = solve_equilibrium(rod, tip, solved.base_wrench, options);
  ASSERT_TRUE(warm.summary.converged()) << warm.brief();
  EXPECT_LE(shooting_residual(tip, warm.configuration).lpNorm<Eigen::Infinity>(),
            options.residual_tolerance);
  EXPECT_EQ(warm.summary.integration_error,
            integration_error_estimate(rod, warm.base_wrench, warm.configuration));
  EXPECT_EQ(warm.summary.jacobian_evaluations, 1) << warm.brief();
  // Without the stage: 1 + 5 rod integrations + the check's half-step run. With it (the rod's 100
  // intervals coarsened to 25): its one integration with derivatives and 6 chord steps, each about
  // a quarter of the rod's, 2 integrations of the rod, and the check's half-step run.
  EXPECT_EQ(warm.summary.integrations, 10) << warm.brief();
  EXPECT_EQ(warm.summary.chord_steps, 6) << warm.brief();
  // The same equilibrium as without the stage (the check off turns the stage off).
  ShootingOptions without = options;
  without.integration_tolerance = std::numeric_limits<double>::infinity();
  const ShootingResult plain = solve_equilibrium(rod, tip, solved.base_wrench, without);
  ASSERT_TRUE(plain.summary.converged()) << plain.brief();
  EXPECT_EQ(plain.summary.integrations, 6) << plain.brief();
  const Vector6d units = rod.properties.bending_wrench_units();
  EXPECT_LE(((warm.base_wrench.to_vector() - plain.base_wrench.to_vector()).cwiseQuotient(units))
                .lpNorm<Eigen::Infinity>(),
            1e-6);
}

// A cold solve's global phase on the stage's rod ends at the rod's own equilibrium: both solves'
// residuals are within τ, so the two roots differ by at most ||J⁻¹||_∞ 2τ (to first order).
TEST(CoarseStage, ColdSolveFromTheStageReachesTheRodsRoot) {
  const ClampedRod rod = samples::rubber_band(ConstitutiveModel::Cosserat, 100);
  const ClampedTip tip{samples::bent_tip()};
  ShootingOptions options = tip_only_output();
  options.continuation = false;
  const ShootingResult staged = solve_equilibrium(rod, tip, {}, options);
  options.integration_tolerance = std::numeric_limits<double>::infinity();  // no stage
  const ShootingResult plain = solve_equilibrium(rod, tip, {}, options);
  ASSERT_TRUE(staged.summary.converged()) << staged.brief();
  ASSERT_TRUE(plain.summary.converged()) << plain.brief();
  EXPECT_LE(shooting_residual(tip, staged.configuration).lpNorm<Eigen::Infinity>(),
            options.residual_tolerance);
  const Matrix6d J = testing::residual_jacobian(rod, tip, plain.base_wrench);
  const double bound = testing::inverse_inf_norm(J) * 2.0 * options.residual_tolerance;
  EXPECT_LE(
      (staged.base_wrench.to_vector() - plain.base_wrench.to_vector()).lpNorm<Eigen::Infinity>(),
      bound);
  // The global phase's Levenberg–Marquardt steps are the same in number on either rod here.
  EXPECT_EQ(staged.summary.iterations, plain.summary.iterations);
}

// Odd intervals and sub-steps: the check integrates at twice the sub-steps, so there is no coarse
// stage, and the solve is the one without the check's stage (the same iterates, bit for bit).
TEST(CoarseStage, NoStageWhereTheCheckRefines) {
  const ClampedRod rod = samples::rubber_band(ConstitutiveModel::Cosserat, 101);
  EXPECT_FALSE(detail::comparison_rod(rod).coarse);
  ShootingOptions options = tip_only_output();
  const ShootingResult checked =
      solve_equilibrium(rod, ClampedTip{samples::bent_tip()}, {}, options);
  options.integration_tolerance = std::numeric_limits<double>::infinity();
  const ShootingResult unchecked =
      solve_equilibrium(rod, ClampedTip{samples::bent_tip()}, {}, options);
  ASSERT_TRUE(checked.summary.converged()) << checked.brief();
  EXPECT_EQ(checked.base_wrench.to_vector(), unchecked.base_wrench.to_vector());
  EXPECT_EQ(checked.summary.integrations, unchecked.summary.integrations + 1);
}

}  // namespace
}  // namespace test_coarse_stage
}  // namespace rodshape
