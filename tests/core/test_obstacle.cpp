// test_obstacle.cpp: the obstacles' signed distances against closed forms, their gradients against
// central differences (within the differences' own error bound), and the segment distance against
// a dense scan of the segment, with the envelope-theorem derivatives ∂d/∂a, ∂d/∂b against
// Richardson-extrapolated central differences.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <variant>
#include <vector>

#include "rodshape/core/obstacle.hpp"
#include "rodshape/core/scene.hpp"
#include "support/input_error.hpp"

namespace test_obstacle {
namespace {

using Eigen::Vector3d;
using rodshape::BoxObstacle;
using rodshape::CapsuleObstacle;
using rodshape::HalfSpaceObstacle;
using rodshape::Obstacle;
using rodshape::SphereObstacle;

std::vector<Obstacle> shapes() {
  const Eigen::Matrix3d turned =
      Eigen::AngleAxisd(0.7, Vector3d(1.0, 2.0, 3.0).normalized()).toRotationMatrix();
  return {{"ball", SphereObstacle{{0.1, 0.0, 0.2}, 0.05}},
          {"crate", BoxObstacle{{0.0, 0.1, 0.1}, {0.08, 0.04, 0.12}, turned}},
          {"rail", CapsuleObstacle{{-0.1, 0.0, 0.1}, {0.1, 0.05, 0.15}, 0.02}},
          {"table", HalfSpaceObstacle{{0.2, 0.1, -1.0}, 0.01}}};
}

TEST(Obstacle, DistancesEqualTheirClosedForms) {
  const Obstacle ball{"", SphereObstacle{{1.0, 0.0, 0.0}, 0.5}};
  EXPECT_DOUBLE_EQ(ball.distance(Vector3d(3.0, 0.0, 0.0)).distance, 1.5);
  EXPECT_DOUBLE_EQ(ball.distance(Vector3d(1.0, 0.25, 0.0)).distance, -0.25);
  const Obstacle box{"",
                     BoxObstacle{{0.0, 0.0, 0.0}, {2.0, 4.0, 6.0}, Eigen::Matrix3d::Identity()}};
  EXPECT_DOUBLE_EQ(box.distance(Vector3d(4.0, 6.0, 0.0)).distance, std::hypot(3.0, 4.0));  // edge
  EXPECT_DOUBLE_EQ(box.distance(Vector3d(0.5, 0.0, 0.0)).distance, -0.5);  // nearest face x
  const Obstacle pole{"", CapsuleObstacle{{0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, 0.1}};
  EXPECT_DOUBLE_EQ(pole.distance(Vector3d(0.3, 0.4, 0.5)).distance, 0.4);
  EXPECT_DOUBLE_EQ(pole.distance(Vector3d(0.0, 0.0, 2.0)).distance, 0.9);  // beyond the end cap
  const Obstacle table{"", HalfSpaceObstacle{{0.0, 0.0, -2.0}, 0.0}};      // z < 0 is solid
  EXPECT_DOUBLE_EQ(table.distance(Vector3d(5.0, 1.0, 0.25)).distance, 0.25);
  EXPECT_DOUBLE_EQ(table.distance(Vector3d(5.0, 1.0, -0.25)).distance, -0.25);
}

/// Whether p lies within `band` of a kink of a box's distance: inside, two faces equally near or
/// the mid-plane between the nearest two (q_k = 0: the nearest face flips); outside, on the
/// boundary of an edge's or corner's region (a component of e = |q| - size/2 at 0).
bool near_box_kink(const Obstacle& obstacle, const Vector3d& p, double band) {
  const auto* box = std::get_if<BoxObstacle>(&obstacle.shape);
  if (box == nullptr) return false;
  const Vector3d q = box->rotation.transpose() * (p - box->center);
  const Vector3d e = q.cwiseAbs() - 0.5 * box->size;
  if (e.maxCoeff() > 0.0) return (e.array().abs() < band).any();
  Eigen::Index k = 0;
  e.maxCoeff(&k);
  std::array<double, 3> sorted{e(0), e(1), e(2)};
  std::sort(sorted.begin(), sorted.end());
  return sorted[2] - sorted[1] < band || std::abs(q(k)) < band;
}

/// The error bound of a central difference of step h of the distance at p: h²/6 |d‴| from the
/// truncation plus 4 ε (1 + |d|) / h from the round-off of the two values. The distance is that to
/// a point (a sphere's centre), a line (a capsule's axis) or, outside a box, an edge or a corner
/// (or linear, near a face), or it is linear (a half-space, inside a box); the distance to a point
/// or a line at range R has |d‴| ≤ 3 / R², R = d + r (sphere, capsule) or R ≥ d (outside a box).
double central_difference_bound(const Obstacle& obstacle, const Vector3d& p, double h) {
  const double d = obstacle.distance(p).distance;
  double R = std::numeric_limits<double>::infinity();
  if (const auto* s = std::get_if<SphereObstacle>(&obstacle.shape)) R = d + s->radius;
  if (const auto* c = std::get_if<CapsuleObstacle>(&obstacle.shape)) R = d + c->radius;
  if (std::holds_alternative<BoxObstacle>(obstacle.shape) && d > 0.0) R = d;
  constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
  return h * h / 6.0 * 3.0 / (R * R) + 4.0 * kEpsilon * (1.0 + std::abs(d)) / h;
}

TEST(Obstacle, GradientsEqualCentralDifferences) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.25, 0.35);
  constexpr double h = 1e-6;
  for (const Obstacle& obstacle : shapes()) {
    for (int k = 0; k < 200; ++k) {
      const Vector3d p(u(rng), u(rng), u(rng));
      const Vector3d g = obstacle.distance(p).gradient;
      EXPECT_NEAR(g.norm(), 1.0, 1e-12);
      Vector3d fd;
      for (int i = 0; i < 3; ++i) {
        const Vector3d e = h * Vector3d::Unit(i);
        fd(i) = (obstacle.distance(p + e).distance - obstacle.distance(p - e).distance) / (2 * h);
      }
      // Central differences: O(h²) on smooth pieces, exact on linear ones. A box's distance has
      // kinks where the nearest face or edge changes; points within 10 h of one are skipped.
      if (near_box_kink(obstacle, p, 10 * h)) continue;
      // Per component; the norm of three such errors is within √3 of the bound.
      EXPECT_LT((fd - g).norm(), std::sqrt(3.0) * central_difference_bound(obstacle, p, h))
          << obstacle.name << " at " << p.transpose();
    }
  }
}

double scanned_segment_distance(const Obstacle& obstacle, const Vector3d& a, const Vector3d& b) {
  double least = std::numeric_limits<double>::infinity();
  for (int k = 0; k <= 20000; ++k)
    least = std::min(least, obstacle.distance(Vector3d(a + (k / 20000.0) * (b - a))).distance);
  return least;
}

TEST(Obstacle, SegmentDistanceIsTheMinimumAlongTheSegmentWithEnvelopeDerivatives) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-0.25, 0.35);
  constexpr double h = 1e-6;
  for (const Obstacle& obstacle : shapes()) {
    for (int k = 0; k < 60; ++k) {
      const Vector3d a(u(rng), u(rng), u(rng));
      const Vector3d b = a + 0.3 * Vector3d(u(rng), u(rng), u(rng));
      const rodshape::SegmentDistance d = obstacle.distance(a, b);
      // Where the minimiser is a box's kink (the segment crossing its inside, where d is the max of
      // the faces' linear distances), d is not differentiable in a, b: skip those.
      if (near_box_kink(obstacle, a + d.t * (b - a), 1e-4)) continue;
      // The scan's grid spacing is |b - a| / 20000 and |∇d| = 1: it overestimates by at most that.
      const double scanned = scanned_segment_distance(obstacle, a, b);
      EXPECT_LE(d.distance, scanned + 1e-12) << obstacle.name;
      EXPECT_GE(d.distance, scanned - (b - a).norm() / 20000.0 - 1e-12) << obstacle.name;
      // Central differences of steps h and 2h, Richardson-extrapolated; their difference estimates
      // the truncation error (the segment's minimum has no simple bound on its third derivative:
      // near-parallel segments make it large). Round-off: 4 ε (1 + |d|) / h per difference; the
      // box's golden-section search leaves the value within |b - a| · 1e-10 (its t tolerance,
      // |∇d| = 1), which the difference divides by h.
      constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
      const double noise =
          4.0 * kEpsilon * (1.0 + std::abs(d.distance)) / h +
          (std::holds_alternative<BoxObstacle>(obstacle.shape) ? (b - a).norm() * 1e-10 / h : 0.0);
      for (int i = 0; i < 3; ++i) {
        const auto central = [&](double step, bool at_a) {
          const Vector3d e = step * Vector3d::Unit(i);
          const double plus =
              at_a ? obstacle.distance(a + e, b).distance : obstacle.distance(a, b + e).distance;
          const double minus =
              at_a ? obstacle.distance(a - e, b).distance : obstacle.distance(a, b - e).distance;
          return (plus - minus) / (2 * step);
        };
        for (const bool at_a : {true, false}) {
          const double fd = central(h, at_a), fd2 = central(2 * h, at_a);
          const double extrapolated = fd + (fd - fd2) / 3.0;
          const double analytic = at_a ? d.dd_da()(i) : d.dd_db()(i);
          EXPECT_NEAR(extrapolated, analytic, std::abs(fd - fd2) + 2.0 * noise)
              << obstacle.name << " " << k << (at_a ? " a" : " b");
        }
      }
    }
  }
}

