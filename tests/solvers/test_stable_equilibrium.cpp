// The compressed band of issue 9: the tip held 0.20 m above the clamp and 0.04 m aside, unrotated
// (31 % end shortening, no gravity). A cold solve converges to a planar shape with a conjugate
// point; out-of-plane shapes of lower energy are stable, and the search finds one.
#include <gtest/gtest.h>

#include <cmath>

#include "rodshape/samples/rubber_band.hpp"
#include "rodshape/solvers/shooting_solver.hpp"
#include "rodshape/solvers/stable_equilibrium.hpp"

namespace rodshape {
namespace test_stable_equilibrium {
namespace {

ClampedTip compressed_tip() {
  ClampedTip tip;
  tip.pose.position = {0.04, 0.0, 0.20};
  return tip;
}

TEST(StableEquilibrium, FindsAStableShapeOfTheCompressedBand) {
  const ClampedRod rod = samples::rubber_band();
  const ClampedTip tip = compressed_tip();
  const ShootingResult cold = solve_equilibrium(rod, tip);
  ASSERT_TRUE(cold.summary.converged()) << cold.summary.brief();
  ClampedRod solved = rod;
  solved.substeps = cold.summary.substeps;
  const StabilityResult verdict = assess_stability(solved, cold.configuration, TipCondition{tip});
  // The premise: the cold solve lands on the planar, unstable shape.
  ASSERT_FALSE(verdict.stable) << verdict.brief();
  ASSERT_TRUE(verdict.conjugate_point_s.has_value());
  double planar = 0.0;
  for (const Eigen::Vector3d& p : cold.configuration.p) planar = std::max(planar, std::abs(p.y()));
  EXPECT_LE(planar, 1e-12);

  const StableEquilibriumResult found = seek_stable_equilibrium(rod, tip, cold, verdict);
  ASSERT_TRUE(found.found) << found.message;
  EXPECT_TRUE(found.solution.summary.converged());
  EXPECT_TRUE(found.stability.stable) << found.stability.brief();
  EXPECT_LT(found.solution.configuration.energy, cold.configuration.energy);
  EXPECT_LE(found.solves, 60);
  // The same boundary condition, to the solver's tolerance (its residual is scaled by L).
  const Pose end = found.solution.configuration.tip();
  EXPECT_LE((end.position - tip.pose.position).norm(),
            ShootingOptions{}.residual_tolerance * rod.properties.length);
  // Out of the plane of the unstable shape.
  double lateral = 0.0;
  for (const Eigen::Vector3d& p : found.solution.configuration.p)
    lateral = std::max(lateral, std::abs(p.y()));
  EXPECT_GT(lateral, 1e-3);
  EXPECT_NE(found.message.find("stable one"), std::string::npos) << found.message;
}

}  // namespace
}  // namespace test_stable_equilibrium
}  // namespace rodshape
