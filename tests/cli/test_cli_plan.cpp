// test_cli_plan.cpp: `rodshape plan` as a user runs it. A complete plan writes plan.json (every
// documented key, one entry per step, the last step's objective points equal to the target),
// trajectory.csv (increasing times, unit quaternions) and plan.svg; an infeasible target gives exit
// code 2 naming the point, with nothing written; a workspace that excludes the initial tip gives
// exit code 2 and no files; a step that fails gives exit code 3 and a partial plan. The task files
// are small (51 nodes, two or three steps) to keep the runtime short.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/cli_runner.hpp"
#include "support/task_text.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace test_cli_plan {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

using Outcome = rodshape::testing::CliOutcome;
using rodshape::testing::expect_unit_quaternion;
using rodshape::testing::expect_vector3;
using rodshape::testing::quoted;
using rodshape::testing::read_file;

class CliPlan : public rodshape::testing::CliTest {
 protected:
  /// Runs `rodshape plan <task> -o <outdir>`.
  Outcome plan(const fs::path& task, const fs::path& outdir) const {
    return run("plan " + quoted(task.string()) + " -o " + quoted(outdir.string()));
  }
};

// A gentle bend of the rubber band (the points lie on the band integrated from the base wrench
// m(0) = [0, 0.08, 0] N m, rounded to the millimetre). Line numbers below refer to this text.
const std::string kTask = R"(rod:
  length: 0.29
  nodes: 51
  section: {shape: rectangle, width: 0.02, height: 0.02}
  material: {young_modulus: 3.2e6, poisson_ratio: 0.5, density: 1392}
  stiffness: {EIx: 0.04, EIy: 0.04, GJ: 0.028}
target:
  points:
    - [0.003, 0.000, 0.057]
    - [0.013, 0.000, 0.114]
    - [0.030, 0.000, 0.169]
    - [0.052, 0.000, 0.223]
    - [0.081, 0.000, 0.273]
trajectory:
  steps: 2
  tracking_substeps: 3
)";

std::string task_with(const std::string& from, const std::string& to) {
  return rodshape::testing::replaced_first(kTask, from, to);
}

void expect_one_line(const std::string& text) {
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.find('\n'), text.size() - 1) << "not one line: " << text;
}

void expect_pose(const Json& pose) {
  ASSERT_TRUE(pose.is_object());
  expect_vector3(pose["position"]);
  expect_unit_quaternion(pose["rotation"]);
}

/// The object `equilibrium` writes after its solver fields.
void expect_configuration(const Json& c, std::size_t nodes) {
  ASSERT_TRUE(c.is_object());
  for (const char* key :
       {"model", "energy", "stable", "stability", "base_wrench", "tip_wrench", "tip", "nodes"})
    EXPECT_TRUE(c.contains(key)) << key;
  EXPECT_EQ(c["model"], "cosserat");
  EXPECT_TRUE(c["energy"].is_number());
  expect_vector3(c["base_wrench"]["force"]);
  expect_vector3(c["base_wrench"]["moment"]);
  expect_pose(c["tip"]);
  for (const char* key : {"s", "position", "rotation", "force", "moment", "u", "v"})
    EXPECT_EQ(c["nodes"][key].size(), nodes) << key;
}

std::vector<std::vector<double>> read_csv(const fs::path& path, std::string& header) {
  std::ifstream file(path);
  std::getline(file, header);
  std::vector<std::vector<double>> rows;
  for (std::string line; std::getline(file, line);) {
    std::vector<double> row;
    std::stringstream fields(line);
    for (std::string field; std::getline(fields, field, ',');) row.push_back(std::stod(field));
    rows.push_back(row);
  }
  return rows;
}

