// test_contact_ledge.cpp: a heavy strip clamped level on the edge of a ledge, at height h above
// a frictionless floor, hangs off it and lies on the floor up to its free tip (issue 45's "cable
// hanging off a ledge onto the floor").
//
// The lying part carries nothing: on the floor the line reaction cancels the weight (n' = 0) and
// the free tip has n(L) = m(L) = 0, so n = m = 0 there, to the solve's residual. The hanging span
// of length l, from the clamp to the touch-down, has a level clamp at height h and, at the
// touch-down, the floor's height, a level tangent, zero moment and a vertical concentrated
// reaction (Kirchhoff): the same conditions, mirrored, as the lifted strip's free span
// (test_contact_equilibrium.cpp: the level grasp that slides along its tangent leaves no
// horizontal force, as the lying part does here). The two solves, which take different branches
// of the formulation (a segment from the clamp with a lift-off and a held tip; a touch-down and a
// segment to a free tip, solved in least squares; and on the way there, the free tip resting on
// the floor at an angle), must give the same l to the precision the contact ends are solved to,
// and both small-deflection theory's (72 EI h / w)^(1/4) to its own O((h/l)²) (1.7e-4 relative
// at h = 4 mm, as measured on the lifted strip).
#include <gtest/gtest.h>

#include <cmath>

#include "rodshape/core/rod_properties.hpp"
#include "rodshape/solvers/contact_equilibrium.hpp"
#include "support/contact_cases.hpp"

