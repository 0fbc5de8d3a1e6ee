// test_moving_base_output.cpp: what `rodshape plan` writes for a moving base (issue 21), on a plan
// made by hand: steps[i].base_end_effector always; trajectory.csv's base columns, plan.json's
// base_robot and base_joint_trajectory and the files base_joint_trajectory.{csv,json} only when
// the base moves (or has an arm), so that a plan with a fixed clamp writes what it wrote before.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "rodshape/core/so3.hpp"
#include "rodshape/io/output_files.hpp"
#include "rodshape/io/plan_output.hpp"
#include "rodshape/io/task_reader.hpp"
#include "rodshape/io/validation_output.hpp"
#include "rodshape/robot/arm_clearance.hpp"
#include "support/hand_made_plan.hpp"
#include "support/input_error.hpp"

namespace rodshape {
namespace test_moving_base_output {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using testing::kHandMadeTask;
using testing::make_plan;

/// The hand-made task with a moving base whose gripper sits 3 cm behind the base end.
std::string moving_task_text() {
  return kHandMadeTask +
         "base:\n  position: [0, 0, 0]\n  moving: true\n"
         "base_grasp:\n  base_to_end_effector: {position: [0, 0, -0.03]}\n";
}

/// The base gripper's pose at time fraction `f` of the hand-made path: along -y, turning about z
/// by up to 4 rad (so that its quaternions change hemisphere with w ≥ 0 each).
Pose base_pose(double f) {
  return {Eigen::Vector3d(0, -0.02 * f, -0.03), exp_so3(Eigen::Vector3d(0, 0, 4.0 * f))};
}

/// make_plan() with the base moving: each step's and the path's base gripper, one per sample.
PlanResult moving_plan(const PlanTask& task) {
  PlanResult plan = make_plan(task, 3);
  const double duration = plan.end_effector_path.back().t;
  for (std::size_t k = 0; k < plan.steps.size(); ++k)
    plan.steps[k].base_end_effector = base_pose(static_cast<double>(k + 1) / 3.0);
  for (const TimedPose& sample : plan.end_effector_path)
    plan.base_end_effector_path.push_back({sample.t, base_pose(sample.t / duration)});
  return plan;
}

/// An arm result with a complete two-joint trajectory on the path's clock.
ArmPlanResult base_arm_result(const PlanResult& plan) {
  ArmPlanResult arm;
  arm.status = ArmPlanStatus::Reachable;
  arm.message = "every pose reachable";
  arm.shell =
      Workspace::ReachShell{Eigen::Vector3d(0, 0, -0.5), 0.1, 0.8, Eigen::Vector3d(0, 0, -0.1)};
  arm.reach = ArmReach{};
  arm.reach->min_distance = 0.1;
  arm.reach->max_distance = 0.8;
  arm.waypoint_q = {Eigen::Vector2d(0, 0), Eigen::Vector2d(0.1, -0.1)};
  JointTrajectoryResult& joints = arm.joints;
  joints.status = JointTrajectoryStatus::Complete;
  joints.joint_names = {"base_joint1", "base_joint2"};
  for (const TimedPose& sample : plan.base_end_effector_path) {
    joints.t.push_back(sample.t);
    joints.q.push_back(Eigen::Vector2d(sample.t, -sample.t));
    joints.qdot.push_back(Eigen::Vector2d(1, -1));
  }
  joints.path_duration = joints.duration();
  return arm;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::vector<double> numbers_of(const std::string& line) {
  std::vector<double> values;
  std::istringstream in(line);
  for (std::string cell; std::getline(in, cell, ',');) values.push_back(std::stod(cell));
  return values;
}

std::string read_file(const fs::path& path) {
  std::ifstream in(path);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

fs::path fresh_directory(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() /
                       ("rodshape_moving_base_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  return dir;
}

TEST(MovingBaseOutput, StepsHaveTheBaseEndEffectorNextToTheEndEffector) {
  const PlanTask task = parse_plan_task(kHandMadeTask, "plan.yaml");
  PlanResult plan = make_plan(task, 3);
  const Pose clamp{Eigen::Vector3d(0.1, 0.2, 0.3), Eigen::Matrix3d::Identity()};
  for (PlanStep& step : plan.steps) step.base_end_effector = clamp;
  const nlohmann::ordered_json j = nlohmann::ordered_json::parse(plan_result_json(plan, task));
  for (const auto& step : j["steps"]) {
    std::vector<std::string> keys;
    for (const auto& item : step.items()) keys.push_back(item.key());
    const auto at = std::find(keys.begin(), keys.end(), "end_effector");
    ASSERT_NE(at, keys.end());
    ASSERT_NE(at + 1, keys.end());
    EXPECT_EQ(*(at + 1), "base_end_effector");
    EXPECT_EQ(step["base_end_effector"]["position"],
              nlohmann::ordered_json::parse("[0.1, 0.2, 0.3]"));
    // A quaternion [w, x, y, z], as end_effector's: the identity here.
    EXPECT_EQ(step["base_end_effector"]["rotation"], nlohmann::ordered_json::parse("[1, 0, 0, 0]"));
  }
}

TEST(MovingBaseOutput, FixedClampWritesNoBaseColumnsOrObjects) {
  const PlanTask task = parse_plan_task(kHandMadeTask, "plan.yaml");
  const PlanResult plan = make_plan(task, 3);
  const Json j = Json::parse(plan_result_json(plan, task));
  EXPECT_FALSE(j.contains("base_robot"));
  EXPECT_FALSE(j.contains("base_joint_trajectory"));
  EXPECT_TRUE(j["robot"].is_null());
  EXPECT_EQ(trajectory_csv(plan.end_effector_path, plan.base_end_effector_path),
            trajectory_csv(plan.end_effector_path));
  EXPECT_EQ(lines_of(trajectory_csv(plan.end_effector_path)).front(), "t,x,y,z,qw,qx,qy,qz");

  const fs::path dir = fresh_directory("fixed");
  const std::vector<std::string> written = write_plan(dir.string(), plan, task, {.html = false});
  for (const std::string& name : written) EXPECT_FALSE(name.starts_with("base_")) << name;
  EXPECT_FALSE(fs::exists(dir / "base_joint_trajectory.csv"));
  fs::remove_all(dir);
}

TEST(MovingBaseOutput, TrajectoryCsvHasTheBaseColumns) {
  const PlanTask task = parse_plan_task(moving_task_text(), "plan.yaml");
  ASSERT_TRUE(task.problem.base_moves());
  const PlanResult plan = moving_plan(task);
  const std::vector<std::string> lines =
      lines_of(trajectory_csv(plan.end_effector_path, plan.base_end_effector_path));
  ASSERT_EQ(lines.size(), plan.end_effector_path.size() + 1);
  EXPECT_EQ(lines.front(), "t,x,y,z,qw,qx,qy,qz,bx,by,bz,bqw,bqx,bqy,bqz");
  EXPECT_EQ(lines.front(), kTrajectoryCsvHeaderWithBase);
  Eigen::Vector4d previous = Eigen::Vector4d::Zero();
  for (std::size_t i = 0; i < plan.end_effector_path.size(); ++i) {
    const std::vector<double> row = numbers_of(lines[i + 1]);
    ASSERT_EQ(row.size(), 15u) << lines[i + 1];
    const TimedPose& tip = plan.end_effector_path[i];
    const TimedPose& base = plan.base_end_effector_path[i];
    EXPECT_NEAR(row[0], tip.t, 1e-9);
    EXPECT_NEAR(row[1], tip.pose.position.x(), 1e-9);
    EXPECT_NEAR(row[8], base.pose.position.x(), 1e-9);
    EXPECT_NEAR(row[9], base.pose.position.y(), 1e-9);
    EXPECT_NEAR(row[10], base.pose.position.z(), 1e-9);
    const Eigen::Vector4d q(row[11], row[12], row[13], row[14]);
    EXPECT_NEAR(q.norm(), 1.0, 1e-9);
    // The same rotation as the path's, in the previous sample's hemisphere.
    EXPECT_NEAR(std::abs(q.dot(base.pose.quaternion_wxyz())), 1.0, 1e-9);
    if (i > 0) {
      EXPECT_GE(q.dot(previous), 0.0) << "sample " << i;
    }
    previous = q;
  }
  // Turned by 4 rad about z, the last quaternion has left the w ≥ 0 hemisphere.
  EXPECT_LT(previous[0], 0.0);
}

TEST(MovingBaseOutput, PathsOfDifferentLengthsAreRefused) {
  const PlanTask task = parse_plan_task(moving_task_text(), "plan.yaml");
  PlanResult plan = moving_plan(task);
  plan.base_end_effector_path.pop_back();
  const std::string message = testing::input_error_message(
      [&] { trajectory_csv(plan.end_effector_path, plan.base_end_effector_path); });
  EXPECT_EQ(message.rfind("PlanResult.base_end_effector_path has ", 0), 0u) << message;
}

TEST(MovingBaseOutput, BaseArmObjectsAndFiles) {
  const PlanTask task = parse_plan_task(moving_task_text(), "plan.yaml");
  PlanResult plan = moving_plan(task);
  plan.base_arm = base_arm_result(plan);
  const Json j = Json::parse(plan_result_json(plan, task));
  ASSERT_TRUE(j.contains("base_robot"));
  ASSERT_TRUE(j.contains("base_joint_trajectory"));
  EXPECT_TRUE(j["robot"].is_null());  // the tip has no arm here
  const Json& robot = j["base_robot"];
  EXPECT_EQ(robot["status"], "reachable");
  EXPECT_EQ(robot["message"], "every pose reachable");
  EXPECT_EQ(robot["reach"]["wrist_range"], Json::parse("[0.1, 0.8]"));
  EXPECT_EQ(robot["reach"]["margin"], task.options.arm.reach_margin);
  // |q - c| at the rod's base pose p(0), R(0): initial and each step.
  const Workspace::ReachShell& shell = *plan.base_arm->shell;
  ASSERT_EQ(robot["reach"]["wrist_distances"].size(), plan.steps.size() + 1);
  const RodConfiguration& last = plan.steps.back().solution.configuration;
  EXPECT_NEAR(robot["reach"]["wrist_distances"].back().get<double>(),
              shell.distance(Pose{last.p.front(), last.R.front()}), 1e-12);
  EXPECT_EQ(robot["waypoint_joint_positions"].size(), 2u);
  for (const char* key : {"status", "message", "reach", "replans", "waypoint_joint_positions"})
    EXPECT_TRUE(robot.contains(key)) << key;
  const Json& joints = j["base_joint_trajectory"];
  EXPECT_EQ(joints["status"], "complete");
  EXPECT_EQ(joints["file"], "base_joint_trajectory.csv");
  EXPECT_EQ(joints["samples"], static_cast<int>(plan.end_effector_path.size()));
  for (const char* key :
       {"status", "message", "file", "samples", "duration", "path_duration", "slowed", "slowdown",
        "failed_sample", "ik_restarts", "max_position_error", "max_rotation_error"})
    EXPECT_TRUE(joints.contains(key)) << key;
  // The two objects end the document, after the tip's.
  std::vector<std::string> keys;
  const nlohmann::ordered_json ordered =
      nlohmann::ordered_json::parse(plan_result_json(plan, task));
  for (const auto& item : ordered.items()) keys.push_back(item.key());
  ASSERT_GE(keys.size(), 4u);
  EXPECT_EQ(keys[keys.size() - 4], "robot");
  EXPECT_EQ(keys[keys.size() - 3], "joint_trajectory");
  EXPECT_EQ(keys[keys.size() - 2], "base_robot");
  EXPECT_EQ(keys[keys.size() - 1], "base_joint_trajectory");

  const fs::path dir = fresh_directory("arm");
  const std::vector<std::string> written = write_plan(dir.string(), plan, task, {.html = false});
  EXPECT_NE(std::find(written.begin(), written.end(), "base_joint_trajectory.csv"), written.end());
  EXPECT_NE(std::find(written.begin(), written.end(), "base_joint_trajectory.json"), written.end());
  EXPECT_EQ(std::find(written.begin(), written.end(), "joint_trajectory.csv"), written.end());
  const std::string csv = read_file(dir / "base_joint_trajectory.csv");
  EXPECT_EQ(csv, joint_trajectory_csv(plan.base_arm->joints));
  EXPECT_EQ(lines_of(csv).front(), "t,base_joint1,base_joint2");
  const Json trajectory = Json::parse(read_file(dir / "base_joint_trajectory.json"));
  EXPECT_EQ(trajectory["generator"].get<std::string>().rfind("rodshape", 0), 0u);
  EXPECT_EQ(trajectory["joint_names"], Json::parse(R"(["base_joint1", "base_joint2"])"));
  EXPECT_EQ(trajectory["points"].size(), plan.end_effector_path.size());
  EXPECT_EQ(lines_of(read_file(dir / "trajectory.csv")).front(), kTrajectoryCsvHeaderWithBase);
  // Each is recognised as rodshape's, so that the next run may replace it.
  for (const char* name : {"trajectory.csv", "base_joint_trajectory.csv",
                           "base_joint_trajectory.json", "plan.json", "plan.svg"})
    EXPECT_TRUE(is_rodshape_output((dir / name).string())) << name;

  // A later run without the base arm removes the base arm's files of this one.
  const PlanTask fixed = parse_plan_task(kHandMadeTask, "plan.yaml");
  write_plan(dir.string(), make_plan(fixed, 3), fixed, {.html = false});
  EXPECT_FALSE(fs::exists(dir / "base_joint_trajectory.csv"));
  EXPECT_FALSE(fs::exists(dir / "base_joint_trajectory.json"));
  EXPECT_EQ(lines_of(read_file(dir / "trajectory.csv")).front(), kTrajectoryCsvHeader);
  fs::remove_all(dir);
}

TEST(MovingBaseOutput, TwoArmsReportTheirGapWithOrWithoutAScene) {
  const std::string panda = std::string(RODSHAPE_SOURCE_DIR) + "/data/robots/panda.urdf";
  const PlanTask task = parse_plan_task(
      moving_task_text() + "robot:\n  urdf: " + panda + "\nbase_robot:\n  urdf: " + panda + "\n",
      "plan.yaml");
  ASSERT_TRUE(task.problem.arm && task.problem.base_arm && task.problem.scene.empty());
  PlanResult plan = moving_plan(task);
  plan.base_arm = base_arm_result(plan);
  RobotGapResult gap;
  gap.min_gap = 0.004;
  gap.margin = -0.001;
  gap.sample = 7;
  gap.step = 2;
  gap.arm = "tip";
  gap.link = "panda_link7";
  gap.obstacle = kOtherArm;
  gap.other_link = "panda_link6";
  plan.scene.emplace().robot = gap;
  const Json j = Json::parse(plan_result_json(plan, task));
  ASSERT_TRUE(j["scene"].is_object());
  EXPECT_EQ(j["scene"]["obstacles"].size(), 0u);
  EXPECT_EQ(j["scene"]["robot_min_gap"], 0.004);
  EXPECT_EQ(j["scene"]["robot_clear"], false);
  const Json& at = j["scene"]["robot_min_gap_at"];
  EXPECT_EQ(at["obstacle"], "other_arm");
  EXPECT_EQ(at["arm"], "tip");
  EXPECT_EQ(at["link"], "panda_link7");
  EXPECT_EQ(at["other_link"], "panda_link6");
  // A gap to the rod: no other link.
  plan.scene->robot->obstacle = -1;
  plan.scene->robot->arm = "base";
  const Json rod = Json::parse(plan_result_json(plan, task));
  EXPECT_EQ(rod["scene"]["robot_min_gap_at"]["obstacle"], "rod");
  EXPECT_EQ(rod["scene"]["robot_min_gap_at"]["arm"], "base");
  EXPECT_TRUE(rod["scene"]["robot_min_gap_at"]["other_link"].is_null());

  // One arm and no scene: no scene object, as before.
  const PlanTask one =
      parse_plan_task(kHandMadeTask + "robot:\n  urdf: " + panda + "\n", "plan.yaml");
  PlanResult one_plan = make_plan(one, 3);
  one_plan.scene.emplace().robot = gap;
  EXPECT_TRUE(Json::parse(plan_result_json(one_plan, one))["scene"].is_null());
}

TEST(MovingBaseOutput, ValidationSaysWhatDroveTheBase) {
  // The document (no runs here: a run's own objects need a plant run), then the runs' flags.
  const PlanTask fixed = parse_plan_task(kHandMadeTask, "plan.yaml");
  ValidationResult result;
  result.real_rod = fixed.plant.real_rod(fixed.problem.rod);
  EXPECT_FALSE(
      Json::parse(validation_json(result, PlanResult{}, fixed)).contains("base_driven_by"));
  const PlanTask task = parse_plan_task(moving_task_text(), "plan.yaml");
  EXPECT_EQ(Json::parse(validation_json(result, PlanResult{}, task))["base_driven_by"], "clamp");

  result.runs.resize(2);
  EXPECT_EQ(base_driven_by(result), "clamp");
  for (ValidationRun& run : result.runs) run.base_moved = true;
  EXPECT_EQ(base_driven_by(result), "base_end_effector_path");
  for (ValidationRun& run : result.runs) run.base_driven_by_joints = true;
  EXPECT_EQ(base_driven_by(result), "base_joint_trajectory");
  result.runs[1].base_driven_by_joints = false;  // a closed-loop segment without IK
  EXPECT_EQ(base_driven_by(result), "base_end_effector_path");
}

TEST(MovingBaseOutput, IncompleteBaseJointTrajectoryWritesNoFile) {
  const PlanTask task = parse_plan_task(moving_task_text(), "plan.yaml");
  PlanResult plan = moving_plan(task);
  plan.base_arm = base_arm_result(plan);
  plan.base_arm->status = ArmPlanStatus::Unreachable;
  plan.base_arm->joints.status = JointTrajectoryStatus::Unreachable;
  plan.base_arm->joints.failed_sample = 4;
  const Json j = Json::parse(plan_result_json(plan, task));
  EXPECT_TRUE(j["base_joint_trajectory"]["file"].is_null());
  EXPECT_EQ(j["base_joint_trajectory"]["failed_sample"], 4);
  const fs::path dir = fresh_directory("unreachable");
  write_plan(dir.string(), plan, task, {.html = false});
  EXPECT_FALSE(fs::exists(dir / "base_joint_trajectory.csv"));
  fs::remove_all(dir);
}

TEST(MovingBaseOutput, BaseFilesAreInTheFileList) {
  const std::vector<std::string>& names = plan_file_names();
  EXPECT_NE(std::find(names.begin(), names.end(), "base_joint_trajectory.csv"), names.end());
  EXPECT_NE(std::find(names.begin(), names.end(), "base_joint_trajectory.json"), names.end());
  // A foreign file in the way is refused, as for the other outputs.
  const fs::path dir = fresh_directory("foreign");
  fs::create_directories(dir);
  std::ofstream(dir / "base_joint_trajectory.csv") << "not rodshape's\n";
  EXPECT_FALSE(is_rodshape_output((dir / "base_joint_trajectory.csv").string()));
  EXPECT_NE(testing::input_error_message([&] { check_output_files(dir.string(), names, {}); }), "");
  fs::remove_all(dir);
}

TEST(MovingBaseOutput, SvgDrawsTheBasePathOnlyWhenTheBaseMoves) {
  const PlanTask fixed = parse_plan_task(kHandMadeTask, "plan.yaml");
  const std::string fixed_svg = plan_svg(make_plan(fixed, 3), fixed);
  EXPECT_EQ(fixed_svg.find("base gripper"), std::string::npos);
  EXPECT_NE(fixed_svg.find("clamp p(0)"), std::string::npos);

  const PlanTask task = parse_plan_task(moving_task_text(), "plan.yaml");
  const PlanResult plan = moving_plan(task);
  const std::string svg = plan_svg(plan, task);
  EXPECT_NE(svg.find("base gripper's path"), std::string::npos) << "legend";
  EXPECT_NE(svg.find("stroke-dasharray=\"2 3\""), std::string::npos) << "the path";
  // The base at each step, in each of the three panels.
  std::size_t marks = 0;
  for (std::size_t at = svg.find("width=\"6\" height=\"6\""); at != std::string::npos;
       at = svg.find("width=\"6\" height=\"6\"", at + 1))
    ++marks;
  EXPECT_EQ(marks, 3 * plan.steps.size());
}

}  // namespace
}  // namespace test_moving_base_output
}  // namespace rodshape
