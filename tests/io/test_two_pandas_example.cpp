// test_two_pandas_example.cpp: the bundled two-arm examples (issue 21), planned from their task
// files: complete; every step re-integrated from its base pose and base wrench puts the tip, and
// through the grasp the end effector, where the plan says to 1e-9 m; both arms' forward kinematics
// at the last joint samples put the two grippers on their last waypoints to 1e-6 m; the fixture of
// plan_base_arm.yaml holds the tip within its box while only the base moves.
#include <gtest/gtest.h>

#include <string>

#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/core/so3.hpp"
#include "rodshape/io/task_reader.hpp"
#include "rodshape/robot/arm_placement.hpp"

namespace rodshape {
namespace test_two_pandas_example {
namespace {

PlanTask example(const std::string& name) {
  return read_plan_task(std::string(RODSHAPE_SOURCE_DIR) + "/examples/" + name);
}

/// Each step's tip from its own base pose and base wrench, and its end effectors.
void expect_steps_reintegrate(const PlanTask& task, const PlanResult& plan) {
  const PlanProblem& problem = task.problem;
  for (std::size_t k = 0; k < plan.steps.size(); ++k) {
    const PlanStep& step = plan.steps[k];
    const RodConfiguration& c = step.solution.configuration;
    ClampedRod rod = problem.rod;
    rod.clamp = {c.p[0], c.R[0]};
    const RodConfiguration again = integrate(rod, step.solution.base_wrench);
    EXPECT_LT((again.p.back() - c.p.back()).norm(), 1e-9) << "step " << k;
    const Pose ee = compose(again.tip(), problem.grasp.tip_to_end_effector);
    EXPECT_LT((ee.position - step.end_effector.position).norm(), 1e-9) << "step " << k;
    EXPECT_LT(log_so3(ee.rotation.transpose() * step.end_effector.rotation).norm(), 1e-9);
    const Pose base_ee = compose(rod.clamp, problem.moving_base->grasp.tip_to_end_effector);
    EXPECT_LT((base_ee.position - step.base_end_effector.position).norm(), 1e-12);
  }
}

/// The arm's forward kinematics at its last joint sample on the gripper's last waypoint.
void expect_last_sample_on(const PlanArm& arm, const ArmPlanResult& result, const Pose& gripper) {
  ASSERT_TRUE(result.reachable()) << result.brief();
  ASSERT_FALSE(result.joints.q.empty());
  const Pose fk = end_effector_pose(arm.model, arm.placement, result.joints.q.back());
  EXPECT_LT((fk.position - gripper.position).norm(), 1e-6);
  EXPECT_LT(log_so3(fk.rotation.transpose() * gripper.rotation).norm(), 1e-6);
}

TEST(TwoPandasExample, BothEndsMoveAndBothArmsEndOnTheirGrippers) {
  const PlanTask task = example("plan_two_pandas.yaml");
  const PlanResult plan = rodshape::plan(task.problem, task.options);
  ASSERT_EQ(plan.status, PlanStatus::Complete) << plan.message;
  EXPECT_LT(plan.steps.back().solution.cost.max_distance, 1e-3);
  expect_steps_reintegrate(task, plan);
  ASSERT_TRUE(plan.arm && plan.base_arm);
  expect_last_sample_on(*task.problem.arm, *plan.arm, plan.steps.back().end_effector);
  expect_last_sample_on(*task.problem.base_arm, *plan.base_arm,
                        plan.steps.back().base_end_effector);
  EXPECT_EQ(plan.arm->joints.t, plan.base_arm->joints.t);  // one clock
  const double base_moved =
      (plan.steps.back().solution.configuration.p[0] - task.problem.rod.clamp.position).norm();
  EXPECT_GT(base_moved, 0.02);
}

TEST(BaseArmExample, OnlyTheBaseMovesTheTipStaysInItsFixture) {
  const PlanTask task = example("plan_base_arm.yaml");
  const PlanResult plan = rodshape::plan(task.problem, task.options);
  ASSERT_EQ(plan.status, PlanStatus::Complete) << plan.message;
  expect_steps_reintegrate(task, plan);
  ASSERT_TRUE(plan.base_arm && !plan.arm);
  expect_last_sample_on(*task.problem.base_arm, *plan.base_arm,
                        plan.steps.back().base_end_effector);
  const double tolerance = task.options.optimiser.constraint_tolerance;
  for (const PlanStep& step : plan.steps)
    EXPECT_TRUE(task.problem.workspace.contains(step.solution.configuration.tip(), tolerance));
}

}  // namespace
}  // namespace test_two_pandas_example
}  // namespace rodshape