TEST_F(CliPlan, CompletePlanWritesPlanTrajectoryAndPicture) {
  const fs::path task = write_task("bend.yaml", kTask);
  const fs::path outdir = directory_ / "out" / "bend";  // created, parents included
  const Outcome result = plan(task, outdir);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(result.err, "");
  expect_one_line(result.out);
  EXPECT_EQ(result.out.rfind(task.string() + ": complete plan, 2 steps (2 requested)", 0), 0u)
      << result.out;

  // plan.json: every documented key.
  const Json j = Json::parse(read_file(outdir / "plan.json"));
  for (const char* key : {"status", "message", "reason", "failed_step", "steps_requested",
                          "steps_completed", "source", "target", "feasibility", "final", "initial",
                          "initial_points", "steps", "end_effector_path", "tracking"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["status"], "complete");
  EXPECT_TRUE(j["reason"].is_null());
  EXPECT_TRUE(j["failed_step"].is_null());
  EXPECT_EQ(j["steps_requested"], 2);
  EXPECT_EQ(j["steps_completed"], 2);
  EXPECT_EQ(j["target"]["points"].size(), 5u);
  EXPECT_EQ(j["target"]["weights"]["energy"], 1e-3);
  EXPECT_EQ(j["feasibility"]["feasible"], true);
  expect_configuration(j["initial"], 51);
  EXPECT_EQ(j["initial_points"].size(), 5u);

  const Json& steps = j["steps"];
  ASSERT_EQ(steps.size(), 2u);
  for (std::size_t k = 0; k < steps.size(); ++k) {
    SCOPED_TRACE("step " + std::to_string(k + 1));
    const Json& step = steps[k];
    for (const char* key : {"step", "objective_points", "configuration", "end_effector", "energy",
                            "cost", "distances", "max_distance", "stable", "solver"})
      EXPECT_TRUE(step.contains(key)) << key;
    EXPECT_EQ(step["step"], k + 1);
    EXPECT_EQ(step["objective_points"].size(), 5u);
    expect_configuration(step["configuration"], 51);
    expect_pose(step["end_effector"]);
    EXPECT_EQ(step["energy"], step["configuration"]["energy"]);
    ASSERT_EQ(step["distances"].size(), 5u);
    double largest = 0.0;
    for (const Json& d : step["distances"]) largest = std::max(largest, d.get<double>());
    EXPECT_EQ(step["max_distance"].get<double>(), largest);
    EXPECT_TRUE(step["stable"].is_boolean());
    EXPECT_EQ(step["solver"]["status"], "converged");
    EXPECT_GE(step["solver"]["iterations"].get<int>(), 0);
    // The grasp has no offset: the end effector is the tip.
    EXPECT_EQ(step["end_effector"]["position"], step["configuration"]["tip"]["position"]);
  }
  EXPECT_EQ(steps.back()["objective_points"], j["target"]["points"]);
  // The target lies on a reachable shape, up to the points' millimetre rounding (≤ 0.87 mm) and the
  // coarse discretisation: the final rod passes within 2 mm of every point.
  EXPECT_LT(steps.back()["max_distance"].get<double>(), 2e-3);
  EXPECT_EQ(j["final"]["max_distance"], steps.back()["max_distance"]);

  const Json& path = j["end_effector_path"];
  EXPECT_EQ(path["file"], "trajectory.csv");
  EXPECT_GT(path["duration"].get<double>(), 0.0);
  EXPECT_EQ(path["waypoints"].size(), 2u);
  const Json& tracking = j["tracking"];
  for (const char* key :
       {"performed", "arrival_deviation", "max_deviation", "jump", "jump_step", "refinements",
        "energy_released", "peak_energy", "peak_curvature", "note"})
    EXPECT_TRUE(tracking.contains(key)) << key;
  EXPECT_EQ(tracking["performed"], true);

  // trajectory.csv: from the initial tip to the last waypoint, times increasing, unit quaternions.
  std::string header;
  const std::vector<std::vector<double>> rows = read_csv(outdir / "trajectory.csv", header);
  EXPECT_EQ(header, "t,x,y,z,qw,qx,qy,qz");
  ASSERT_EQ(rows.size(), path["samples"].get<std::size_t>());
  ASSERT_GE(rows.size(), 3u);
  EXPECT_EQ(rows.front()[0], 0.0);
  EXPECT_NEAR(rows.back()[0], path["duration"].get<double>(), 1e-9);
  for (std::size_t r = 0; r < rows.size(); ++r) {
    ASSERT_EQ(rows[r].size(), 8u) << "row " << r;
    if (r > 0) {
      EXPECT_GT(rows[r][0], rows[r - 1][0]) << "row " << r;
    }
    const double norm = std::sqrt(rows[r][4] * rows[r][4] + rows[r][5] * rows[r][5] +
                                  rows[r][6] * rows[r][6] + rows[r][7] * rows[r][7]);
    EXPECT_NEAR(norm, 1.0, 1e-9) << "row " << r;
  }
  EXPECT_NEAR(rows.front()[3], 0.29, 1e-9);  // the band at rest, tip straight up
  const Json& last = steps.back()["end_effector"]["position"];
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(rows.back()[1 + c], last[c].get<double>(), 1e-9);

  // plan.svg: a whole SVG document with the three projections.
  const std::string svg = read_file(outdir / "plan.svg");
  EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
  EXPECT_NE(svg.find("<svg xmlns=\"http://www.w3.org/2000/svg\""), std::string::npos);
  EXPECT_EQ(svg.substr(svg.size() - 7), "</svg>\n");
  for (const char* view : {"x\u2013z", "y\u2013z", "x\u2013y", "target points"})
    EXPECT_NE(svg.find(view), std::string::npos) << view;
}

// plan.html (issue 23): written beside plan.svg when three.js is found; without it a warning, the
// SVG and the usual exit code; --no-html writes no page and says nothing of it.
TEST_F(CliPlan, ThePageIsWrittenOrWarnedAboutOrTurnedOff) {
  const fs::path task = write_task("band.yaml", kTask);
  const fs::path three = directory_ / "three";
  fs::create_directories(three / "examples/js/controls");
  std::ofstream(three / "three.min.js") << "window.THREE = {};\n";
  std::ofstream(three / "examples/js/controls/OrbitControls.js") << "THREE.OrbitControls = 1;\n";
  ::setenv("RODSHAPE_THREE_JS_DIR", three.string().c_str(), 1);
  Outcome result = plan(task, directory_ / "page");
  EXPECT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(result.err, "");
  EXPECT_NE(result.out.find("plan.html"), std::string::npos) << result.out;
  EXPECT_EQ(read_file(directory_ / "page" / "plan.html").rfind("<!DOCTYPE html>\n", 0), 0u);

  ::setenv("RODSHAPE_THREE_JS_DIR", (directory_ / "none").string().c_str(), 1);
  result = plan(task, directory_ / "page");
  EXPECT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(
      result.err.rfind("warning: the 3D pages (plan.html, validation.html) are not written: ", 0),
      0u)
      << result.err;
  EXPECT_NE(result.err.find("libjs-three"), std::string::npos) << result.err;
  EXPECT_TRUE(fs::exists(directory_ / "page" / "plan.svg"));
  EXPECT_FALSE(fs::exists(directory_ / "page" / "plan.html"));  // the earlier run's is removed

  result = run("plan " + quoted(task.string()) + " -o " +
               quoted((directory_ / "no_html").string()) + " --no-html");
  ::unsetenv("RODSHAPE_THREE_JS_DIR");
  EXPECT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(result.err, "");
  EXPECT_TRUE(fs::exists(directory_ / "no_html" / "plan.svg"));
  EXPECT_FALSE(fs::exists(directory_ / "no_html" / "plan.html"));
}

TEST_F(CliPlan, InfeasibleTargetIsBadInputNamingThePointAndNothingIsWritten) {
  // Issue 24: an infeasible target was exit 2 with a plan.json here and exit 3 in validate; it is
  // bad input as any other: one line naming the offending point and its line, nothing written.
  // A point 2 L from the clamp: no rod of length L passes through it.
  const fs::path task =
      write_task("far.yaml", task_with("[0.081, 0.000, 0.273]", "[0.0, 0.0, 0.58]"));
  const fs::path outdir = directory_ / "far";
  // An earlier run's file stays as it was: bad input writes and removes nothing.
  fs::create_directories(outdir);
  write_task("far/trajectory.csv", "t,x,y,z,qw,qx,qy,qz\n");
  const Outcome result = plan(task, outdir);
  EXPECT_EQ(result.exit_code, 2) << result.err;
  expect_one_line(result.err);
  EXPECT_EQ(result.err.rfind("error: " + task.string() + ":8: target.points[4] is 0.58 m from", 0),
            0u)
      << result.err;
  EXPECT_NE(result.err.find(": the target is infeasible\n"), std::string::npos) << result.err;
  EXPECT_EQ(result.out, "");
  EXPECT_FALSE(fs::exists(outdir / "plan.json"));
  EXPECT_FALSE(fs::exists(outdir / "plan.svg"));
  EXPECT_EQ(read_file(outdir / "trajectory.csv"), "t,x,y,z,qw,qx,qy,qz\n");
}

TEST_F(CliPlan, WorkspaceExcludingTheInitialTipExitsTwoAndWritesNothing) {
  // The band at rest has its tip at z = 0.29, above this box.
  const fs::path task = write_task(
      "box.yaml", kTask + "workspace:\n  box: {lower: [-1, -1, -1], upper: [1, 1, 0.25]}\n");
  const fs::path outdir = directory_ / "box";
  const Outcome result = plan(task, outdir);
  EXPECT_EQ(result.exit_code, 2);
  expect_one_line(result.err);
  EXPECT_EQ(
      result.err.rfind("error: " + task.string() + ":17: workspace excludes the initial tip", 0),
      0u)
      << result.err;
  EXPECT_EQ(result.out, "");
  EXPECT_FALSE(fs::exists(outdir));
}

TEST_F(CliPlan, BadPlanFieldsExitTwoWithFileLineAndField) {
  struct Bad {
    const char* name;
    std::string text;
    const char* message;
  };
  const std::vector<Bad> cases = {
      {"steps", task_with("steps: 2", "steps: 0"), ":15: trajectory.steps = 0 must be >= 1"},
      {"tip", kTask + "tip:\n  position: [0.1, 0, 0.2]\n", ":17: tip: unknown key; a plan decides"},
      {"weights", kTask + "weights: {energy: -1}\n", ":17: weights.energy = -1 must be >= 0"},
      {"points",
       kTask.substr(0, kTask.find("  points:")) + "  points: []\n" +
           kTask.substr(kTask.find("trajectory:")),
       ":8: target.points is empty"},
      // Issue 24, item 5: a point beyond the position range, named in the task's words at its line.
      {"far_point", task_with("[0.013, 0.000, 0.114]", "[1e300, 0, 0]"),
       ":10: target.points[1] has magnitude 1e+300 m; at most 10000 m"},
      {"plant_gravity", kTask + "plant: {gravity: [0, 0, -1e300]}\n",
       ":17: plant.gravity has magnitude 1e+300 m/s^2; at most 10000 m/s^2"},
      // Issue 20: the scene's fields, checked like the rest.
      {"scene_shape", kTask + "scene:\n  obstacles:\n    - {shape: cone, center: [1, 0, 0]}\n",
       ":19: scene.obstacles[0].shape = cone"},
      {"scene_normal",
       kTask + "scene:\n  obstacles:\n    - {shape: half_space, normal: [0, 0, 0], "
               "offset: -0.1}\n",
       ":19: scene.obstacles[0].normal must not be zero"},
      {"scene_radius",
       kTask + "scene:\n  obstacles:\n    - {shape: sphere, center: [1, 0, 0], "
               "radius: .nan}\n",
       ":19: scene.obstacles[0].radius"},
      {"scene_key",
       kTask + "scene:\n  obstacles:\n    - {shape: sphere, centre: [1, 0, 0], "
               "radius: 0.1}\n",
       ":19: scene.obstacles[0].centre: unknown key; did you mean 'center'?"},
      {"scene_clamp",
       kTask + "scene:\n  obstacles:\n    - {shape: sphere, center: [0, 0, 0], "
               "radius: 0.01}\n",
       ": base.position lies inside obstacle 0 (0.01 m deep)"},
      {"scene_section",
       [] {
         std::string text =
             task_with("  section: {shape: rectangle, width: 0.02, height: 0.02}\n", "");
         const std::string stiffness = "stiffness: {EIx: 0.04, EIy: 0.04, GJ: 0.028}";
         text.replace(text.find(stiffness), stiffness.size(),
                      "stiffness: {EA: 1280, GA: 426.7, EIx: 0.04, EIy: 0.04, GJ: 0.028}");
         return text + "scene:\n  obstacles: []\n";
       }(),
       ":16: scene needs rod.section, which is missing"},
  };
  for (const Bad& bad : cases) {
    SCOPED_TRACE(bad.name);
    const fs::path task = write_task(std::string(bad.name) + ".yaml", bad.text);
    const fs::path outdir = directory_ / bad.name;
    const Outcome result = plan(task, outdir);
    EXPECT_EQ(result.exit_code, 2);
    expect_one_line(result.err);
    EXPECT_EQ(result.err.rfind("error: " + task.string() + bad.message, 0), 0u) << result.err;
    EXPECT_FALSE(fs::exists(outdir));
  }
}

TEST_F(CliPlan, UnboundedWorkIsBadInputNamedBeforePlanning) {
  // Each of these ran out of memory or for minutes before the bounds (docs/limits.md, "Sizes").
  struct Bad {
    const char* name;
    std::string text;
    const char* message;
  };
  const std::vector<Bad> cases = {
      {"speed", task_with("steps: 2", "steps: 2\n  max_linear_speed: 1e-12"),
       ":16: trajectory.max_linear_speed = 1e-12: a move of 1 m from rest to rest would take "
       "1e+12 s, 1e+14 samples at trajectory.rate = 100 Hz; an end-effector path has at most "
       "1e+06 samples"},
      {"rate", task_with("steps: 2", "steps: 2\n  rate: 1e9"),
       ":16: trajectory.rate = 1e9 must be <= 10000"},
      {"steps", task_with("steps: 2", "steps: 1e9"), ":15: trajectory.steps = 1e9 must be <= 1000"},
  };
  for (const Bad& bad : cases) {
    SCOPED_TRACE(bad.name);
    const fs::path task = write_task(std::string(bad.name) + "_bound.yaml", bad.text);
    const fs::path outdir = directory_ / (std::string(bad.name) + "_bound");
    const Outcome result = plan(task, outdir);
    EXPECT_EQ(result.exit_code, 2);
    expect_one_line(result.err);
    EXPECT_EQ(result.err, "error: " + task.string() + bad.message + "\n");
    EXPECT_FALSE(fs::exists(outdir));
  }
}

TEST_F(CliPlan, APathWithTooManySamplesIsBadInputCountedBeforeSampling) {
  // Each limit passes the check of a 1 m / 1 rad move (0.9e6 samples), but ten steps that each
  // turn the tip a little, every one from rest at this slow angular acceleration, take 2.2e6.
  const fs::path task = write_task(
      "long_path.yaml",
      task_with("steps: 2", "steps: 10\n  rate: 10000\n  max_angular_acceleration: 4.9e-4"));
  const fs::path outdir = directory_ / "long_path";
  const Outcome result = plan(task, outdir);
  EXPECT_EQ(result.exit_code, 2);
  expect_one_line(result.err);
  EXPECT_EQ(
      result.err.rfind(
          "error: " + task.string() + ":14: trajectory: the end-effector path would have 2.", 0),
      0u)
      << result.err;
  EXPECT_NE(result.err.find("e+06 samples (duration "), std::string::npos) << result.err;
  EXPECT_NE(result.err.find(" s at trajectory.rate = 10000 Hz); at most 1e+06: raise the speed "
                            "or acceleration limits, or lower trajectory.rate\n"),
            std::string::npos)
      << result.err;
  EXPECT_FALSE(fs::exists(outdir));
}

TEST_F(CliPlan, BadInputFoundWhilePlanningLeavesAnEarlierRunsFilesAlone) {
  // Issue 24: bad input found while planning (here the workspace excludes the initial tip;
  // likewise an initial.tip with no equilibrium) removed the earlier run's plan files. Bad input
  // writes and removes nothing; a run that plans replaces them.
  const fs::path outdir = directory_ / "stale";
  ASSERT_EQ(plan(write_task("earlier.yaml", kTask), outdir).exit_code, 0);
  const std::string earlier = read_file(outdir / "plan.json");
  std::ofstream(outdir / "notes.txt") << "mine\n";
  const fs::path task = write_task(
      "stale.yaml", kTask + "workspace:\n  box: {lower: [-1, -1, -1], upper: [1, 1, 0.25]}\n");
  EXPECT_EQ(plan(task, outdir).exit_code, 2);
  EXPECT_EQ(read_file(outdir / "plan.json"), earlier);
  for (const char* name : {"trajectory.csv", "plan.svg"})
    EXPECT_TRUE(fs::exists(outdir / name)) << name;

  // A run that plans replaces the earlier files; one it does not write (an earlier arm's joint
  // trajectory, recognised by its header) is removed; other files are left alone.
  std::ofstream(outdir / "joint_trajectory.csv") << "t,panda_joint1\n0,0\n";
  EXPECT_EQ(plan(write_task("again.yaml", kTask), outdir).exit_code, 0);
  EXPECT_FALSE(fs::exists(outdir / "joint_trajectory.csv"));
  EXPECT_TRUE(fs::exists(outdir / "notes.txt"));
}

TEST_F(CliPlan, AFileInTheWayThatIsNotAnEarlierRunsIsBadInputAndLeftAlone) {
  // Issue 24: any file named like a plan file was taken for an earlier run's and deleted.
  const fs::path outdir = directory_ / "mine";
  fs::create_directories(outdir);
  std::ofstream(outdir / "plan.svg") << "<svg>my drawing</svg>\n";
  const Outcome result = plan(write_task("mine.yaml", kTask), outdir);
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.err.rfind("error: " + (outdir / "plan.svg").string() +
                                 ": is in the way of an output and is not one rodshape wrote",
                             0),
            0u)
      << result.err;
  expect_one_line(result.err);
  EXPECT_EQ(read_file(outdir / "plan.svg"), "<svg>my drawing</svg>\n");
  EXPECT_FALSE(fs::exists(outdir / "plan.json"));
}

