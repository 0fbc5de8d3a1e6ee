// test_scene_plan.cpp: plans through a scene. The bundled example needs a detour around its post;
// its plan is checked by re-solving the held rod independently of the planner: the equilibrium
// followed along every sample of the timed end-effector path (the rate's step, not the planner's
// tracking substeps), whose least gap to every obstacle must stay at or above the clearance.
// Targets inside an obstacle are infeasible; a clamp inside one, or a scene without tracking, is
// bad input; a way the planner cannot get past ends in the status Collision; a clamp mounted on an
// obstacle of any shape plans clear of it.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "rodshape/io/task_reader.hpp"
#include "rodshape/solvers/follow_equilibrium.hpp"
#include "rodshape/trajectory/plan.hpp"
#include "support/input_error.hpp"
#include "support/scene_replay.hpp"

namespace rodshape {
namespace test_scene_plan {
namespace {

using testing::input_error_message;

const std::string kExamples = std::string(RODSHAPE_SOURCE_DIR) + "/examples/";

TEST(ScenePlan, TheBundledPostIsPassedByADetourAndAnIndependentReplayStaysClear) {
  const PlanTask task = read_plan_task(kExamples + "plan_around_post.yaml");
  const PlanResult plan = rodshape::plan(task.problem, task.options);
  ASSERT_EQ(plan.status, PlanStatus::Complete) << plan.message;
  ASSERT_TRUE(plan.scene.has_value());
  EXPECT_GE(plan.scene->min_gap, task.problem.scene.clearance - SceneResult::kTolerance);
  EXPECT_TRUE(std::any_of(plan.steps.begin(), plan.steps.end(), [](const PlanStep& step) {
    return step.detour;
  })) << "the post blocks the straight way: a detour is expected";
  // Gentle: no coiled shape on the way (the detour's edges are capped at 1.5× their ends).
  EXPECT_LE(plan.tracking.peak_energy,
            1.5 * std::max(plan.initial_configuration.energy,
                           plan.steps.back().solution.configuration.energy));

  const testing::SceneReplay check = testing::replay_scene(task.problem, plan);
  ASSERT_TRUE(check.followed.followed()) << check.followed.brief();
  // Arrives on the planned final shape (1 mm: the tracking's branch tolerance).
  EXPECT_LT(check.followed.arrival_deviation, 1e-3);
  EXPECT_GE(check.least.gap, task.problem.scene.clearance - SceneResult::kTolerance)
      << "segment " << check.least.segment << " of obstacle " << check.least.obstacle;
}

// A clamp mounted on an obstacle of each shape (the band stands on it, along its outward normal):
// the plan completes and stays clear of the mount (it ended in a false collision, the first
// segment's swept bound half a node step below the mount's own gap).
TEST(ScenePlan, ABandClampedOnAnObstacleOfEveryShapePlansClearOfItsMount) {
  const std::vector<Obstacle> mounts = {
      {"table", HalfSpaceObstacle{{0.0, 0.0, -1.0}, 0.0}},
      {"block", BoxObstacle{{0.0, 0.0, -0.05}, {0.4, 0.4, 0.1}, Eigen::Matrix3d::Identity()}},
      {"knob", SphereObstacle{{0.0, 0.0, -0.03}, 0.03}},
      {"rail", CapsuleObstacle{{0.0, -0.1, -0.02}, {0.0, 0.1, -0.02}, 0.02}}};
  for (const Obstacle& mount : mounts) {
    PlanTask task = read_plan_task(kExamples + "plan_s_curve.yaml");
    task.problem.scene.clearance = 0.005;
    task.problem.scene.rod_radius = 0.5 * std::sqrt(2.0) * 0.02;  // the 2 cm square's
    task.problem.scene.obstacles = {mount};
    const PlanResult plan = rodshape::plan(task.problem, task.options);
    EXPECT_EQ(plan.status, PlanStatus::Complete) << mount.name << ": " << plan.message;
    ASSERT_TRUE(plan.scene.has_value());
    EXPECT_TRUE(plan.scene->clear()) << mount.name << ": margin " << plan.scene->margin;
    // The mount's own gap: the clamp on the surface, the rod's surface a radius into it.
    EXPECT_NEAR(plan.scene->min_gap, -task.problem.scene.rod_radius, 1e-9) << mount.name;
  }
}

TEST(ScenePlan, ATargetPointInsideAnObstacleIsInfeasibleAndNamed) {
  PlanTask task = read_plan_task(kExamples + "plan_around_post.yaml");
  const Eigen::Vector3d point = task.problem.target.points[6];
  task.problem.scene.obstacles.push_back({"block", SphereObstacle{point, 0.01}});
  const PlanResult plan = rodshape::plan(task.problem, task.options);
  EXPECT_EQ(plan.status, PlanStatus::Infeasible);
  EXPECT_NE(plan.message.find("objective point 6"), std::string::npos) << plan.message;
  EXPECT_NE(plan.message.find("'block'"), std::string::npos) << plan.message;
  EXPECT_TRUE(plan.steps.empty());
}

TEST(ScenePlan, AClampInsideAnObstacleAndASceneWithoutTrackingAreBadInput) {
  PlanTask task = read_plan_task(kExamples + "plan_around_post.yaml");
  PlanTask inside = task;
  inside.problem.scene.obstacles.push_back({"", SphereObstacle{Eigen::Vector3d::Zero(), 0.01}});
  EXPECT_EQ(input_error_message([&] {
              rodshape::plan(inside.problem, inside.options);
            }).rfind("ClampedRod.clamp.position lies inside obstacle 2", 0),
            0u);
  PlanTask untracked = task;
  untracked.options.track_between_waypoints = false;
  EXPECT_EQ(input_error_message([&] {
              rodshape::plan(untracked.problem, untracked.options);
            }).rfind("PlanOptions.track_between_waypoints must be true with a scene", 0),
            0u);
}

TEST(ScenePlan, ARodStartingThroughAnObstacleIsBadInput) {
  PlanTask task = read_plan_task(kExamples + "plan_around_post.yaml");
  // A rail across the straight rod at rest (it stands along +z from the clamp).
  task.problem.scene.obstacles.push_back(
      {"rail", CapsuleObstacle{{-0.05, 0.0, 0.15}, {0.05, 0.0, 0.15}, 0.005}});
  EXPECT_NE(input_error_message([&] {
              rodshape::plan(task.problem, task.options);
            }).find("the initial rod comes within"),
            std::string::npos);
}

TEST(ScenePlan, WithoutADetourThePostEndsInCollisionNamingItAndWhere) {
  PlanTask task = read_plan_task(kExamples + "plan_around_post.yaml");
  task.options.scene_detour = false;
  const PlanResult plan = rodshape::plan(task.problem, task.options);
  ASSERT_EQ(plan.status, PlanStatus::Collision) << plan.message;
  EXPECT_NE(plan.message.find("obstacle 'post'"), std::string::npos) << plan.message;
  ASSERT_TRUE(plan.scene.has_value());
  EXPECT_LT(plan.scene->margin, 0.0);
  EXPECT_EQ(plan.scene->obstacle_label, "'post'");
  EXPECT_GT(plan.scene->step, 0);
  EXPECT_TRUE(plan.scene->detours.empty());
  EXPECT_TRUE(std::none_of(plan.steps.begin(), plan.steps.end(),
                           [](const PlanStep& step) { return step.detour; }));
}

}  // namespace
}  // namespace test_scene_plan
}  // namespace rodshape
