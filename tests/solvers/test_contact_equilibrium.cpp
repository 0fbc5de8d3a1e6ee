// test_contact_equilibrium.cpp: the rod resting on a frictionless table (issue 45), against
// small-deflection theory.
//
// A heavy strip (weight w per length, bending stiffness EI) lies on a table from its clamp and is
// lifted at its end by a gripper that holds it level at height h above where it lay and lets it
// slide along its tangent (released force z, the grasp frame's z being the tangent): no axial
// force. The free length l, from the lift-off point to the gripper, is a beam with zero slope at
// both ends, zero moment at the lift-off (where the lying part has none) and a concentrated
// reaction there (Kirchhoff); small-deflection theory gives
//   EI y'''' = -w,  y(0) = y'(0) = y''(0) = 0,  y(l) = h, y'(l) = 0  ⇒  l = (72 EI h / w)^(1/4).
// The reaction at the lift-off is P = w l / 3. The exact (large-deflection) free length differs
// from it by O((h/l)²) = O(h^(3/2)) relatively (l ∝ h^(1/4)): the relative difference falls by
// 2^(3/2) = 2.83 as h halves, asserted within 10 % (the next order's share, O((h/l)²) of it, is
// below 1 % here), with the difference itself below 0.1 % at h = 2 mm. The solver's own error is
// far below: the lift-off is located to the residual tolerance between the nodes, and RK4 on 200
// intervals is accurate to ~1e-10 L.
#include <gtest/gtest.h>

#include <cmath>

#include "rodshape/core/rod_properties.hpp"
#include "rodshape/solvers/contact_equilibrium.hpp"
#include "support/contact_cases.hpp"

namespace rodshape {
namespace test_contact_equilibrium {
namespace {

constexpr double kLength = 0.6;  // m
constexpr double kEI = 1e-3;     // N·m²
constexpr double kWeight = 0.5;  // N/m
constexpr double kRadius = 0.002;

using testing::along_x;

ClampedRod heavy_strip(ConstitutiveModel model, int intervals) {
  return testing::heavy_strip({kLength, kEI, kWeight, kRadius}, model, {0.0, 0.0, kRadius},
                              intervals);
}

Scene table() {
  Scene scene = testing::table_scene();
  scene.rod_radius = kRadius;
  return scene;
}

/// The lifted strip's free length L - s_b at lift h.
ContactEquilibriumResult lift(double h, ConstitutiveModel model = ConstitutiveModel::Kirchhoff) {
  const ClampedRod rod = heavy_strip(model, 200);
  GraspedTip tip;
  tip.pose = {Eigen::Vector3d(kLength, 0.0, kRadius + h), along_x()};
  tip.released[2] = true;  // slides along its tangent
  return solve_contact_equilibrium(rod, tip, table());
}

TEST(ContactEquilibrium, ALiftedStripsFreeLengthApproachesSmallDeflectionTheory) {
  std::vector<double> differences, force_differences;
  for (const double h : {0.008, 0.004, 0.002}) {
    const ContactEquilibriumResult r = lift(h);
    ASSERT_TRUE(r.shooting.summary.converged()) << r.shooting.summary.message;
    ASSERT_EQ(r.contacts.size(), 1u) << r.brief();
    const RodContact& c = r.contacts.front();
    EXPECT_EQ(c.s_start, 0.0);
    const double l = kLength - c.s_end;
    const double theory = std::pow(72.0 * kEI * h / kWeight, 0.25);
    differences.push_back(std::abs(l - theory) / theory);
    std::cout << "h = " << h << ": l = " << l << ", theory " << theory << ", lift-off force "
              << c.end_force << " N, " << r.brief() << ", least gap " << r.least_gap << "\n";
    EXPECT_GE(r.least_gap, -1e-9);
    EXPECT_NEAR(c.end_force, kWeight * l / 3.0,
                2.0 * differences.back() * kWeight * l / 3.0 + 1e-3 * kWeight * l);
    // the reaction carries the weight the gripper does not: w L = R_z + n_z(L)
    EXPECT_NEAR(c.force.z() + r.shooting.configuration.n.back().z(), kWeight * kLength, 1e-9);
  }
  EXPECT_LT(differences.back(), 1e-3);
  for (std::size_t k = 1; k < differences.size(); ++k) {
    const double ratio = differences[k - 1] / differences[k];
    EXPECT_NEAR(ratio, std::pow(2.0, 1.5), 0.1 * std::pow(2.0, 1.5)) << k;
  }
}

/// The total potential: the elastic energy and the weight's, ∫ w z ds (Simpson's rule on the
/// nodes; the rod's nodes are uniform and their count odd).
double total_potential(const ContactEquilibriumResult& r) {
  const RodConfiguration& c = r.shooting.configuration;
  const int N = c.nodes() - 1;
  const double h = kLength / N;
  double gravity = 0.0;
  for (int i = 0; i <= N; ++i)
    gravity +=
        (i == 0 || i == N ? 1.0 : (i % 2 ? 4.0 : 2.0)) * c.p[static_cast<std::size_t>(i)].z();
  return c.energy + kWeight * gravity * h / 3.0;
}

TEST(ContactEquilibrium, TheHeldForceIsTheRateOfTheTotalPotentialWithTheHeight) {
  // Virtual work: the gripper's vertical force n_z(L) = dPi/dh (the clamp, the sliding grasp and
  // the frictionless table do no work). The central difference's truncation error is
  // F'' delta^2 / 6 with F = 2 w l / 3 proportional to h^(1/4) (small deflection), so
  // F'' = -(3/16) F / h^2 and the error is (1/32)(delta/h)^2 of F: 2.0e-5 for delta = 0.1 mm at
  // h = 4 mm. The solve's residual (1e-10 m in the held pose) moves Pi by about F 1e-10, 1e-6 of F
  // after the division by delta; Simpson's rule on 200 intervals is far below both. Asserted:
  // twice the truncation plus that.
  const double h = 0.004, delta = 1e-4;
  const ContactEquilibriumResult at = lift(h);
  const ContactEquilibriumResult up = lift(h + delta), down = lift(h - delta);
  for (const ContactEquilibriumResult* r : {&at, &up, &down})
    ASSERT_TRUE(r->shooting.summary.converged()) << r->shooting.summary.message;
  const double rate = (total_potential(up) - total_potential(down)) / (2.0 * delta);
  const double held = at.shooting.configuration.n.back().z();
  const double truncation = (delta / h) * (delta / h) / 32.0;
  EXPECT_NEAR(rate, held, (2.0 * truncation + 1e-6) * std::abs(held))
      << "dPi/dh " << rate << ", n_z(L) " << held;
}

}  // namespace
}  // namespace test_contact_equilibrium
}  // namespace rodshape
