// test_curve_distance.cpp: project_onto_curve() and distance_gradient().
//
// Accuracy model. Between nodes Γ is the cubic Hermite interpolant of the nodes' p and p' = R v.
// For an exact curve through exact nodes, its error is
//     |p(s_i + t h) - H(t)| = |∫ K(t, σ) p''''(σ) dσ| ≤ (t(1 - t))² h⁴ / 24 · max|p''''| ≤ h⁴/384 ·
//     max|p''''|
// (the Peano kernel K of cubic Hermite interpolation has one sign, so the bound holds for the
// vector norm, not only per component). The nodes themselves carry the integrator's RK4 error,
// bounded by testing::rk4_error_bound (tests/support/analytic_rods.hpp). The distance from a point
// to a curve is 1-Lipschitz in the curve (sup norm), so both errors bound the distance error.
// For a circular arc of curvature κ, |p''''| = κ³.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "optimisation/optimisation_fixtures.hpp"
#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/core/so3.hpp"
#include "rodshape/optimisation/curve_distance.hpp"
#include "support/analytic_rods.hpp"
#include "support/eigen_compare.hpp"

namespace rodshape {
namespace test_curve_distance {
namespace {

using testing::CompareMatrices;
using testing::CompareScalars;

/// The rubber band bent into an exact arc by an end moment M = EI κ about x (no force, so v = ṽ):
/// p(s) = (0, (cos κs - 1)/κ, sin κs / κ), centre c = (0, -1/κ, 0), radius ρ = 1/κ.
struct Arc {
  ClampedRod rod;
  double kappa = 0.0;
  RodConfiguration configuration;
  Eigen::Vector3d center;
  double radius = 0.0;
  double tolerance = 0.0;  // Hermite + RK4 bound on the distance error
  double hermite_bound = 0.0;
};

Arc make_arc(double kappa_L, int intervals) {
  Arc arc;
  arc.rod = testing::rubber_band(ConstitutiveModel::Cosserat, intervals);
  const double L = arc.rod.properties.length;
  arc.kappa = kappa_L / L;
  const double M = arc.rod.properties.K_rot.x() * arc.kappa;
  arc.configuration = integrate(arc.rod, {Eigen::Vector3d::Zero(), {M, 0.0, 0.0}});
  arc.radius = 1.0 / arc.kappa;
  arc.center = Eigen::Vector3d(0.0, -arc.radius, 0.0);
  const double h = arc.rod.step();
  arc.hermite_bound = std::pow(h, 4) * std::pow(arc.kappa, 3) / 384.0;
  arc.tolerance = arc.hermite_bound + testing::rk4_error_bound(L, arc.kappa, intervals);
  return arc;
}

Eigen::Vector3d arc_point(const Arc& arc, double s) {
  const double a = arc.kappa * s;
  return {0.0, (std::cos(a) - 1.0) / arc.kappa, std::sin(a) / arc.kappa};
}

TEST(CurveDistance, PointsOnAnArcBetweenNodesAreAtHermiteDistance) {
  const Arc arc = make_arc(3.0, 20);
  const double h = arc.rod.step();
  // The test can fail: a polyline between the nodes would be h²κ/8 away mid-interval.
  ASSERT_LT(10.0 * arc.tolerance, h * h * arc.kappa / 8.0);
  double worst = 0.0;
  for (int i = 0; i < arc.rod.intervals; ++i) {
    for (double t : {0.25, 0.5, 0.7}) {
      const double s = (i + t) * h;
      const Eigen::Vector3d point = arc_point(arc, s);
      const CurveProjection projection = project_onto_curve(arc.configuration, point);
      worst = std::max(worst, projection.distance);
      EXPECT_LE(projection.distance, arc.tolerance) << "s = " << s;
      EXPECT_EQ(projection.interval, i) << "s = " << s;
      EXPECT_NEAR(projection.s, s, 1e-3 * h);
      EXPECT_TRUE(CompareScalars((projection.closest - point).norm(), projection.distance, 1e-15));
    }
  }
  RecordProperty("worst_distance", testing::scientific(worst));
  RecordProperty("hermite_bound", testing::scientific(arc.hermite_bound));
  RecordProperty("total_bound", testing::scientific(arc.tolerance));
}

TEST(CurveDistance, PointsOffAnArcMatchTheCircleFormula) {
  const Arc arc = make_arc(3.0, 20);
  const double L = arc.rod.properties.length, rho = arc.radius;
  for (double s : {0.1 * L, 0.33 * L, 0.5 * L, 0.71 * L, 0.9 * L}) {
    const Eigen::Vector3d radial = (arc_point(arc, s) - arc.center) / rho;
    for (double r : {0.3 * rho, 0.9 * rho, 1.1 * rho, 2.0 * rho}) {
      for (double z : {0.0, 0.4 * rho}) {  // z: out of the arc's plane (along x)
        const Eigen::Vector3d point = arc.center + r * radial + Eigen::Vector3d(z, 0.0, 0.0);
        // Nearest point of the full circle: same angle, hence on the arc.
        const double expected = std::hypot(r - rho, z);
        const CurveProjection projection = project_onto_curve(arc.configuration, point);
        EXPECT_TRUE(CompareScalars(projection.distance, expected, arc.tolerance))
            << "s = " << s << ", r/ρ = " << r / rho << ", z/ρ = " << z / rho;
        // The foot point moves with the curve's error e (position) and e' (tangent): from
        // (Γ - q)·Γ' = 0, δs = -(e·Γ' + (Γ - q)·e') / (|Γ'|² + (Γ - q)·Γ''), and on the circle the
        // denominator is r/ρ inside (1 + (r - ρ)/ρ outside). e' ≤ h³κ³/72 (Hermite derivative)
        // plus the integrator's angle error.
        const double e_tangent = std::pow(arc.rod.step() * arc.kappa, 3) / 72.0 +
                                 testing::rk4_angle_error_bound(L, arc.kappa, arc.rod.intervals);
        const double s_tolerance =
            (arc.tolerance + std::abs(r - rho) * e_tangent) / std::min(1.0, r / rho);
        EXPECT_NEAR(projection.s, s, s_tolerance) << "r/ρ = " << r / rho << ", z/ρ = " << z / rho;
      }
    }
  }
  // Beyond the ends: the end points are the minima (t = 0 and t = 1 are candidates).
  const Eigen::Vector3d beyond_tip =
      arc.configuration.p.back() + 0.05 * arc.configuration.R.back().col(2);
  const CurveProjection tip = project_onto_curve(arc.configuration, beyond_tip);
  EXPECT_DOUBLE_EQ(tip.s, L);
  EXPECT_TRUE(CompareScalars(tip.distance, 0.05, 1e-15));
  const CurveProjection clamp = project_onto_curve(arc.configuration, {0.0, 0.0, -0.03});
  EXPECT_EQ(clamp.s, 0.0);
  EXPECT_TRUE(CompareScalars(clamp.distance, 0.03, 1e-15));
}

TEST(CurveDistance, AWarmStartFromAnyIntervalDescendsToTheArcsOneMinimum) {
  // Near an arc of κL = 3 (less than a circle) the distance along the curve, with d² = r² + ρ² -
  // 2rρ cos Δθ, has one minimum: project_from_interval must reach it from every start interval,
  // however far (align_base's warm starts), bit for bit the global projection's distance up to the
  // foot point found from the neighbouring interval (t = 1 of i-1 against t = 0 of i).
  const Arc arc = make_arc(3.0, 20);
  const double L = arc.rod.properties.length, rho = arc.radius;
  for (double s : {0.0, 0.02 * L, 0.33 * L, 0.5 * L, 0.97 * L, L}) {
    const Eigen::Vector3d radial = (arc_point(arc, s) - arc.center) / rho;
    for (double r : {0.3 * rho, 0.95 * rho, 1.0 * rho, 1.5 * rho}) {
      const Eigen::Vector3d point = arc.center + r * radial + Eigen::Vector3d(0.1 * rho, 0, 0);
      const CurveProjection global = project_onto_curve(arc.configuration, point);
      for (int start = 0; start < arc.rod.intervals; ++start) {
        const CurveProjection local = project_from_interval(arc.configuration, point, start, 0);
        EXPECT_TRUE(CompareScalars(local.distance, global.distance, 1e-15))
            << "s = " << s << ", r/ρ = " << r / rho << ", from interval " << start;
        EXPECT_NEAR(local.s, global.s, 1e-9 * L) << "from interval " << start;
      }
    }
  }
}

/// A precurved rod under no load is a helix of 1.55 turns: a point between two turns has a local
/// minimum of the distance on each.
RodConfiguration make_helix(ClampedRod& rod) {
  rod = testing::rubber_band(ConstitutiveModel::Cosserat, 64);
  rod.properties.u_rest = Eigen::Vector3d(30.0, 0.0, 15.0);  // |u| L = 9.7 rad
  rod.validate();
  return integrate(rod, BaseWrench{});
}

TEST(CurveDistance, FindsTheGlobalMinimumNearARodThatCurlsBack) {
  ClampedRod rod;
  const RodConfiguration helix = make_helix(rod);
  const double turn = 2.0 * std::numbers::pi / rod.properties.u_rest.norm();  // arc length
  const double h = rod.step();
  const int per_interval = 200;
  const double sampling = 0.5 * h / per_interval * 1.01;  // |H'| ≈ |v| = 1 (+1% margin)

  // A point between the turns at s1 and s2 = s1 + turn, 45% of the way from turn 2 to turn 1.
  const double s1 = 0.21 * rod.properties.length;
  const int i1 = static_cast<int>(s1 / h), i2 = static_cast<int>((s1 + turn) / h);
  const Eigen::Vector3d p1 = testing::hermite_point(helix, i1, 0.5);
  const Eigen::Vector3d p2 = testing::hermite_point(helix, i2, 0.5);
  const Eigen::Vector3d point = p2 + 0.45 * (p1 - p2);
  const CurveProjection projection = project_onto_curve(helix, point);
  const double brute = testing::brute_force_distance(helix, point, per_interval);
  EXPECT_LE(projection.distance, brute + 1e-15);
  EXPECT_GE(projection.distance, brute - sampling);
  EXPECT_LT(std::abs(projection.s - helix.s[i2]), 0.25 * turn) << "went to the other turn";

  // Seeded random points around the helix against brute force.
  std::mt19937 rng(20240521);
  std::uniform_real_distribution<double> box(-0.12, 0.12), up(-0.05, 0.2);
  for (int k = 0; k < 150; ++k) {
    const Eigen::Vector3d q(box(rng), box(rng), up(rng));
    const CurveProjection found = project_onto_curve(helix, q);
    const double reference = testing::brute_force_distance(helix, q, per_interval);
    EXPECT_LE(found.distance, reference + 1e-15) << "point " << q.transpose();
    EXPECT_GE(found.distance, reference - sampling) << "point " << q.transpose();
    EXPECT_TRUE(CompareMatrices(found.closest,
                                testing::hermite_point(helix, found.interval, found.t), 1e-15));
  }
}

TEST(CurveDistance, PrecomputedBallsGiveTheSameProjection) {
  // The balls computed once per configuration (the optimiser's path) must change nothing: the
  // same intervals are searched, so the projections are bit for bit those computed point by point.
  ClampedRod rod;
  const RodConfiguration helix = make_helix(rod);
  std::vector<IntervalBall> balls;
  interval_balls(helix, balls);
  ASSERT_EQ(balls.size(), static_cast<std::size_t>(rod.intervals));
  std::mt19937 rng(20261125);
  std::uniform_real_distribution<double> box(-0.12, 0.12), up(-0.05, 0.2);
  for (int k = 0; k < 200; ++k) {
    const Eigen::Vector3d q(box(rng), box(rng), up(rng));
    const CurveProjection one = project_onto_curve(helix, q);
    const CurveProjection shared = project_onto_curve(helix, q, balls);
    EXPECT_EQ(one.distance, shared.distance);
    EXPECT_EQ(one.interval, shared.interval);
    EXPECT_EQ(one.t, shared.t);
    EXPECT_EQ(one.s, shared.s);
  }
  // Every node lies in its intervals' balls (the segment's ends are control points).
  for (int i = 0; i < rod.intervals; ++i) {
    const IntervalBall& ball = balls[static_cast<std::size_t>(i)];
    EXPECT_LE((helix.p[i] - ball.center).norm(), ball.radius * (1 + 1e-15));
    EXPECT_LE((helix.p[i + 1] - ball.center).norm(), ball.radius * (1 + 1e-15));
  }
}

/// A loaded, precurved, 3D configuration (the integrator-derivative test's kind of rod).
struct GradientCase {
  ClampedRod rod;
  BaseWrench w;
  Vector6d S;
};

GradientCase make_gradient_case(ConstitutiveModel model) {
  GradientCase g;
  g.rod = testing::rubber_band(model, 20);
  g.rod.properties.u_rest = Eigen::Vector3d(0.5, -0.3, 1.0);
  g.rod.load =
      DistributedLoad::gravity(testing::kBandMassPerLength, Eigen::Vector3d(0.0, -9.81, 0.0));
  g.rod.clamp.position = Eigen::Vector3d(0.1, 0.2, 0.3);
  g.rod.clamp.rotation = exp_so3(Eigen::Vector3d(0.2, -0.5, 0.3));
  g.rod.validate();
  g.S = testing::wrench_scale(g.rod);
  Vector6d xi;
  xi << 0.6, -0.4, 0.3, 0.7, -0.5, 0.4;
  g.w = Wrench::from_vector(xi.cwiseProduct(g.S));
  return g;
}

class DistanceGradient : public ::testing::TestWithParam<ConstitutiveModel> {};

TEST_P(DistanceGradient, MatchesCentralFiniteDifferences) {
  const GradientCase g = make_gradient_case(GetParam());
  const RodConfiguration c = integrate(g.rod, g.w, Derivatives::AllNodes);
  const double L = g.rod.properties.length;
  // Points off the curve beside interval midpoints (interior minima) and one beyond the tip
  // (a minimum at the end point s = L, where the envelope argument holds at fixed s = L).
  std::vector<Eigen::Vector3d> points;
  for (int i : {5, 11, 16}) {
    const Eigen::Matrix3d& R = c.R[i];
    points.push_back(testing::hermite_point(c, i, 0.5) + 0.03 * R.col(0) - 0.02 * R.col(1));
  }
  points.push_back(c.p.back() + 0.04 * c.R.back().col(2) + 0.01 * c.R.back().col(0));

  const testing::FdModel fd = testing::central_difference_model(g.rod.intervals);
  RodConfiguration plus, minus;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const CurveProjection projection = project_onto_curve(c, points[k]);
    ASSERT_GT(projection.distance, 0.01);  // far from the kink of |·| at 0
    const Eigen::Matrix<double, 1, 6> analytic = distance_gradient(g.rod, c, projection, points[k]);
    for (int j = 0; j < 6; ++j) {
      Vector6d step = Vector6d::Zero();
      step(j) = fd.eta * g.S(j);
      integrate(g.rod, Wrench::from_vector(g.w.to_vector() + step), plus);
      integrate(g.rod, Wrench::from_vector(g.w.to_vector() - step), minus);
      const double numeric = (project_onto_curve(plus, points[k]).distance -
                              project_onto_curve(minus, points[k]).distance) /
                             (2.0 * step(j));
      // |FD - ∂d/∂ξ| ≤ bound · F with F = L (distances move like positions): in w, / S_j.
      EXPECT_TRUE(CompareScalars(analytic(j), numeric, fd.bound * L / g.S(j)))
          << to_string(GetParam()) << ", point " << k << ", column " << j;
    }
  }
}

TEST_P(DistanceGradient, IsZeroAtZeroDistance) {
  const GradientCase g = make_gradient_case(GetParam());
  const RodConfiguration c = integrate(g.rod, g.w, Derivatives::AllNodes);
  const CurveProjection projection = project_onto_curve(c, c.p[7]);
  EXPECT_EQ(projection.distance, 0.0);
  EXPECT_TRUE(CompareMatrices(distance_gradient(g.rod, c, projection, c.p[7]),
                              Eigen::Matrix<double, 1, 6>::Zero(), 0.0));
}

INSTANTIATE_TEST_SUITE_P(BothModels,
                         DistanceGradient,
                         ::testing::Values(ConstitutiveModel::Cosserat,
                                           ConstitutiveModel::Kirchhoff),
                         [](const auto& info) { return to_string(info.param); });

}  // namespace
}  // namespace test_curve_distance
}  // namespace rodshape
