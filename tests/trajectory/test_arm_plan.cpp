// test_arm_plan.cpp: planning with the arm (the Panda example's scene). Every planned pose's IK
// solution puts the end effector on the planned pose; the wrist stays in the reach shell; an arm
// placed so that the target needs the wrist beyond its reach gets a plan that stops on the shell;
// a pose on the shell that IK cannot reach leads to one re-plan with the shell tightened exactly as
// documented, or, with no re-plans allowed, to the status Unreachable; a start outside the shell
// and a doubled reach shell are bad input.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <string>

#include "rodshape/io/task_reader.hpp"
#include "rodshape/robot/arm_placement.hpp"
#include "rodshape/robot/inverse_kinematics.hpp"
#include "rodshape/trajectory/plan.hpp"
#include "support/eigen_compare.hpp"
#include "support/input_error.hpp"

namespace test_arm_plan {
namespace {

using rodshape::ArmPlanOptions;
using rodshape::ArmPlanResult;
using rodshape::ArmPlanStatus;
using rodshape::PlanResult;
using rodshape::PlanTask;
using rodshape::Pose;
using rodshape::testing::input_error_message;
using rodshape::testing::rotation_angle;

const std::string kExample = std::string(RODSHAPE_SOURCE_DIR) + "/examples/plan_panda_s_curve.yaml";

/// The example's task with the arm's base moved to x = `base_x` (the example has -0.45).
PlanTask panda_task(double base_x = -0.45) {
  PlanTask task = rodshape::read_plan_task(kExample);
  task.problem.arm->placement.world_T_base.position.x() = base_x;
  return task;
}

/// Plans `task` with the arm options `options`.
PlanResult plan(PlanTask task, const ArmPlanOptions& options) {
  task.options.arm = options;
  return rodshape::plan(task.problem, task.options);
}

double wrist_distance(const ArmPlanResult& arm, const Pose& tip) {
  return (arm.shell->point(tip) - arm.shell->center).norm();
}

TEST(ArmPlan, EveryPlannedPoseHasJointsThatPutTheHandThere) {
  const PlanTask task = panda_task();
  const PlanResult arm_plan = plan(task, task.options.arm);
  ASSERT_TRUE(arm_plan.arm.has_value());
  const ArmPlanResult& arm = *arm_plan.arm;
  ASSERT_EQ(arm.status, ArmPlanStatus::Reachable) << arm.message;
  ASSERT_EQ(arm_plan.status, rodshape::PlanStatus::Complete) << arm_plan.message;
  EXPECT_TRUE(arm.replans.empty());
  ASSERT_TRUE(arm.shell.has_value());
  EXPECT_DOUBLE_EQ(arm.shell->outer_radius, arm.reach->max_distance - 0.02);  // default margin
  ASSERT_EQ(arm.waypoint_q.size(), arm_plan.steps.size() + 1);
  // IK converges to 1e-10 m and rad (IkOptions); the pose chain adds round-off only.
  for (std::size_t k = 1; k < arm.waypoint_q.size(); ++k) {
    const Pose reached = rodshape::end_effector_pose(
        task.problem.arm->model, task.problem.arm->placement, arm.waypoint_q[k]);
    const Pose& planned = arm_plan.steps[k - 1].end_effector;
    EXPECT_LE((reached.position - planned.position).norm(), 1e-9) << "step " << k;
    EXPECT_LE(rotation_angle(reached.rotation, planned.rotation), 1e-9) << "step " << k;
    const Pose tip = arm_plan.steps[k - 1].solution.configuration.tip();
    EXPECT_LE(wrist_distance(arm, tip), arm.shell->outer_radius) << "step " << k;
    EXPECT_GE(wrist_distance(arm, tip), arm.shell->inner_radius) << "step " << k;
  }
  EXPECT_TRUE(arm.joints.complete()) << arm.joints.message;
  EXPECT_EQ(arm.joints.t.size(), arm_plan.end_effector_path.size());
}

TEST(ArmPlan, ATargetBeyondTheArmsReachStopsOnTheShell) {
  // 0.13 m further back, the S-curve's last shape would need the wrist 0.81 m from the shoulder,
  // beyond the shell's 0.787 m: the last step's constraint is active and the points are missed by
  // more than the unconstrained plan's sub-millimetre distances: 5.2 mm, beyond the default reach
  // tolerance (1 % of L, 2.9 mm: the plan is partial), within 6 mm (complete).
  PlanTask task = panda_task(-0.58);
  EXPECT_EQ(plan(task, task.options.arm).status, rodshape::PlanStatus::Partial);
  task.options.reach_tolerance = 0.006;
  const PlanResult arm_plan = plan(task, task.options.arm);
  ASSERT_TRUE(arm_plan.arm.has_value());
  const ArmPlanResult& arm = *arm_plan.arm;
  ASSERT_EQ(arm.status, ArmPlanStatus::Reachable) << arm.message;
  ASSERT_EQ(arm_plan.status, rodshape::PlanStatus::Complete) << arm_plan.message;
  EXPECT_GT(arm_plan.target_distance, 0.0029);
  const rodshape::ShapeResult& last = arm_plan.steps.back().solution;
  const double tolerance = task.options.optimiser.constraint_tolerance;
  const double r = wrist_distance(arm, last.configuration.tip());
  // g = r² ≤ r_out² holds to the constraint tolerance and is active (to IPOPT's tolerance).
  EXPECT_LE(r * r, arm.shell->outer_radius * arm.shell->outer_radius + tolerance);
  EXPECT_GE(r, arm.shell->outer_radius - 1e-4);
  EXPECT_GT(last.cost.max_distance, 1e-3);
  EXPECT_TRUE(arm.joints.complete()) << arm.joints.message;
}

TEST(ArmPlan, APoseOnTheShellThatIkCannotReachIsReplannedWithATighterShell) {
  // With no margin the shell's outer radius is the sampled maximum itself, where the wrist's
  // position is reachable only with the orientation it was found with: the last step (on the
  // shell, as above) has no IK solution; one re-plan with the shell pulled in by the tightening
  // below that pose's wrist distance succeeds.
  const PlanTask task = panda_task(-0.58);
  ArmPlanOptions options = task.options.arm;
  options.reach_margin = 0.0;
  const PlanResult arm_plan = plan(task, options);
  ASSERT_TRUE(arm_plan.arm.has_value());
  const ArmPlanResult& arm = *arm_plan.arm;
  ASSERT_EQ(arm.status, ArmPlanStatus::Reachable) << arm.message;
  ASSERT_EQ(arm.replans.size(), 1u);
  const rodshape::Replan& replan = arm.replans.front();
  EXPECT_NE(replan.reason.find("has no inverse kinematics solution"), std::string::npos)
      << replan.reason;
  EXPECT_DOUBLE_EQ(
      replan.shell.outer_radius,
      std::min(arm.reach->max_distance, replan.wrist_distance) - options.replan_tightening);
  EXPECT_DOUBLE_EQ(replan.shell.inner_radius, arm.reach->min_distance);
  EXPECT_DOUBLE_EQ(arm.shell->outer_radius, replan.shell.outer_radius);
  EXPECT_NE(arm.message.find("after 1 re-plan"), std::string::npos) << arm.message;

  options.max_replans = 0;
  const PlanResult reported_plan = plan(task, options);
  ASSERT_TRUE(reported_plan.arm.has_value());
  const ArmPlanResult& reported = *reported_plan.arm;
  EXPECT_EQ(reported.status, ArmPlanStatus::Unreachable);
  EXPECT_TRUE(reported.replans.empty());
  EXPECT_NE(reported.message.find("after 0 re-plans"), std::string::npos) << reported.message;
  EXPECT_NE(reported.joints.message.find("not computed"), std::string::npos)
      << reported.joints.message;
}

TEST(ArmPlan, AStartOutsideTheShellAndTwoReachShellsAreBadInput) {
  const PlanTask far = panda_task(-3.0);
  const std::string start = input_error_message([&] { plan(far, far.options.arm); });
  EXPECT_NE(start.find("the arm's wrist would be"), std::string::npos) << start;
  EXPECT_NE(start.find("outside its reach shell"), std::string::npos) << start;

  PlanTask twice = panda_task();
  twice.problem.workspace.reach =
      rodshape::Workspace::ReachShell{Eigen::Vector3d::Zero(), 0.0, 1.0, Eigen::Vector3d::Zero()};
  const std::string doubled = input_error_message([&] { plan(twice, twice.options.arm); });
  EXPECT_NE(doubled.find("workspace.reach"), std::string::npos) << doubled;

  ArmPlanOptions options = far.options.arm;
  options.replan_tightening = 0.0;
  const std::string tightening = input_error_message([&] { plan(far, options); });
  EXPECT_NE(tightening.find("ArmPlanOptions.replan_tightening"), std::string::npos) << tightening;
}

TEST(ArmPlan, WithoutTheReachAnUnreachableStartIsReportedNotThrown) {
  PlanTask far = panda_task(-3.0);
  ArmPlanOptions options = far.options.arm;
  options.use_reach = false;
  const PlanResult arm_plan = plan(far, options);
  ASSERT_TRUE(arm_plan.arm.has_value());
  const ArmPlanResult& arm = *arm_plan.arm;
  EXPECT_EQ(arm.status, ArmPlanStatus::Unreachable);
  EXPECT_FALSE(arm.shell.has_value());
  EXPECT_NE(arm.message.find("the initial end-effector pose has no inverse kinematics solution"),
            std::string::npos)
      << arm.message;
  EXPECT_EQ(arm_plan.status, rodshape::PlanStatus::Complete);
}

}  // namespace
}  // namespace test_arm_plan
