// test_arm_model.cpp: the Panda URDF against Franka's modified Denavit–Hartenberg table, written
// out by hand in support/panda_dh.hpp; the Jacobian against central differences; every kind of bad
// URDF or chain.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "rodshape/error.hpp"
#include "rodshape/robot/arm_model.hpp"
#include "support/panda_dh.hpp"

namespace test_arm_model {
namespace {

using rodshape::ArmModel;
using rodshape::InputError;
using rodshape::Pose;

const std::string kPanda = rodshape::testing::kPandaUrdf;
using rodshape::testing::panda_dh;
Eigen::VectorXd ready_pose() { return rodshape::testing::panda_ready_pose(); }

void expect_pose_near(const Pose& pose, const Eigen::Isometry3d& expected, double tolerance) {
  EXPECT_LE((pose.position - expected.translation()).norm(), tolerance)
      << "position " << pose.position.transpose() << " vs " << expected.translation().transpose();
  EXPECT_LE((pose.rotation - expected.rotation()).cwiseAbs().maxCoeff(), tolerance)
      << "rotation\n"
      << pose.rotation << "\nvs\n"
      << expected.rotation();
}

TEST(ArmModel, PandaChainJointsAndLimitsComeFromTheUrdf) {
  const ArmModel arm = ArmModel::from_urdf_file(kPanda);
  EXPECT_EQ(arm.robot_name(), "panda");
  EXPECT_EQ(arm.base_link(), "panda_link0");
  EXPECT_EQ(arm.tip_link(), "panda_link8");
  ASSERT_EQ(arm.joints(), 7);
  EXPECT_EQ(arm.joint_names().front(), "panda_joint1");
  EXPECT_EQ(arm.joint_names().back(), "panda_joint7");
  Eigen::VectorXd lower(7), upper(7), velocity(7);
  lower << -2.8973, -1.7628, -2.8973, -3.0718, -2.8973, -0.0175, -2.8973;
  upper << 2.8973, 1.7628, 2.8973, -0.0698, 2.8973, 3.7525, 2.8973;
  velocity << 2.1750, 2.1750, 2.1750, 2.1750, 2.6100, 2.6100, 2.6100;
  EXPECT_EQ(arm.lower_limits(), lower);
  EXPECT_EQ(arm.upper_limits(), upper);
  EXPECT_EQ(arm.velocity_limits(), velocity);
}

// The URDF's origins are the DH table's constant factors, rounded only by rpy -> quaternion ->
// matrix conversions (a few ε per joint), so 1e-12 is ample.
TEST(ArmModel, PandaForwardKinematicsMatchesTheDhTableAtZeroAndReady) {
  const ArmModel arm = ArmModel::from_urdf_file(kPanda);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(7);
  expect_pose_near(arm.forward_kinematics(zero), panda_dh(zero), 1e-12);
  // By hand at q = 0: x = a4 - a5 + a7 = 0.088, z = d1 + d3 + d5 - d_F = 0.333 + 0.316 + 0.384 -
  // 0.107.
  EXPECT_NEAR(arm.forward_kinematics(zero).position.x(), 0.088, 1e-12);
  EXPECT_NEAR(arm.forward_kinematics(zero).position.z(), 0.926, 1e-12);

  const Pose ready = arm.forward_kinematics(ready_pose());
  expect_pose_near(ready, panda_dh(ready_pose()), 1e-12);
  // The flange at the ready pose, pointing down: (0.30689, 0, 0.59028).
  EXPECT_NEAR(ready.position.x(), 0.306891, 1e-6);
  EXPECT_NEAR(ready.position.y(), 0.0, 1e-12);
  EXPECT_NEAR(ready.position.z(), 0.590282, 1e-6);
  EXPECT_NEAR(ready.rotation(2, 2), -1.0, 1e-12);
}

TEST(ArmModel, PandaForwardKinematicsMatchesTheDhTableAtRandomJoints) {
  const ArmModel arm = ArmModel::from_urdf_file(kPanda);
  std::mt19937 rng(7);
  for (int trial = 0; trial < 200; ++trial) {
    Eigen::VectorXd q(7);
    for (int i = 0; i < 7; ++i)
      q(i) =
          std::uniform_real_distribution<double>(arm.lower_limits()(i), arm.upper_limits()(i))(rng);
    expect_pose_near(arm.forward_kinematics(q), panda_dh(q), 1e-12);
  }
}

// Central differences: error ≈ h²|f'''|/6 + ε|f|/h ≈ 1e-12 + 1e-10 at h = 1e-6 with |f| ≲ 1.
TEST(ArmModel, JacobianMatchesCentralDifferences) {
  const ArmModel arm = ArmModel::from_urdf_file(kPanda);
  const Eigen::VectorXd q = ready_pose() + 0.1 * Eigen::VectorXd::LinSpaced(7, -1.0, 1.0);
  Pose pose;
  Eigen::Matrix<double, 6, Eigen::Dynamic> J;
  arm.forward_kinematics(q, pose, J);
  ASSERT_EQ(J.cols(), 7);
  const double h = 1e-6;
  for (int i = 0; i < 7; ++i) {
    Eigen::VectorXd plus = q, minus = q;
    plus(i) += h;
    minus(i) -= h;
    const Pose a = arm.forward_kinematics(plus), b = arm.forward_kinematics(minus);
    const Eigen::Vector3d v = (a.position - b.position) / (2 * h);
    const Eigen::AngleAxisd delta(a.rotation * b.rotation.transpose());
    const Eigen::Vector3d w = delta.angle() * delta.axis() / (2 * h);
    EXPECT_LE((J.col(i).head<3>() - v).norm(), 1e-8) << "joint " << i;
    EXPECT_LE((J.col(i).tail<3>() - w).norm(), 1e-8) << "joint " << i;
  }
}

TEST(ArmModel, BaseAndTipSelectASubChain) {
  const ArmModel arm = ArmModel::from_urdf_file(kPanda, "panda_link2", "panda_link5");
  EXPECT_EQ(arm.joints(), 3);
  EXPECT_EQ(arm.joint_names(),
            (std::vector<std::string>{"panda_joint3", "panda_joint4", "panda_joint5"}));
  // Link2 -> link5 at the ready pose equals the full chain's link0_T_link2⁻¹ · link0_T_link5.
  const ArmModel to5 = ArmModel::from_urdf_file(kPanda, "", "panda_link5");
  const ArmModel to2 = ArmModel::from_urdf_file(kPanda, "", "panda_link2");
  const Eigen::VectorXd q = ready_pose();
  const Pose a = to2.forward_kinematics(q.head(2)), b = to5.forward_kinematics(q.head(5));
  const Pose sub = arm.forward_kinematics(q.segment(2, 3));
  EXPECT_LE((sub.position - a.rotation.transpose() * (b.position - a.position)).norm(), 1e-12);
  EXPECT_LE((sub.rotation - a.rotation.transpose() * b.rotation).norm(), 1e-12);
}

// ---- small URDFs for the other joint types and the bad cases -----------------------------------

std::string link(const std::string& name) { return "<link name=\"" + name + "\"/>"; }

std::string joint(
    const std::string& name,
    const std::string& type,
    const std::string& parent,
    const std::string& child,
    const std::string& limit = "<limit lower=\"-1\" upper=\"1\" velocity=\"2\" effort=\"1\"/>") {
  return "<joint name=\"" + name + "\" type=\"" + type + "\"><parent link=\"" + parent +
         "\"/><child link=\"" + child +
         "\"/><origin xyz=\"0 0 0.5\" rpy=\"0 0 0\"/><axis xyz=\"0 0 2\"/>" + limit + "</joint>";
}

std::string robot(const std::string& body) { return "<robot name=\"toy\">" + body + "</robot>"; }

const std::string kThreeLinks = link("a") + link("b") + link("c");

TEST(ArmModel, ContinuousAndPrismaticJoints) {
  const ArmModel arm = ArmModel::from_urdf_string(robot(
      kThreeLinks + joint("j1", "continuous", "a", "b", "") + joint("j2", "prismatic", "b", "c")));
  ASSERT_EQ(arm.joints(), 2);
  EXPECT_TRUE(std::isinf(arm.lower_limits()(0)) && std::isinf(arm.upper_limits()(0)));
  EXPECT_TRUE(std::isinf(arm.velocity_limits()(0)));
  EXPECT_TRUE(arm.joint_info()[1].prismatic);
  const Pose pose = arm.forward_kinematics(Eigen::Vector2d(0.3, 0.25));
  // The axis "0 0 2" is normalised: z = 0.5 + 0.5 + 0.25.
  EXPECT_NEAR(pose.position.z(), 1.25, 1e-15);
  EXPECT_NEAR(pose.rotation(0, 0), std::cos(0.3), 1e-15);
  EXPECT_DOUBLE_EQ(arm.reach(), 2.0);
}

void expect_input_error(const std::function<void()>& action, const std::string& fragment) {
  try {
    action();
    ADD_FAILURE() << "no InputError; expected one containing \"" << fragment << "\"";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find(fragment), std::string::npos)
        << "message: " << error.what() << "\nexpected: " << fragment;
  }
}

TEST(ArmModel, BadUrdfsAndChainsThrowInputErrorsThatSayWhy) {
  const auto from = [](const std::string& urdf, const std::string& base = "",
                       const std::string& tip = "") {
    return [=] { ArmModel::from_urdf_string(urdf, base, tip, "toy.urdf"); };
  };
  const std::string chain =
      kThreeLinks + joint("j1", "revolute", "a", "b") + joint("j2", "revolute", "b", "c");
  expect_input_error([] { ArmModel::from_urdf_file("/nonexistent/arm.urdf"); },
                     "/nonexistent/arm.urdf: cannot read");
  expect_input_error(from("this is not xml"), "toy.urdf: the URDF does not parse");
  expect_input_error(from("<robot name=\"toy\"><link name=\"a\"/>"), "does not parse");
  expect_input_error(from(robot(kThreeLinks + joint("j1", "revolute", "a", "b") +
                                joint("j2", "revolute", "b", "x"))),
                     "child link [x] of joint [j2] not found");
  expect_input_error(from(robot(chain), "nope"), "unknown base link 'nope'");
  expect_input_error(from(robot(chain), "", "c2"),
                     "unknown tip link 'c2' in robot 'toy' (links: a, b, c)");
  expect_input_error(from(robot(chain), "c", "a"), "tip link 'a' is not below base link 'c'");
  // A loop: c is also b's parent, so b has two parents.
  expect_input_error(from(robot(chain + joint("j3", "revolute", "c", "b"))),
                     "closed loop: link 'b' is the child of both");
  // A cycle through every link leaves no root.
  expect_input_error(from(robot(chain + joint("j3", "revolute", "c", "a"))), "closed loop");
  expect_input_error(from(robot(kThreeLinks + joint("j1", "floating", "a", "b", "") +
                                joint("j2", "revolute", "b", "c"))),
                     "joint 'j1' is floating");
  expect_input_error(from(robot(kThreeLinks + joint("j1", "planar", "a", "b", "") +
                                joint("j2", "revolute", "b", "c"))),
                     "joint 'j1' is planar");
  expect_input_error(
      from(robot(kThreeLinks + joint("j1", "revolute", "a", "b") +
                 joint("j2", "revolute", "b", "c",
                       "<limit lower=\"1\" upper=\"-1\" velocity=\"2\" effort=\"1\"/>"))),
      "joint 'j2': limit lower = 1 and upper = -1 must be finite with lower <= upper");
  expect_input_error(
      from(robot(kThreeLinks + joint("j1", "revolute", "a", "b") +
                 joint("j2", "revolute", "b", "c",
                       "<limit lower=\"-1\" upper=\"1\" velocity=\"0\" effort=\"1\"/>"))),
      "joint 'j2': limit velocity = 0 must be > 0");
  expect_input_error(from(robot(kThreeLinks + joint("j1", "fixed", "a", "b", "") +
                                joint("j2", "fixed", "b", "c", ""))),
                     "has no moving joint");
  // Two equally long branches: the tip must be named.
  expect_input_error(from(robot(kThreeLinks + joint("j1", "revolute", "a", "b") +
                                joint("j2", "revolute", "a", "c"))),
                     "equally long chains ending at b, c; name the tip link");
  EXPECT_EQ(ArmModel::from_urdf_string(robot(kThreeLinks + joint("j1", "revolute", "a", "b") +
                                             joint("j2", "revolute", "a", "c")),
                                       "", "c")
                .joints(),
            1);
}

TEST(ArmModel, JointVectorsOfTheWrongSizeOrOutsideTheLimitsAreBadInput) {
  const ArmModel arm = ArmModel::from_urdf_file(kPanda);
  expect_input_error([&] { arm.forward_kinematics(Eigen::VectorXd::Zero(6)); },
                     "q has 6 values but the chain from 'panda_link0' to 'panda_link8' has 7");
  Eigen::VectorXd q = ready_pose();
  q(2) = std::nan("");
  expect_input_error([&] { arm.forward_kinematics(q); }, "q[2] = nan must be finite");
  q = ready_pose();
  q(3) = 0.0;
  expect_input_error([&] { arm.check_joint_positions(q, "q"); },
                     "q[3] = 0 is outside the limits of joint 'panda_joint4': [-3.0718, -0.0698]");
  EXPECT_NO_THROW(arm.check_joint_positions(ready_pose()));
  EXPECT_EQ(arm.clamp_to_limits(q)(3), -0.0698);
}

}  // namespace
}  // namespace test_arm_model
