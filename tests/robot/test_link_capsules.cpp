// test_link_capsules.cpp: URDF <collision> primitives read as link capsules (each covering its
// primitive), the bundled Panda's capsules (Franka's self-collision model and the hand), the link
// frames against the Denavit–Hartenberg oracle and the point Jacobian against central differences.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "rodshape/error.hpp"
#include "rodshape/robot/arm_model.hpp"
#include "rodshape/samples/panda.hpp"
#include "support/panda_dh.hpp"

namespace test_link_capsules {
namespace {

using rodshape::ArmModel;
using rodshape::LinkCapsule;
using rodshape::LinkFrames;

double distance_to_capsule_axis(const LinkCapsule& c, const Eigen::Vector3d& p) {
  const Eigen::Vector3d ab = c.to - c.from;
  const double l2 = ab.squaredNorm();
  const double t = l2 > 0.0 ? std::clamp((p - c.from).dot(ab) / l2, 0.0, 1.0) : 0.0;
  return (p - c.from - t * ab).norm();
}

// One link with a sphere, a cylinder turned onto x, a box turned about z, a mesh and a sphere
// inside the cylinder's capsule (dropped).
const char* const kPrimitives = R"(<?xml version="1.0"?>
<robot name="shapes">
  <link name="base"/>
  <link name="arm">
    <collision name="ball"><origin xyz="0.1 0.2 0.3"/><geometry><sphere radius="0.05"/></geometry></collision>
    <collision><origin xyz="0 0 0.5" rpy="0 1.5707963267948966 0"/><geometry><cylinder radius="0.04" length="0.3"/></geometry></collision>
    <collision><origin xyz="0.15 0 0.5"/><geometry><sphere radius="0.03"/></geometry></collision>
    <collision name="plate"><origin xyz="0 0.4 0" rpy="0 0 0.5"/><geometry><box size="0.1 0.3 0.02"/></geometry></collision>
    <collision name="shell"><geometry><mesh filename="package://x/shell.stl"/></geometry></collision>
  </link>
  <joint name="j" type="revolute">
    <parent link="base"/><child link="arm"/><axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" velocity="1" effort="1"/>
  </joint>
</robot>)";

TEST(LinkCapsules, UrdfPrimitivesBecomeCapsulesThatCoverThem) {
  const ArmModel arm = ArmModel::from_urdf_string(kPrimitives);
  const std::vector<LinkCapsule>& capsules = arm.link_capsules();
  ASSERT_EQ(capsules.size(), 3u);  // ball, cylinder, plate; the inner sphere dropped, mesh ignored
  ASSERT_EQ(arm.collision_notes().size(), 1u);
  EXPECT_NE(arm.collision_notes()[0].find("'shell'"), std::string::npos);
  EXPECT_NE(arm.collision_notes()[0].find("ignored"), std::string::npos);

  const LinkCapsule& ball = capsules[0];
  EXPECT_EQ(ball.label(), "arm (ball)");
  EXPECT_EQ(ball.frame, 1);
  EXPECT_EQ(ball.from, ball.to);
  EXPECT_LE((ball.from - Eigen::Vector3d(0.1, 0.2, 0.3)).norm(), 1e-15);
  EXPECT_EQ(ball.radius, 0.05);

  const LinkCapsule& cylinder = capsules[1];  // its axis turned onto x
  EXPECT_EQ(cylinder.label(), "arm");
  EXPECT_LE((cylinder.from - Eigen::Vector3d(-0.15, 0, 0.5)).norm(), 1e-12);
  EXPECT_LE((cylinder.to - Eigen::Vector3d(0.15, 0, 0.5)).norm(), 1e-12);
  EXPECT_EQ(cylinder.radius, 0.04);

  // The box: every corner within the capsule, and the capsule no fatter than its cross-section's
  // half-diagonal.
  const LinkCapsule& plate = capsules[2];
  EXPECT_NEAR(plate.radius, 0.5 * std::hypot(0.1, 0.02), 1e-15);
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  double worst = 0.0;
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3d local((corner & 1 ? 0.05 : -0.05), (corner & 2 ? 0.15 : -0.15),
                                (corner & 4 ? 0.01 : -0.01));
    const Eigen::Vector3d p = Eigen::Vector3d(0, 0.4, 0) + R * local;
    worst = std::max(worst, distance_to_capsule_axis(plate, p) - plate.radius);
  }
  EXPECT_LE(worst, 1e-12);
  EXPECT_GE(worst, -1e-12);  // the corners are on its surface: the cover is tight there
  // The cylinder's rim is covered too.
  for (int k = 0; k < 16; ++k) {
    const double a = 2.0 * std::numbers::pi * k / 16.0;
    for (const double x : {-0.15, 0.15}) {
      const Eigen::Vector3d rim(x, 0.04 * std::cos(a), 0.5 + 0.04 * std::sin(a));
      EXPECT_LE(distance_to_capsule_axis(cylinder, rim), cylinder.radius + 1e-12);
    }
  }
}

