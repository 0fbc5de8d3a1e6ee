// test_arm_clearance.cpp: link-capsule gaps against brute-force sampled distances, their gradients
// against central differences, the mount and the hand rules, and IK's null-space clearance (the tip
// held to 1e-10 while the elbow leaves an obstacle).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "rodshape/robot/arm_clearance.hpp"
#include "rodshape/robot/inverse_kinematics.hpp"
#include "rodshape/samples/panda.hpp"
#include "support/panda_dh.hpp"

namespace test_arm_clearance {
namespace {

using namespace rodshape;

Obstacle sphere(const Eigen::Vector3d& c, double r, const std::string& name = "") {
  return {name, SphereObstacle{c, r}};
}

Scene mixed_scene() {
  Scene scene;
  scene.clearance = 0.01;
  scene.rod_radius = 0.005;
  scene.obstacles.push_back(sphere({0.35, 0.15, 0.6}, 0.08, "ball"));
  BoxObstacle box;
  box.center = {0.1, -0.35, 0.4};
  box.size = {0.2, 0.1, 0.3};
  box.rotation = Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  scene.obstacles.push_back({"box", box});
  scene.obstacles.push_back({"pole", CapsuleObstacle{{0.5, -0.2, 0.0}, {0.5, 0.3, 0.9}, 0.03}});
  scene.obstacles.push_back({"table", HalfSpaceObstacle{{0, 0, -1}, 0.0}});
  return scene;
}

Pose base_pose() {
  Pose pose;
  pose.position = {0.02, -0.01, 0.0};
  pose.rotation = Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return pose;
}

Eigen::VectorXd random_q(const ArmModel& arm, std::mt19937& rng) {
  Eigen::VectorXd q(arm.joints());
  for (int j = 0; j < arm.joints(); ++j) {
    std::uniform_real_distribution<double> u(arm.lower_limits()(j), arm.upper_limits()(j));
    q(j) = u(rng);
  }
  return q;
}

/// Brute force: every capsule's axis sampled at 1001 points, against every obstacle's point
/// distance, and against a rod sampled densely too.
double brute_force_least_margin(const ArmClearance& clearance,
                                const Eigen::VectorXd& q,
                                const RodNodes* rod) {
  const ArmModel& arm = clearance.arm();
  LinkFrames frames;
  arm.link_frames(q, frames);
  const Pose w = base_pose();
  double least = std::numeric_limits<double>::infinity();
  for (std::size_t c = 0; c < arm.link_capsules().size(); ++c) {
    const LinkCapsule& capsule = arm.link_capsules()[c];
    const Pose& f = frames.frames[static_cast<std::size_t>(capsule.frame)];
    const Eigen::Vector3d a = w.rotation * (f.rotation * capsule.from + f.position) + w.position;
    const Eigen::Vector3d b = w.rotation * (f.rotation * capsule.to + f.position) + w.position;
    for (int k = 0; k <= 1000; ++k) {
      const Eigen::Vector3d p = a + (k / 1000.0) * (b - a);
      for (std::size_t j = 0; j < clearance.scene().obstacles.size(); ++j) {
        const double gap = clearance.scene().obstacles[j].distance(p).distance - capsule.radius;
        LinkGap pair;
        pair.capsule = static_cast<int>(c);
        pair.obstacle = static_cast<int>(j);
        pair.margin = gap - clearance.required_gap(pair.capsule, pair.obstacle);
        if (clearance.is_mount(pair) && pair.clear()) continue;  // as least_gap(): not news
        least = std::min(least, pair.margin);
      }
      if (rod != nullptr && clearance.checks_rod(static_cast<int>(c))) {
        for (std::size_t i = 0; i + 1 < rod->size(); ++i) {
          for (int m = 0; m <= 10; ++m) {
            const Eigen::Vector3d r = (*rod)[i] + (m / 10.0) * ((*rod)[i + 1] - (*rod)[i]);
            least = std::min(least, (p - r).norm() - capsule.radius - clearance.scene().rod_radius -
                                        clearance.scene().clearance);
          }
        }
      }
    }
  }
  return least;
}

RodNodes wavy_rod() {
  RodNodes rod;
  for (int i = 0; i <= 40; ++i) {
    const double s = i / 40.0;
    rod.emplace_back(0.2 + 0.3 * s, 0.25 * std::sin(3 * s), 0.3 + 0.4 * s);
  }
  return rod;
}

TEST(ArmClearance, LeastGapMatchesBruteForceSampling) {
  const ArmModel arm = samples::panda();
  const Scene scene = mixed_scene();
  const ArmClearance clearance(arm, base_pose(), scene, samples::panda_ready_pose());
  const RodNodes rod = wavy_rod();
  std::mt19937 rng(11);
  for (int trial = 0; trial < 12; ++trial) {
    const Eigen::VectorXd q = trial == 0 ? samples::panda_ready_pose() : random_q(arm, rng);
    const LinkGap gap = clearance.least_gap(q, {&rod});
    const double brute = brute_force_least_margin(clearance, q, &rod);
    ASSERT_GE(gap.capsule, 0);
    // The exact minimum is below every sample and within the sampling's resolution of the best.
    EXPECT_LE(gap.margin, brute + 1e-12) << "trial " << trial;
    EXPECT_GE(gap.margin, brute - 5e-4) << "trial " << trial;
  }
}

TEST(ArmClearance, GapGradientsMatchCentralDifferences) {
  const ArmModel arm = samples::panda();
  const Scene scene = mixed_scene();
  const ArmClearance clearance(arm, base_pose(), scene, samples::panda_ready_pose());
  const RodNodes rod = wavy_rod();
  std::mt19937 rng(5);
  const double influence = 100.0;  // every pair is a row, in the same order at every q
  int checked = 0;
  for (int trial = 0; trial < 10; ++trial) {
    const Eigen::VectorXd q = random_q(arm, rng);
    std::vector<LinkGapRow> rows, plus, minus;
    clearance.near_pairs(q, {&rod}, influence, rows);
    ASSERT_FALSE(rows.empty());
    const double h = 1e-7;
    Eigen::MatrixXd numeric(static_cast<Eigen::Index>(rows.size()), 7);
    bool same = true;
    for (int j = 0; j < 7; ++j) {
      Eigen::VectorXd qp = q, qm = q;
      qp(j) += h;
      qm(j) -= h;
      clearance.near_pairs(qp, {&rod}, influence, plus);
      clearance.near_pairs(qm, {&rod}, influence, minus);
      same = same && plus.size() == rows.size() && minus.size() == rows.size();
      if (!same) break;
      for (std::size_t k = 0; k < rows.size(); ++k)  // gap = required + influence - shortfall
        numeric(static_cast<Eigen::Index>(k), j) =
            -(plus[k].shortfall - minus[k].shortfall) / (2 * h);
    }
    ASSERT_TRUE(same);
    for (std::size_t k = 0; k < rows.size(); ++k) {
      const Eigen::VectorXd analytic = rows[k].gradient;
      const Eigen::VectorXd fd = numeric.row(static_cast<Eigen::Index>(k)).transpose();
      // A pair whose nearest point jumps (a box's edge, the rod's nearest segment changing) has a
      // kink; away from kinks the envelope gradient is exact.
      if ((analytic - fd).norm() < 1e-5 * std::max(1.0, fd.norm())) ++checked;
    }
  }
  EXPECT_GE(checked, 10 * 14 * 95 / 100) << "most pairs' gradients match";
}

TEST(ArmClearance, TheMountMayStandOnTheTableAndTheHandMayHoldTheRod) {
  const ArmModel arm = samples::panda();
  Scene scene;
  scene.clearance = 0.005;
  scene.rod_radius = 0.01;
  // the table top at the base plane: free where -z ≤ 0, the solid below z = 0
  scene.obstacles.push_back({"table", HalfSpaceObstacle{{0, 0, -1}, 0.0}});
  const ArmClearance clearance(arm, Pose{}, scene, samples::panda_ready_pose());
  // link0's capsule touches the base plane (its balls reach z = 0), link1's bottom ball sinks 6 cm:
  // both are the mount and keep what they have; the others keep the clearance.
  EXPECT_NEAR(clearance.required_gap(0, 0), 0.0, 1e-12);
  EXPECT_NEAR(clearance.required_gap(1, 0), -0.06, 1e-12);
  EXPECT_EQ(clearance.required_gap(2, 0), 0.005);
  const LinkGap ready = clearance.least_gap(samples::panda_ready_pose());
  EXPECT_TRUE(ready.clear()) << clearance.describe(ready);
  // The rod through the hand is not a collision; through the forearm it is.
  LinkFrames frames;
  arm.link_frames(samples::panda_ready_pose(), frames);
  const Eigen::Vector3d fingertip =
      frames.frames[8].rotation * Eigen::Vector3d(0, 0, 0.1034) + frames.frames[8].position;
  const RodNodes held{fingertip, fingertip + Eigen::Vector3d(0, 0, -0.2)};
  for (int c = 0; c < static_cast<int>(arm.link_capsules().size()); ++c)
    EXPECT_EQ(clearance.checks_rod(c), arm.link_capsules()[c].frame < 7) << c;
  const LinkGap with_held = clearance.least_gap(samples::panda_ready_pose(), {&held});
  EXPECT_TRUE(with_held.clear()) << clearance.describe(with_held);
  const Eigen::Vector3d elbow = frames.frames[4].position;
  const RodNodes through{elbow + Eigen::Vector3d(0, -0.2, 0), elbow + Eigen::Vector3d(0, 0.2, 0)};
  const LinkGap hit = clearance.least_gap(samples::panda_ready_pose(), {&through});
  EXPECT_FALSE(hit.clear());
  EXPECT_EQ(hit.obstacle, -1);
  EXPECT_NE(clearance.describe(hit).find("the rod"), std::string::npos);
}

// A ball on the elbow at the ready pose: IK with the clearance keeps the flange where it was (to
// 1e-10) and swings the elbow out through the Panda's redundancy; without it the elbow stays in.
TEST(ArmClearance, NullSpaceIkMovesTheElbowOutOfAnObstacleAndKeepsTheTip) {
  const ArmModel arm = samples::panda();
  const Eigen::VectorXd ready = samples::panda_ready_pose();
  LinkFrames frames;
  arm.link_frames(ready, frames);
  Scene scene;
  scene.clearance = 0.01;
  scene.obstacles.push_back(
      sphere(frames.frames[4].position + Eigen::Vector3d(0.0, 0.09, 0.05), 0.05, "post"));
  const ArmClearance clearance(arm, Pose{}, scene, ready);
  const LinkGap before = clearance.least_gap(ready);
  ASSERT_FALSE(before.clear()) << clearance.describe(before);
  const Pose target = arm.forward_kinematics(ready);

  const IkResult plain = solve_ik(arm, target, ready);
  ASSERT_TRUE(plain.converged());
  EXPECT_FALSE(clearance.least_gap(plain.q).clear());

  IkClearance keep;
  keep.clearance = &clearance;
  const IkResult ik = solve_ik(arm, target, ready, IkOptions{}, keep);
  ASSERT_TRUE(ik.converged()) << ik.brief();
  EXPECT_GT(ik.clearance_steps, 0);
  const Pose pose = arm.forward_kinematics(ik.q);
  EXPECT_LE((pose.position - target.position).norm(), 1e-10);
  EXPECT_LE((pose.rotation - target.rotation).cwiseAbs().maxCoeff(), 1e-10);
  const LinkGap after = clearance.least_gap(ik.q);
  EXPECT_TRUE(after.clear()) << clearance.describe(after);
  EXPECT_GT(after.gap, before.gap + 0.05);
}

}  // namespace
}  // namespace test_arm_clearance

