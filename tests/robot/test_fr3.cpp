// test_fr3.cpp: the bundled Franka Research 3 (data/robots/fr3.urdf): its link and joint names as
// franka_description writes them, its forward kinematics against the joint origins of
// franka_description's robots/fr3/kinematics.yaml composed by hand, Franka's published limits
// (both arms'), the capsules on every link, and ArmModel::with_motion_limits.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include "rodshape/error.hpp"
#include "rodshape/robot/arm_model.hpp"
#include "rodshape/samples/bundled_arms.hpp"
#include "rodshape/samples/fr3.hpp"
#include "rodshape/samples/franka_limits.hpp"
#include "rodshape/samples/panda.hpp"

namespace test_fr3 {
namespace {

using rodshape::ArmModel;
using rodshape::LinkCapsule;
constexpr double pi = std::numbers::pi;

Eigen::VectorXd vector_of(const std::array<double, 7>& values) {
  return Eigen::Map<const Eigen::VectorXd>(values.data(), 7);
}

/// base_T_flange from kinematics.yaml's origins (x, y, z, roll; pitch and yaw are 0), each
/// joint's frame the origin times RotZ(q_i), the flange 0.107 m along link7's z.
Eigen::Isometry3d flange_by_hand(const Eigen::VectorXd& q) {
  struct Origin {
    double x, y, z, roll;
  };
  const std::array<Origin, 8> origins = {{{0, 0, 0.333, 0},
                                          {0, 0, 0, -pi / 2},
                                          {0, -0.316, 0, pi / 2},
                                          {0.0825, 0, 0, pi / 2},
                                          {-0.0825, 0.384, 0, -pi / 2},
                                          {0, 0, 0, pi / 2},
                                          {0.088, 0, 0, pi / 2},
                                          {0, 0, 0.107, 0}}};
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  for (std::size_t i = 0; i < origins.size(); ++i) {
    const Origin& o = origins[i];
    T = T * Eigen::Translation3d(o.x, o.y, o.z) *
        Eigen::AngleAxisd(o.roll, Eigen::Vector3d::UnitX());
    if (i < 7) T = T * Eigen::AngleAxisd(q(static_cast<Eigen::Index>(i)), Eigen::Vector3d::UnitZ());
  }
  return T;
}

TEST(Fr3, NamesAreFrankaDescriptions) {
  const ArmModel arm = rodshape::samples::fr3();
  EXPECT_EQ(arm.robot_name(), "fr3");
  EXPECT_EQ(arm.base_link(), "fr3_link0");
  EXPECT_EQ(arm.tip_link(), "fr3_link8");
  ASSERT_EQ(arm.joints(), 7);
  const std::vector<std::string> joints = arm.joint_names();
  for (int i = 0; i < 7; ++i)
    EXPECT_EQ(joints[static_cast<std::size_t>(i)], "fr3_joint" + std::to_string(i + 1));
  const std::vector<std::string>& links = arm.frame_links();
  ASSERT_EQ(links.size(), 9u);  // link0 … link8, joint8 the fixed flange
  for (std::size_t i = 0; i < links.size(); ++i)
    EXPECT_EQ(links[i], "fr3_link" + std::to_string(i));
}

TEST(Fr3, FlangeAtZeroIsTheSumOfTheOrigins) {
  // At q = 0 (outside the FR3's limits of joints 4 and 6, which forward kinematics does not
  // check): up 0.333 + 0.316 + 0.384 = 1.033 m, out a3 + a6 = 0.0825 − 0.0825 + 0.088 m, then
  // 0.107 m down along link7's z, which points down (rolls −π/2, π/2, π/2, −π/2, π/2, π/2: π).
  const rodshape::Pose flange =
      rodshape::samples::fr3().forward_kinematics(Eigen::VectorXd::Zero(7));
  EXPECT_NEAR((flange.position - Eigen::Vector3d(0.088, 0.0, 0.926)).norm(), 0.0, 1e-12);
  const Eigen::Matrix3d down = Eigen::Vector3d(1, -1, -1).asDiagonal();
  EXPECT_NEAR((flange.rotation - down).norm(), 0.0, 1e-12);
  // Joint 1 at π/2 turns it onto y.
  Eigen::VectorXd q = Eigen::VectorXd::Zero(7);
  q(0) = pi / 2;
  EXPECT_NEAR(
      (rodshape::samples::fr3().forward_kinematics(q).position - Eigen::Vector3d(0.0, 0.088, 0.926))
          .norm(),
      0.0, 1e-12);
}

TEST(Fr3, ForwardKinematicsMatchesTheOriginsComposedByHand) {
  const ArmModel arm = rodshape::samples::fr3();
  Eigen::VectorXd other(7);
  other << 0.3, -0.6, 0.4, -2.0, -0.5, 2.2, 1.1;
  for (const Eigen::VectorXd& q : {rodshape::samples::fr3_ready_pose(), other}) {
    arm.check_joint_positions(q);  // within the FR3's limits
    const rodshape::Pose flange = arm.forward_kinematics(q);
    const Eigen::Isometry3d expected = flange_by_hand(q);
    EXPECT_NEAR((flange.position - expected.translation()).norm(), 0.0, 1e-12);
    EXPECT_NEAR((flange.rotation - expected.rotation()).norm(), 0.0, 1e-12);
    // The FR3's chain is the Panda's.
    EXPECT_NEAR(
        (rodshape::samples::panda().forward_kinematics(q).position - flange.position).norm(), 0.0,
        1e-12);
  }
  // The ready pose by hand: the flange 0.307 m in front of the base and 0.590 m up (Python, the
  // same origins).
  const rodshape::Pose ready = arm.forward_kinematics(rodshape::samples::fr3_ready_pose());
  EXPECT_NEAR(ready.position.x(), 0.30689, 1e-5);
  EXPECT_NEAR(ready.position.y(), 0.0, 1e-12);
  EXPECT_NEAR(ready.position.z(), 0.59028, 1e-5);
}

TEST(Fr3, LimitsAreFrankasPublishedTable) {
  // "Limits for Franka Research 3" (frankaemika/docs, control-parameters-joint-fr3.csv).
  const ArmModel arm = rodshape::samples::fr3();
  Eigen::VectorXd lower(7), upper(7), velocity(7);
  lower << -2.7437, -1.7837, -2.9007, -3.0421, -2.8065, 0.5445, -3.0159;
  upper << 2.7437, 1.7837, 2.9007, -0.1518, 2.8065, 4.5169, 3.0159;
  velocity << 2.62, 2.62, 2.62, 2.62, 5.26, 4.18, 5.26;
  EXPECT_EQ(arm.lower_limits(), lower);
  EXPECT_EQ(arm.upper_limits(), upper);
  EXPECT_EQ(arm.velocity_limits(), velocity);
  EXPECT_EQ(arm.acceleration_limits(), Eigen::VectorXd::Constant(7, 10.0));
  EXPECT_EQ(arm.jerk_limits(), Eigen::VectorXd::Constant(7, 5000.0));
  const rodshape::samples::FrankaJointLimits& table = rodshape::samples::fr3_joint_limits();
  EXPECT_EQ(vector_of(table.lower), lower);
  EXPECT_EQ(vector_of(table.upper), upper);
  EXPECT_EQ(vector_of(table.velocity), velocity);
}

TEST(Fr3, PandaLimitsAreFrankasPublishedTable) {
  // "Limits for Panda" (control-parameters-joint-panda.csv); its URDF holds the same positions
  // and velocities.
  const ArmModel arm = rodshape::samples::panda();
  Eigen::VectorXd acceleration(7), jerk(7);
  acceleration << 15, 7.5, 10, 12.5, 15, 20, 20;
  jerk << 7500, 3750, 5000, 6250, 7500, 10000, 10000;
  EXPECT_EQ(arm.acceleration_limits(), acceleration);
  EXPECT_EQ(arm.jerk_limits(), jerk);
  const rodshape::samples::FrankaJointLimits& table = rodshape::samples::panda_joint_limits();
  EXPECT_EQ(arm.lower_limits(), vector_of(table.lower));
  EXPECT_EQ(arm.upper_limits(), vector_of(table.upper));
  EXPECT_EQ(arm.velocity_limits(), vector_of(table.velocity));
  EXPECT_EQ(arm.upper_limits()(5), 3.7525);
}

TEST(Fr3, EveryLinkHasItsCapsules) {
  const ArmModel arm = rodshape::samples::fr3();
  std::map<std::string, std::vector<LinkCapsule>> by_link;
  for (const LinkCapsule& c : arm.link_capsules()) by_link[c.link].push_back(c);
  // franka_arm.xacro's self-collision model: one capsule a link, two on links 5 and 7; the hand
  // (two capsules and two fingers) on the flange.
  const std::map<std::string, std::size_t> counts = {
      {"fr3_link0", 1}, {"fr3_link1", 1}, {"fr3_link2", 1}, {"fr3_link3", 1}, {"fr3_link4", 1},
      {"fr3_link5", 2}, {"fr3_link6", 1}, {"fr3_link7", 2}, {"fr3_link8", 4}};
  EXPECT_EQ(by_link.size(), counts.size());
  for (const auto& [link, count] : counts) EXPECT_EQ(by_link[link].size(), count) << link;
  EXPECT_TRUE(arm.collision_notes().empty());
  // link1's capsule: centre 0.1915 m below the link's origin, 0.283 m long, radius 0.06.
  const LinkCapsule& link1 = by_link["fr3_link1"].front();
  EXPECT_NEAR(link1.radius, 0.06, 1e-15);
  EXPECT_NEAR((link1.from - link1.to).norm(), 0.283, 1e-12);
  EXPECT_NEAR(0.5 * (link1.from + link1.to).z(), -0.1915, 1e-12);
  // The same geometry as the bundled Panda's, link for link.
  const ArmModel panda_arm = rodshape::samples::panda();
  const std::vector<LinkCapsule>& panda = panda_arm.link_capsules();
  ASSERT_EQ(panda.size(), arm.link_capsules().size());
  for (std::size_t i = 0; i < panda.size(); ++i) {
    const LinkCapsule& c = arm.link_capsules()[i];
    EXPECT_EQ(c.link, "fr3_" + panda[i].link.substr(6));
    EXPECT_EQ(c.frame, panda[i].frame);
    EXPECT_EQ(c.radius, panda[i].radius);
    EXPECT_NEAR((c.from - panda[i].from).norm() + (c.to - panda[i].to).norm(), 0.0, 1e-15);
  }
}

TEST(Fr3, BundledNamesAndPartsOfTheChain) {
  EXPECT_EQ(rodshape::samples::bundled_arm_names(), "fr3, panda");
  EXPECT_FALSE(rodshape::samples::bundled_arm("fr-3").has_value());
  ASSERT_TRUE(rodshape::samples::bundled_arm("panda").has_value());
  EXPECT_EQ(rodshape::samples::bundled_arm("panda")->tip_link(), "panda_link8");
  // Up to link4: joints 1 … 4 with their own limits.
  const std::optional<ArmModel> part =
      rodshape::samples::bundled_arm("panda", "panda_link0", "panda_link4");
  ASSERT_TRUE(part.has_value());
  ASSERT_EQ(part->joints(), 4);
  EXPECT_EQ(part->acceleration_limits(), Eigen::Vector4d(15, 7.5, 10, 12.5));
}

TEST(Fr3, MotionLimitsAreSetAndChecked) {
  const ArmModel file = ArmModel::from_urdf_string(std::string(rodshape::samples::fr3_urdf()));
  EXPECT_TRUE(std::isinf(file.acceleration_limits()(0)));  // a URDF holds none
  EXPECT_TRUE(std::isinf(file.jerk_limits()(6)));
  const ArmModel set =
      file.with_motion_limits(Eigen::VectorXd::Constant(7, 3.0), Eigen::VectorXd::Constant(7, 9.0));
  EXPECT_EQ(set.jerk_limits(), Eigen::VectorXd::Constant(7, 9.0));
  EXPECT_TRUE(std::isinf(file.jerk_limits()(0)));  // the original is unchanged
  EXPECT_EQ(set.velocity_limits(), file.velocity_limits());
  EXPECT_THROW(
      file.with_motion_limits(Eigen::VectorXd::Constant(6, 3.0), Eigen::VectorXd::Constant(7, 9.0)),
      rodshape::InputError);
  Eigen::VectorXd bad = Eigen::VectorXd::Constant(7, 9.0);
  bad(2) = 0.0;
  try {
    (void)file.with_motion_limits(Eigen::VectorXd::Constant(7, 3.0), bad, "limits.yaml");
    FAIL() << "no error";
  } catch (const rodshape::InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              "limits.yaml: joint 'fr3_joint3': jerk limit = 0 must be > 0");
  }
}

}  // namespace
}  // namespace test_fr3
