// test_plan_output.cpp: plan.json, trajectory.csv and plan.svg on a hand-made plan (configurations
// integrated from chosen base wrenches, no optimiser): every documented key, a step's configuration
// written exactly as `equilibrium` writes its result, times and quaternions of the CSV, and an SVG
// that is one well-formed document with the three projections.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/core/so3.hpp"
#include "rodshape/io/output_files.hpp"
#include "rodshape/io/plan_output.hpp"
#include "rodshape/io/result_json.hpp"
#include "rodshape/io/task_reader.hpp"
#include "support/hand_made_plan.hpp"

namespace rodshape {
namespace test_plan_output {
namespace {

using Json = nlohmann::json;

using testing::kHandMadeTask;
using testing::make_plan;
const std::string& kTask = kHandMadeTask;

TEST(PlanOutput, JsonHasEveryDocumentedKey) {
  const PlanTask task = parse_plan_task(kTask, "plan.yaml");
  const PlanResult plan = make_plan(task, 3);
  const Json j = Json::parse(plan_result_json(plan, task));
  EXPECT_EQ(j["status"], "complete");
  EXPECT_EQ(j["message"], "complete: 3 steps");
  EXPECT_TRUE(j["reason"].is_null());
  EXPECT_TRUE(j["failed_step"].is_null());
  EXPECT_EQ(j["steps_requested"], 3);
  EXPECT_EQ(j["steps_completed"], 3);
  EXPECT_EQ(j["source"], "plan.yaml");
  EXPECT_EQ(j["target"]["points"].size(), 3u);
  EXPECT_EQ(j["target"]["squared_distances"], false);
  EXPECT_EQ(j["feasibility"]["feasible"], true);
  EXPECT_TRUE(j["feasibility"]["offending_point"].is_null());
  EXPECT_EQ(j["final"]["step"], 3);
  EXPECT_EQ(j["final"]["max_distance"], 0.002);
  EXPECT_EQ(j["final"]["iterations"], 11 + 12 + 13);
  EXPECT_EQ(j["initial"]["nodes"]["s"].size(), 21u);
  EXPECT_TRUE(j["initial"]["stable"].is_null());
  EXPECT_EQ(j["initial_points"].size(), 3u);
  ASSERT_EQ(j["steps"].size(), 3u);
  const Json& step = j["steps"][1];
  EXPECT_EQ(step["step"], 2);
  EXPECT_EQ(step["distances"], Json::parse("[0.002, 0.002, 0.0005]"));
  EXPECT_EQ(step["stable"], true);
  EXPECT_EQ(step["solver"]["status"], "converged");
  EXPECT_EQ(step["solver"]["iterations"], 12);
  EXPECT_EQ(step["solver"]["ipopt_status"], "Solve_Succeeded");
  for (const char* key : {"total", "energy_term", "distance_term"})
    EXPECT_TRUE(step["cost"].contains(key)) << key;
  EXPECT_EQ(j["end_effector_path"]["samples"], plan.end_effector_path.size());
  EXPECT_EQ(j["end_effector_path"]["waypoints"].size(), 3u);
  EXPECT_EQ(j["tracking"]["performed"], false);
}

TEST(PlanOutput, StepConfigurationIsWhatEquilibriumWrites) {
  const PlanTask task = parse_plan_task(kTask, "plan.yaml");
  const PlanResult plan = make_plan(task, 3);
  const Json j = Json::parse(plan_result_json(plan, task));
  const ShapeResult& last = plan.steps.back().solution;
  ShootingResult as_equilibrium;
  as_equilibrium.base_wrench = last.base_wrench;
  as_equilibrium.configuration = last.configuration;
  const Json equilibrium =
      Json::parse(equilibrium_result_json(as_equilibrium, last.stability, task.problem.rod));
  const Json& configuration = j["steps"][2]["configuration"];
  ASSERT_FALSE(configuration.empty());
  for (const auto& [key, value] : configuration.items()) EXPECT_EQ(value, equilibrium[key]) << key;
  EXPECT_EQ(configuration.size() + 10, equilibrium.size());  // + the solver's ten fields
  EXPECT_TRUE(configuration.contains("strain"));
}

TEST(PlanOutput, PartialPlanSaysWhichStepFailed) {
  const PlanTask task = parse_plan_task(kTask, "plan.yaml");
  const PlanResult plan = make_plan(task, 2);
  const Json j = Json::parse(plan_result_json(plan, task));
  EXPECT_EQ(j["status"], "partial");
  EXPECT_EQ(j["failed_step"], 3);
  EXPECT_EQ(j["reason"], "step 3 of 3 failed: <because>");
  EXPECT_EQ(j["steps"].size(), 2u);
  EXPECT_EQ(j["final"]["step"], 2);
}

TEST(PlanOutput, InfeasiblePlanNamesTheOffendingPoint) {
  const PlanTask task = parse_plan_task(kTask + "# far\n", "plan.yaml");
  PlanTask far = task;
  far.problem.target.points[1] = Eigen::Vector3d(0, 0.6, 0);
  PlanResult plan;
  plan.status = PlanStatus::Infeasible;
  plan.feasibility =
      check_feasibility(far.problem.target, far.problem.rod);  // as plan() records it
  plan.message = plan.feasibility.reason;
  ASSERT_TRUE(plan.message.starts_with("ShapeTarget.points[1] ")) << plan.message;
  const Json j = Json::parse(plan_result_json(plan, far));
  EXPECT_EQ(j["status"], "infeasible");
  // The library's field, said as the task file says it.
  EXPECT_EQ(j["reason"], "target.points[1] " + plan.message.substr(22));
  EXPECT_EQ(j["feasibility"]["feasible"], false);
  EXPECT_EQ(j["feasibility"]["offending_point"], 1);
  EXPECT_EQ(j["feasibility"]["offending_position"], Json::parse("[0.0, 0.6, 0.0]"));
  EXPECT_TRUE(j["initial"].is_null());
  EXPECT_TRUE(j["final"].is_null());
  EXPECT_EQ(j["steps"].size(), 0u);
}

TEST(PlanOutput, TrajectoryCsvHasIncreasingTimesAndContinuousUnitQuaternions) {
  std::vector<TimedPose> path;
  for (int k = 0; k <= 40; ++k) {
    // A full turn about z: the quaternion passes w = 0, where q and -q would swap.
    const Eigen::Matrix3d R = exp_so3(Eigen::Vector3d(0, 0, 2 * M_PI * k / 40.0));
    path.push_back({0.1 * k, Pose{Eigen::Vector3d(0.01 * k, 0, 0.2), R}});
  }
  std::istringstream csv(trajectory_csv(path));
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line, "t,x,y,z,qw,qx,qy,qz");
  double previous_t = -1.0;
  Eigen::Vector4d previous_q = Eigen::Vector4d::Zero();
  int rows = 0;
  while (std::getline(csv, line)) {
    std::vector<double> v;
    std::stringstream fields(line);
    for (std::string field; std::getline(fields, field, ',');) v.push_back(std::stod(field));
    ASSERT_EQ(v.size(), 8u);
    EXPECT_GT(v[0], previous_t);
    previous_t = v[0];
    const Eigen::Vector4d q(v[4], v[5], v[6], v[7]);
    EXPECT_NEAR(q.norm(), 1.0, 1e-11);
    if (rows == 0) {
      EXPECT_GE(q[0], 0.0);
    } else {
      EXPECT_GT(q.dot(previous_q), 0.0) << "row " << rows;
    }
    previous_q = q;
    ++rows;
  }
  EXPECT_EQ(rows, 41);
}

TEST(PlanOutput, SvgIsOneDocumentWithThreeProjections) {
  const PlanTask task = parse_plan_task(kTask, "a<b&c.yaml");
  const PlanResult plan = make_plan(task, 3);
  const std::string svg = plan_svg(plan, task);
  // The declaration, then the signature that tells an earlier run's output (issue 24).
  EXPECT_EQ(
      svg.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n" + svg_signature_comment() + "\n<svg",
                0),
      0u);
  EXPECT_EQ(svg.substr(svg.size() - 7), "</svg>\n");
  EXPECT_EQ(svg.find("<svg"), svg.rfind("<svg"));  // one document
  int panels = 0;
  for (std::size_t at = svg.find("<clipPath"); at != std::string::npos;
       at = svg.find("<clipPath", at + 1))
    ++panels;
  EXPECT_EQ(panels, 3);
  // Initial rod + 3 steps in each panel, and the legend's lines.
  int polylines = 0;
  for (std::size_t at = svg.find("<polyline"); at != std::string::npos;
       at = svg.find("<polyline", at + 1))
    ++polylines;
  EXPECT_EQ(polylines, 3 * 4);
  EXPECT_NE(svg.find("a&lt;b&amp;c.yaml"), std::string::npos);  // text is escaped
  EXPECT_EQ(svg.find("a<b&c"), std::string::npos);
  EXPECT_EQ(svg.find("nan"), std::string::npos);
  EXPECT_EQ(svg.find("inf"), std::string::npos);
}

TEST(PlanOutput, SvgOfAPlanWithoutStepsStillDrawsTheInitialRod) {
  const PlanTask task = parse_plan_task(kTask, "plan.yaml");
  PlanResult plan = make_plan(task, 0);
  const std::string svg = plan_svg(plan, task);
  EXPECT_EQ(svg.substr(svg.size() - 7), "</svg>\n");
  EXPECT_NE(svg.find("step 3 of 3 failed"), std::string::npos);
  EXPECT_EQ(svg.find("nan"), std::string::npos);
}

}  // namespace
}  // namespace test_plan_output
}  // namespace rodshape