namespace rodshape {
namespace test_contact_ledge {
namespace {

constexpr double kLength = 0.6;  // m
constexpr double kEI = 1e-3;     // N·m²
constexpr double kWeight = 0.5;  // N/m
constexpr double kRadius = 0.002;
constexpr double kHeight = 0.004;  // of the ledge's edge above where the strip lies, m

using testing::along_x;
using testing::touchable;

ClampedRod strip(ConstitutiveModel model, const Eigen::Vector3d& clamp) {
  return testing::heavy_strip({kLength, kEI, kWeight, kRadius}, model, clamp, 200);
}

/// The floor (z < 0) and the ledge (x in [-0.2, 0], its top at the strip's underside).
Scene floor_and_ledge() {
  Scene scene;
  scene.obstacles.push_back(touchable("floor", HalfSpaceObstacle{-Eigen::Vector3d::UnitZ(), 0.0}));
  scene.obstacles.push_back(touchable(
      "ledge",
      BoxObstacle{{-0.1, 0.0, 0.5 * kHeight}, {0.2, 0.2, kHeight}, Eigen::Matrix3d::Identity()}));
  return scene;
}

ContactEquilibriumResult hang(ConstitutiveModel model) {
  return solve_contact_equilibrium(strip(model, {0.0, 0.0, kHeight + kRadius}), FreeTip{},
                                   floor_and_ledge());
}

ContactEquilibriumResult lift(ConstitutiveModel model) {
  Scene scene = floor_and_ledge();
  scene.obstacles.pop_back();
  GraspedTip tip;
  tip.pose = {Eigen::Vector3d(kLength, 0.0, kRadius + kHeight), along_x()};
  tip.released[2] = true;
  return solve_contact_equilibrium(strip(model, {0.0, 0.0, kRadius}), tip, scene);
}

TEST(ContactLedge, TheStripLiesOnTheFloorFromTheTouchDownToItsTipCarryingNothing) {
  const ContactEquilibriumResult r = hang(ConstitutiveModel::Kirchhoff);
  ASSERT_TRUE(r.shooting.summary.converged()) << r.shooting.summary.message;
  ASSERT_EQ(r.contacts.size(), 1u) << r.brief();
  const RodContact& c = r.contacts.front();
  EXPECT_EQ(c.obstacle, 0);  // the floor; the ledge only holds the clamp
  EXPECT_EQ(c.s_end, kLength);
  EXPECT_EQ(c.end_force, 0.0);  // the free tip takes none
  EXPECT_GE(r.least_gap, -1e-9);
  const double tolerance = ShootingOptions{}.residual_tolerance;  // N, N·m at the free tip
  const RodConfiguration& q = r.shooting.configuration;
  const double lying = kLength - c.s_start;
  // A tip error δn, δm bends the lying part off the floor by at most δm l²/(2EI) + δn l³/(6EI).
  const double drift = tolerance * lying * lying / (2.0 * kEI) * (1.0 + lying / 3.0);
  for (int i = 0; i < q.nodes(); ++i) {
    const std::size_t k = static_cast<std::size_t>(i);
    if (q.s[k] <= c.s_start) continue;
    // n is n(L) there (n' = 0), m is m(L) plus at most |n| L (m' = -p' × n): each within the
    // tip's residual, asserted to twice it.
    EXPECT_LE(q.n[k].norm(), 2.0 * tolerance) << "s = " << q.s[k];
    EXPECT_LE(q.m[k].norm(), 2.0 * tolerance * (1.0 + kLength)) << "s = " << q.s[k];
    EXPECT_NEAR(q.p[k].z(), kRadius, drift) << "s = " << q.s[k];
  }
  // The reaction carries the whole weight but what the clamp holds: w L = R_z - n_z(0).
  EXPECT_NEAR(c.force.z() - q.n.front().z(), kWeight * kLength, 1e-9);
  const double l = c.s_start;
  // The touch-down's reaction, w l / 3 in small deflection, which it differs from at O((h/l)²)
  // relatively like l (measured 0.34 (h/l)² here): asserted to (h/l)².
  const double order = (kHeight / l) * (kHeight / l);
  EXPECT_NEAR(c.start_force, kWeight * l / 3.0, order * kWeight * l / 3.0);
}

TEST(ContactLedge, TheHangingSpanMirrorsTheLiftedStrips) {
  const double theory = std::pow(72.0 * kEI * kHeight / kWeight, 0.25);
  for (const ConstitutiveModel model :
       {ConstitutiveModel::Kirchhoff, ConstitutiveModel::Cosserat}) {
    const ContactEquilibriumResult hung = hang(model), lifted = lift(model);
    ASSERT_TRUE(hung.shooting.summary.converged()) << hung.shooting.summary.message;
    ASSERT_TRUE(lifted.shooting.summary.converged()) << lifted.shooting.summary.message;
    ASSERT_EQ(hung.contacts.size(), 1u);
    ASSERT_EQ(lifted.contacts.size(), 1u);
    const double l_hung = hung.contacts.front().s_start;
    const double l_lifted = kLength - lifted.contacts.front().s_end;
    // The contact ends solve g = 0, g' = 0 to the residual tolerance ε; beside a Kirchhoff
    // rod's touch-down the gap is cubic, g ≈ P (s - a)³ / (6 EI) (the moment vanishes there and
    // its rate jumps by P), so g' = ε leaves the end free by δ = √(2 EI ε / P), and the reaction
    // w l / 3 by w δ / 3. Each solve may be off by that: asserted to twice it.
    const double P = hung.contacts.front().start_force;
    const double delta = std::sqrt(2.0 * kEI * ShootingOptions{}.residual_tolerance / P);
    EXPECT_NEAR(l_hung, l_lifted, 2.0 * delta) << static_cast<int>(model);
    EXPECT_NEAR(P, lifted.contacts.front().end_force, 2.0 * kWeight * delta / 3.0);
    EXPECT_NEAR(l_hung, theory, 2.5e-4 * theory);  // small deflection's own O((h/l)²)
  }
}

TEST(ContactLedge, AStripClampedOnTheFloorWithAFreeTipLiesOnItsWholeLength) {
  // The whole rod goes under at once: one segment [0, L] carrying the weight, nothing inside.
  Scene floor = floor_and_ledge();
  floor.obstacles.pop_back();
  const ContactEquilibriumResult r = solve_contact_equilibrium(
      strip(ConstitutiveModel::Cosserat, {0.0, 0.0, kRadius}), FreeTip{}, floor);
  ASSERT_TRUE(r.shooting.summary.converged()) << r.shooting.summary.message;
  ASSERT_EQ(r.contacts.size(), 1u) << r.brief();
  EXPECT_EQ(r.contacts.front().s_start, 0.0);
  EXPECT_EQ(r.contacts.front().s_end, kLength);
  EXPECT_NEAR(r.contacts.front().max_line_force, kWeight, 1e-12);
  const double tolerance = ShootingOptions{}.residual_tolerance;
  for (const Eigen::Vector3d& n : r.shooting.configuration.n) EXPECT_LE(n.norm(), 2.0 * tolerance);
  EXPECT_GE(r.least_gap, -ContactOptions{}.gap_tolerance);
}

}  // namespace
}  // namespace test_contact_ledge
}  // namespace rodshape