TEST(Scene, TheClampsMountRequiresOnlyTheClampsOwnGap) {
  rodshape::Scene scene;
  scene.clearance = 0.005;
  scene.rod_radius = 0.002;
  scene.obstacles = {{"table", HalfSpaceObstacle{{0.0, 0.0, -1.0}, 0.0}},
                     {"post", SphereObstacle{{0.2, 0.0, 0.1}, 0.03}}};
  const std::vector<double> required = scene.required_gaps(Vector3d(0.0, 0.0, 0.003));
  EXPECT_DOUBLE_EQ(required[0], 0.001);  // the clamp's own gap: 0.003 - 0.002
  EXPECT_DOUBLE_EQ(required[1], 0.005);
  // A rod along the table at the clamp's height, then up through the post's ball.
  const std::vector<Vector3d> rod{{0.0, 0.0, 0.003}, {0.1, 0.0, 0.003}, {0.2, 0.0, 0.08}};
  const rodshape::SceneGap gap = scene.least_gap(rod, required);
  EXPECT_EQ(gap.obstacle, 1);
  EXPECT_EQ(gap.segment, 1);
  EXPECT_FALSE(gap.clear());
  EXPECT_THROW(scene.check_clamp(Vector3d(0.2, 0.0, 0.1)), rodshape::InputError);
}

