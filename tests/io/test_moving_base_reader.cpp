// test_moving_base_reader.cpp: the task file's keys of a moving base (issue 21): base.moving,
// base.motion_weight, base_grasp, base_workspace, trajectory.base_end_effector and base_robot,
// read into PlanProblem::moving_base, base_arm, PlanOptions::base_end_effector and
// PlanOptions::arm (base_seed; the options the two arms share); their defaults; and each bad value
// named with its file and line.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "rodshape/io/field_names.hpp"
#include "rodshape/io/task_reader.hpp"
#include "rodshape/trajectory/plan.hpp"
#include "support/input_error.hpp"
#include "support/task_text.hpp"

namespace rodshape {
namespace test_moving_base_reader {
namespace {

// Line numbers below refer to this text (the base section is lines 6-8).
const std::string kPlan = R"(rod:
  length: 0.29
  nodes: 21
  stiffness: {EA: 1280, GA: 427, EIx: 0.04, EIy: 0.04, GJ: 0.028}
base:
  position: [0, 0, 0]
  moving: true
target:
  points: [[0.01, 0, 0.1], [0.05, 0, 0.2], [0.1, 0, 0.25]]
trajectory:
  steps: 3
)";

const std::string kPanda = std::string(RODSHAPE_SOURCE_DIR) + "/data/robots/panda.urdf";

std::string plan_with(const std::string& from, const std::string& to) {
  return testing::replaced_first(kPlan, from, to);
}

std::string error_of(const std::string& text) {
  const std::string message =
      testing::input_error_message([&] { parse_plan_task(text, "plan.yaml"); });
  EXPECT_EQ(message.find('\n'), std::string::npos) << "not one line: " << message;
  return message;
}

/// `message` begins with `prefix` (file, line, field).
::testing::AssertionResult starts_with(const std::string& message, const std::string& prefix) {
  if (message.rfind(prefix, 0) == 0) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "'" << message << "' does not begin with '" << prefix << "'";
}

// ---- defaults -----------------------------------------------------------------------------------

TEST(MovingBaseReader, FixedClampByDefault) {
  const PlanTask task = parse_plan_task(plan_with("  moving: true\n", ""), "plan.yaml");
  EXPECT_FALSE(task.problem.moving_base.has_value());
  EXPECT_FALSE(task.problem.base_arm.has_value());
  EXPECT_FALSE(task.problem.base_moves());
  const PlanTask explicit_false =
      parse_plan_task(plan_with("moving: true", "moving: false"), "plan.yaml");
  EXPECT_FALSE(explicit_false.problem.moving_base.has_value());
}

TEST(MovingBaseReader, MovingBaseDefaults) {
  const PlanTask task = parse_plan_task(kPlan, "plan.yaml");
  ASSERT_TRUE(task.problem.moving_base.has_value());
  const MovingBase& base = *task.problem.moving_base;
  EXPECT_EQ(base.motion_weight, MovingBase{}.motion_weight);
  for (const bool released : base.grasp.released) EXPECT_FALSE(released);
  EXPECT_TRUE(base.grasp.tip_to_end_effector.position.isZero(0.0));
  EXPECT_TRUE(base.grasp.tip_to_end_effector.rotation.isIdentity(0.0));
  for (int k = 0; k < 6; ++k) {
    EXPECT_TRUE(std::isinf(base.wrench_bounds.lower(k)) && base.wrench_bounds.lower(k) < 0);
    EXPECT_TRUE(std::isinf(base.wrench_bounds.upper(k)) && base.wrench_bounds.upper(k) > 0);
  }
  EXPECT_FALSE(base.workspace.box.has_value());
  EXPECT_TRUE(base.workspace.inside.empty());
  EXPECT_FALSE(task.problem.base_arm.has_value());
  // The base gripper's limits are the tip's.
  EXPECT_EQ(task.options.base_end_effector.max_linear_speed,
            task.options.end_effector.max_linear_speed);
  EXPECT_EQ(task.options.base_end_effector.sample_rate, task.options.end_effector.sample_rate);
}

TEST(MovingBaseReader, EveryKeyIsRead) {
  const std::string text = plan_with("  moving: true\n",
                                     "  rotation: [1, 0, 0, 0]\n"
                                     "  moving: true\n"
                                     "  motion_weight: 0.02\n") +
                           "  max_linear_speed: 0.2\n"
                           "  base_end_effector:\n"
                           "    max_linear_speed: 0.05\n"
                           "    max_angular_speed: 0.4\n"
                           "    max_linear_acceleration: 0.3\n"
                           "    max_angular_acceleration: 2.5\n"
                           "base_grasp:\n"
                           "  zero_wrench: [mx, fz]\n"
                           "  base_to_end_effector: {position: [0, 0, -0.03]}\n"
                           "  wrench_bounds:\n"
                           "    lower: {force: [-5, -6, -7]}\n"
                           "    upper: {moment: [1, 2, 3]}\n"
                           "base_workspace:\n"
                           "  box: {lower: [-1, -1, -0.5], upper: [1, 1, 1]}\n"
                           "  inside:\n"
                           "    - {center: [0, 0, 0], radius: 0.8}\n";
  const PlanTask task = parse_plan_task(text, "plan.yaml");
  ASSERT_TRUE(task.problem.moving_base.has_value());
  const MovingBase& base = *task.problem.moving_base;
  EXPECT_EQ(base.motion_weight, 0.02);
  const std::array<bool, 6> released{false, false, true, true, false, false};
  EXPECT_EQ(base.grasp.released, released);
  EXPECT_TRUE(base.grasp.tip_to_end_effector.position.isApprox(Eigen::Vector3d(0, 0, -0.03)));
  EXPECT_EQ(base.wrench_bounds.lower.head<3>(), Eigen::Vector3d(-5, -6, -7));
  EXPECT_TRUE(std::isinf(base.wrench_bounds.lower(3)));
  EXPECT_EQ(base.wrench_bounds.upper.tail<3>(), Eigen::Vector3d(1, 2, 3));
  EXPECT_TRUE(std::isinf(base.wrench_bounds.upper(0)));
  ASSERT_TRUE(base.workspace.box.has_value());
  EXPECT_EQ(base.workspace.box->lower, Eigen::Vector3d(-1, -1, -0.5));
  ASSERT_EQ(base.workspace.inside.size(), 1u);
  EXPECT_EQ(base.workspace.inside[0].radius, 0.8);
  const EndEffectorLimits& limits = task.options.base_end_effector;
  EXPECT_EQ(limits.max_linear_speed, 0.05);
  EXPECT_EQ(limits.max_angular_speed, 0.4);
  EXPECT_EQ(limits.max_linear_acceleration, 0.3);
  EXPECT_EQ(limits.max_angular_acceleration, 2.5);
  EXPECT_EQ(limits.sample_rate, task.options.end_effector.sample_rate);
  EXPECT_EQ(task.options.end_effector.max_linear_speed, 0.2);  // the tip's stay its own
  // The tip's grasp and wrench bounds are untouched.
  for (const bool released_axis : task.problem.grasp.released) EXPECT_FALSE(released_axis);
}

TEST(MovingBaseReader, BaseLimitsLeftOutAreTheTips) {
  const PlanTask task = parse_plan_task(kPlan +
                                            "  max_linear_speed: 0.07\n"
                                            "  max_angular_speed: 0.3\n"
                                            "  base_end_effector: {max_angular_speed: 0.6}\n",
                                        "plan.yaml");
  EXPECT_EQ(task.options.base_end_effector.max_linear_speed, 0.07);
  EXPECT_EQ(task.options.base_end_effector.max_angular_speed, 0.6);
  EXPECT_EQ(task.options.end_effector.max_angular_speed, 0.3);
}

TEST(MovingBaseReader, BaseRobotImpliesMovingAndMayNameTheSameUrdf) {
  const std::string text = plan_with("  moving: true\n", "") + "robot:\n  urdf: " + kPanda +
                           "\n  base: {position: [0.4, 0, 0]}\n"
                           "base_robot:\n  urdf: " +
                           kPanda +
                           "\n  base_link: panda_link0\n  tip_link: panda_link8\n"
                           "  base: {position: [-0.4, 0, 0], rotation: [0, 0, 0, 1]}\n"
                           "  flange_to_end_effector: {position: [0, 0, 0.1]}\n"
                           "  seed: [0, -0.5, 0, -2, 0, 1.5, 0.8]\n"
                           "  reach: {use: false, margin: 0.05, max_replans: 2}\n"
                           "  links: {clearance: false, influence: 0.05}\n";
  const PlanTask task = parse_plan_task(text, "plan.yaml");
  ASSERT_TRUE(task.problem.moving_base.has_value());
  ASSERT_TRUE(task.problem.base_arm.has_value());
  ASSERT_TRUE(task.problem.arm.has_value());
  EXPECT_EQ(task.problem.base_arm->model.tip_link(), "panda_link8");
  EXPECT_TRUE(
      task.problem.base_arm->placement.world_T_base.position.isApprox(Eigen::Vector3d(-0.4, 0, 0)));
  EXPECT_TRUE(
      task.problem.base_arm->placement.flange_T_ee.position.isApprox(Eigen::Vector3d(0, 0, 0.1)));
  EXPECT_TRUE(
      task.problem.arm->placement.world_T_base.position.isApprox(Eigen::Vector3d(0.4, 0, 0)));
  const ArmPlanOptions& options = task.options.arm;
  ASSERT_EQ(options.base_seed.size(), 7);
  EXPECT_EQ(options.base_seed(3), -2.0);
  EXPECT_EQ(options.joints.seed.size(), 0);  // the tip arm's seed: its default
  // Given in base_robot (robot has none), the options the two arms share.
  EXPECT_FALSE(options.use_reach);
  EXPECT_EQ(options.reach_margin, 0.05);
  EXPECT_EQ(options.max_replans, 2);
  EXPECT_FALSE(options.link_clearance);
  EXPECT_EQ(options.link_influence, 0.05);
  // Both URDFs are inputs of the run.
  EXPECT_EQ(std::count(task.input_files.begin(), task.input_files.end(), kPanda), 2);
}

TEST(MovingBaseReader, TheArmsSharedOptionsAreGivenOnce) {
  const std::string both = kPlan + "robot:\n  urdf: " + kPanda +
                           "\n  seed: [0, -0.7, 0, -2.3, 0, 1.6, 0.7]\n  reach: {margin: 0.03}\n"
                           "base_robot:\n  urdf: " +
                           kPanda + "\n  reach: {margin: 0.04}\n";
  EXPECT_TRUE(starts_with(error_of(both), "plan.yaml:18: base_robot.reach: the two arms share"));
  EXPECT_NE(error_of(both).find("robot.reach"), std::string::npos);
  const std::string links = kPlan + "robot:\n  urdf: " + kPanda +
                            "\n  links: {influence: 0.04}\nbase_robot:\n  urdf: " + kPanda +
                            "\n  links: {influence: 0.05}\n";
  EXPECT_TRUE(starts_with(error_of(links), "plan.yaml:17: base_robot.links: the two arms share"));
  // Each arm keeps its own seed.
  const PlanTask task = parse_plan_task(testing::replaced_first(both, "\n  reach: {margin: 0.04}",
                                                                "\n  seed: [0, 0, 0, -2, 0, 2, 0]"),
                                        "plan.yaml");
  EXPECT_EQ(task.options.arm.joints.seed(1), -0.7);
  EXPECT_EQ(task.options.arm.base_seed(5), 2.0);
  EXPECT_EQ(task.options.arm.reach_margin, 0.03);
}

TEST(MovingBaseReader, MovingAloneKeepsTheDefaultPose) {
  const PlanTask task = parse_plan_task(plan_with("  position: [0, 0, 0]\n", ""), "plan.yaml");
  EXPECT_TRUE(task.problem.moving_base.has_value());
  EXPECT_TRUE(task.problem.rod.clamp.position.isZero(0.0));
  EXPECT_TRUE(task.problem.rod.clamp.rotation.isIdentity(0.0));
  // A rotation still needs its position.
  EXPECT_TRUE(
      starts_with(error_of(plan_with("  position: [0, 0, 0]\n", "  rotation: [1, 0, 0, 0]\n")),
                  "plan.yaml:5: base.position is required"));
}

TEST(MovingBaseReader, BaseRobotWithoutBaseSection) {
  const std::string text = R"(rod:
  length: 0.29
  nodes: 21
  stiffness: {EA: 1280, GA: 427, EIx: 0.04, EIy: 0.04, GJ: 0.028}
target:
  points: [[0.01, 0, 0.1], [0.05, 0, 0.2], [0.1, 0, 0.25]]
base_robot:
  urdf: )" + kPanda + "\n";
  const PlanTask task = parse_plan_task(text, "plan.yaml");
  EXPECT_TRUE(task.problem.moving_base.has_value());
  EXPECT_TRUE(task.problem.base_arm.has_value());
}

// ---- bad input ----------------------------------------------------------------------------------

TEST(MovingBaseReader, BadMovingIsNamed) {
  EXPECT_TRUE(starts_with(error_of(plan_with("moving: true", "moving: maybe")),
                          "plan.yaml:7: base.moving"));
  EXPECT_NE(error_of(plan_with("moving: true", "movng: true")).find("did you mean 'moving'"),
            std::string::npos);
  EXPECT_NE(error_of(plan_with("moving: true", "moving: true\n  motion_wieght: 1"))
                .find("did you mean 'motion_weight'"),
            std::string::npos);
}

TEST(MovingBaseReader, NegativeMotionWeightIsNamed) {
  const std::string message =
      error_of(plan_with("moving: true", "moving: true\n  motion_weight: -1"));
  EXPECT_TRUE(starts_with(message, "plan.yaml:8: base.motion_weight = -1 must be >= 0"));
  EXPECT_TRUE(starts_with(error_of(plan_with("moving: true", "moving: true\n  motion_weight: x")),
                          "plan.yaml:8: base.motion_weight"));
}

TEST(MovingBaseReader, BaseKeysNeedAMovingBase) {
  const std::string fixed = plan_with("  moving: true\n", "");
  EXPECT_TRUE(starts_with(error_of(fixed + "base_grasp:\n  zero_wrench: [mz]\n"),
                          "plan.yaml:11: base_grasp needs a moving base: set base.moving: true"));
  EXPECT_TRUE(starts_with(error_of(fixed + "base_workspace:\n  box: {lower: [0, 0, 0], upper: "
                                           "[1, 1, 1]}\n"),
                          "plan.yaml:11: base_workspace needs a moving base"));
  EXPECT_TRUE(starts_with(error_of(fixed + "  base_end_effector: {max_linear_speed: 0.1}\n"),
                          "plan.yaml:11: trajectory.base_end_effector needs a moving base"));
  EXPECT_TRUE(starts_with(error_of(plan_with("  moving: true\n", "  motion_weight: 1\n")),
                          "plan.yaml:7: base.motion_weight needs a moving base"));
  EXPECT_TRUE(starts_with(error_of(plan_with("moving: true", "moving: false") +
                                   "base_robot:\n  urdf: " + kPanda + "\n"),
                          "plan.yaml:7: base.moving = false, but base_robot holds the base end"));
}

TEST(MovingBaseReader, BadBaseGraspIsNamed) {
  EXPECT_TRUE(starts_with(error_of(kPlan + "base_grasp:\n  zero_wrench: [fq]\n"),
                          "plan.yaml:13: base_grasp.zero_wrench[0]"));
  EXPECT_TRUE(starts_with(error_of(kPlan + "base_grasp:\n  zero_wrench: [mz, mz]\n"),
                          "plan.yaml:13: base_grasp.zero_wrench[1]"));
  const std::string offset = error_of(kPlan + "base_grasp:\n  tip_to_end_effector: {}\n");
  EXPECT_TRUE(starts_with(offset, "plan.yaml:13: base_grasp.tip_to_end_effector"));
  EXPECT_NE(offset.find("base_grasp.base_to_end_effector"), std::string::npos) << offset;
  EXPECT_TRUE(
      starts_with(error_of(kPlan + "base_grasp:\n  base_to_end_effector: {rotation: [1, 0, 0]}\n"),
                  "plan.yaml:13: base_grasp.base_to_end_effector"));
  EXPECT_NE(error_of(kPlan + "base_grasp:\n  base_to_end_efector: {position: [0, 0, 0]}\n")
                .find("did you mean 'base_to_end_effector'"),
            std::string::npos);
  EXPECT_TRUE(starts_with(
      error_of(kPlan + "base_grasp:\n  wrench_bounds:\n    lower: {force: [1, 0, 0]}\n"
                       "    upper: {force: [0, 0, 0]}\n"),
      "plan.yaml:13: base_grasp.wrench_bounds: lower.force[0] is above upper.force[0]"));
  EXPECT_TRUE(starts_with(
      error_of(kPlan + "base_grasp:\n  wrench_bounds:\n    lower: {force: [1, .nan, 0]}\n"),
      "plan.yaml:14: base_grasp.wrench_bounds.lower.force"));
}

TEST(MovingBaseReader, BadBaseWorkspaceIsNamed) {
  EXPECT_TRUE(starts_with(
      error_of(kPlan + "base_workspace:\n  box: {lower: [0, 0, 2], upper: [1, 1, 1]}\n"),
      "plan.yaml:13: base_workspace.box"));
  EXPECT_TRUE(starts_with(error_of(kPlan + "base_workspace:\n  inside:\n    - {center: [0, 0, 0], "
                                           "radius: -1}\n"),
                          "plan.yaml:14: base_workspace.inside[0].radius"));
  EXPECT_NE(error_of(kPlan + "base_workspace:\n  bx: {}\n").find("did you mean 'box'"),
            std::string::npos);
}

TEST(MovingBaseReader, BadBaseLimitsAreNamed) {
  EXPECT_TRUE(starts_with(error_of(kPlan + "  base_end_effector: {max_linear_speed: -1}\n"),
                          "plan.yaml:12: trajectory.base_end_effector.max_linear_speed"));
  EXPECT_TRUE(starts_with(error_of(kPlan + "  base_end_effector: {max_angular_speed: 0}\n"),
                          "plan.yaml:12: trajectory.base_end_effector.max_angular_speed"));
  const std::string rate = error_of(kPlan + "  base_end_effector: {rate: 100}\n");
  EXPECT_TRUE(starts_with(rate, "plan.yaml:12: trajectory.base_end_effector.rate"));
  EXPECT_NE(rate.find("trajectory.rate"), std::string::npos) << rate;
  // A bad tip limit is the tip's, not the base's copy of it.
  EXPECT_TRUE(starts_with(error_of(kPlan + "  max_linear_speed: -1\n"
                                           "  base_end_effector: {max_angular_speed: 0.5}\n"),
                          "plan.yaml:12: trajectory.max_linear_speed"));
}

TEST(MovingBaseReader, BadBaseRobotIsNamed) {
  const std::string robot = kPlan + "base_robot:\n  urdf: " + kPanda + "\n";
  EXPECT_TRUE(starts_with(error_of(robot + "  tip_link: panda_hand\n"),
                          "plan.yaml:14: base_robot.tip_link: "));
  EXPECT_TRUE(starts_with(error_of(robot + "  base_link: nowhere\n"),
                          "plan.yaml:14: base_robot.base_link: "));
  EXPECT_TRUE(
      starts_with(error_of(robot + "  seed: [0, 0, 0]\n"), "plan.yaml:14: base_robot.seed"));
  EXPECT_TRUE(starts_with(error_of(robot + "  reach: {margin: -0.1}\n"),
                          "plan.yaml:14: base_robot.reach.margin = -0.1 must be >= 0"));
  EXPECT_NE(error_of(robot + "  bse: {position: [0, 0, 0]}\n").find("base_robot.bse"),
            std::string::npos);
  EXPECT_NE(error_of(robot + "  flange_T_ee: {position: [0, 0, 0]}\n")
                .find("base_robot.flange_to_end_effector"),
            std::string::npos);
  EXPECT_TRUE(starts_with(error_of(kPlan + "base_robot:\n  urdf: /nowhere/arm.urdf\n"),
                          "plan.yaml:13: base_robot.urdf: /nowhere/arm.urdf: cannot read"));
  EXPECT_TRUE(starts_with(error_of(kPlan + "base_robot:\n  base_link: x\n"),
                          "plan.yaml:12: base_robot.urdf is required"));
}

TEST(MovingBaseReader, MisplacedKeysGetHints) {
  EXPECT_NE(error_of(kPlan + "base_arm: {}\n").find("base_robot"), std::string::npos);
  EXPECT_NE(error_of(kPlan + "base_wrench_bounds: {}\n").find("base_grasp.wrench_bounds"),
            std::string::npos);
  EXPECT_NE(error_of(kPlan + "grasp:\n  base_to_end_effector: {position: [0, 0, 0]}\n")
                .find("base_grasp.base_to_end_effector"),
            std::string::npos);
  EXPECT_NE(error_of(kPlan + "base_grsp: {}\n").find("did you mean 'base_grasp'"),
            std::string::npos);
}

TEST(MovingBaseReader, EquilibriumTasksHaveAFixedClamp) {
  const std::string equilibrium = R"(rod:
  length: 0.29
  stiffness: {EA: 1280, GA: 427, EIx: 0.04, EIy: 0.04, GJ: 0.028}
base:
  position: [0, 0, 0]
  moving: true
tip:
  wrench: {force: [0, 0, 0]}
)";
  const std::string message =
      testing::input_error_message([&] { parse_equilibrium_task(equilibrium, "eq.yaml"); });
  EXPECT_TRUE(starts_with(message, "eq.yaml:6: base.moving"));
  EXPECT_NE(message.find("plan tasks"), std::string::npos) << message;
  const std::string robot = testing::input_error_message([&] {
    parse_equilibrium_task(
        testing::replaced_first(equilibrium, "  moving: true\n", "") + "base_robot: {}\n",
        "eq.yaml");
  });
  EXPECT_NE(robot.find("base_robot is a section of plan tasks"), std::string::npos) << robot;
}

