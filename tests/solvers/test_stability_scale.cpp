// test_stability_scale.cpp: the conjugate-point test does not depend on units (issue 12, item 5).
// The bundled band pose (tip 0.12 m aside, 0.22 m up, turned 90° about y) with EIx, EIy, GJ given
// directly and Young's modulus from 3.2e6 Pa to 1e19 Pa: only EA and GA grow, the
// band tends to the Kirchhoff rod of the same bending stiffness, and its verdict (stable, as the
// paper's experiment) must not change. Before the fix it flipped: unstable at 1e13, stable at 1e15,
// unstable from 1e20.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

#include "rodshape/solvers/shooting_solver.hpp"
#include "rodshape/solvers/stability.hpp"
#include "support/solver_fixtures.hpp"

namespace rodshape {
namespace test_stability_scale {
namespace {

ClampedTip band_pose() {
  Pose pose;
  pose.position = {0.12, 0.0, 0.22};
  pose.rotation =
      Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitY()).toRotationMatrix();
  return ClampedTip{pose};
}

StabilityResult verdict(const ClampedRod& rod, const TipCondition& tip) {
  const ShootingResult solution = solve_equilibrium(rod, tip);
  EXPECT_TRUE(solution.summary.converged()) << solution.summary.message;
  return assess_stability(rod, solution.configuration, tip);
}

TEST(StabilityScale, BandPoseIsStableForYoungsModulusOverTwelveDecades) {
  // Up to E = 1e19 (EA L²/EI ≈ 1e16): beyond, dp/dn_z along the tangent, L/EA, is below the
  // round-off of the bending terms and the Cosserat rod is a Kirchhoff rod to double precision
  // (use rod.model: kirchhoff there).
  const ClampedTip tip = band_pose();
  for (const double E :
       {3.2e6, 3.2e7, 3.2e8, 3.2e9, 2e11, 1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19}) {
    SCOPED_TRACE(E);
    ClampedRod rod = testing::rubber_band();
    rod.properties.K_tra = Eigen::Vector3d(E / 3.0, E / 3.0, E) * 4e-4;  // GA, GA, EA; ν = 0.5
    const StabilityResult report = verdict(rod, tip);
    EXPECT_TRUE(report.stable);
    EXPECT_FALSE(report.degenerate);
    EXPECT_FALSE(report.conjugate_point_s.has_value());
  }
}

TEST(StabilityScale, VerdictAndMarginsDoNotDependOnTheOverallStiffnessScale) {
  // Every stiffness times λ: the same shape (no loads), the base wrench times λ; J̃ is the same.
  const ClampedTip tip = band_pose();
  const StabilityResult reference = verdict(testing::rubber_band(), tip);
  ASSERT_TRUE(reference.stable);
  for (int decade = -6; decade <= 6; ++decade) {
    const double lambda = std::pow(10.0, decade);
    SCOPED_TRACE(lambda);
    ClampedRod rod = testing::rubber_band();
    rod.properties.K_rot *= lambda;
    rod.properties.K_tra *= lambda;
    const StabilityResult report = verdict(rod, tip);
    EXPECT_TRUE(report.stable);
    EXPECT_NEAR(report.min_singular_value, reference.min_singular_value,
                1e-6 * reference.min_singular_value);
    EXPECT_NEAR(report.tip_singular_value, reference.tip_singular_value,
                1e-6 * reference.tip_singular_value);
  }
}

}  // namespace
}  // namespace test_stability_scale
}  // namespace rodshape
