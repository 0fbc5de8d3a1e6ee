// test_obstacle_ops.cpp: the obstacle shapes' operations besides the distance
// (obstacle_shapes.hpp): ray hits against closed forms and against the distance along the ray, a
// rigid motion's round trip and the distances' invariance under it, bounds holding the surface, the
// task file's fields, and the segment helpers (segment.hpp).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <concepts>
#include <limits>
#include <numbers>
#include <optional>
#include <random>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "rodshape/core/obstacle.hpp"
#include "rodshape/core/pose.hpp"
#include "rodshape/core/segment.hpp"

namespace test_obstacle_ops {
namespace {

using Eigen::Vector3d;
using rodshape::BoxObstacle;
using rodshape::CapsuleObstacle;
using rodshape::HalfSpaceObstacle;
using rodshape::Obstacle;
using rodshape::Pose;
using rodshape::SphereObstacle;

constexpr double kInf = std::numeric_limits<double>::infinity();

/// Every alternative of the variant has every operation (the visitors would not compile else).
template <class S>
concept HasEveryOperation = requires(const S& s, const Vector3d& p, const Pose& pose) {
  rodshape::shape_kind(s);
  rodshape::shape_distance(s, p);
  rodshape::shape_distance(s, p, p);
  rodshape::shape_ray_hit(s, p, p);
  { rodshape::transformed(pose, s) } -> std::same_as<S>;
  rodshape::shape_bounds(s);
  rodshape::shape_fields(s);
  rodshape::validate_shape(s, std::string());
};
template <class V>
struct EveryShapeHasEveryOperation;
template <class... S>
struct EveryShapeHasEveryOperation<std::variant<S...>>
    : std::bool_constant<(HasEveryOperation<S> && ...)> {};
static_assert(EveryShapeHasEveryOperation<rodshape::ObstacleShape>::value);

Eigen::Matrix3d turned() {
  return Eigen::AngleAxisd(0.7, Vector3d(1.0, 2.0, 3.0).normalized()).toRotationMatrix();
}

std::vector<Obstacle> shapes() {
  return {{"ball", SphereObstacle{{0.1, 0.0, 0.2}, 0.05}},
          {"crate", BoxObstacle{{0.0, 0.1, 0.1}, {0.08, 0.04, 0.12}, turned()}},
          {"rail", CapsuleObstacle{{-0.1, 0.0, 0.1}, {0.1, 0.05, 0.15}, 0.02}},
          {"table", HalfSpaceObstacle{{0.2, 0.1, -1.0}, 0.01}}};
}

Vector3d random_unit(std::mt19937& random) {
  std::normal_distribution<double> normal;
  return Vector3d(normal(random), normal(random), normal(random)).normalized();
}

Pose random_pose(std::mt19937& random) {
  std::uniform_real_distribution<double> angle(-3.0, 3.0), shift(-0.5, 0.5);
  return {Vector3d(shift(random), shift(random), shift(random)),
          Eigen::AngleAxisd(angle(random), random_unit(random)).toRotationMatrix()};
}

Vector3d moved(const Pose& a_T_b, const Vector3d& x) { return a_T_b.position + a_T_b.rotation * x; }

TEST(ObstacleRay, HitsEqualTheirClosedForms) {
  const Vector3d o = Vector3d::Zero(), z = Vector3d::UnitZ(), x = Vector3d::UnitX();
  const Obstacle ball{"", SphereObstacle{{0.0, 0.0, 5.0}, 1.0}};
  EXPECT_DOUBLE_EQ(ball.ray_hit(o, z), 4.0);
  EXPECT_DOUBLE_EQ(ball.ray_hit(Vector3d(0.6, 0.0, 0.0), z), 5.0 - 0.8);  // |x| = 0.6 off axis
  EXPECT_EQ(ball.ray_hit(o, -z), kInf);                                   // behind the origin
  EXPECT_EQ(ball.ray_hit(Vector3d(1.5, 0.0, 0.0), z), kInf);              // passes beside
  EXPECT_EQ(ball.ray_hit(Vector3d(0.0, 0.0, 5.5), x), 0.0);               // from inside

  const Obstacle box{"",
                     BoxObstacle{{0.0, 0.0, 3.0}, {2.0, 4.0, 2.0}, Eigen::Matrix3d::Identity()}};
  EXPECT_DOUBLE_EQ(box.ray_hit(o, z), 2.0);
  EXPECT_EQ(box.ray_hit(Vector3d(1.5, 0.0, 0.0), z), kInf);  // parallel to the x slab, outside
  // Turned 45° about z: the ray along x meets the vertical edge at x = -√2.
  const Eigen::Matrix3d eighth = Eigen::AngleAxisd(std::numbers::pi / 4.0, z).toRotationMatrix();
  const Obstacle diamond{"", BoxObstacle{Vector3d::Zero(), {2.0, 2.0, 2.0}, eighth}};
  EXPECT_NEAR(diamond.ray_hit(Vector3d(-5.0, 0.0, 0.0), x), 5.0 - std::sqrt(2.0), 1e-12);

  const Obstacle pole{"", CapsuleObstacle{{0.0, 0.0, -1.0}, {0.0, 0.0, 1.0}, 0.5}};
  EXPECT_DOUBLE_EQ(pole.ray_hit(Vector3d(-3.0, 0.0, 0.0), x), 2.5);  // the cylinder
  EXPECT_DOUBLE_EQ(pole.ray_hit(Vector3d(0.0, 0.0, 5.0), -z), 3.5);  // the end ball, on axis
  EXPECT_NEAR(pole.ray_hit(Vector3d(-3.0, 0.0, 1.2), x), 3.0 - std::sqrt(0.21), 1e-12);  // cap
  EXPECT_EQ(pole.ray_hit(Vector3d(-3.0, 0.0, 1.6), x), kInf);

  const Obstacle floor{"", HalfSpaceObstacle{{0.0, 0.0, -2.0}, 0.0}};  // solid where z < 0
  EXPECT_NEAR(floor.ray_hit(z, Vector3d(1.0, 0.0, -1.0).normalized()), std::sqrt(2.0), 1e-12);
  EXPECT_EQ(floor.ray_hit(z, z), kInf);
  EXPECT_EQ(floor.ray_hit(-z, x), 0.0);
}

/// A ray from outside meets the surface where it hits (d = 0 there) and no point before it lies
/// inside; a miss has no point inside along the ray.
TEST(ObstacleRay, TheHitIsTheFirstPointOfTheSurfaceAlongTheRay) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> from(-0.4, 0.4);
  int hits = 0;
  for (const Obstacle& obstacle : shapes()) {
    for (int trial = 0; trial < 300; ++trial) {
      const Vector3d o(from(random), from(random), from(random));
      if (obstacle.distance(o).distance <= 1e-6) continue;
      // Aim near the obstacle half the time (a point near the origin of the cell).
      const Vector3d d = trial % 2 == 0
                             ? random_unit(random)
                             : Vector3d(Vector3d(0.05 * from(random), 0.1, 0.15) - o).normalized();
      const double t = obstacle.ray_hit(o, d);
      const double end = std::isfinite(t) ? t : 2.0;
      for (int k = 0; k < 200; ++k) {
        const double s = end * k / 200.0;
        EXPECT_GT(obstacle.distance(Vector3d(o + s * d)).distance, -1e-12)
            << obstacle.name << " trial " << trial << " s " << s;
      }
      if (std::isfinite(t)) {
        ++hits;
        EXPECT_NEAR(obstacle.distance(Vector3d(o + t * d)).distance, 0.0, 1e-9)
            << obstacle.name << " trial " << trial;
      }
    }
  }
  EXPECT_GT(hits, 100);  // the test saw hits, not only misses
}

TEST(ObstacleTransform, ThereAndBackIsTheIdentity) {
  std::mt19937 random(11);
  for (int trial = 0; trial < 20; ++trial) {
    const Pose a_T_b = random_pose(random);
    for (const Obstacle& obstacle : shapes()) {
      const Obstacle back = transformed(rodshape::inverse(a_T_b), transformed(a_T_b, obstacle));
      const rodshape::ObstacleDescription before = obstacle.describe(), after = back.describe();
      EXPECT_EQ(after.name, before.name);
      EXPECT_EQ(after.kind, before.kind);
      ASSERT_EQ(after.fields.size(), before.fields.size());
      for (std::size_t k = 0; k < before.fields.size(); ++k) {
        const auto& x = before.fields[k].value;
        const auto& y = after.fields[k].value;
        ASSERT_EQ(x.index(), y.index());
        if (const auto* number = std::get_if<double>(&x)) {
          EXPECT_NEAR(std::get<double>(y), *number, 1e-12) << obstacle.name;
        } else if (const auto* vector = std::get_if<Vector3d>(&x)) {
          EXPECT_LT((std::get<Vector3d>(y) - *vector).norm(), 1e-12) << obstacle.name;
        } else {
          EXPECT_LT((std::get<Eigen::Matrix3d>(y) - std::get<Eigen::Matrix3d>(x)).norm(), 1e-12)
              << obstacle.name;
        }
      }
    }
  }
}

/// d_a(T p) = d_b(p), ∇d_a(T p) = R ∇d_b(p), the segment's minimiser keeps its t, and a ray's hit
/// keeps its length.
TEST(ObstacleTransform, DistancesAndHitsAreInvariantUnderARigidMotion) {
  std::mt19937 random(13);
  std::uniform_real_distribution<double> near(-0.3, 0.3);
  for (int trial = 0; trial < 20; ++trial) {
    const Pose a_T_b = random_pose(random);
    for (const Obstacle& in_b : shapes()) {
      const Obstacle in_a = transformed(a_T_b, in_b);
      for (int k = 0; k < 20; ++k) {
        const Vector3d p(near(random), near(random), near(random));
        const Vector3d q(near(random), near(random), near(random));
        const rodshape::PointDistance db = in_b.distance(p), da = in_a.distance(moved(a_T_b, p));
        EXPECT_NEAR(da.distance, db.distance, 1e-12) << in_b.name;
        EXPECT_LT((da.gradient - a_T_b.rotation * db.gradient).norm(), 1e-9) << in_b.name;
        const rodshape::SegmentDistance sb = in_b.distance(p, q);
        const rodshape::SegmentDistance sa = in_a.distance(moved(a_T_b, p), moved(a_T_b, q));
        EXPECT_NEAR(sa.distance, sb.distance, 1e-9) << in_b.name;
        const Vector3d d = random_unit(random);
        const double hb = in_b.ray_hit(p, d),
                     ha = in_a.ray_hit(moved(a_T_b, p), a_T_b.rotation * d);
        if (std::isfinite(hb))
          EXPECT_NEAR(ha, hb, 1e-9) << in_b.name;
        else
          EXPECT_EQ(ha, kInf) << in_b.name;
      }
    }
  }
}

/// The nearest surface point p - d(p) ∇d(p) of points around a finite shape lies in its bounds,
/// and the bounds are tight: each of their six faces is reached by the surface within 1 %.
TEST(ObstacleBounds, HoldTheSurfaceAndTouchIt) {
  std::mt19937 random(17);
  std::uniform_real_distribution<double> around(-0.4, 0.4);
  for (const Obstacle& obstacle : shapes()) {
    const std::optional<rodshape::AxisAlignedBox> box = obstacle.bounds();
    if (std::holds_alternative<HalfSpaceObstacle>(obstacle.shape)) {
      EXPECT_FALSE(box.has_value());
      continue;
    }
    ASSERT_TRUE(box.has_value()) << obstacle.name;
    Vector3d lowest = Vector3d::Constant(kInf), highest = -lowest;
    const auto surface = [&](const Vector3d& p) {
      const rodshape::PointDistance d = obstacle.distance(p);
      const Vector3d on = p - d.distance * d.gradient;
      EXPECT_TRUE(box->contains(on, 1e-12)) << obstacle.name << " at " << on.transpose();
      lowest = lowest.cwiseMin(on);
      highest = highest.cwiseMax(on);
    };
    for (int k = 0; k < 20000; ++k)
      surface(Vector3d(around(random), around(random), around(random)));
    // and points far along each axis, whose nearest surface point is the extreme one
    const Vector3d centre = 0.5 * (box->lower + box->upper);
    for (int axis = 0; axis < 3; ++axis)
      for (const double side : {-1.0, 1.0}) surface(centre + side * 10.0 * Vector3d::Unit(axis));
    const double size = (box->upper - box->lower).maxCoeff();
    EXPECT_LT((lowest - box->lower).maxCoeff(), 0.01 * size) << obstacle.name;
    EXPECT_LT((box->upper - highest).maxCoeff(), 0.01 * size) << obstacle.name;
  }
}

TEST(ObstacleDescription, GivesTheTaskFilesKindAndFieldsInItsOrder) {
  const std::vector<std::pair<std::string, std::vector<std::string>>> expected = {
      {"sphere", {"center", "radius"}},
      {"box", {"center", "size", "rotation"}},
      {"capsule", {"from", "to", "radius"}},
      {"half_space", {"normal", "offset"}}};
  const std::vector<Obstacle> all = shapes();
  for (std::size_t i = 0; i < all.size(); ++i) {
    const rodshape::ObstacleDescription description = all[i].describe();
    EXPECT_EQ(description.name, all[i].name);
    EXPECT_EQ(description.kind, expected[i].first);
    EXPECT_EQ(description.kind, all[i].kind());
    std::vector<std::string> keys;
    for (const rodshape::ObstacleField& field : description.fields) keys.emplace_back(field.key);
    EXPECT_EQ(keys, expected[i].second);
  }
}

TEST(Segment, TheNearestPointIsTheClampedProjection) {
  const Vector3d a(0.0, 0.0, 0.0), b(2.0, 0.0, 0.0);
  EXPECT_DOUBLE_EQ(rodshape::nearest_on_segment(Vector3d(0.5, 1.0, 0.0), a, b), 0.25);
  EXPECT_DOUBLE_EQ(rodshape::nearest_on_segment(Vector3d(-1.0, 1.0, 0.0), a, b), 0.0);
  EXPECT_DOUBLE_EQ(rodshape::nearest_on_segment(Vector3d(3.0, 1.0, 0.0), a, b), 1.0);
  EXPECT_DOUBLE_EQ(rodshape::nearest_on_segment(Vector3d(3.0, 1.0, 0.0), a, a), 0.0);  // a point
  EXPECT_DOUBLE_EQ(rodshape::distance_to_segment(Vector3d(1.0, 3.0, 4.0), a, b), 5.0);
  EXPECT_DOUBLE_EQ(rodshape::distance_to_segment(Vector3d(5.0, 4.0, 0.0), a, b), 5.0);  // beyond b
  const Eigen::Vector2d a2(0.0, 0.0), b2(0.0, 2.0);  // any dimension
  EXPECT_DOUBLE_EQ(rodshape::distance_to_segment(Eigen::Vector2d(-3.0, 1.0), a2, b2), 3.0);
  // Two segments: crossing skew lines, and one end nearest.
  const auto [s, t] =
      rodshape::nearest_between_segments(a, b, Vector3d(0.5, -1.0, 1.0), Vector3d(0.5, 1.0, 1.0));
  EXPECT_DOUBLE_EQ(s, 0.25);
  EXPECT_DOUBLE_EQ(t, 0.5);
  const auto [s2, t2] =
      rodshape::nearest_between_segments(a, b, Vector3d(3.0, 0.0, 1.0), Vector3d(4.0, 0.0, 5.0));
  EXPECT_DOUBLE_EQ(s2, 1.0);
  EXPECT_DOUBLE_EQ(t2, 0.0);
}

}  // namespace
}  // namespace test_obstacle_ops
