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
namespace test_end_effector_path {
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

// ---- Two ends on one clock ----

/// The world-frame rotation vector from a to b (log(R_b R_aᵀ)): along a slerp segment its axis is
/// fixed, so its differences are the angular displacement exactly.
Eigen::Vector3d rotation_vector(const Pose& a, const Pose& b) {
  const Eigen::AngleAxisd turn(b.rotation * a.rotation.transpose());
  return turn.angle() * turn.axis();
}

/// Finite differences of one end's samples against its limits: mean speeds (first differences)
/// and mean accelerations (second differences, over the mean interval) never exceed the profile's
/// own bounds, since σ̇ is continuous and Lipschitz with σ̈'s bound. Returns how many samples were
/// checked.
int expect_within_limits(const std::vector<TimedPose>& path, const EndEffectorLimits& limits) {
  const double tol = 1 + 1e-9;
  for (std::size_t k = 1; k < path.size(); ++k) {
    const double dt = path[k].t - path[k - 1].t;
    EXPECT_GT(dt, 0.0) << "sample " << k;
    EXPECT_LE((path[k].pose.position - path[k - 1].pose.position).norm() / dt,
              limits.max_linear_speed * tol)
        << "sample " << k;
    EXPECT_LE(rotation_angle(path[k - 1].pose, path[k].pose) / dt, limits.max_angular_speed * tol)
        << "sample " << k;
    if (k + 1 < path.size()) {
      const double dt2 = path[k + 1].t - path[k].t;
      const Eigen::Vector3d v0 = (path[k].pose.position - path[k - 1].pose.position) / dt;
      const Eigen::Vector3d v1 = (path[k + 1].pose.position - path[k].pose.position) / dt2;
      const Eigen::Vector3d w0 = rotation_vector(path[k - 1].pose, path[k].pose) / dt;
      const Eigen::Vector3d w1 = rotation_vector(path[k].pose, path[k + 1].pose) / dt2;
      const double mid = 0.5 * (dt + dt2);
      // + 1e-9: the difference of two nearly equal speeds divided by 10 ms.
      EXPECT_LE((v1 - v0).norm() / mid, limits.max_linear_acceleration * tol + 1e-9)
          << "sample " << k;
      EXPECT_LE((w1 - w0).norm() / mid, limits.max_angular_acceleration * tol + 1e-9)
          << "sample " << k;
    }
  }
  return static_cast<int>(path.size());
}

TEST(TwoEndPath, ASegmentWhereOnlyTheBaseMovesTakesTheBasesTime) {
  // The tip stays put; the base moves 0.1 m at its own (slower) limits: v = 0.01 m/s, a = 0.05:
  // t_acc = 0.2 s (1 mm each side), cruise (0.1 - 0.002) / 0.01 = 9.8 s, T = 10.2 s.
  EndEffectorLimits tip, base;
  base.max_linear_speed = 0.01;
  base.max_linear_acceleration = 0.05;
  const Pose still = pose_at({0.3, 0, 0});
  const TwoEndPath path = time_parameterize_together(
      {still, still}, {pose_at({0, 0, 0}), pose_at({0, 0.1, 0})}, tip, base);
  ASSERT_EQ(path.tip.size(), path.base.size());
  EXPECT_NEAR(path.base.back().t, 10.2, 1e-12);
  EXPECT_EQ(path.base.size(), 1021u);  // t = 0, 0.01, …, 10.19, then 10.2
  for (const TimedPose& sample : path.tip) EXPECT_EQ(sample.pose.position, still.position);
  expect_within_limits(path.base, base);
}

TEST(TwoEndPath, EachSegmentTakesTheLongerTimeAndBothLimitsHoldAtEverySample) {
  EndEffectorLimits tip, base;
  tip.sample_rate = 500.0;
  base.max_linear_speed = 0.015;
  base.max_angular_speed = 0.1;
  base.max_linear_acceleration = 0.05;
  base.max_angular_acceleration = 0.4;
  base.sample_rate = 20.0;  // not used: the tip's rate is the clock's
  const std::vector<Pose> tips = {pose_at({0.4, 0, 0}), pose_at({0.45, 0.02, 0}, 0.3),
                                  pose_at({0.45, 0.02, 0}, 0.3),  // neither moves: no time
                                  pose_at({0.45, 0.02, 0}, 0.3),  // only the base moves
                                  pose_at({0.40, 0.05, 0.01}, -0.2)};
  const std::vector<Pose> bases = {pose_at({0, 0, 0}), pose_at({0.01, 0, 0}, 0.05),
                                   pose_at({0.01, 0, 0}, 0.05), pose_at({0.0, 0.03, 0}, -0.3),
                                   pose_at({0.0, 0.03, 0}, -0.3)};  // only the tip moves
  const TwoEndPath path = time_parameterize_together(tips, bases, tip, base);
  ASSERT_EQ(path.tip.size(), path.base.size());
  for (std::size_t i = 0; i < path.tip.size(); ++i) ASSERT_EQ(path.tip[i].t, path.base[i].t);
  EXPECT_GT(expect_within_limits(path.tip, tip), 1000);
  expect_within_limits(path.base, base);
  // Arrivals: every waypoint pair is on both paths exactly, at the same sample, in order, and the
  // segment durations are at least the longer of the two ends' own.
  std::vector<double> arrival;  // the arrival time of waypoints 1 …, the repeated one skipped
  std::size_t next = 1;
  for (std::size_t i = 0; i < path.tip.size() && next < tips.size(); ++i) {
    if (next == 2) ++next;  // waypoint 2 repeats 1 on both ends: no sample of its own
    if (path.tip[i].pose.position == tips[next].position &&
        path.tip[i].pose.rotation == tips[next].rotation &&
        path.base[i].pose.position == bases[next].position &&
        path.base[i].pose.rotation == bases[next].rotation) {
      // (Waypoint 3's tip equals waypoint 1's: both ends must match.)
      arrival.push_back(path.tip[i].t);
      ++next;
    }
  }
  ASSERT_EQ(arrival.size(), 3u);
  EXPECT_EQ(arrival.back(), path.tip.back().t);
  double t_before = 0.0;
  const std::size_t segment_of[] = {1, 3, 4};
  for (std::size_t a = 0; a < 3; ++a) {
    const std::size_t k = segment_of[a];
    const double alone = std::max(path_size({tips[k - 1], tips[k]}, tip).duration,
                                  path_size({bases[k - 1], bases[k]}, base).duration);
    EXPECT_GE(arrival[a] - t_before, alone * (1 - 1e-12)) << "segment " << k;
    t_before = arrival[a];
  }
  EXPECT_NEAR(path_size_together(tips, bases, tip, base).duration, path.tip.back().t, 1e-9);
}

TEST(TwoEndPath, ABaseThatStaysPutLeavesTheTipsTimingBitIdentical) {
  EndEffectorLimits tip, base;
  tip.sample_rate = 250.0;
  base.max_linear_speed = 1e-3;  // would be slow, but the base never moves
  const std::vector<Pose> tips = {pose_at({0, 0, 0}), pose_at({0.05, 0.02, 0.0}, 0.3),
                                  pose_at({0.05, 0.02, 0.0}, 0.3),
                                  pose_at({0.0, 0.04, 0.01}, -0.4)};
  const std::vector<Pose> bases(tips.size(), pose_at({-0.2, 0, 0}, 1.0));
  const TwoEndPath together = time_parameterize_together(tips, bases, tip, base);
  const std::vector<TimedPose> alone = time_parameterize(tips, tip);
  ASSERT_EQ(together.tip.size(), alone.size());
  for (std::size_t i = 0; i < alone.size(); ++i) {
    EXPECT_EQ(together.tip[i].t, alone[i].t);
    EXPECT_EQ(together.tip[i].pose.position, alone[i].pose.position);
    EXPECT_EQ(together.tip[i].pose.rotation, alone[i].pose.rotation);
    EXPECT_EQ(together.base[i].pose.position, bases[0].position);
  }
}

TEST(TwoEndPath, ListsOfDifferentLengthsAndBadBaseLimitsAreRefused) {
  EndEffectorLimits tip, base;
  EXPECT_THROW(time_parameterize_together({Pose{}, Pose{}}, {Pose{}}, tip, base), InputError);
  base.max_angular_speed = 0.0;
  try {
    time_parameterize_together({Pose{}}, {Pose{}}, tip, base);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("EndEffectorLimits.max_angular_speed"), std::string::npos);
  }
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
}  // namespace test_end_effector_path
}  // namespace rodshape