TEST(LinkCapsules, ACylinderOfNegativeLengthIsBadInput) {
  std::string urdf = kPrimitives;
  urdf.replace(urdf.find("length=\"0.3\""), 12, "length=\"-0.3\"");
  try {
    (void)ArmModel::from_urdf_string(urdf);
    FAIL() << "no InputError";
  } catch (const rodshape::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("link 'arm': <collision> cylinder length = -0.3"),
              std::string::npos)
        << error.what();
  }
}

TEST(LinkCapsules, PandaHasFrankasCapsulesAndAHand) {
  const ArmModel arm = rodshape::samples::panda();
  EXPECT_TRUE(arm.collision_notes().empty());
  std::map<std::string, std::vector<LinkCapsule>> by_link;
  for (const LinkCapsule& c : arm.link_capsules()) by_link[c.link].push_back(c);
  // Franka's model: a capsule per link, two on links 5 and 7; the hand (two capsules) and the
  // fingers on the flange. The two balls written at the ends of each cylinder are dropped.
  EXPECT_EQ(arm.link_capsules().size(), 14u);
  EXPECT_EQ(by_link["panda_link0"].size(), 1u);
  EXPECT_EQ(by_link["panda_link1"].size(), 1u);
  EXPECT_EQ(by_link["panda_link5"].size(), 2u);
  EXPECT_EQ(by_link["panda_link7"].size(), 2u);
  EXPECT_EQ(by_link["panda_link8"].size(), 4u);
  // link1: radius 0.06 along z from -0.333 to -0.05 (centre -0.1915, length 0.283).
  const LinkCapsule& link1 = by_link["panda_link1"][0];
  EXPECT_EQ(link1.frame, 1);
  EXPECT_EQ(link1.radius, 0.06);
  EXPECT_LE((link1.from - Eigen::Vector3d(0, 0, -0.333)).norm(), 1e-12);
  EXPECT_LE((link1.to - Eigen::Vector3d(0, 0, -0.05)).norm(), 1e-12);
  // link7's second capsule: turned by π/4 about z, centred 0.06 m out, 0.082 m up.
  const LinkCapsule& flange = by_link["panda_link7"][1];
  const Eigen::Vector3d centre = 0.5 * (flange.from + flange.to);
  EXPECT_LE((centre - Eigen::Vector3d(0.06 * std::sqrt(0.5), 0.06 * std::sqrt(0.5), 0.082)).norm(),
            1e-12);
  EXPECT_NEAR((flange.to - flange.from).norm(), 0.01, 1e-12);
  EXPECT_EQ(flange.radius, 0.03);
  // The hand: its wide capsule spans 0.1 m + 2 × 0.04 m = 0.18 m across, the fingers reach out to
  // z = 0.0857 + 0.02725 + their radius in the flange frame (beyond the fingertip centre, 0.1034).
  std::vector<std::string> names;
  for (const LinkCapsule& c : by_link["panda_link8"]) names.push_back(c.label());
  EXPECT_EQ(names,
            (std::vector<std::string>{"panda_link8 (hand)", "panda_link8 (hand)",
                                      "panda_link8 (left_finger)", "panda_link8 (right_finger)"}));
  const LinkCapsule& hand = by_link["panda_link8"][0];
  EXPECT_NEAR((hand.to - hand.from).norm() + 2 * hand.radius, 0.18, 1e-12);
  const LinkCapsule& finger = by_link["panda_link8"][2];
  EXPECT_GT(std::max(finger.from.z(), finger.to.z()) + finger.radius, 0.1034);
  for (const LinkCapsule& c : arm.link_capsules()) EXPECT_EQ(c.frame, std::stoi(c.link.substr(10)));
}

