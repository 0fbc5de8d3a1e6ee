// test_cli_plan_robot.cpp: `rodshape plan` with a robot section. The bundled Panda examples (and
// the FR3's, within its own limits) write joint_trajectory.csv and joint_trajectory.json (the shape
// of ROS trajectory_msgs/JointTrajectory) whose last positions put the end effector where plan.json
// says; an unknown tip link is bad input (exit 2) named with its line; an arm too far from the
// clamp to hold the rod where it starts is bad input (exit 2) that gives the wrist's distance;
// without the reach shell it gives exit 3, plan.json saying why; plan.json's robot section holds
// the shell and every step's joints. Bad input the library finds (two bases in each other, a hand
// starting in a box, a base out of its arm's reach, the plant's bounds) names the task file's
// fields, never the library's types.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <nlohmann/json.hpp>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "rodshape/io/task_reader.hpp"
#include "rodshape/robot/arm_model.hpp"
#include "rodshape/samples/bundled_arms.hpp"
#include "support/cli_runner.hpp"
#include "support/eigen_compare.hpp"
#include "support/task_text.hpp"

namespace test_cli_plan_robot {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

const fs::path kSource = RODSHAPE_SOURCE_DIR;
const fs::path kExample = kSource / "examples" / "plan_panda_s_curve.yaml";

using Outcome = rodshape::testing::CliOutcome;
using rodshape::testing::quoted;
using rodshape::testing::read_file;
using rodshape::testing::rotation_angle;

using rodshape::testing::replaced_first;

/// The 1-based line of the first occurrence of `needle` in `text`.
int line_of(const std::string& text, const std::string& needle) {
  const std::size_t at = text.find(needle);
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
}

class CliPlanRobot : public rodshape::testing::CliTest {
 protected:
  Outcome plan(const fs::path& task, const fs::path& outdir) const {
    return run("plan " + quoted(task.string()) + " -o " + quoted(outdir.string()));
  }