// The swept gap bounds the gap of every polyline on the straight way between its two ends from
// below (here an oracle of 200 samples along the way), for random motions past every kind of
// obstacle; without motion it is the least gap itself.
TEST(Scene, TheSweptGapBoundsTheGapAlongTheWayFromBelow) {
  rodshape::Scene scene;
  scene.clearance = 0.005;
  scene.rod_radius = 0.002;
  scene.obstacles = {
      {"ball", SphereObstacle{{0.1, 0.02, 0.0}, 0.02}},
      {"box", BoxObstacle{{0.2, -0.03, 0.01}, {0.02, 0.03, 0.04}, Eigen::Matrix3d::Identity()}},
      {"pole", CapsuleObstacle{{0.15, 0.0, -0.1}, {0.15, 0.0, 0.1}, 0.004}},
      {"table", HalfSpaceObstacle{{0.0, 0.0, -1.0}, 0.06}}};
  const std::vector<double> required(scene.obstacles.size(), scene.clearance);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<Vector3d> from, to;
    for (int i = 0; i <= 20; ++i) {
      const Vector3d p(0.3 * i / 20.0, 0.05 * unit(rng), 0.05 * unit(rng));
      from.push_back(p);
      to.push_back(p + 0.01 * Vector3d(unit(rng), unit(rng), unit(rng)));
    }
    double least = std::numeric_limits<double>::infinity();
    for (int k = 0; k <= 200; ++k) {
      std::vector<Vector3d> between(from.size());
      for (std::size_t i = 0; i < from.size(); ++i)
        between[i] = from[i] + (k / 200.0) * (to[i] - from[i]);
      least = std::min(least, scene.least_gap(between, required).margin);
    }
    const rodshape::SceneGap swept = scene.swept_gap(from, to, required);
    EXPECT_LE(swept.margin, least) << "trial " << trial;
    EXPECT_LE(swept.margin, std::min(scene.least_gap(from, required).margin,
                                     scene.least_gap(to, required).margin));
    EXPECT_DOUBLE_EQ(scene.swept_gap(to, to, required).margin,
                     scene.least_gap(to, required).margin);
  }
}