TEST(LinkCapsules, LinkFramesMatchTheDhTable) {
  const ArmModel arm = rodshape::samples::panda();
  std::mt19937 rng(7);
  LinkFrames frames;
  for (int trial = 0; trial < 50; ++trial) {
    Eigen::VectorXd q = rodshape::testing::panda_ready_pose();
    if (trial > 0) {
      for (int j = 0; j < 7; ++j) {
        std::uniform_real_distribution<double> u(arm.lower_limits()(j), arm.upper_limits()(j));
        q(j) = u(rng);
      }
    }
    arm.link_frames(q, frames);
    const std::vector<Eigen::Isometry3d> dh = rodshape::testing::panda_dh_frames(q);
    ASSERT_EQ(frames.frames.size(), 9u);
    EXPECT_LE(frames.frames[0].position.norm(), 0.0);
    for (int i = 0; i < 8; ++i) {
      const auto& f = frames.frames[static_cast<std::size_t>(i + 1)];
      EXPECT_LE((f.position - dh[static_cast<std::size_t>(i)].translation()).norm(), 1e-12);
      EXPECT_LE((f.rotation - dh[static_cast<std::size_t>(i)].rotation()).cwiseAbs().maxCoeff(),
                1e-12);
    }
    EXPECT_EQ(arm.joints_moving_frame(0), 0);
    EXPECT_EQ(arm.joints_moving_frame(4), 4);
    EXPECT_EQ(arm.joints_moving_frame(8), 7);
  }
  // At the ready pose by hand: link1's capsule bottom stands on the base plane (z = 0.333 -
  // 0.333 = 0), and link4's origin (the elbow) is the shoulder plus d3 along the upper arm, tilted
  // back by q2 = -π/4, plus a4 along link3's x (tilted up by π/4).
  arm.link_frames(rodshape::testing::panda_ready_pose(), frames);
  const LinkCapsule& link1 = arm.link_capsules()[1];
  const Eigen::Vector3d bottom = frames.frames[1].rotation * link1.from + frames.frames[1].position;
  EXPECT_LE(bottom.norm(), 1e-12);
  const double s = std::sqrt(0.5);
  const Eigen::Vector3d elbow(-0.316 * s + 0.0825 * s, 0.0, 0.333 + 0.316 * s + 0.0825 * s);
  EXPECT_LE((frames.frames[4].position - elbow).norm(), 1e-12)
      << frames.frames[4].position.transpose();
}

TEST(LinkCapsules, PointJacobianMatchesCentralDifferences) {
  const ArmModel arm = rodshape::samples::panda();
  Eigen::VectorXd q = rodshape::testing::panda_ready_pose();
  q += Eigen::VectorXd::LinSpaced(7, 0.1, -0.2);
  LinkFrames frames, plus, minus;
  arm.link_frames(q, frames);
  for (int f = 1; f <= 8; ++f) {
    const Eigen::Vector3d local(0.03, -0.02, 0.05);
    const Eigen::Vector3d p = frames.frames[f].rotation * local + frames.frames[f].position;
    Eigen::Matrix<double, 3, Eigen::Dynamic> J;
    arm.point_jacobian(frames, f, p, J);
    const double h = 1e-6;
    for (int j = 0; j < 7; ++j) {
      Eigen::VectorXd qp = q, qm = q;
      qp(j) += h;
      qm(j) -= h;
      arm.link_frames(qp, plus);
      arm.link_frames(qm, minus);
      const Eigen::Vector3d dp = (plus.frames[f].rotation * local + plus.frames[f].position -
                                  minus.frames[f].rotation * local - minus.frames[f].position) /
                                 (2 * h);
      EXPECT_LE((J.col(j) - dp).norm(), 1e-8) << "frame " << f << " joint " << j;
    }
  }
}

}  // namespace
}  // namespace test_link_capsules