  /// The example, its URDF path made absolute so that the copy works from the temporary directory.
  std::string example_text() const {
    return replaced_first(read_file(kExample), "urdf: ../data/robots/panda.urdf",
                          "urdf: " + (kSource / "data" / "robots" / "panda.urdf").string());
  }
};

Eigen::Vector3d vector3(const Json& value) {
  return {value.at(0).get<double>(), value.at(1).get<double>(), value.at(2).get<double>()};
}

/// A bundled Panda (or FR3) example and where its arm's base stands (robot.base.position.x).
struct PandaExample {
  const char* file;
  double base_x;
  const char* name;
  const char* robot = "panda";  // the bundled arm's name
};

void PrintTo(const PandaExample& example, std::ostream* out) { *out << example.file; }

class CliPandaExamples : public CliPlanRobot, public ::testing::WithParamInterface<PandaExample> {};

TEST_P(CliPandaExamples, WriteJointTrajectoriesThatReplayOntoThePlannedPath) {
  const fs::path out = directory_ / "out";
  const Outcome outcome = plan(kSource / "examples" / GetParam().file, out);
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  ASSERT_TRUE(fs::exists(out / "joint_trajectory.csv"));
  ASSERT_TRUE(fs::exists(out / "joint_trajectory.json"));

  const Json plan = Json::parse(read_file(out / "plan.json"));
  const Json& summary = plan.at("joint_trajectory");
  EXPECT_EQ(summary.at("status"), "complete");
  EXPECT_EQ(summary.at("message"), "");
  EXPECT_EQ(summary.at("file"), "joint_trajectory.csv");
  const int samples = summary.at("samples").get<int>();
  EXPECT_EQ(samples, plan.at("end_effector_path").at("samples").get<int>());
  EXPECT_GE(summary.at("slowdown").get<double>(), 1.0);
  EXPECT_GE(summary.at("duration").get<double>(),
            plan.at("end_effector_path").at("duration").get<double>() - 1e-12);

  const Json trajectory = Json::parse(read_file(out / "joint_trajectory.json"));
  const rodshape::ArmModel arm = *rodshape::samples::bundled_arm(GetParam().robot);
  EXPECT_EQ(trajectory.at("joint_names").get<std::vector<std::string>>(), arm.joint_names());
  const Json& points = trajectory.at("points");
  ASSERT_EQ(static_cast<int>(points.size()), samples);
  double previous = -1.0;
  for (const Json& point : points) {
    ASSERT_EQ(point.at("positions").size(), 7u);
    ASSERT_EQ(point.at("velocities").size(), 7u);
    const Json& time = point.at("time_from_start");
    ASSERT_TRUE(time.at("sec").is_number_integer());
    ASSERT_TRUE(time.at("nanosec").is_number_integer());
    const long long nanosec = time.at("nanosec").get<long long>();
    EXPECT_GE(nanosec, 0);
    EXPECT_LT(nanosec, 1000000000);
    const double t = time.at("sec").get<double>() + 1e-9 * static_cast<double>(nanosec);
    EXPECT_GT(t, previous);
    previous = t;
  }

  // Every sample replays onto the planned end-effector path (trajectory.csv, the same samples):
  // the end effector is world_T_base · FK · flange_T_ee, as the example places the arm. IK
  // converges to 1e-10 m and rad; the files' 12 significant digits add ~1e-12. So 1e-9.
  Eigen::VectorXd q(7);
  const Eigen::Vector3d base(GetParam().base_x, 0.0, -0.2);              // robot.base
  const Eigen::Matrix3d turn = Eigen::Vector3d(1, -1, -1).asDiagonal();  // π about x
  std::istringstream path(read_file(out / "trajectory.csv"));
  std::string row;
  std::getline(path, row);  // header
  double worst_position = 0.0, worst_angle = 0.0;
  for (const Json& point : points) {
    ASSERT_TRUE(std::getline(path, row));
    std::istringstream fields(row);
    std::vector<double> v;
    for (std::string field; std::getline(fields, field, ',');) v.push_back(std::stod(field));
    ASSERT_EQ(v.size(), 8u) << row;
    for (int j = 0; j < 7; ++j) q(j) = point.at("positions").at(j).get<double>();
    arm.check_joint_positions(q, "a sample", 1e-9);  // within this arm's limits (the FR3's own)
    for (int j = 0; j < 7; ++j)
      EXPECT_LE(std::abs(point.at("velocities").at(j).get<double>()),
                arm.velocity_limits()(j) * (1 + 1e-9));
    const rodshape::Pose f = arm.forward_kinematics(q);
    const Eigen::Vector3d p = base + f.position + f.rotation * Eigen::Vector3d(0, 0, 0.1034);
    const Eigen::Quaterniond planned(v[4], v[5], v[6], v[7]);
    worst_position = std::max(worst_position, (p - Eigen::Vector3d(v[1], v[2], v[3])).norm());
    worst_angle = std::max(
        worst_angle, rotation_angle(f.rotation * turn, planned.normalized().toRotationMatrix()));
  }
  EXPECT_LT(worst_position, 1e-9);
  EXPECT_LT(worst_angle, 1e-9);

  // The robot section: the reach shell around the shoulder (0.333 m above the base), the wrist
  // 0.107 + 0.1034 m beyond the tip along the tip's tangent (the hand grasps from above), and the
  // joints of the initial pose and of each step.
  const Json& robot = plan.at("robot");
  EXPECT_EQ(robot.at("status"), "reachable");
  const Json& reach = robot.at("reach");
  EXPECT_LT((vector3(reach.at("center")) - Eigen::Vector3d(GetParam().base_x, 0.0, 0.133)).norm(),
            1e-12);
  EXPECT_LT((vector3(reach.at("tip_point")) - Eigen::Vector3d(0.0, 0.0, 0.2104)).norm(), 1e-12);
  const double outer = reach.at("outer_radius").get<double>();
  EXPECT_DOUBLE_EQ(outer, reach.at("wrist_range").at(1).get<double>() - 0.02);
  EXPECT_EQ(robot.at("replans").size(), 0u);
  EXPECT_EQ(robot.at("waypoint_joint_positions").size(), plan.at("steps").size() + 1);
  const Json& wrist = reach.at("wrist_distances");
  ASSERT_EQ(wrist.size(), plan.at("steps").size() + 1);
  // g = r² ≤ outer² holds to IPOPT's constraint tolerance on g (optimizer.constraint_tolerance).
  const double tolerance =
      rodshape::read_plan_task((kSource / "examples" / GetParam().file).string())
          .options.optimiser.constraint_tolerance;
  for (const Json& r : wrist) {
    const double distance = r.get<double>();
    EXPECT_LE(distance * distance, outer * outer + tolerance) << distance;
  }
  // The S-curve stays well inside; 0.13 m further back, the last step stops on the shell.
  const double last_wrist = wrist.back().get<double>();
  if (GetParam().base_x == -0.45)
    EXPECT_LT(last_wrist, outer - 0.05);
  else
    EXPECT_GT(last_wrist, outer - 1e-4);

  // The CSV: header t and the joint names, one line per sample.
  std::istringstream csv(read_file(out / "joint_trajectory.csv"));
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header.rfind("t," + std::string(GetParam().robot) + "_joint1,", 0), 0u) << header;
  int lines = 0;
  for (std::string line; std::getline(csv, line);) ++lines;
  EXPECT_EQ(lines, samples);
}