// A clamp mounted on an obstacle of any shape (on its surface, or nearer than the rod's radius):
// the rod swings about the clamp, leaving it outwards. The gap at the clamp cannot change, so the
// swept bound must not fall below the mount's own gap (the first segment's Lipschitz bound did,
// by half its free node's step: a false collision on every mounted clamp), and it still bounds
// the gap along the way from below (the 200-sample oracle).
TEST(Scene, AClampMountedOnAnyShapeStaysClearAsTheRodSwingsAboutIt) {
  const Eigen::Matrix3d turned =
      Eigen::AngleAxisd(0.4, Vector3d(1.0, -1.0, 2.0).normalized()).toRotationMatrix();
  struct Mount {
    Obstacle obstacle;
    Vector3d surface;  // a point on its surface
    Vector3d normal;   // the outward normal there
  };
  const std::vector<Mount> mounts = {
      {{"ball", SphereObstacle{{0.0, 0.0, -0.05}, 0.05}}, {0.0, 0.0, 0.0}, Vector3d::UnitZ()},
      {{"crate", BoxObstacle{{0.0, 0.0, -0.02}, {0.1, 0.1, 0.04}, turned}},
       turned * Vector3d(0.01, -0.02, 0.02) + Vector3d(0.0, 0.0, -0.02),
       turned * Vector3d::UnitZ()},
      {{"rail", CapsuleObstacle{{-0.1, 0.0, -0.01}, {0.1, 0.0, -0.01}, 0.01}},
       {0.02, 0.0, 0.0},
       Vector3d::UnitZ()},
      {{"table", HalfSpaceObstacle{{0.0, 0.0, -1.0}, 0.0}}, {0.0, 0.0, 0.0}, Vector3d::UnitZ()}};
  for (const Mount& mount : mounts) {
    for (const double height : {0.0, 0.001}) {  // on the surface; 1 mm above it (radius 2 mm)
      rodshape::Scene scene;
      scene.clearance = 0.005;
      scene.rod_radius = 0.002;
      scene.obstacles = {mount.obstacle};
      const Vector3d clamp = mount.surface + height * mount.normal;
      const std::vector<double> required = scene.required_gaps(clamp);
      ASSERT_NEAR(required[0], height - scene.rod_radius, 1e-12) << mount.obstacle.name;
      const Vector3d side = mount.normal.unitOrthogonal();
      const auto rod_at = [&](double angle) {  // 20 intervals over 0.2 m, turned about the clamp
        const Vector3d e = std::cos(angle) * mount.normal + std::sin(angle) * side;
        std::vector<Vector3d> nodes;
        for (int i = 0; i <= 20; ++i) nodes.push_back(clamp + 0.01 * i * e);
        return nodes;
      };
      for (const double step : {1e-5, 1e-3, 0.05}) {  // radians per substep
        const std::vector<Vector3d> from = rod_at(0.3), to = rod_at(0.3 + step);
        const rodshape::SceneGap swept = scene.swept_gap(from, to, required);
        EXPECT_TRUE(swept.clear()) << mount.obstacle.name << " at " << height << " m, step " << step
                                   << ": margin " << swept.margin;
        double least = std::numeric_limits<double>::infinity();
        for (int k = 0; k <= 200; ++k)
          least = std::min(least, scene.least_gap(rod_at(0.3 + step * k / 200.0), required).margin);
        EXPECT_LE(swept.margin, least) << mount.obstacle.name;
      }
    }
  }
}