TEST_F(CliPlan, ATaskFileNamedLikeAnOutputIsNeverOverwrittenOrRemoved) {
  // Issue 24: a task file named plan.json in the output directory was deleted as an earlier
  // run's output.
  const fs::path outdir = directory_ / "here";
  fs::create_directories(outdir);
  const fs::path task = write_task("here/plan.json", kTask);
  const Outcome result = plan(task, outdir);
  EXPECT_EQ(result.exit_code, 2);
  expect_one_line(result.err);
  EXPECT_NE(result.err.find(", an input of this run"), std::string::npos) << result.err;
  EXPECT_EQ(read_file(task), kTask);
}

TEST_F(CliPlan, FailedStepExitsThreeAndWritesAPartialPlan) {
  const fs::path task = write_task("stuck.yaml", kTask + "optimizer: {max_iterations: 1}\n");
  const fs::path outdir = directory_ / "stuck";
  const Outcome result = plan(task, outdir);
  EXPECT_EQ(result.exit_code, 3) << result.err;
  expect_one_line(result.err);
  EXPECT_EQ(result.err.rfind("error: " + task.string() + ": partial plan: step ", 0), 0u)
      << result.err;
  const Json j = Json::parse(read_file(outdir / "plan.json"));
  EXPECT_EQ(j["status"], "partial");
  ASSERT_TRUE(j["failed_step"].is_number_integer());
  const int failed = j["failed_step"].get<int>();
  EXPECT_EQ(j["steps_completed"].get<int>(), failed - 1);
  EXPECT_EQ(j["steps"].size(), static_cast<std::size_t>(failed - 1));
  EXPECT_NE(result.err.find("step " + std::to_string(failed)), std::string::npos) << result.err;
  EXPECT_TRUE(j["reason"].is_string());
  // The steps that succeeded (none, or some) are still drawn and timed.
  EXPECT_TRUE(fs::exists(outdir / "trajectory.csv"));
  EXPECT_TRUE(fs::exists(outdir / "plan.svg"));
  expect_configuration(j["initial"], 51);
}

