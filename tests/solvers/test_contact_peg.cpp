// test_contact_peg.cpp: a point contact on a curved obstacle (issue 45): a stiff cantilever
// under its weight propped by a peg (a horizontal cylinder, a capsule) just touching it from below
// where it would lie unloaded.
//
// Small-deflection theory of a cantilever (clamp at x = 0, length L, weight w per length, bending
// stiffness EI) propped at x = c where the deflection vanishes:
//   y_w(c) = -w c² (6L² - 4Lc + c²) / (24 EI),  y_R(c) = R c³ / (3 EI)
//   ⇒ R(c) = w (6L² - 4Lc + c²) / (8c),
// and the slope there θ(c) = -w c (3L² - 3Lc + c²) / (6 EI) + R c² / (2 EI). The rod touches the
// cylinder (axis at x = a, (r_peg + r) below the rod's line) where its normal passes through the
// axis: at c = a - θ (r_peg + r), at the height of the line to O(θ² r_peg). The Kirchhoff rod's
// exact solution differs from these by O(θ²) relatively (θ ≈ 2e-4 here; measured 1.6 θ_max² for
// R, 1e-10 m for the contact's s): R is asserted to 10 θ_max² of it plus ten times the solve's
// residual tolerance (N), and the contact's s, which exceeds its x by the arc's excess ∫ θ²/2 ≤ c
// θ_max²/2, to that excess plus 1e-9 m.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "rodshape/core/rod_properties.hpp"
#include "rodshape/solvers/contact_equilibrium.hpp"
#include "support/contact_cases.hpp"

namespace rodshape {
namespace test_contact_peg {
namespace {

constexpr double kLength = 0.5, kEI = 1.0, kWeight = 0.1;  // m, N·m², N/m
constexpr double kRadius = 0.002, kPegRadius = 0.005, kPegAt = 0.3;

using testing::along_x;

ClampedRod cantilever() {
  ClampedRod rod;
  rod.properties.length = kLength;
  rod.properties.model = ConstitutiveModel::Kirchhoff;
  rod.properties.K_rot = Eigen::Vector3d(kEI, kEI, 0.8 * kEI);
  rod.properties.K_tra = Eigen::Vector3d(1e8, 1e8, 1e8);
  rod.properties.section = CrossSection::circle(kRadius);
  rod.load.force = Eigen::Vector3d(0.0, 0.0, -kWeight);
  rod.clamp = {Eigen::Vector3d::Zero(), along_x()};
  rod.intervals = 100;
  return rod;
}

Scene peg() {
  const double z = -(kPegRadius + kRadius);
  Scene scene;
  scene.obstacles.push_back(
      testing::touchable("peg", CapsuleObstacle{{kPegAt, -0.1, z}, {kPegAt, 0.1, z}, kPegRadius}));
  return scene;
}

TEST(ContactPeg, AStiffCantileverRestsOnAPegWithThePropsReaction) {
  const ContactEquilibriumResult r = solve_contact_equilibrium(cantilever(), FreeTip{}, peg());
  ASSERT_TRUE(r.shooting.summary.converged()) << r.shooting.summary.message;
  ASSERT_EQ(r.contacts.size(), 1u) << r.brief();
  const RodContact& c = r.contacts.front();
  ASSERT_TRUE(c.point());
  EXPECT_GE(r.least_gap, -1e-9);

  const double L = kLength, a = kPegAt, offset = kPegRadius + kRadius;
  const auto reaction = [&](double c) {
    return kWeight * (6 * L * L - 4 * L * c + c * c) / (8 * c);
  };
  const auto slope = [&](double c) {
    return -kWeight * c * (3 * L * L - 3 * L * c + c * c) / (6 * kEI) +
           reaction(c) * c * c / (2 * kEI);
  };
  const double x_contact = a - slope(a) * offset;  // θ(c) - θ(a) = O(θ r_peg / a): 2nd order
  const double R = reaction(x_contact), theta = slope(x_contact);
  double theta_max = 0.0;
  for (const Eigen::Matrix3d& Ri : r.shooting.configuration.R)
    theta_max = std::max(theta_max, std::abs(Ri.col(2).z()));
  EXPECT_GT(theta_max, 1e-4);  // the case bends as the estimates assume
  EXPECT_LT(theta_max, 1e-3);

  const double force_tolerance = 10.0 * theta_max * theta_max * R + 10.0 * 1e-10;
  EXPECT_NEAR(c.start_force, R, force_tolerance);
  EXPECT_NEAR(c.force.z(), R, force_tolerance);
  EXPECT_NEAR(c.force.x(), -R * theta, force_tolerance);  // along the normal
  EXPECT_NEAR(c.s_start, x_contact, 0.5 * x_contact * theta_max * theta_max + 1e-9);
  // The rod's free body: the clamp applies -n(0), the free tip nothing: w L = R_z - n_z(0).
  EXPECT_NEAR(c.force.z() - r.shooting.configuration.n.front().z(), kWeight * L, 1e-9);
}

}  // namespace
}  // namespace test_contact_peg
}  // namespace rodshape
