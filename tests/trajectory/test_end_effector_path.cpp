// Tests of the end-effector path's timing: limits respected (checked by finite differences of the
// sampled path, whose error model is stated where it is used), waypoints reached exactly and in
// order, durations in closed form for the trapezoid.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

#include "rodshape/error.hpp"
#include "rodshape/trajectory/end_effector_path.hpp"

namespace rodshape {
namespace {

Pose pose_at(const Eigen::Vector3d& p, double angle_about_z = 0.0) {
  return {p, Eigen::AngleAxisd(angle_about_z, Eigen::Vector3d::UnitZ()).toRotationMatrix()};
}

double rotation_angle(const Pose& a, const Pose& b) {
  return Eigen::AngleAxisd(a.rotation.transpose() * b.rotation).angle();
}

TEST(EndEffectorPath, LongTranslationIsATrapezoidWithClosedFormDuration) {
  // d = 0.1 m at v = 0.02 m/s, a = 0.1 m/s²: t_acc = 0.2 s covering 2 mm on each side, cruise
  // (0.1 - 0.004)/0.02 = 4.8 s, T = 5.2 s.
  EndEffectorLimits limits;
  const auto path = time_parameterize({pose_at({0, 0, 0}), pose_at({0.1, 0, 0})}, limits);
  EXPECT_NEAR(path.back().t, 5.2, 1e-12);
  EXPECT_TRUE(path.back().pose.position.isApprox(Eigen::Vector3d(0.1, 0, 0), 1e-15));
}

TEST(EndEffectorPath, ShortMoveIsTriangular) {
  // d = 1 mm: v_max²/a_max = 4 mm > d, so the profile is triangular: T = 2 sqrt(d / a) = 0.2 s.
  EndEffectorLimits limits;
  const auto path = time_parameterize({pose_at({0, 0, 0}), pose_at({0.001, 0, 0})}, limits);
  EXPECT_NEAR(path.back().t, 2.0 * std::sqrt(0.001 / 0.1), 1e-12);
}

TEST(EndEffectorPath, RotationLimitGovernsATurnInPlace) {
  // φ = π/2 at ω = 0.2 rad/s, α = 1 rad/s²: t_acc = 0.2 s (0.02 rad each side), cruise
  // (π/2 - 0.04)/0.2 s.
  EndEffectorLimits limits;
  const auto path =
      time_parameterize({pose_at({0, 0, 0}), pose_at({0, 0, 0}, std::numbers::pi / 2)}, limits);
  EXPECT_NEAR(path.back().t, 0.4 + (std::numbers::pi / 2 - 0.04) / 0.2, 1e-12);
}

TEST(EndEffectorPath, SampledSpeedsRespectTheLimits) {
  EndEffectorLimits limits;
  limits.sample_rate = 1000.0;
  const std::vector<Pose> waypoints = {pose_at({0, 0, 0}), pose_at({0.05, 0.02, 0.0}, 0.3),
                                       pose_at({0.05, 0.02, 0.0}, 0.3),  // no motion: no time
                                       pose_at({0.0, 0.04, 0.01}, -0.4)};
  const auto path = time_parameterize(waypoints, limits);
  // Between consecutive samples the mean speed is at most the largest speed in the interval; the
  // profile's speed is continuous, so the mean never exceeds the limit (up to round-off).
  for (std::size_t k = 1; k < path.size(); ++k) {
    const double dt = path[k].t - path[k - 1].t;
    ASSERT_GT(dt, 0.0) << "times strictly increase at sample " << k;
    EXPECT_LE((path[k].pose.position - path[k - 1].pose.position).norm() / dt,
              limits.max_linear_speed * (1 + 1e-9));
    EXPECT_LE(rotation_angle(path[k - 1].pose, path[k].pose) / dt,
              limits.max_angular_speed * (1 + 1e-9));
  }
  // Every distinct waypoint is on the path exactly, in order (the repeated one adds no sample).
  const std::vector<Pose> distinct = {waypoints[0], waypoints[1], waypoints[3]};
  std::size_t found = 0;
  for (const TimedPose& sample : path)
    if (found < distinct.size() &&
        (sample.pose.position - distinct[found].position).norm() == 0.0 &&
        rotation_angle(sample.pose, distinct[found]) < 1e-12)
      ++found;
  EXPECT_EQ(found, distinct.size());
}

TEST(EndEffectorPath, BadLimitsNameTheField) {
  EndEffectorLimits limits;
  limits.max_linear_speed = -1.0;
  try {
    time_parameterize({Pose{}}, limits);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("EndEffectorLimits.max_linear_speed"), std::string::npos);
  }
}

}  // namespace
}  // namespace rodshape
