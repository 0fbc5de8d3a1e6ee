// test_arm_link_clearance.cpp: plans whose arm keeps its links off the scene. The bundled shelf
// example completes with every link clear, checked sample by sample independently of the planner;
// without the links' null-space term the same plan's forearm runs 4 cm into the board; an obstacle
// on the hand's own path, which no redundancy can avoid, gives the status collision naming the
// step, the link, the obstacle and the gap; a scene plan without link geometry has no robot gap; a
// hand that starts inside an obstacle is bad input before any plan.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "rodshape/io/task_reader.hpp"
#include "rodshape/robot/arm_clearance.hpp"
#include "rodshape/trajectory/plan.hpp"
#include "support/input_error.hpp"

namespace rodshape {
namespace test_arm_link_clearance {
namespace {

const std::string kShelf = std::string(RODSHAPE_SOURCE_DIR) + "/examples/plan_panda_shelf.yaml";

/// The least link gap over the joint trajectory's samples against the scene alone, measured anew.
LinkGap replay_link_gap(const PlanTask& task, const PlanResult& plan, int& sample) {
  const ArmClearance clearance(task.problem.arm->model, task.problem.arm->placement.world_T_base,
                               task.problem.scene,
                               task.options.arm.joints.first_seed(task.problem.arm->model));
  LinkGap least;
  for (std::size_t i = 0; i < plan.arm->joints.q.size(); ++i) {
    const LinkGap gap = clearance.least_gap(plan.arm->joints.q[i]);
    if (gap.margin < least.margin) {
      least = gap;
      sample = static_cast<int>(i);
    }
  }
  return least;
}

TEST(ArmLinkClearance, TheShelfExampleCompletesWithEveryLinkClear) {
  const PlanTask task = read_plan_task(kShelf);
  const PlanResult plan = rodshape::plan(task.problem, task.options);
  ASSERT_EQ(plan.status, PlanStatus::Complete) << plan.message;
  ASSERT_TRUE(plan.arm && plan.arm->joints.complete());
  ASSERT_TRUE(plan.scene && plan.scene->robot);
  const RobotGapResult& robot = *plan.scene->robot;
  const double clearance = task.problem.scene.clearance;
  EXPECT_GE(robot.min_gap, clearance);
  EXPECT_TRUE(robot.clear());
  EXPECT_GT(robot.sample, 0);
  EXPECT_EQ(robot.t, plan.arm->joints.t[static_cast<std::size_t>(robot.sample)]);
  EXPECT_FALSE(robot.link.empty());
  EXPECT_GT(plan.arm->joints.clearance_steps, 0) << "the board is in the plain IK's way";
  // Independently: every sample's links against the scene.
  int sample = -1;
  const LinkGap replay = replay_link_gap(task, plan, sample);
  EXPECT_TRUE(replay.clear()) << "sample " << sample;
  EXPECT_GE(replay.gap, clearance);
  // The summary line gives it.
  EXPECT_NE(plan.brief().find("least gap of the arm's links"), std::string::npos);
}

TEST(ArmLinkClearance, WithoutTheNullSpaceTermTheForearmRunsIntoTheBoard) {
  PlanTask task = read_plan_task(kShelf);
  task.options.arm.link_clearance = false;
  const PlanResult plan = rodshape::plan(task.problem, task.options);
  ASSERT_EQ(plan.status, PlanStatus::Complete) << plan.message;  // nothing measured the links
  EXPECT_FALSE(plan.scene && plan.scene->robot);
  int sample = -1;
  const LinkGap replay = replay_link_gap(task, plan, sample);
  EXPECT_FALSE(replay.clear()) << replay.gap << " capsule " << replay.capsule << " obstacle "
                               << replay.obstacle << " sample " << sample;
  EXPECT_LT(replay.gap, task.problem.scene.clearance);
  EXPECT_EQ(task.problem.scene.obstacles[static_cast<std::size_t>(replay.obstacle)].name, "board");
  const std::string link =
      task.problem.arm->model.link_capsules()[static_cast<std::size_t>(replay.capsule)].link;
  EXPECT_EQ(link, "panda_link5");  // the forearm, from the elbow to the wrist
  EXPECT_LT(replay.gap, -0.04);    // 4.35 cm deep into the board
}

// A ball just above the flange on its way: the flange's link moves with the hand, so no motion
// of the elbow helps, and the tighter reach shells of the re-plans do not move the hand out of it.
TEST(ArmLinkClearance, AnObstacleTheHandItselfMeetsGivesCollisionNamingStepLinkObstacleGap) {
  PlanTask task = read_plan_task(kShelf);
  task.problem.scene.obstacles.push_back({"lamp", SphereObstacle{{0.09, 0.0, 0.62}, 0.03}});
  const PlanResult plan = rodshape::plan(task.problem, task.options);
  EXPECT_EQ(plan.status, PlanStatus::Collision) << plan.message;
  ASSERT_TRUE(plan.arm);
  EXPECT_EQ(plan.arm->status, ArmPlanStatus::Collision);
  for (const char* word : {"step ", "link panda_link7", "obstacle 'lamp'", "gap "})
    EXPECT_NE(plan.message.find(word), std::string::npos) << word << " in " << plan.message;
  ASSERT_TRUE(plan.scene && plan.scene->robot);
  EXPECT_FALSE(plan.scene->robot->clear());
  EXPECT_EQ(plan.scene->robot->obstacle_name, "lamp");
  EXPECT_GT(plan.scene->robot->step, 0);
  // The rod itself is clear: the collision is the arm's.
  EXPECT_TRUE(plan.scene->clear());
}

// Issue 43, item 7: a box in which the hand starts was found only after planning (status
// collision, exit 3): the pose where the rod starts fixes the hand, so it is bad input before any
// plan, naming the obstacle and the link.
TEST(ArmLinkClearance, AHandStartingInsideABoxIsBadInputBeforeAnyPlan) {
  PlanTask task = read_plan_task(kShelf);
  const PlanResult clear = rodshape::plan(task.problem, task.options);
  ASSERT_EQ(clear.status, PlanStatus::Complete) << clear.message;
  ASSERT_TRUE(clear.arm && !clear.arm->joints.q.empty());
  // The hand's capsule where the rod starts; a 2 cm box on its end farther from the rod.
  const PlanArm& arm = *task.problem.arm;
  const std::vector<Obstacle> links =
      world_capsules(arm.model, arm.placement.world_T_base, clear.arm->joints.q.front());
  const auto hand = std::find_if(links.begin(), links.end(), [](const Obstacle& link) {
    return link.name == "panda_link8 (hand)";
  });
  ASSERT_NE(hand, links.end());
  const auto& capsule = std::get<CapsuleObstacle>(hand->shape);
  const auto rod_distance = [&](const Eigen::Vector3d& p) {
    double least = std::numeric_limits<double>::infinity();
    for (const Eigen::Vector3d& node : clear.initial_configuration.p)
      least = std::min(least, (node - p).norm());
    return least;
  };
  const Eigen::Vector3d end =
      rod_distance(capsule.from) > rod_distance(capsule.to) ? capsule.from : capsule.to;
  PlanProblem boxed = task.problem;
  boxed.scene.obstacles.push_back({"crate", BoxObstacle{end, Eigen::Vector3d(0.02, 0.02, 0.02)}});
  // The box keeps off the rod (its clearance and more): only the hand is in it.
  ASSERT_GT(rod_distance(end) - std::sqrt(3.0) * 0.01 - boxed.scene.rod_radius,
            boxed.scene.clearance);
  const std::string index = std::to_string(boxed.scene.obstacles.size() - 1);
  const std::string message =
      testing::input_error_message([&] { (void)rodshape::plan(boxed, task.options); });
  EXPECT_EQ(message.find("Scene.obstacles[" + index + "] ('crate'): the arm's link panda_link"), 0u)
      << message;
  EXPECT_NE(message.find("fixed to its hand, starts inside it ("), std::string::npos) << message;
  EXPECT_NE(message.find("where the rod starts"), std::string::npos) << message;
}

TEST(ArmLinkClearance, AnArmWithoutCollisionGeometryHasNoRobotGap) {
  PlanTask task = read_plan_task(kShelf);
  const std::string urdf =
      R"(<robot name="bare"><link name="a"/><link name="b"/><link name="c"/>
      <joint name="j1" type="revolute"><parent link="a"/><child link="b"/><axis xyz="0 0 1"/>
      <limit lower="-3" upper="3" velocity="1" effort="1"/></joint>
      <joint name="j2" type="revolute"><parent link="b"/><child link="c"/><origin xyz="0.3 0 0"/>
      <axis xyz="0 0 1"/><limit lower="-3" upper="3" velocity="1" effort="1"/></joint></robot>)";
  const ArmModel bare = ArmModel::from_urdf_string(urdf);
  EXPECT_TRUE(bare.link_capsules().empty());
  // The ArmClearance of such an arm measures nothing.
  const ArmClearance clearance(bare, Pose{}, task.problem.scene, Eigen::VectorXd::Zero(2));
  EXPECT_EQ(clearance.least_gap(Eigen::VectorXd::Zero(2)).capsule, -1);
}

}  // namespace
}  // namespace test_arm_link_clearance
}  // namespace rodshape