INSTANTIATE_TEST_SUITE_P(
    BundledPandaExamples,
    CliPandaExamples,
    ::testing::Values(PandaExample{"plan_panda_s_curve.yaml", -0.45, "SCurve"},
                      PandaExample{"plan_panda_reach_limit.yaml", -0.58, "ReachLimit"},
                      PandaExample{"plan_panda_shelf.yaml", -0.45, "Shelf"},
                      PandaExample{"plan_fr3_s_curve.yaml", -0.45, "Fr3SCurve", "fr3"}),
    [](const auto& info) { return std::string(info.param.name); });

// plan.json's scene with an arm: the least gap of the links over the joint trajectory and where;
// the summary line says it. An obstacle on the hand's own way: exit 3, status collision, the step,
// link, obstacle and gap named.
TEST_F(CliPlanRobot, TheShelfPlanReportsTheLinksLeastGapAndAnUnavoidableObstacleExitsThree) {
  const fs::path shelf = kSource / "examples" / "plan_panda_shelf.yaml";
  const Outcome outcome = plan(shelf, directory_ / "out");
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  EXPECT_NE(outcome.out.find("least gap of the arm's links 40 mm (panda_link5, obstacle 'board')"),
            std::string::npos)
      << outcome.out;
  const Json scene = Json::parse(read_file(directory_ / "out" / "plan.json")).at("scene");
  EXPECT_GE(scene.at("robot_min_gap").get<double>(), 0.01);
  EXPECT_EQ(scene.at("robot_clear"), true);
  const Json& at = scene.at("robot_min_gap_at");
  EXPECT_EQ(at.at("link"), "panda_link5");
  EXPECT_EQ(at.at("obstacle"), "board");
  EXPECT_GT(at.at("sample").get<int>(), 0);
  EXPECT_GT(at.at("t").get<double>(), 0.0);

  std::string text =
      replaced_first(read_file(shelf), "urdf: ../data/robots/panda.urdf",
                     "urdf: " + (kSource / "data" / "robots" / "panda.urdf").string());
  text += "    - {name: lamp, shape: sphere, center: [0.09, 0, 0.62], radius: 0.03}\n";
  const fs::path task = directory_ / "lamp.yaml";
  std::ofstream(task) << text;
  const Outcome collision = plan(task, directory_ / "lamp");
  EXPECT_EQ(collision.exit_code, 3) << collision.err;
  for (const char* word : {"collision", "step ", "link panda_link7", "obstacle 'lamp'", "gap "})
    EXPECT_NE(collision.err.find(word), std::string::npos) << word << " in " << collision.err;
  const Json lamp = Json::parse(read_file(directory_ / "lamp" / "plan.json"));
  EXPECT_EQ(lamp.at("status"), "collision");
  EXPECT_EQ(lamp.at("scene").at("robot_clear"), false);
  EXPECT_EQ(lamp.at("scene").at("robot_min_gap_at").at("obstacle"), "lamp");
}

TEST_F(CliPlanRobot, AnUnknownTipLinkIsBadInputNamedWithItsLine) {
  const std::string text =
      replaced_first(example_text(), "tip_link: panda_link8", "tip_link: panda_hnd");
  const fs::path task = write_task("bad_tip.yaml", text);
  const Outcome outcome = plan(task, directory_ / "out");
  EXPECT_EQ(outcome.exit_code, 2) << outcome.err;
  const std::string where = task.string() + ":" + std::to_string(line_of(text, "tip_link:")) + ":";
  EXPECT_NE(outcome.err.find(where + " robot.tip_link"), std::string::npos) << outcome.err;
  EXPECT_NE(outcome.err.find("unknown tip link 'panda_hnd'"), std::string::npos) << outcome.err;
  EXPECT_FALSE(fs::exists(directory_ / "out" / "plan.json"));
}