TEST(MovingBaseReader, LibraryFieldsInTaskNames) {
  EXPECT_EQ(task_field_name("PlanProblem.moving_base.motion_weight"), "base.motion_weight");
  EXPECT_EQ(task_field_name("PlanProblem.moving_base.grasp.tip_to_end_effector"),
            "base_grasp.base_to_end_effector");
  EXPECT_EQ(task_field_name("PlanProblem.moving_base.grasp.released[2]"),
            "base_grasp.zero_wrench[2]");
  EXPECT_EQ(task_field_name("PlanProblem.moving_base.wrench_bounds"), "base_grasp.wrench_bounds");
  EXPECT_EQ(task_field_name("PlanProblem.moving_base.workspace.box"), "base_workspace.box");
  EXPECT_EQ(task_field_name("PlanProblem.base_arm"), "base_robot");
  EXPECT_EQ(task_field_name("PlanOptions.base_end_effector.max_linear_speed"),
            "trajectory.base_end_effector.max_linear_speed");
  // The tip's stay as they were.
  EXPECT_EQ(task_field_name("Grasp.tip_to_end_effector"), "grasp.tip_to_end_effector");
  EXPECT_EQ(task_field_name("PlanArm"), "robot");
}

// Issue 43, 4c: library names that reached task-file errors unmapped (PlanProblem.rod.clamp, the
// base arm's seed, the interpolation with a moving base, the arms' placements of item 7).
TEST(MovingBaseReader, EveryLibraryFieldATaskErrorNamesHasItsTaskField) {
  EXPECT_EQ(task_field_name("PlanProblem.rod.clamp"), "base");
  EXPECT_EQ(task_field_name("PlanProblem.rod.clamp.position"), "base.position");
  EXPECT_EQ(task_field_name("ArmPlanOptions.base_seed"), "base_robot.seed");
  EXPECT_EQ(fields_in_task_names("ArmPlanOptions.base_seed[3] = 0 must be in [-3.07, -0.07]"),
            "base_robot.seed[3] = 0 must be in [-3.07, -0.07]");
  EXPECT_EQ(task_field_name("PlanOptions.interpolation"), "trajectory.interpolation");
  EXPECT_EQ(task_field_name("PlanArm.placement.world_T_base"), "robot.base");
  EXPECT_EQ(task_field_name("PlanArm.placement.flange_T_ee"), "robot.flange_to_end_effector");
  EXPECT_EQ(task_field_name("PlanProblem.base_arm.placement.world_T_base"), "base_robot.base");
  EXPECT_EQ(task_field_name("PlanProblem.base_arm.placement.flange_T_ee"),
            "base_robot.flange_to_end_effector");
  EXPECT_EQ(task_field_name("BaseMotion.motion_weight"), "base.motion_weight");
  EXPECT_EQ(task_field_name("Scene.obstacles[2]"), "scene.obstacles[2]");
  EXPECT_EQ(task_field_name("PlantModel.factors.EIx"), "plant.stiffness_factors.EIx");
  EXPECT_EQ(task_field_name("EstimateTask.tip"), "tip");
}

TEST(MovingBaseReader, LibraryErrorsAreLocatedInTheTask) {
  const PlanTask task =
      parse_plan_task(plan_with("moving: true", "moving: true\n  motion_weight: 0.5") +
                          "base_robot:\n  urdf: " + kPanda + "\n",
                      "plan.yaml");
  EXPECT_TRUE(
      starts_with(task.locate(InputError("PlanProblem.moving_base.motion_weight", " is too large")),
                  "plan.yaml:8: base.motion_weight is too large"));
  EXPECT_TRUE(starts_with(task.locate(InputError("PlanProblem.base_arm", ": cannot reach")),
                          "plan.yaml:13: base_robot: cannot reach"));
}

}  // namespace
}  // namespace test_moving_base_reader
}  // namespace rodshape
