// test_free_tip_stability.cpp: the stability verdict of free (loaded) tips (issue 12, item 4): the
// conjugate-point test plus the tip stiffness over the free directions (tip_stiffness.hpp).
//
// Closed forms:
//  * a straight cantilever under a compressive dead tip load P buckles at Euler's clamped–free load
//    P_cr = π² EI / (4 L²) (shear and extension change it by O(P/GA), 1e-3 here);
//  * a vertical column clamped at its foot buckles under its own weight q beyond Greenhill's
//    length (7.837 EI / q)^(1/3).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/solvers/shooting_solver.hpp"
#include "rodshape/solvers/stability.hpp"
#include "support/solver_fixtures.hpp"

namespace rodshape {
namespace test_free_tip_stability {
namespace {

using std::numbers::pi;

StabilityResult free_tip_verdict(const ClampedRod& rod,
                                 const FreeTip& tip,
                                 const ShootingOptions& options = {}) {
  const ShootingResult solution = solve_equilibrium(rod, tip, {}, options);
  EXPECT_TRUE(solution.summary.converged()) << solution.summary.message;
  return assess_stability(rod, solution.configuration, tip);
}

TEST(FreeTipStability, UnloadedBandIsStableWithUnitTipStiffness) {
  // The unloaded straight rod is the reference: its tip stiffness is K0, eigenvalue 1. RK4 is exact
  // on its (polynomial) variational equations, so only round-off remains.
  const ClampedRod rod = testing::rubber_band();
  const StabilityResult report = free_tip_verdict(rod, FreeTip{});
  EXPECT_TRUE(report.stable);
  EXPECT_FALSE(report.degenerate);
  ASSERT_TRUE(report.tip_stiffness_eigenvalue.has_value());
  EXPECT_NEAR(*report.tip_stiffness_eigenvalue, 1.0, 1e-9);
}

TEST(FreeTipStability, TransverseTipLoadIsStable) {
  const ClampedRod rod = testing::rubber_band();
  const StabilityResult report = free_tip_verdict(rod, FreeTip{{{1.0, 0.3, 0}, {0, 0, 0.01}}});
  EXPECT_TRUE(report.stable);
  EXPECT_GT(*report.tip_stiffness_eigenvalue, 0.0);
}

TEST(FreeTipStability, StraightColumnUnderDeadLoadBucklesAtEulersClampedFreeLoad) {
  const ClampedRod rod = testing::rubber_band();
  const double P_cr =
      pi * pi * testing::kBandEI / (4.0 * testing::kBandLength * testing::kBandLength);
  for (const double factor : {0.9, 1.1}) {
    SCOPED_TRACE(factor);
    const FreeTip tip{{{0, 0, -factor * P_cr}, {0, 0, 0}}};
    // The straight shape is the equilibrium: n = (0, 0, -P) along the whole rod.
    const RodConfiguration c =
        integrate(rod, BaseWrench{tip.wrench.force, {0, 0, 0}}, Derivatives::AllNodes);
    const StabilityResult report = assess_stability(rod, c, tip);
    EXPECT_EQ(report.stable, factor < 1.0);
    EXPECT_FALSE(report.degenerate);
    // The held rod is stable up to 4 P_cr: the tip stiffness decides.
    ASSERT_TRUE(report.tip_stiffness_eigenvalue.has_value());
    EXPECT_EQ(*report.tip_stiffness_eigenvalue > 0.0, factor < 1.0);
    // Held at the same pose, the rod is stable: the old (held-tip) test cannot see it.
    EXPECT_TRUE(assess_stability(rod, c).stable);
  }
}

/// A thin steel wire of length L standing straight up from a clamp at its foot, under gravity.
ClampedRod upright_wire(double length, double radius) {
  RodDescription description;
  description.length = length;
  description.section = CrossSection::circle(radius);
  description.material = Material{200e9, 0.3, 7850.0};
  ClampedRod rod;
  rod.properties = make_rod_properties(description);
  rod.load = DistributedLoad::gravity(rod.properties.mass_per_length, {0, 0, -9.81});
  rod.validate();
  return rod;
}

TEST(FreeTipStability, WireStandingUpAgainstGravityIsUnstableBeyondGreenhillsLength) {
  // Issue 12: a 1 m wire of radius 5e-6 m "converged" standing up, stable: null.
  // Greenhill: EI = E π r⁴/4 = 9.8e-11 N·m², q = ρ π r² g = 6.0e-6 N/m, l_c = 0.051 m.
  const double radius = 5e-6;
  const ClampedRod probe = upright_wire(1.0, radius);
  const double q = probe.properties.mass_per_length * 9.81;
  const double l_c = std::cbrt(7.837 * probe.properties.K_rot.x() / q);
  ASSERT_NEAR(l_c, 0.051, 0.001);
  for (const double length : {0.8 * l_c, 1.2 * l_c, 1.0}) {
    SCOPED_TRACE(length);
    const ClampedRod rod = upright_wire(length, radius);
    // Straight up is an equilibrium: the rod above presses on the clamp, n(0) = -q L e_z
    // (n' = -f, n(L) = 0).
    const BaseWrench w{{0, 0, -q * length}, {0, 0, 0}};
    const RodConfiguration c = integrate(rod, w, Derivatives::AllNodes);
    ASSERT_LE(c.tip_wrench().force.norm(), 1e-12 * q * length);
    const StabilityResult report = assess_stability(rod, c, FreeTip{});
    EXPECT_EQ(report.stable, length < l_c);
  }
}

TEST(FreeTipStability, VerdictDoesNotDependOnTheStiffnessScale) {
  // Every stiffness and load times λ: the same shape, the same eigenvalue.
  const double P = 0.5;  // N, transverse: a bent, stable cantilever
  double reference = 0.0;
  for (int decade = -6; decade <= 6; ++decade) {
    const double lambda = std::pow(10.0, decade);
    ClampedRod rod = testing::rubber_band();
    rod.properties.K_rot *= lambda;
    rod.properties.K_tra *= lambda;
    const FreeTip tip{{{lambda * P, 0, -lambda * 0.5}, {0, 0, 0}}};
    ShootingOptions options;  // the residual in N, N·m: its tolerance scales with the loads
    options.residual_tolerance = 1e-10 * lambda;
    const StabilityResult report = free_tip_verdict(rod, tip, options);
    EXPECT_TRUE(report.stable) << lambda;
    ASSERT_TRUE(report.tip_stiffness_eigenvalue.has_value());
    if (decade == -6) reference = *report.tip_stiffness_eigenvalue;
    EXPECT_NEAR(*report.tip_stiffness_eigenvalue, reference, 1e-6 * reference) << lambda;
  }
}

}  // namespace
}  // namespace test_free_tip_stability
}  // namespace rodshape