// The C arc with the paper's objective sets (projection): every step succeeds, but the tracked rod
// would jump even after the refinements. That is a defect with its own status and exit code 3.
TEST_F(CliPlan, SnapThroughExitsThreeWithItsOwnStatus) {
  std::string text = read_file(fs::path(RODSHAPE_SOURCE_DIR) / "examples" / "plan_c_arc.yaml");
  const std::string steps = "  steps: 7";
  const std::size_t at = text.find(steps);
  ASSERT_NE(at, std::string::npos);
  text.insert(at, "  interpolation: projection\n");
  const fs::path task = write_task("c_arc_projection.yaml", text);
  const fs::path outdir = directory_ / "snap";
  const Outcome result = plan(task, outdir);
  EXPECT_EQ(result.exit_code, 3) << result.err;
  expect_one_line(result.err);
  EXPECT_EQ(result.err.rfind("error: " + task.string() + ": snap-through: ", 0), 0u) << result.err;
  EXPECT_NE(result.err.find("towards waypoint"), std::string::npos) << result.err;
  const Json j = Json::parse(read_file(outdir / "plan.json"));
  EXPECT_EQ(j["status"], "snap_through");
  EXPECT_TRUE(j["tracking"]["jump"].get<bool>());
  EXPECT_TRUE(j["tracking"]["jump_step"].is_number_integer());
  EXPECT_GT(j["tracking"]["peak_energy"].get<double>(), 0.0);
  EXPECT_GT(j["tracking"]["peak_curvature"].get<double>(), 0.0);
  EXPECT_TRUE(j["reason"].is_string());
  EXPECT_TRUE(fs::exists(outdir / "trajectory.csv"));  // the plan is still written, to be looked at
}