TEST_F(CliPlanRobot, AnUnknownKeyAndAMissingUrdfAreBadInput) {
  const fs::path typo =
      write_task("typo.yaml", replaced_first(example_text(), "  base_link:", "  base_lnk:"));
  Outcome outcome = plan(typo, directory_ / "out");
  EXPECT_EQ(outcome.exit_code, 2) << outcome.err;
  EXPECT_NE(outcome.err.find("robot.base_lnk"), std::string::npos) << outcome.err;

  const fs::path missing =
      write_task("missing.yaml",
                 replaced_first(read_file(kExample), "../data/robots/panda.urdf", "nowhere.urdf"));
  outcome = plan(missing, directory_ / "out");
  EXPECT_EQ(outcome.exit_code, 2) << outcome.err;
  EXPECT_NE(outcome.err.find("robot.urdf"), std::string::npos) << outcome.err;
  EXPECT_NE(outcome.err.find((directory_ / "nowhere.urdf").string()), std::string::npos)
      << outcome.err;

  // robot.links: checked like the rest, the field and its line named.
  const std::string links = example_text() + "  links: {clearance: true, influence: -0.5}\n";
  outcome = plan(write_task("links.yaml", links), directory_ / "out");
  EXPECT_EQ(outcome.exit_code, 2) << outcome.err;
  EXPECT_NE(outcome.err.find("robot.links.influence = -0.5 must be >= 0"), std::string::npos)
      << outcome.err;
  EXPECT_NE(outcome.err.find(
                std::string(":").append(std::to_string(line_of(links, "  links:"))).append(":")),
            std::string::npos)
      << outcome.err;
  outcome = plan(write_task("links2.yaml", example_text() + "  links: {clearence: false}\n"),
                 directory_ / "out");
  EXPECT_EQ(outcome.exit_code, 2) << outcome.err;
  EXPECT_NE(outcome.err.find("did you mean 'clearance'"), std::string::npos) << outcome.err;
}

TEST_F(CliPlanRobot, AnArmTooFarFromTheClampIsBadInputGivingTheWristsDistance) {
  const fs::path task = write_task(
      "far.yaml",
      replaced_first(example_text(), "position: [-0.45, 0, -0.2]", "position: [-3, 0, 0]"));
  const Outcome outcome = plan(task, directory_ / "out");
  EXPECT_EQ(outcome.exit_code, 2) << outcome.err;
  EXPECT_NE(outcome.err.find("far.yaml:47: robot: where the rod starts, the arm's wrist would be"),
            std::string::npos)
      << outcome.err;
  EXPECT_NE(outcome.err.find("outside its reach shell"), std::string::npos) << outcome.err;
  EXPECT_FALSE(fs::exists(directory_ / "out" / "plan.json"));
}

TEST_F(CliPlanRobot, WithoutTheReachShellAnArmOutOfReachWritesThePlanAndExitsThree) {
  const fs::path task = write_task(
      "far.yaml",
      replaced_first(example_text(), "position: [-0.45, 0, -0.2]", "position: [-3, 0, 0]") +
          "  reach: {use: false}\n");
  const fs::path out = directory_ / "out";
  fs::create_directories(out);
  // From an earlier run (recognised by its header: issue 24), so removed: it would not match.
  std::ofstream(out / "joint_trajectory.csv") << "t,panda_joint1\n0,0\n";
  const Outcome outcome = plan(task, out);
  EXPECT_EQ(outcome.exit_code, 3) << outcome.err;
  EXPECT_NE(
      outcome.err.find("robot: the initial end-effector pose has no inverse kinematics solution"),
      std::string::npos)
      << outcome.err;
  EXPECT_TRUE(fs::exists(out / "plan.json"));
  EXPECT_TRUE(fs::exists(out / "trajectory.csv"));
  EXPECT_FALSE(fs::exists(out / "joint_trajectory.csv"));
  EXPECT_FALSE(fs::exists(out / "joint_trajectory.json"));
  const Json plan = Json::parse(read_file(out / "plan.json"));
  EXPECT_EQ(plan.at("status"), "complete");
  const Json& robot = plan.at("robot");
  EXPECT_EQ(robot.at("status"), "unreachable");
  EXPECT_TRUE(robot.at("reach").is_null());
  EXPECT_EQ(robot.at("waypoint_joint_positions").size(), 0u);
  const Json& summary = plan.at("joint_trajectory");
  EXPECT_EQ(summary.at("status"), "not_run");
  EXPECT_TRUE(summary.at("file").is_null());
  EXPECT_NE(summary.at("message").get<std::string>().find("not computed"), std::string::npos)
      << summary.at("message");
}

// ---- issue 43: checks up front (item 7) and no library names in task-file errors (item 4c) -----

/// An example with every `../data/robots/panda.urdf` made absolute (the copy is elsewhere).
std::string example_text_of(const std::string& name) {
  std::string text = read_file(kSource / "examples" / name);
  const std::string from = "urdf: ../data/robots/panda.urdf";
  const std::string to = "urdf: " + (kSource / "data" / "robots" / "panda.urdf").string();
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at))
    text.replace(at, from.size(), to);
  return text;
}

