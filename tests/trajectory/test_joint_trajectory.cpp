// Tests of joint_trajectory(): the joint path replays the end-effector path through forward
// kinematics, respects the joint velocity limits (slowing the path down where needed) and reports
// an unreachable pose with its time.
#include "rodshape/trajectory/joint_trajectory.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "rodshape/error.hpp"
#include "rodshape/robot/arm_model.hpp"
#include "rodshape/trajectory/end_effector_path.hpp"
#include "support/eigen_compare.hpp"
#include "support/panda_dh.hpp"

namespace rodshape {
namespace test_joint_trajectory {
namespace {

using testing::rotation_angle;

const ArmModel& panda() {
  static const ArmModel arm = samples::panda();
  return arm;
}

Pose pose(const Eigen::Vector3d& position, double angle_about_y) {
  Pose result;
  result.position = position;
  result.rotation = Eigen::AngleAxisd(angle_about_y, Eigen::Vector3d::UnitY()).toRotationMatrix();
  return result;
}

/// The arm as the band task places it: base 0.5 m behind the clamp (the world origin), the hand
/// grasping the band's tip from above (the flange's z, the approach axis, against the tip's z).
ArmPlacement band_placement() {
  ArmPlacement placement;
  placement.world_T_base.position = Eigen::Vector3d(-0.5, 0.0, 0.0);
  placement.flange_T_ee.rotation =
      Eigen::AngleAxisd(std::numbers::pi, Eigen::Vector3d::UnitX()).toRotationMatrix();
  return placement;
}

/// Three tip poses of a band clamped at the origin along +z, bent towards +x.
std::vector<Pose> band_waypoints() {
  return {pose({0.0, 0.0, 0.29}, 0.0), pose({0.06, 0.0, 0.27}, 0.3), pose({0.15, 0.0, 0.24}, 0.05)};
}

void expect_replays(const JointTrajectoryResult& trajectory,
                    const std::vector<TimedPose>& path,
                    const ArmPlacement& placement) {
  ASSERT_EQ(trajectory.q.size(), path.size());
  // IK converges to 1e-10 m and rad (IkOptions); the placement's pose chain adds round-off only.
  for (std::size_t i = 0; i < path.size(); ++i) {
    const Pose reached = end_effector_pose(panda(), placement, trajectory.q[i]);
    EXPECT_LE((reached.position - path[i].pose.position).norm(), 1e-9) << "sample " << i;
    EXPECT_LE(rotation_angle(reached.rotation, path[i].pose.rotation), 1e-9) << "sample " << i;
  }
}

void expect_within_velocity_limits(const JointTrajectoryResult& trajectory) {
  const Eigen::VectorXd limits = panda().velocity_limits();
  ASSERT_EQ(trajectory.qdot.size(), trajectory.q.size());
  for (std::size_t i = 0; i < trajectory.qdot.size(); ++i) {
    for (Eigen::Index j = 0; j < limits.size(); ++j)
      EXPECT_LE(std::abs(trajectory.qdot[i](j)), limits(j) * (1.0 + 1e-9))
          << "sample " << i << ", joint " << j;
  }
  for (std::size_t i = 0; i + 1 < trajectory.t.size(); ++i)
    EXPECT_GT(trajectory.t[i + 1], trajectory.t[i]);
}

TEST(JointTrajectoryResult, ReplaysTheEndEffectorPathWithinTheVelocityLimits) {
  const std::vector<TimedPose> path = time_parameterize(band_waypoints(), EndEffectorLimits{});
  const JointTrajectoryResult trajectory = joint_trajectory(panda(), path, band_placement());
  ASSERT_TRUE(trajectory.complete()) << trajectory.message;
  EXPECT_EQ(trajectory.joint_names, panda().joint_names());
  EXPECT_EQ(trajectory.t.size(), path.size());
  expect_replays(trajectory, path, band_placement());
  expect_within_velocity_limits(trajectory);
  // Quasi-static speeds are far below the Panda's joint limits: no slowing down.
  EXPECT_FALSE(trajectory.slowed);
  EXPECT_DOUBLE_EQ(trajectory.slowdown, 1.0);
  for (std::size_t i = 0; i < path.size(); ++i) EXPECT_DOUBLE_EQ(trajectory.t[i], path[i].t);
  // The velocities are the finite differences (central inside, one-sided at the ends).
  const std::size_t n = path.size();
  const Eigen::VectorXd first = (trajectory.q[1] - trajectory.q[0]) / (path[1].t - path[0].t);
  EXPECT_LT((trajectory.qdot[0] - first).norm(), 1e-12);
  const Eigen::VectorXd middle =
      (trajectory.q[n / 2 + 1] - trajectory.q[n / 2 - 1]) / (path[n / 2 + 1].t - path[n / 2 - 1].t);
  EXPECT_LT((trajectory.qdot[n / 2] - middle).norm(), 1e-12);
  const Eigen::VectorXd last =
      (trajectory.q[n - 1] - trajectory.q[n - 2]) / (path[n - 1].t - path[n - 2].t);
  EXPECT_LT((trajectory.qdot[n - 1] - last).norm(), 1e-12);
}

TEST(JointTrajectoryResult, SlowsAPathThatIsTooFastForTheJoints) {
  EndEffectorLimits fast;  // 1000 times the quasi-static limits: a few ms for the whole path
  fast.max_linear_speed *= 1000.0;
  fast.max_angular_speed *= 1000.0;
  fast.max_linear_acceleration *= 1000.0;
  fast.max_angular_acceleration *= 1000.0;
  fast.sample_rate = 10000.0;
  const std::vector<TimedPose> path = time_parameterize(band_waypoints(), fast);
  ASSERT_GT(path.size(), 3u);
  const JointTrajectoryResult trajectory = joint_trajectory(panda(), path, band_placement());
  ASSERT_TRUE(trajectory.complete()) << trajectory.message;
  EXPECT_TRUE(trajectory.slowed);
  EXPECT_GT(trajectory.slowdown, 1.0);
  EXPECT_GT(trajectory.duration(), path.back().t - path.front().t);
  expect_replays(trajectory, path, band_placement());
  expect_within_velocity_limits(trajectory);
  // Re-timed, not clipped: some joint runs at its limit on some segment.
  const Eigen::VectorXd limits = panda().velocity_limits();
  double highest = 0.0;
  for (std::size_t i = 0; i + 1 < trajectory.t.size(); ++i) {
    const Eigen::VectorXd rate = (trajectory.q[i + 1] - trajectory.q[i]).cwiseAbs() /
                                 (trajectory.t[i + 1] - trajectory.t[i]);
    highest = std::max(highest, rate.cwiseQuotient(limits).maxCoeff());
  }
  EXPECT_NEAR(highest, 1.0, 1e-9);
}

TEST(JointTrajectoryResult, TwoArmsOnOneClockAreRetimedTogether) {
  // A fast path for arm A (slowed alone) and a second arm B whose hand moves a short way on the
  // same clock (not slowed alone): re-timed together, both keep the same times, which are A's
  // own re-timing (B never needs more), and both stay within their velocity limits.
  EndEffectorLimits fast;
  fast.max_linear_speed *= 1000.0;
  fast.max_angular_speed *= 1000.0;
  fast.max_linear_acceleration *= 1000.0;
  fast.max_angular_acceleration *= 1000.0;
  fast.sample_rate = 10000.0;
  std::vector<Pose> other = band_waypoints();
  for (std::size_t k = 0; k < other.size(); ++k) other[k].position.y() = 0.002 * k;
  other[0] = other[1] = band_waypoints()[0];  // B stays put in the first segment
  const TwoEndPath path = time_parameterize_together(band_waypoints(), other, fast, fast);
  JointTrajectoryResult a = joint_trajectory(panda(), path.tip, band_placement());
  JointTrajectoryResult b = joint_trajectory(panda(), path.base, band_placement());
  ASSERT_TRUE(a.complete() && b.complete()) << a.message << b.message;
  ASSERT_TRUE(a.slowed);
  std::vector<double> t;
  for (const TimedPose& sample : path.tip) t.push_back(sample.t);
  const std::vector<double> a_alone = a.t;
  retime_together(panda(), a, panda(), b, t);
  EXPECT_EQ(a.t, b.t);
  EXPECT_TRUE(a.slowed && b.slowed);
  EXPECT_EQ(a.slowdown, b.slowdown);
  // Each segment takes the longer of the two arms' needs: at least A's own re-timed duration.
  for (std::size_t i = 0; i + 1 < t.size(); ++i)
    EXPECT_GE(a.t[i + 1] - a.t[i], (a_alone[i + 1] - a_alone[i]) * (1 - 1e-12)) << i;
  expect_within_velocity_limits(a);
  expect_within_velocity_limits(b);
  expect_replays(b, path.base, band_placement());
  // A trajectory that did not complete is refused.
  JointTrajectoryResult failed;
  EXPECT_THROW(retime_together(panda(), a, panda(), failed, t), InputError);
}

TEST(JointTrajectoryResult, ReportsAnUnreachablePoseWithItsTime) {
  std::vector<Pose> waypoints = band_waypoints();
  waypoints.push_back(pose({3.0, 0.0, 0.24}, 0.0));  // 3.5 m from the arm's base
  const std::vector<TimedPose> path = time_parameterize(waypoints, EndEffectorLimits{});
  const JointTrajectoryResult trajectory = joint_trajectory(panda(), path, band_placement());
  EXPECT_EQ(trajectory.status, JointTrajectoryStatus::Unreachable);
  EXPECT_FALSE(trajectory.complete());
  ASSERT_GT(trajectory.failed_sample, 0);
  const double when = path[static_cast<std::size_t>(trajectory.failed_sample)].t;
  std::ostringstream time;
  time.precision(6);
  time << "t = " << when << " s";
  EXPECT_NE(trajectory.message.find(time.str()), std::string::npos) << trajectory.message;
  EXPECT_NE(trajectory.message.find("position ["), std::string::npos) << trajectory.message;
  EXPECT_EQ(trajectory.q.size(), static_cast<std::size_t>(trajectory.failed_sample));
  EXPECT_TRUE(trajectory.qdot.empty());
}

TEST(JointTrajectoryResult, RejectsABadSeed) {
  const std::vector<TimedPose> path = time_parameterize(band_waypoints(), EndEffectorLimits{});
  JointTrajectoryOptions options;
  options.seed = Eigen::VectorXd::Zero(3);
  EXPECT_THROW(joint_trajectory(panda(), path, band_placement(), options), InputError);
}

TEST(JointTrajectoryResult, DefaultSeedIsTheReadyPoseOfASevenJointArm) {
  // The ready pose is within the Panda's limits, so default_seed() returns it unclamped.
  EXPECT_TRUE(testing::CompareMatrices(default_seed(panda()), testing::panda_ready_pose(), 0.0));
}

}  // namespace
}  // namespace test_joint_trajectory
}  // namespace rodshape