// The refinement does not hide a motion that does pass through an obstacle: a rod swept across
// a ball between two places clear of it.
TEST(Scene, TheSweptGapStillFindsAMotionThroughAnObstacle) {
  rodshape::Scene scene;
  scene.clearance = 0.005;
  scene.rod_radius = 0.002;
  scene.obstacles = {{"ball", SphereObstacle{{0.1, 0.0, 0.0}, 0.01}}};
  const std::vector<double> required(1, scene.clearance);
  std::vector<Vector3d> from, to;
  for (int i = 0; i <= 20; ++i) {
    from.emplace_back(0.01 * i, -0.05, 0.0);
    to.emplace_back(0.01 * i, 0.05, 0.0);
  }
  ASSERT_TRUE(scene.least_gap(from, required).clear());
  ASSERT_TRUE(scene.least_gap(to, required).clear());
  const rodshape::SceneGap swept = scene.swept_gap(from, to, required);
  EXPECT_FALSE(swept.clear());
  EXPECT_LE(swept.gap, -0.01 - scene.rod_radius + 1e-12);  // at least as deep as the centre passes
  EXPECT_EQ(swept.segment == 9 || swept.segment == 10, true);
}

TEST(Scene, BadObstaclesNameTheirField) {
  using rodshape::testing::input_error_message;
  rodshape::Scene scene;
  scene.obstacles = {{"", SphereObstacle{{0.0, 0.0, 0.0}, 0.1}},
                     {"", HalfSpaceObstacle{Vector3d::Zero(), 0.0}}};
  EXPECT_EQ(input_error_message([&] { scene.validate(); }),
            "Scene.obstacles[1].normal must not be zero");
  scene.obstacles[1] = {"", BoxObstacle{{0.0, 0.0, std::nan("")}, {1.0, 1.0, 1.0}}};
  EXPECT_EQ(input_error_message([&] { scene.validate(); }),
            "Scene.obstacles[1].center[2] = nan must be finite");
  scene.obstacles[1] = {"", CapsuleObstacle{{0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, -0.1}};
  EXPECT_EQ(input_error_message([&] { scene.validate(); }),
            "Scene.obstacles[1].radius = -0.1 must be > 0");
  scene.obstacles.assign(rodshape::Scene::kMaxObstacles + 1, scene.obstacles[0]);
  EXPECT_EQ(input_error_message([&] { scene.validate(); }),
            "Scene.obstacles has 1001 entries; at most 1000");
}

// Issue 43: a half-space's normal is normalised; |n|² of 1e300 overflowed (every distance read 0)
// and 1e-300 was said to be zero.
TEST(Scene, AHalfSpaceNormalOfHugeOrTinyMagnitudeIsRefused) {
  using rodshape::testing::input_error_message;
  rodshape::Scene scene;
  scene.obstacles = {{"", SphereObstacle{{0.0, 0.0, 0.0}, 0.1}},
                     {"", HalfSpaceObstacle{{0.0, 0.0, -1e300}, 0.0}}};
  EXPECT_EQ(input_error_message([&] { scene.validate(); }),
            "Scene.obstacles[1].normal has magnitude 1e+300; it must be in [1e-06, 1e+06] (it is "
            "normalised; docs/task-file.md)");
  scene.obstacles[1] = {"", HalfSpaceObstacle{{1e-300, 0.0, 0.0}, 0.0}};
  EXPECT_EQ(input_error_message([&] { scene.validate(); }),
            "Scene.obstacles[1].normal has magnitude 1e-300; it must be in [1e-06, 1e+06] (it is "
            "normalised; docs/task-file.md)");
  for (const double norm : {1e-6, 1e6}) {
    scene.obstacles[1] = {"", HalfSpaceObstacle{{0.0, 0.0, -norm}, 0.0}};
    EXPECT_EQ(input_error_message([&] { scene.validate(); }), "") << norm;
  }
}

}  // namespace
}  // namespace test_obstacle
