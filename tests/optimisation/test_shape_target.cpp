// test_shape_target.cpp: ShapeTarget::validate() and check_feasibility().
//
// Spline length accuracy. Points on a straight line, parameterised by chord length, are
// interpolated exactly by the straight line itself (the linear map u ↦ p(0) + u (p_n - p(0)) is a
// cubic through the data at their chord-length parameters, and interpolation is unique), so
// |C'| is constant and Gauss–Legendre integrates it exactly: the length equals the distance to
// round-off (a few ε per panel; 1e-14 relative allowed).
#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <numbers>
#include <sstream>
#include <string>

#include "optimisation/optimisation_fixtures.hpp"
#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/optimisation/shape_target.hpp"
#include "support/eigen_compare.hpp"
#include "support/input_error.hpp"

namespace rodshape {
namespace test_shape_target {
namespace {

using testing::CompareScalars;
using testing::input_error_message;

/// A message that mentions `needle`.
::testing::AssertionResult Mentions(const std::string& message, const std::string& needle) {
  if (message.find(needle) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "\"" << message << "\" does not mention \"" << needle << "\"";
}

TEST(ShapeTarget, ValidateNamesTheField) {
  ShapeTarget target;
  EXPECT_TRUE(Mentions(input_error_message([&] { target.validate(); }), "ShapeTarget.points"));
  target.points = {{0.0, 0.0, 0.1}, {0.0, std::nan(""), 0.2}};
  EXPECT_TRUE(Mentions(input_error_message([&] { target.validate(); }), "ShapeTarget.points[1]"));
  target.points[1] = {0.0, 0.0, 0.2};
  EXPECT_NO_THROW(target.validate());
  target.energy_weight = -1.0;
  EXPECT_TRUE(
      Mentions(input_error_message([&] { target.validate(); }), "ShapeTarget.energy_weight"));
  target.energy_weight = 0.0;
  target.distance_weight = 0.0;
  EXPECT_TRUE(Mentions(input_error_message([&] { target.validate(); }), "both 0"));
  target.distance_weight = std::nan("");
  EXPECT_TRUE(
      Mentions(input_error_message([&] { target.validate(); }), "ShapeTarget.distance_weight"));
}

TEST(ShapeTarget, PointsSampledFromARealConfigurationAreFeasible) {
  for (ConstitutiveModel model : {ConstitutiveModel::Cosserat, ConstitutiveModel::Kirchhoff}) {
    ClampedRod rod = testing::rubber_band(model, 40);
    rod.clamp.position = Eigen::Vector3d(0.1, -0.2, 0.3);
    const RodConfiguration c = integrate(rod, {{0.1, 0.2, 0.0}, {0.3, -0.1, 0.05}});
    ShapeTarget target;
    for (int i : {8, 16, 24, 32, 40}) target.points.push_back(c.p[i]);  // up to the tip
    const FeasibilityResult feasibility = check_feasibility(target, rod);
    EXPECT_TRUE(feasibility.feasible) << feasibility.reason;
    EXPECT_TRUE(feasibility.reason.empty());
    EXPECT_EQ(feasibility.offending_point, -1);
    // The spline through points of the rod is about as long as the rod (interpolation error).
    EXPECT_NEAR(feasibility.curve_length, rod.properties.length, 0.01 * rod.properties.length);
  }
}

TEST(ShapeTarget, APointBeyondReachIsInfeasibleAndNamed) {
  const ClampedRod rod = testing::rubber_band(ConstitutiveModel::Cosserat, 20);
  ShapeTarget target;
  target.points = {{0.0, 0.05, 0.1}, {0.0, 0.1, 0.2}, {0.0, 0.3, 0.28}, {0.0, 0.1, 0.25}};
  const FeasibilityResult feasibility = check_feasibility(target, rod);
  EXPECT_FALSE(feasibility.feasible);
  EXPECT_EQ(feasibility.offending_point, 2);
  EXPECT_TRUE(Mentions(feasibility.reason, "ShapeTarget.points[2] is 0.41 m from the clamp"));
  EXPECT_TRUE(Mentions(feasibility.reason, "(0.29 m)"));
}

TEST(ShapeTarget, AZigZagLongerThanTheRodIsInfeasibleWithItsLength) {
  const ClampedRod rod = testing::rubber_band(ConstitutiveModel::Cosserat, 20);
  ShapeTarget target;
  // Every point within 0.22 m of the clamp, but the polyline alone is 0.61 m long.
  target.points = {{0.0, 0.08, 0.08}, {0.0, -0.08, 0.12}, {0.0, 0.08, 0.16}, {0.0, -0.08, 0.2}};
  const FeasibilityResult feasibility = check_feasibility(target, rod);
  EXPECT_FALSE(feasibility.feasible);
  EXPECT_GT(feasibility.curve_length, 0.4);
  // The chain: 0.113 + 0.165 + 0.165 + 0.165 = 0.607 m, beyond 0.29 m at the third point.
  const double chain = std::hypot(0.08, 0.08) + 3 * std::hypot(0.16, 0.04);
  std::ostringstream length;
  length << std::setprecision(3) << chain;
  EXPECT_TRUE(Mentions(feasibility.reason,
                       "through the points in order (the shortest curve "
                       "through them) is " +
                           length.str()));
  EXPECT_TRUE(Mentions(feasibility.reason, "longer than the rod (0.29 m)"));
  EXPECT_EQ(feasibility.offending_point, 2);  // the chain reaches it at 0.44 m
}

TEST(ShapeTarget, ReachIsTheLengthForKirchhoffAndStretchesForCosserat) {
  ShapeTarget target;
  target.points = {{0.0, 0.0, 0.3}};  // 0.30 m straight ahead: beyond L = 0.29, within 1.1 L
  const ClampedRod kirchhoff = testing::rubber_band(ConstitutiveModel::Kirchhoff, 20);
  const FeasibilityResult k = check_feasibility(target, kirchhoff, 0.1);
  EXPECT_EQ(k.reach, kirchhoff.properties.length);  // the model cannot stretch
  EXPECT_FALSE(k.feasible);
  EXPECT_EQ(k.offending_point, 0);
  const ClampedRod cosserat = testing::rubber_band(ConstitutiveModel::Cosserat, 20);
  const FeasibilityResult c = check_feasibility(target, cosserat, 0.1);
  EXPECT_TRUE(CompareScalars(c.reach, 1.1 * cosserat.properties.length, 1e-15));
  EXPECT_TRUE(c.feasible) << c.reason;
  EXPECT_FALSE(check_feasibility(target, cosserat).feasible);  // no stretch allowed by default
}

// Four points at s = L/4 … L on 1.1 turns of a helix of the rod's length (pitch angle 25°): they
// lie on a curve of exactly L, but the spline through them bulges (each gap spans 100°) and is
// longer than L. Feasible (the chain is shorter than L); the arc lengths scaled to the reach, the
// last point at the rod's end.
TEST(ShapeTarget, SparsePointsOnAHelixOfTheRodsLengthAreFeasible) {
  const ClampedRod rod = testing::rubber_band(ConstitutiveModel::Kirchhoff, 20);
  const double L = rod.properties.length, turns = 1.1, pitch = 25.0 * std::numbers::pi / 180.0;
  const double ell = L / (2 * std::numbers::pi * turns), r = ell * std::cos(pitch);
  const double h = ell * std::sin(pitch);
  ShapeTarget target;
  for (int k = 1; k <= 4; ++k) {  // the helix about +y through the clamp, starting along +z
    const double phi = 2 * std::numbers::pi * turns * k / 4.0;
    target.points.push_back({r * (1.0 - std::cos(phi)), h * phi, r * std::sin(phi)});
  }
  const FeasibilityResult feasibility = check_feasibility(target, rod);
  EXPECT_TRUE(feasibility.feasible) << feasibility.reason;
  EXPECT_GT(feasibility.curve_length, L);
  ASSERT_EQ(feasibility.arc_lengths.size(), 4u);
  EXPECT_TRUE(CompareScalars(feasibility.arc_lengths.back(), L, 1e-14));
  for (int k = 1; k < 4; ++k) EXPECT_GT(feasibility.arc_lengths[k], feasibility.arc_lengths[k - 1]);
}

TEST(ShapeTarget, SplineLengthOfCollinearPointsIsTheStraightDistance) {
  ClampedRod rod = testing::rubber_band(ConstitutiveModel::Cosserat, 20);
  rod.clamp.position = Eigen::Vector3d(0.3, -0.1, 0.2);
  const Eigen::Vector3d direction = Eigen::Vector3d(1.0, 2.0, -0.5).normalized();
  // Uneven spacing; 1, 2 and 5 points (spline degree 1, 2 and 3).
  const std::vector<double> along = {0.01, 0.05, 0.06, 0.15, 0.21};
  for (std::size_t count : {1u, 2u, 5u}) {
    ShapeTarget target;
    for (std::size_t k = 0; k < count; ++k)
      target.points.push_back(rod.clamp.position + along[k] * direction);
    const FeasibilityResult feasibility = check_feasibility(target, rod);
    EXPECT_TRUE(feasibility.feasible) << feasibility.reason;
    EXPECT_TRUE(
        CompareScalars(feasibility.curve_length, along[count - 1], 1e-14 * along[count - 1]))
        << count << " points";
  }
}

TEST(ShapeTarget, SplineLengthOfPointsOnAnArcApproachesTheArcLength) {
  // 12 points on a quarter circle of radius 0.15 (arc 0.2356 m): the chord-length cubic spline's
  // length agrees with the arc to its interpolation error, O(h⁴) with h the point spacing
  // (h/ρ = 0.13: (h/ρ)⁴ ≈ 3e-4 relative; allow 1e-3).
  const ClampedRod rod = testing::rubber_band(ConstitutiveModel::Cosserat, 20);
  const double rho = 0.15, quarter = 0.5 * std::numbers::pi;
  ShapeTarget target;
  for (int k = 1; k <= 12; ++k) {
    const double a = quarter * k / 12.0;
    target.points.push_back({0.0, rho * (1.0 - std::cos(a)), rho * std::sin(a)});
  }
  const FeasibilityResult feasibility = check_feasibility(target, rod);
  EXPECT_TRUE(feasibility.feasible) << feasibility.reason;
  EXPECT_NEAR(feasibility.curve_length, rho * quarter, 1e-3 * rho * quarter);
}

}  // namespace
}  // namespace test_shape_target
}  // namespace rodshape
