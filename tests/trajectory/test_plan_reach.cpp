// test_plan_reach.cpp: what `complete` promises: the final shape passes within the reach
// tolerance of every target point (PlanOptions::reach_tolerance; the distance measured to the
// target, not to the last intermediate set), and a gripper that holds nothing is bad input.
#include <gtest/gtest.h>

#include <string>

#include "rodshape/io/task_reader.hpp"
#include "rodshape/trajectory/plan.hpp"
#include "support/input_error.hpp"

namespace rodshape {
namespace test_plan_reach {
namespace {

using testing::input_error_message;

const std::string kExamples = std::string(RODSHAPE_SOURCE_DIR) + "/examples/";

// Complete means the final shape reaches the target: a target the energy weight keeps the band
// from (W1 = 3: every step's optimum is a compromise 84 mm off) is partial, with the distance to
// the target, not to the last intermediate set.
TEST(PlanReach, AllStepsSucceedingFarFromTheTargetIsPartialWithTheDistance) {
  PlanTask task = read_plan_task(kExamples + "plan_s_curve.yaml");
  task.problem.target.energy_weight = 3.0;
  const PlanResult plan = rodshape::plan(task.problem, task.options);
  EXPECT_EQ(plan.status, PlanStatus::Partial) << plan.message;
  EXPECT_EQ(plan.steps.size(), 7u);
  EXPECT_DOUBLE_EQ(plan.reach_tolerance, 0.01 * task.problem.rod.properties.length);
  EXPECT_GT(plan.target_distance, 10.0 * plan.reach_tolerance);
  EXPECT_NE(plan.message.find("mm from target point " + std::to_string(plan.target_point)),
            std::string::npos)
      << plan.message;
  // The same plan with the tolerance above its distance is complete.
  task.options.reach_tolerance = 1.01 * plan.target_distance;
  EXPECT_EQ(rodshape::plan(task.problem, task.options).status, PlanStatus::Complete);
}

// The bundled plans still complete, within the default tolerance, and measure their distance to
// the target itself (here equal to the last step's: its set is the target).
TEST(PlanReach, ACompletePlanIsWithinTheToleranceOfEveryTargetPoint) {
  const PlanTask task = read_plan_task(kExamples + "plan_s_curve.yaml");
  const PlanResult plan = rodshape::plan(task.problem, task.options);
  ASSERT_EQ(plan.status, PlanStatus::Complete) << plan.message;
  EXPECT_LE(plan.target_distance, plan.reach_tolerance);
  EXPECT_NEAR(plan.target_distance, plan.steps.back().solution.cost.max_distance, 1e-12);
}

// A gripper that transmits nothing does not hold the rod: bad input, before any work (it planned
// a 0 s path that ended 84.5 mm off, or 11.9 mm off with zero energy for the base gripper).
TEST(PlanReach, AGripperReleasingEveryComponentIsBadInput) {
  PlanTask task = read_plan_task(kExamples + "plan_s_curve.yaml");
  task.problem.grasp.released.fill(true);
  EXPECT_EQ(input_error_message([&] {
              rodshape::plan(task.problem, task.options);
            }).rfind("Grasp.released releases all six components", 0),
            0u);
  PlanTask moving = read_plan_task(kExamples + "plan_base_arm.yaml");
  ASSERT_TRUE(moving.problem.moving_base.has_value());
  moving.problem.moving_base->grasp.released.fill(true);
  EXPECT_EQ(input_error_message([&] {
              rodshape::plan(moving.problem, moving.options);
            }).rfind("PlanProblem.moving_base.grasp.released releases all six components", 0),
            0u);
}

}  // namespace
}  // namespace test_plan_reach
}  // namespace rodshape
