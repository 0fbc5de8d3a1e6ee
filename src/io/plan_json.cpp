// plan_json.cpp: plan.json and trajectory.csv (schemas in docs/task-file.md). A step's
// configuration is written by configuration_json(), exactly as `equilibrium` writes its result.
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <sstream>
#include <string>

#include "io/json_format.hpp"
#include "io/scene_json.hpp"
#include "rodshape/error.hpp"
#include "rodshape/io/field_names.hpp"
#include "rodshape/io/output_files.hpp"
#include "rodshape/io/plan_output.hpp"
#include "rodshape/optimisation/shape_target.hpp"
#include "rodshape/solvers/solve_status.hpp"

namespace rodshape {

namespace {

using io_detail::Json;
using io_detail::json_number;
using io_detail::json_pose;
using io_detail::json_vector;
using io_detail::json_vectors;

Json numbers(const std::vector<double>& values) {
  Json list = Json::array();
  for (const double value : values) list.push_back(json_number(value));
  return list;
}

Json target_object(const ShapeTarget& target) {
  return {
      {"points", json_vectors(target.points)},
      {"weights",
       {{"energy", json_number(target.energy_weight)},
        {"distance", json_number(target.distance_weight)}}},
      {"squared_distances", target.squared_distances},
  };
}

Json feasibility_object(const FeasibilityResult& feasibility, const PointSet& target) {
  const int offending = feasibility.offending_point;
  const bool has_offending = offending >= 0 && offending < static_cast<int>(target.size());
  return {
      {"feasible", feasibility.feasible},
      {"reason",
       feasibility.feasible ? Json(nullptr) : Json(fields_in_task_names(feasibility.reason))},
      {"offending_point", has_offending ? Json(offending) : Json(nullptr)},
      {"offending_position",
       has_offending ? json_vector(target[static_cast<std::size_t>(offending)]) : Json(nullptr)},
      {"curve_length", json_number(feasibility.curve_length)},
      {"reach", json_number(feasibility.reach)},
  };
}

Json solver_object(const ShapeResult& solution) {
  return {
      {"status", to_string(solution.status)},
      {"message", fields_in_task_names(solution.message)},
      {"iterations", solution.ipopt.iterations},
      {"ipopt_status", solution.ipopt.application_status_name},
      {"objective", json_number(solution.ipopt.objective)},
      {"starts_tried", solution.starts_tried},
      {"max_constraint_violation", json_number(solution.max_constraint_violation)},
  };
}

Json step_object(const PlanStep& step, int number, const RodProperties& properties) {
  const ShapeResult& solution = step.solution;
  const ShapeCostBreakdown& cost = solution.cost;
  Json result;
  result["step"] = number;
  result["fraction"] = json_number(step.fraction);
  result["inserted"] = step.inserted;
  result["detour"] = step.detour;
  result["objective_points"] = json_vectors(step.objective_points);
  result["configuration"] = io_detail::configuration_json(
      solution.configuration, solution.base_wrench, solution.stability, properties);
  result["end_effector"] = json_pose(step.end_effector);
  result["base_end_effector"] = json_pose(step.base_end_effector);
  result["energy"] = json_number(cost.energy);
  result["cost"] = {
      {"total", json_number(cost.cost)},
      {"energy_term", json_number(cost.energy_term)},
      {"distance_term", json_number(cost.distance_term)},
  };
  result["distances"] = numbers(cost.distances);
  result["max_distance"] = json_number(cost.max_distance);
  result["stable"] = solution.stability ? Json(solution.stability->stable) : Json(nullptr);
  result["solver"] = solver_object(solution);
  return result;
}

Json final_object(const PlanResult& plan) {
  if (plan.steps.empty()) return nullptr;
  const ShapeResult& last = plan.steps.back().solution;
  int iterations = 0;
  for (const PlanStep& step : plan.steps) iterations += step.solution.ipopt.iterations;
  double mean = 0.0;
  for (const double d : last.cost.distances) mean += d;
  if (!last.cost.distances.empty()) mean /= static_cast<double>(last.cost.distances.size());
  return {
      {"step", static_cast<int>(plan.steps.size())},
      {"max_distance", json_number(last.cost.max_distance)},
      {"mean_distance", json_number(mean)},
      {"energy", json_number(last.cost.energy)},
      {"stable", last.stability ? Json(last.stability->stable) : Json(nullptr)},
      {"iterations", iterations},
  };
}

Json path_object(const PlanResult& plan) {
  const std::vector<TimedPose>& path = plan.end_effector_path;
  Json waypoints = Json::array();
  for (const PlanStep& step : plan.steps) waypoints.push_back(json_pose(step.end_effector));
  return {
      {"file", path.empty() ? Json(nullptr) : Json("trajectory.csv")},
      {"duration", path.empty() ? Json(nullptr) : json_number(path.back().t)},
      {"samples", static_cast<int>(path.size())},
      {"start", path.empty() ? Json(nullptr) : json_pose(path.front().pose)},
      {"waypoints", std::move(waypoints)},
  };
}

Json tracking_object(const TrackingResult& tracking) {
  return {
      {"performed", tracking.performed},
      {"arrival_deviation", numbers(tracking.arrival_deviation)},
      {"max_deviation", json_number(tracking.max_deviation)},
      {"jump", tracking.jump},
      {"jump_step", tracking.jump_step >= 0 ? Json(tracking.jump_step + 1) : Json(nullptr)},
      {"refinements", tracking.refinements},
      {"energy_released",
       tracking.energy_released ? json_number(*tracking.energy_released) : Json(nullptr)},
      {"peak_energy", json_number(tracking.peak_energy)},
      {"peak_curvature", json_number(tracking.peak_curvature)},
      {"note", tracking.note},
  };
}

/// `file`: joint_trajectory.csv (the tip's arm) or base_joint_trajectory.csv (the base's).
Json joint_trajectory_object(const JointTrajectoryResult& joints, const char* file) {
  const bool complete = joints.complete();
  return {
      {"status", to_string(joints.status)},
      {"message", fields_in_task_names(joints.message)},
      {"file", complete ? Json(file) : Json(nullptr)},
      {"samples", static_cast<int>(joints.t.size())},
      {"duration", complete ? json_number(joints.duration()) : Json(nullptr)},
      {"path_duration", json_number(joints.path_duration)},
      {"slowed", joints.slowed},
      {"slowdown", json_number(joints.slowdown)},
      {"failed_sample", joints.failed_sample >= 0 ? Json(joints.failed_sample) : Json(nullptr)},
      {"ik_restarts", joints.ik_restarts},
      {"max_position_error", json_number(joints.max_position_error)},
      {"max_rotation_error", json_number(joints.max_rotation_error)},
  };
}

Json joint_values(const Eigen::VectorXd& values) {
  Json list = Json::array();
  for (Eigen::Index j = 0; j < values.size(); ++j) list.push_back(json_number(values(j)));
  return list;
}

/// ROS builtin_interfaces/Duration: whole seconds and nanoseconds in [0, 1e9).
Json ros_duration(double seconds) {
  const auto total = static_cast<std::int64_t>(std::llround(seconds * 1e9));
  std::int64_t sec = total / 1000000000;
  std::int64_t nanosec = total % 1000000000;
  if (nanosec < 0) {
    nanosec += 1000000000;
    --sec;
  }
  return {{"sec", sec}, {"nanosec", nanosec}};
}

Json shell_object(const Workspace::ReachShell& shell) {
  return {{"center", json_vector(shell.center)},
          {"inner_radius", json_number(shell.inner_radius)},
          {"outer_radius", json_number(shell.outer_radius)},
          {"tip_point", json_vector(shell.tip_point)}};
}

/// The rod's base pose of a configuration: p(0), R(0), the pose the base arm's shell bounds.
Pose base_pose(const RodConfiguration& configuration) {
  return {configuration.p[0], configuration.R[0]};
}

/// `robot` (the tip's arm, its shell's distances at the rod's tip) or `base_robot` (the base's, at
/// the rod's base pose).
Json robot_object(const PlanResult& plan,
                  const ArmPlanResult& arm,
                  const ArmPlanOptions& options,
                  bool base_end) {
  const auto end_pose = [&](const RodConfiguration& configuration) {
    return base_end ? base_pose(configuration) : configuration.tip();
  };
  Json reach = nullptr;
  if (arm.reach && arm.shell) {
    reach = shell_object(*arm.shell);
    reach["wrist_range"] = {json_number(arm.reach->min_distance),
                            json_number(arm.reach->max_distance)};
    reach["margin"] = json_number(options.reach_margin);
    // |w - c| where the rod starts and at each step: how close the plan came to the shell.
    Json distances = Json::array();
    const auto distance = [&](const Pose& tip) { return json_number(arm.shell->distance(tip)); };
    distances.push_back(distance(end_pose(plan.initial_configuration)));
    for (const PlanStep& step : plan.steps)
      distances.push_back(distance(end_pose(step.solution.configuration)));
    reach["wrist_distances"] = std::move(distances);
  }
  Json replans = Json::array();
  for (const Replan& replan : arm.replans) {
    Json entry = shell_object(replan.shell);
    entry["reason"] = fields_in_task_names(replan.reason);
    entry["wrist_distance"] = json_number(replan.wrist_distance);
    replans.push_back(std::move(entry));
  }
  Json waypoints = Json::array();
  for (const Eigen::VectorXd& q : arm.waypoint_q) waypoints.push_back(joint_values(q));
  return {{"status", to_string(arm.status)},
          {"message", fields_in_task_names(arm.message)},
          {"reach", std::move(reach)},
          {"replans", std::move(replans)},
          {"waypoint_joint_positions", std::move(waypoints)}};
}

/// `interpolation`: the scheme that made the plan and each one tried (trajectory.interpolation).
Json interpolation_object(const InterpolationResult& interpolation) {
  Json tried = Json::array();
  for (const InterpolationTrial& trial : interpolation.tried) {
    Json entry;
    entry["scheme"] = to_string(trial.scheme);
    entry["status"] = to_string(trial.status);
    entry["peak_ratio"] = std::isfinite(trial.peak_ratio) ? Json(trial.peak_ratio) : Json(nullptr);
    entry["note"] = trial.note.empty() ? Json(nullptr) : Json(fields_in_task_names(trial.note));
    tried.push_back(std::move(entry));
  }
  Json result;
  result["used"] = to_string(interpolation.used);
  result["tried"] = std::move(tried);
  return result;
}

}  // namespace

std::string plan_result_json(const PlanResult& plan, const PlanTask& task) {
  const PlanProblem& request = task.problem;
  const RodProperties& properties = request.rod.properties;
  const bool complete = plan.status == PlanStatus::Complete;

  Json result;
  result[kGeneratorKey] = generator_signature();  // an earlier run's output, told by its first key
  result["status"] = to_string(plan.status);
  result["message"] = fields_in_task_names(plan.message);
  result["reason"] = complete ? Json(nullptr) : Json(fields_in_task_names(plan.message));
  result["failed_step"] = plan.failed_step >= 0 ? Json(plan.failed_step + 1) : Json(nullptr);
  result["steps_requested"] = task.options.steps;
  result["steps_completed"] = static_cast<int>(plan.steps.size());
  result["source"] = task.source;
  result["target"] = target_object(request.target);
  result["feasibility"] = feasibility_object(plan.feasibility, task.problem.target.points);
  result["final"] = final_object(plan);
  result["reach"] = {
      {"target_distance", json_number(plan.target_distance)},
      {"target_point", plan.target_point >= 0 ? Json(plan.target_point) : Json(nullptr)},
      {"tolerance", json_number(plan.reach_tolerance)}};
  result["initial"] =
      plan.initial_configuration.nodes() > 0
          ? io_detail::configuration_json(plan.initial_configuration, plan.initial_wrench,
                                          std::nullopt, properties)
          : Json(nullptr);
  result["initial_stable_search"] =
      plan.initial_stable_search ? Json(*plan.initial_stable_search) : Json(nullptr);
  result["initial_points"] = json_vectors(plan.initial_points);
  Json steps = Json::array();
  for (std::size_t k = 0; k < plan.steps.size(); ++k)
    steps.push_back(step_object(plan.steps[k], static_cast<int>(k) + 1, properties));
  result["steps"] = std::move(steps);
  result["end_effector_path"] = path_object(plan);
  result["tracking"] = tracking_object(plan.tracking);
  result["interpolation"] = interpolation_object(plan.interpolation);
  result["scene"] = io_detail::scene_json(request.scene, plan.scene,
                                          request.arm.has_value() && request.base_arm.has_value());
  result["robot"] =
      plan.arm ? robot_object(plan, *plan.arm, task.options.arm, false) : Json(nullptr);
  result["joint_trajectory"] =
      plan.arm ? joint_trajectory_object(plan.arm->joints, "joint_trajectory.csv") : Json(nullptr);
  // The arm that holds the base end (issue 21): only with one, so that a plan without it keeps
  // its document.
  if (plan.base_arm) {
    result["base_robot"] = robot_object(plan, *plan.base_arm, task.options.arm, true);
    result["base_joint_trajectory"] =
        joint_trajectory_object(plan.base_arm->joints, "base_joint_trajectory.csv");
  }
  return io_detail::format_json(result);
}

std::string joint_trajectory_csv(const JointTrajectoryResult& trajectory) {
  std::ostringstream out;
  out << "t";
  for (const std::string& name : trajectory.joint_names) out << ',' << name;
  out << '\n' << std::setprecision(12);
  for (std::size_t i = 0; i < trajectory.t.size() && i < trajectory.q.size(); ++i) {
    out << trajectory.t[i];
    for (Eigen::Index j = 0; j < trajectory.q[i].size(); ++j) out << ',' << trajectory.q[i](j);
    out << '\n';
  }
  return out.str();
}

std::string joint_trajectory_json(const JointTrajectoryResult& trajectory) {
  Json points = Json::array();
  for (std::size_t i = 0; i < trajectory.t.size() && i < trajectory.q.size(); ++i) {
    Json point;
    point["positions"] = joint_values(trajectory.q[i]);
    point["velocities"] =
        i < trajectory.qdot.size() ? joint_values(trajectory.qdot[i]) : Json::array();
    point["time_from_start"] = ros_duration(trajectory.t[i]);
    points.push_back(std::move(point));
  }
  Json result;
  result[kGeneratorKey] = generator_signature();
  result["joint_names"] = trajectory.joint_names;
  result["points"] = std::move(points);
  return io_detail::format_json(result);
}

namespace {

/// ",x,y,z,qw,qx,qy,qz" of `pose`, its quaternion in the hemisphere of `previous` (then updated).
void write_pose_columns(std::ostream& out, const Pose& pose, Eigen::Vector4d& previous) {
  Eigen::Vector4d q = pose.quaternion_wxyz();  // w ≥ 0 for the first
  if (previous.dot(q) < 0.0) q = -q;           // stay in the previous hemisphere
  previous = q;
  const Eigen::Vector3d& p = pose.position;
  out << ',' << p.x() << ',' << p.y() << ',' << p.z() << ',' << q[0] << ',' << q[1] << ',' << q[2]
      << ',' << q[3];
}

}  // namespace

std::string trajectory_csv(const std::vector<TimedPose>& path,
                           const std::vector<TimedPose>& base_path) {
  const bool base = !base_path.empty();
  if (base && base_path.size() != path.size())
    throw InputError("PlanResult.base_end_effector_path",
                     " has " + std::to_string(base_path.size()) +
                         " samples, the end-effector path " + std::to_string(path.size()) +
                         ": the two grippers' paths share one clock, sample for sample");
  std::ostringstream out;
  out << (base ? kTrajectoryCsvHeaderWithBase : kTrajectoryCsvHeader) << '\n';
  out << std::setprecision(12);
  Eigen::Vector4d previous = Eigen::Vector4d::Zero();
  Eigen::Vector4d previous_base = Eigen::Vector4d::Zero();
  for (std::size_t i = 0; i < path.size(); ++i) {
    out << path[i].t;
    write_pose_columns(out, path[i].pose, previous);
    if (base) write_pose_columns(out, base_path[i].pose, previous_base);
    out << '\n';
  }
  return out.str();
}

}  // namespace rodshape