namespace test_arm_clearance {
namespace {

// ---- Two arms (issue 21) ----

/// A second Panda 0.7 m away on the x axis, facing the first.
Pose facing_pose() {
  return {Eigen::Vector3d(0.7, 0.05, 0.0),
          Eigen::AngleAxisd(3.0, Eigen::Vector3d::UnitZ()).toRotationMatrix()};
}

TEST(ArmClearance, TheOtherArmsCapsulesAreMeasuredExactlyAndTheirGradientsMatch) {
  const ArmModel arm = samples::panda();
  Scene empty;
  empty.clearance = 0.01;
  const ArmClearance clearance(arm, base_pose(), empty, samples::panda_ready_pose());
  std::mt19937 rng(21);
  const double influence = 100.0;  // every pair is a row, in the same order at every q
  int checked = 0, rows_seen = 0;
  for (int trial = 0; trial < 8; ++trial) {
    const Eigen::VectorXd q = random_q(arm, rng);
    const Eigen::VectorXd q_other = random_q(arm, rng);
    const std::vector<Obstacle> others = world_capsules(arm, facing_pose(), q_other);
    ASSERT_EQ(others.size(), arm.link_capsules().size());
    // least_gap against the other arm's capsules equals arm_arm_gap over the same pairs.
    const LinkGap gap = clearance.least_gap(q, {}, &others);
    const LinkGap direct = arm_arm_gap(arm, base_pose(), q, arm, facing_pose(), q_other, 0.01);
    ASSERT_EQ(gap.obstacle, kOtherArm) << "trial " << trial;  // the only pairs
    EXPECT_EQ(gap.capsule, direct.capsule);
    EXPECT_EQ(gap.other_capsule, direct.other_capsule);
    EXPECT_NEAR(gap.margin, direct.margin, 1e-12);
    EXPECT_NE(clearance.describe(gap, &arm).find("the other arm's link"), std::string::npos);
    // Gradients of every pair against central differences.
    std::vector<LinkGapRow> rows, plus, minus;
    clearance.near_pairs(q, {}, influence, rows, &others);
    ASSERT_EQ(rows.size(), arm.link_capsules().size() * others.size());
    const double h = 1e-7;
    Eigen::MatrixXd numeric(static_cast<Eigen::Index>(rows.size()), 7);
    for (int j = 0; j < 7; ++j) {
      Eigen::VectorXd qp = q, qm = q;
      qp(j) += h;
      qm(j) -= h;
      clearance.near_pairs(qp, {}, influence, plus, &others);
      clearance.near_pairs(qm, {}, influence, minus, &others);
      ASSERT_EQ(plus.size(), rows.size());
      ASSERT_EQ(minus.size(), rows.size());
      for (std::size_t k = 0; k < rows.size(); ++k)
        numeric(static_cast<Eigen::Index>(k), j) =
            -(plus[k].shortfall - minus[k].shortfall) / (2 * h);
    }
    for (std::size_t k = 0; k < rows.size(); ++k, ++rows_seen) {
      const Eigen::VectorXd fd = numeric.row(static_cast<Eigen::Index>(k)).transpose();
      if ((rows[k].gradient - fd).norm() < 1e-5 * std::max(1.0, fd.norm())) ++checked;
    }
  }
  // Capsule–capsule distances are smooth but where the nearest points jump between ends.
  EXPECT_GE(checked, rows_seen * 95 / 100) << checked << " of " << rows_seen;
}

TEST(ArmClearance, IkKeepsTheLinksOffTheOtherArm) {
  // The first arm's hand held where the ready pose puts it; a second arm's capsule parked next
  // to the elbow: the null space moves the elbow off it, the hand stays.
  const ArmModel arm = samples::panda();
  Scene empty;
  empty.clearance = 0.01;
  const ArmClearance clearance(arm, Pose{}, empty, samples::panda_ready_pose());
  const Eigen::VectorXd ready = samples::panda_ready_pose();
  LinkFrames frames;
  arm.link_frames(ready, frames);
  const Pose flange = arm.forward_kinematics(ready);
  // The elbow: the frame of joint 4's child link.
  const Eigen::Vector3d elbow = frames.frames[4].position;
  const std::vector<Obstacle> others = {
      {"other arm", CapsuleObstacle{elbow + Eigen::Vector3d(0, 0.12, -0.1),
                                    elbow + Eigen::Vector3d(0, 0.12, 0.1), 0.04}}};
  const LinkGap before = clearance.least_gap(ready, {}, &others);
  ASSERT_FALSE(before.clear()) << clearance.describe(before);
  IkClearance push;
  push.clearance = &clearance;
  push.others = &others;
  const IkResult ik = solve_ik(arm, flange, ready, IkOptions{}, push);
  ASSERT_TRUE(ik.converged()) << ik.message;
  EXPECT_GT(ik.clearance_steps, 0);
  const LinkGap after = clearance.least_gap(ik.q, {}, &others);
  EXPECT_GT(after.margin, before.margin) << clearance.describe(after);
  EXPECT_LE(ik.position_error, 1e-9);
}

TEST(ArmClearance, TwoArmsIkKeepsTheirLinksTheClearanceApartAtAKnownNearCollision) {
  // examples/plan_two_pandas.yaml's cell: the tip's arm at x = 0.4 facing -x, the base's at
  // x = -0.4 facing +x. The joints are the last sample of the two-arm sweep's case 583
  // (tests/trajectory/test_random_two_arm.cpp) as main planned it before the tip's arm kept off
  // the base arm: the tip arm's forearm (panda_link5) 0.05 mm into the base arm's hand.
  const ArmModel arm = samples::panda();
  const Pose world_T_tip{Eigen::Vector3d(0.4, 0.0, 0.0),
                         Eigen::AngleAxisd(std::numbers::pi, Eigen::Vector3d::UnitZ()).matrix()};
  const Pose world_T_base{Eigen::Vector3d(-0.4, 0.0, 0.0), Eigen::Matrix3d::Identity()};
  Eigen::VectorXd q_tip(7), q_base(7);
  q_tip << 0.10982531147011051, 0.92459421564264233, -0.64272418649757546, -2.1118524660502889,
      1.438645152876934, 0.62441093269878023, 1.2864523885445844;
  q_base << -0.33921267565997792, -1.0205783443352137, 1.2600011279526664, -2.8323177370036809,
      -0.53127562069349532, 1.7130854110313223, 2.0119355304069679;
  Scene scene;
  scene.clearance = 0.005;  // the example's
  const LinkGap before = arm_arm_gap(arm, world_T_tip, q_tip, arm, world_T_base, q_base, 0.005);
  ASSERT_LT(before.gap, 0.0);
  ASSERT_EQ(arm.link_capsules()[static_cast<std::size_t>(before.capsule)].link, "panda_link5");
  const IkOptions options;
  const auto keep_off = [&](const Pose& world_T_arm, const Eigen::VectorXd& q,
                            const Pose& world_T_other, const Eigen::VectorXd& q_other) {
    const ArmClearance clearance(arm, world_T_arm, scene, q);
    const std::vector<Obstacle> others = world_capsules(arm, world_T_other, q_other);
    IkClearance push;
    push.clearance = &clearance;
    push.others = &others;
    const Pose target = arm.forward_kinematics(q);  // the hand stays where it is
    const IkResult ik = solve_ik(arm, target, q, options, push);
    EXPECT_TRUE(ik.converged()) << ik.message;
    const Pose reached = arm.forward_kinematics(ik.q);
    EXPECT_LE((reached.position - target.position).norm(), options.position_tolerance);
    EXPECT_LE(Eigen::AngleAxisd(reached.rotation.transpose() * target.rotation).angle(),
              options.rotation_tolerance);
    return ik.q;
  };
  // The arms in turn, each keeping off the other where it stands (as the planner does).
  const Eigen::VectorXd tip_apart = keep_off(world_T_tip, q_tip, world_T_base, q_base);
  const Eigen::VectorXd base_apart = keep_off(world_T_base, q_base, world_T_tip, tip_apart);
  const LinkGap after =
      arm_arm_gap(arm, world_T_tip, tip_apart, arm, world_T_base, base_apart, 0.005);
  EXPECT_GE(after.gap, scene.clearance) << "pair " << after.capsule << "/" << after.other_capsule;
}

}  // namespace
}  // namespace test_arm_clearance