/// The library's type names that prefix its field names (grep InputError in src/: the structs
/// whose fields the library's errors name), which no task-file error may show; space-separated.
const std::string kLibraryNames =
    "PlanProblem. PlanOptions. PlanArm ClampedRod. RodProperties. RodDescription. Scene. "
    "ShootingOptions. ShapeTarget. ShapeOptimiserOptions StrainLimits. Workspace. "
    "WrenchBounds Grasp. EndEffectorLimits MovingBase ArmPlanOptions. ArmReachOptions. "
    "ArmPlacement PlantModel MarkerSensorModel DepthSensorModel ValidationOptions. "
    "EstimationOptions. ClosedLoopOptions. FreeTip. ClampedTip. GraspedTip. IkOptions. "
    "FollowOptions. BaseMotion. StatePrior. CloudFrame EstimateTask. ModelValidity "
    "BaseGripperPath";

/// A bad task the library refuses (not the reader's own key checks): the edit, the task-file
/// field the one-line error must start with (after "<file>:<line>: "), and words it must hold.
struct BadTask {
  const char* example;
  const char* from;
  const char* to;
  const char* field;
  const char* words;
};

TEST_F(CliPlanRobot, LibraryErrorsNameTaskFieldsNeverLibraryTypes) {
  const BadTask cases[] = {
      // Item 7: two bases standing in each other, found before planning (was exit 3).
      {"plan_two_pandas.yaml", "position: [0.4, 0, 0]", "position: [-0.45, 0.05, 0]",
       "robot.base: the arm's base link panda_link0 overlaps the base arm's base link panda_link0",
       "(placed by base_robot.base) by 34 mm: the two bases stand in each other"},
      // Item 7: a hand that starts inside a box (the shelf example's hand at the start).
      {"plan_panda_shelf.yaml", "  obstacles:\n",
       "  obstacles:\n"
       "    - {name: crate, shape: box, center: [0.0354, -0.0354, 0.3534], size: [0.02, 0.02, "
       "0.02]}\n",
       "scene.obstacles[0] ('crate'): the arm's link panda_link", "fixed to its hand"},
      // Item 4c: the base outside the base arm's reach (was PlanProblem.rod.clamp).
      {"plan_two_pandas.yaml", "position: [-0.4, 0, 0]", "position: [-1.6, 0, 0]",
       "base: where the rod's base starts, the base arm's wrist would be", "reach shell"},
      // Item 4c: a scheme that follows the tip alone with a moving base (was
      // PlanOptions.interpolation).
      {"plan_two_pandas.yaml", "  steps: 7\n", "  steps: 7\n  interpolation: pose\n",
       "trajectory.interpolation = pose follows the tip alone", "with a moving base"},
      // Item 4b: the plant's scale as given (was rod.stiffness.EIx = 4e+298), before planning.
      {"plan_two_pandas.yaml", "stiffness_scale: 0.85", "stiffness_scale: 1e300",
       "plant.stiffness_scale = 1e+300 makes the plant's EIx = 1e+300 x the planner's 0.04 N*m^2",
       "must be in ["},
  };
  for (const BadTask& bad : cases) {
    SCOPED_TRACE(std::string(bad.example) + ": " + bad.to);
    const std::string text = replaced_first(example_text_of(bad.example), bad.from, bad.to);
    const fs::path task = write_task("bad.yaml", text);
    const Outcome outcome = plan(task, directory_ / "out");
    EXPECT_EQ(outcome.exit_code, 2) << outcome.err;
    EXPECT_EQ(std::count(outcome.err.begin(), outcome.err.end(), '\n'), 1) << outcome.err;
    const std::size_t field = outcome.err.find(bad.field);
    EXPECT_NE(field, std::string::npos) << outcome.err;
    // "error: <file>:<line>: <field>": the field right after the place.
    EXPECT_EQ(outcome.err.rfind(": ", field), field - 2) << outcome.err;
    EXPECT_NE(outcome.err.find(bad.words), std::string::npos) << outcome.err;
    std::istringstream names(kLibraryNames);
    for (std::string name; names >> name;)
      EXPECT_EQ(outcome.err.find(name), std::string::npos) << name << " in " << outcome.err;
    EXPECT_FALSE(fs::exists(directory_ / "out" / "plan.json"));
  }
}

}  // namespace
}  // namespace test_cli_plan_robot