TEST_F(CliPlan, OutputDirectoryThatIsAFileIsBadInput) {
  const fs::path task = write_task("bend.yaml", kTask);
  const fs::path file = write_task("taken", "not a directory\n");
  const Outcome result = plan(task, file);
  EXPECT_EQ(result.exit_code, 2);
  expect_one_line(result.err);
  EXPECT_NE(result.err.find("cannot create the output directory"), std::string::npos) << result.err;
  EXPECT_EQ(read_file(file), "not a directory\n");
}

TEST_F(CliPlan, MissingOutputOptionIsAUsageError) {
  const fs::path task = write_task("bend.yaml", kTask);
  EXPECT_EQ(run("plan " + quoted(task.string())).exit_code, 2);
}

}  // namespace
}  // namespace test_cli_plan

namespace test_cli_plan {
namespace {

// Issue 12, item 3: an initial tip 0.45 m from the clamp of the 0.29 m band (stretched 55 %; within
// its reach, 0.48 m with shear) is bad input, and the limit is the task's
// (limits.model.max_axial_strain). (1.0 m away, it is out of reach before solving: issue 24.)
TEST_F(CliPlan, InitialTipBeyondTheModelsRangeIsBadInput) {
  const std::string far =
      kTask + "initial:\n  tip: {position: [0, 0, 0.45], rotation: [1, 0, 0, 0]}\n";
  const fs::path task = write_task("stretched.yaml", far);
  const fs::path outdir = directory_ / "stretched";
  const Outcome result = plan(task, outdir);
  EXPECT_EQ(result.exit_code, 2);
  expect_one_line(result.err);
  EXPECT_NE(result.err.find("initial.tip: the rod would be stretched"), std::string::npos)
      << result.err;
  EXPECT_NE(result.err.find("limits.model.max_axial_strain = 0.5"), std::string::npos)
      << result.err;
  EXPECT_FALSE(fs::exists(outdir));
}

TEST_F(CliPlan, ModelValidityLimitsAreRead) {
  const fs::path task =
      write_task("limit.yaml", kTask + "limits: {model: {max_axial_strain: -1}}\n");
  const Outcome result = plan(task, directory_ / "limit");
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("limits.model.max_axial_strain"), std::string::npos) << result.err;
}

}  // namespace
}  // namespace test_cli_plan
