// test_arm_reach.cpp: the joint axes against the Panda's DH frames; the shoulder, the wrist and the
// range of |w - c| against what the DH table gives by hand, and exactly on a toy arm whose range
// has a closed form; the shell in the tip frame against forward kinematics; bad margins.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "rodshape/robot/arm_reach.hpp"
#include "support/input_error.hpp"
#include "support/panda_dh.hpp"

namespace test_arm_reach {
namespace {

using rodshape::ArmModel;
using rodshape::ArmPlacement;
using rodshape::ArmReach;
using rodshape::Pose;
constexpr double pi = std::numbers::pi;

const std::string kPanda = rodshape::testing::kPandaUrdf;
using rodshape::testing::input_error_message;
using rodshape::testing::panda_dh_frames;
Eigen::VectorXd ready_pose() { return rodshape::testing::panda_ready_pose(); }

TEST(ArmReach, PandaJointAxesAreTheDhFramesZAxes) {
  const ArmModel arm = ArmModel::from_urdf_file(kPanda);
  const Eigen::VectorXd q = ready_pose();
  const std::vector<rodshape::JointAxis> axes = arm.joint_axes(q);
  const std::vector<Eigen::Isometry3d> frames = panda_dh_frames(q);
  ASSERT_EQ(axes.size(), 7u);
  for (int i = 0; i < 7; ++i) {
    const Eigen::Vector3d z = frames[i].rotation().col(2);
    EXPECT_NEAR(axes[i].direction.dot(z), 1.0, 1e-12) << "joint " << i + 1;
    // The URDF's origin lies on the DH axis line (the DH table's rounding only: 1e-12).
    const Eigen::Vector3d offset = axes[i].origin - frames[i].translation();
    EXPECT_LE((offset - offset.dot(z) * z).norm(), 1e-12) << "joint " << i + 1;
  }
}

TEST(ArmReach, PandaShoulderWristAndRangeMatchTheDhTable) {
  const ArmModel arm = ArmModel::from_urdf_file(kPanda);
  const ArmReach reach = rodshape::compute_arm_reach(arm);
  // Joint 1's axis (z) meets joint 2's at d1 = 0.333; joint 7's axis meets the common
  // perpendicular of joints 6 and 7 (a7 = 0.088 along x6) at frame 7's origin, d = 0.107 behind the
  // flange.
  EXPECT_LE((reach.shoulder - Eigen::Vector3d(0.0, 0.0, 0.333)).norm(), 1e-12);
  EXPECT_LE((reach.wrist_in_tip_link - Eigen::Vector3d(0.0, 0.0, -0.107)).norm(), 1e-12);

  // By hand: the shoulder, elbow (frame 4) and wrist (frame 5 = 6) form a planar two-link arm
  // about joint 4's axis, with links l1 = |(a4, d3)| and l2 = |(a5, d5)|; frame 7 is a7 further
  // along x6. So |w - c| ≤ l1 + l2 + a7 (reached with the links in line, q4 ≈ -0.467 within its
  // limits, and x6 along them) and |w - c| ≥ |c→O5|min - a7, the elbow folded to its limit.
  const double l1 = std::hypot(0.0825, 0.316), l2 = std::hypot(0.0825, 0.384), a7 = 0.088;
  const double upper_bound = l1 + l2 + a7;
  double folded = std::numeric_limits<double>::infinity();
  for (double q4 : {-3.0718, -0.0698}) {  // |c→O5| is monotonic away from the in-line angle
    Eigen::VectorXd q = Eigen::VectorXd::Zero(7);
    q(3) = q4;
    folded = std::min(folded, (panda_dh_frames(q)[4].translation() - reach.shoulder).norm());
  }
  const double lower_bound = folded - a7;
  EXPECT_LE(reach.max_distance, upper_bound + 1e-12);
  EXPECT_GE(reach.min_distance, lower_bound - 1e-12);
  // The estimate is a sampled one: within 1 mm of the in-line maximum (sampling 4096 points and
  // refining them finds it to 0.1 mm), and the minimum within 1 cm of the hand bound (the wrist's
  // limits keep x6 from pointing straight back, so that bound is not reached).
  EXPECT_GE(reach.max_distance, upper_bound - 1e-3);
  EXPECT_LE(reach.min_distance, lower_bound + 1e-2);
  // The configurations reported are within the limits and give the distances reported.
  for (const Eigen::VectorXd* q : {&reach.q_max_distance, &reach.q_min_distance})
    EXPECT_NO_THROW(arm.check_joint_positions(*q, "q", 0.0));
  EXPECT_NEAR(reach.wrist_distance(arm.forward_kinematics(reach.q_max_distance)),
              reach.max_distance, 1e-12);
  EXPECT_NEAR((panda_dh_frames(reach.q_min_distance)[6].translation() - reach.shoulder).norm(),
              reach.min_distance, 1e-12);
}

// A toy arm with a closed-form range: yaw about z, then three pitch joints about y; links a = 0.4
// and b = 0.3 between the pitch axes, then a 0.1 m hand. Shoulder: (0, 0, h) where the yaw axis
// meets the first pitch axis; wrist: the origin of the last pitch joint (its axis is parallel to
// the one before, so the nearest point is the foot of that joint's origin). |w - c| is the planar
// two-link distance sqrt(a² + b² + 2ab cos q3), q3 ∈ [-2, 2.5]: max a + b at q3 = 0, min at 2.5.
std::string toy_arm() {
  const auto joint = [](const std::string& name, const std::string& parent,
                        const std::string& child, const std::string& xyz, const std::string& axis,
                        const std::string& limits) {
    return "<joint name=\"" + name + "\" type=\"revolute\"><parent link=\"" + parent +
           "\"/><child link=\"" + child + "\"/><origin xyz=\"" + xyz +
           "\" rpy=\"0 0 0\"/><axis xyz=\"" + axis + "\"/><limit " + limits +
           " velocity=\"1\" effort=\"1\"/></joint>";
  };
  std::string body;
  for (const char* name : {"base", "l1", "l2", "l3", "l4", "hand"})
    body += "<link name=\"" + std::string(name) + "\"/>";
  body += joint("yaw", "base", "l1", "0 0 0.2", "0 0 1", "lower=\"-3\" upper=\"3\"");
  body += joint("shoulder", "l1", "l2", "0 0 0.1", "0 1 0", "lower=\"-1.5\" upper=\"1.5\"");
  body += joint("elbow", "l2", "l3", "0.4 0 0", "0 1 0", "lower=\"-2\" upper=\"2.5\"");
  body += joint("wrist", "l3", "l4", "0.3 0 0", "0 1 0", "lower=\"-2\" upper=\"2\"");
  body +=
      "<joint name=\"hand_fixed\" type=\"fixed\"><parent link=\"l4\"/><child link=\"hand\"/>"
      "<origin xyz=\"0.1 0 0\" rpy=\"0 0 0\"/></joint>";
  return "<robot name=\"toy\">" + body + "</robot>";
}

TEST(ArmReach, ToyArmRangeIsTheTwoLinkFormula) {
  const ArmModel arm = ArmModel::from_urdf_string(toy_arm());
  const ArmReach reach = rodshape::compute_arm_reach(arm);
  EXPECT_LE((reach.shoulder - Eigen::Vector3d(0.0, 0.0, 0.3)).norm(), 1e-15);
  EXPECT_LE((reach.wrist_in_tip_link - Eigen::Vector3d(-0.1, 0.0, 0.0)).norm(), 1e-15);
  const double a = 0.4, b = 0.3;
  // The maximum is interior (r ≈ (a + b) - ab q3² / (2(a + b))): the refinement stops where a step
  // no longer changes r in double precision, so r is right to a few ulps. The minimum is at the
  // elbow's limit, which the projected steps reach exactly.
  EXPECT_NEAR(reach.max_distance, a + b, 1e-12);
  EXPECT_NEAR(reach.min_distance, std::sqrt(a * a + b * b + 2 * a * b * std::cos(2.5)), 1e-12);
  EXPECT_EQ(reach.q_min_distance(2), 2.5);
}

TEST(ArmReach, ShellPointIsTheWristSeenFromTheRodTip) {
  const ArmModel arm = ArmModel::from_urdf_file(kPanda);
  const ArmReach reach = rodshape::compute_arm_reach(arm);
  ArmPlacement placement;
  placement.world_T_base.position = Eigen::Vector3d(-0.45, 0.1, -0.2);
  placement.world_T_base.rotation = Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()).matrix();
  placement.flange_T_ee.position = Eigen::Vector3d(0.0, 0.0, 0.1034);
  placement.flange_T_ee.rotation = Eigen::AngleAxisd(pi, Eigen::Vector3d::UnitX()).matrix();
  Pose tip_T_ee;
  tip_T_ee.position = Eigen::Vector3d(0.01, -0.02, 0.03);
  tip_T_ee.rotation = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).matrix();
  const double margin = 0.02;
  const rodshape::Workspace::ReachShell shell =
      rodshape::reach_shell(reach, placement, tip_T_ee, margin);
  EXPECT_DOUBLE_EQ(shell.outer_radius, reach.max_distance - margin);
  EXPECT_DOUBLE_EQ(shell.inner_radius, reach.min_distance + margin);
  for (const Eigen::VectorXd& q : {ready_pose(), reach.q_max_distance, reach.q_min_distance}) {
    // The rod's tip where the hand holds it when the arm is at q.
    const Pose world_T_ee = rodshape::end_effector_pose(arm, placement, q);
    const Pose world_T_tip = rodshape::compose(world_T_ee, rodshape::inverse(tip_T_ee));
    EXPECT_NEAR((shell.point(world_T_tip) - shell.center).norm(),
                reach.wrist_distance(arm.forward_kinematics(q)), 1e-12);
  }
}

TEST(ArmReach, BadMarginsAndOptionsThrowInputErrorsThatSayWhy) {
  const ArmModel arm = ArmModel::from_urdf_file(kPanda);
  const ArmReach reach = rodshape::compute_arm_reach(arm);
  const std::string negative =
      input_error_message([&] { rodshape::reach_shell(reach, {}, {}, -0.01); });
  EXPECT_NE(negative.find("margin = -0.01 must be >= 0"), std::string::npos) << negative;
  const std::string wide = input_error_message([&] { rodshape::reach_shell(reach, {}, {}, 0.4); });
  EXPECT_NE(wide.find("leaves no shell"), std::string::npos) << wide;
  const std::string nan =
      input_error_message([&] { rodshape::reach_shell(reach, {}, {}, std::nan("")); });
  EXPECT_NE(nan.find("margin = nan"), std::string::npos) << nan;
  rodshape::ArmReachOptions options;
  options.samples = 0;
  const std::string samples =
      input_error_message([&] { rodshape::compute_arm_reach(arm, options); });
  EXPECT_NE(samples.find("ArmReachOptions.samples"), std::string::npos) << samples;
}

}  // namespace
}  // namespace test_arm_reach
