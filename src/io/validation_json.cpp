// validation_json.cpp: the validation document (validation_output.hpp; schema in
// docs/task-file.md, "validate").
#include <algorithm>
#include <optional>
#include <variant>

#include "io/json_format.hpp"
#include "rodshape/io/output_files.hpp"
#include "rodshape/io/validation_output.hpp"

namespace rodshape {

namespace {

using io_detail::Json;
using io_detail::json_number;

Json validation_numbers(const std::vector<double>& values) {
  Json list = Json::array();
  for (double v : values) list.push_back(json_number(v));
  return list;
}

Json plant_object(const ValidationResult& result, const PlantModel& plant) {
  const RodProperties& k = result.real_rod.properties;
  Json j;
  j["stiffness_scale"] = plant.stiffness_scale;
  j["EA"] = k.K_tra.z();
  j["GA"] = k.K_tra.x();
  j["EIx"] = k.K_rot.x();
  j["EIy"] = k.K_rot.y();
  j["GJ"] = k.K_rot.z();
  j["length"] = k.length;
  j["mass_per_length"] = k.mass_per_length;
  j["gravity"] = io_detail::json_vector(plant.acting_gravity());  // the one that acted
  j["rest_curvature"] = io_detail::json_vector(k.u_rest);
  j["grasp_offset"] = io_detail::json_pose(plant.grasp_offset);
  return j;
}

Json wrench_noise(const std::optional<WristNoise>& wrist) {
  return wrist ? Json{{"force", wrist->force}, {"moment", wrist->moment}} : Json(nullptr);
}

Json sensor_object(const MarkerSensorModel& sensor) {
  Json j;
  j["kind"] = to_string(SensorKind::Markers);
  j["markers"] = sensor.markers;
  j["noise"] = {{"in_plane", sensor.in_plane_noise}, {"depth", sensor.depth_noise}};
  j["dropout"] = sensor.dropout;
  j["frame_rate"] = sensor.frame_rate;
  j["camera"] = io_detail::json_pose(sensor.camera);
  j["wrench_noise"] = wrench_noise(sensor.wrist);
  return j;
}

Json sensor_object(const DepthSensorModel& sensor) {
  Json j;
  j["kind"] = to_string(SensorKind::Depth);
  j["depth"] = {{"resolution", {sensor.width, sensor.height}},
                {"field_of_view", {sensor.fov_x_deg, sensor.fov_y_deg}},
                {"range", {sensor.min_range, sensor.max_range}},
                {"points", sensor.points},
                {"noise",
                 {{"a0", sensor.noise.a0},
                  {"a1", sensor.noise.a1},
                  {"a2", sensor.noise.a2},
                  {"incidence", sensor.noise.incidence},
                  {"lateral_pixels", sensor.noise.lateral_pixels}}},
                {"outliers", sensor.outliers}};
  j["frame_rate"] = sensor.frame_rate;
  j["camera"] = io_detail::json_pose(sensor.camera);
  j["wrench_noise"] = wrench_noise(sensor.wrist);
  return j;
}

Json events_array(const std::vector<PlantEvent>& events) {
  Json list = Json::array();
  for (const PlantEvent& e : events) {
    Json event = {{"time", e.t},
                  {"kind", to_string(e.kind)},
                  {"energy_released", json_number(e.energy_released)},
                  {"message", e.message}};
    if (e.kind == PlantEvent::Kind::Contact) {
      event["obstacle"] = e.obstacle;
      event["depth"] = json_number(e.depth);
    }
    list.push_back(std::move(event));
  }
  return list;
}

Json checkpoints_array(const std::vector<Checkpoint>& checkpoints) {
  Json list = Json::array();
  for (const Checkpoint& c : checkpoints)
    list.push_back({{"time", c.t},
                    {"waypoint", c.waypoint},
                    {"base_wrench", io_detail::json_wrench(c.estimate.base_wrench)},
                    {"stiffness_scale", c.estimate.stiffness_scale},
                    {"load_factor", c.estimate.load_factor},
                    {"stiffness_sigma", json_number(c.estimate.stiffness_sigma)},
                    {"load_factor_sigma", json_number(c.estimate.load_factor_sigma)},
                    {"grasp_offset", io_detail::json_pose(c.grasp_offset)},
                    {"residual", json_number(c.estimate.residual)},
                    {"converged", c.estimate.converged()},
                    {"status", to_string(c.estimate.status)},
                    {"chi2_drop", json_number(c.estimate.prior_chi2 - c.estimate.chi2)},
                    {"parameters", c.estimate.parameters},
                    {"consistent", c.consistent},
                    {"significant", c.significant},
                    {"replanned", c.replanned},
                    {"points", c.points},
                    {"outliers", c.estimate.outliers},
                    {"shape_rms", json_number(c.shape_rms)},
                    {"message", c.message}});
  return list;
}

Json run_object(const ValidationRun& run) {
  Json j;
  j["seed"] = run.seed;
  j["closed_loop"] = run.closed_loop;
  j["time"] = validation_numbers(run.time);
  j["error_3d"] = validation_numbers(run.error_3d);
  j["error_2d"] = validation_numbers(run.error_2d);
  j["true_error"] = validation_numbers(run.true_error);
  j["visible_markers"] = run.visible_markers;  // a depth camera: the points of each frame's cloud
  j["final"] = {{"error_3d", json_number(run.final.error_3d)},
                {"error_2d", json_number(run.final.error_2d)},
                {"true_error", json_number(run.final.true_error)},
                {"true_max_distance", json_number(run.final.true_max_distance)}};
  j["events"] = events_array(run.events);
  j["min_gap"] = json_number(run.min_gap);              // null without a scene
  j["estimates"] = checkpoints_array(run.checkpoints);  // none in open loop
  const PlantFrame& last = run.plant_final;
  j["plant_final"] = {{"time", last.t},
                      {"base_wrench", io_detail::json_wrench(last.base_wrench)},
                      {"tip", io_detail::json_pose(last.configuration.tip())}};
  return j;
}

}  // namespace

std::string base_driven_by(const ValidationResult& result) {
  const auto all = [&](auto flag) {
    return !result.runs.empty() && std::all_of(result.runs.begin(), result.runs.end(), flag);
  };
  if (all([](const ValidationRun& run) { return run.base_driven_by_joints; }))
    return "base_joint_trajectory";
  const bool moved = std::any_of(result.runs.begin(), result.runs.end(),
                                 [](const ValidationRun& run) { return run.base_moved; });
  return moved ? "base_end_effector_path" : "clamp";
}

std::string validation_json(const ValidationResult& result,
                            const PlanResult& plan,
                            const PlanTask& task) {
  Json j;
  j[kGeneratorKey] = generator_signature();  // an earlier run's output, told by its first key
  j["status"] = to_string(result.status);
  j["message"] = result.message;
  j["source"] = task.source;
  j["plan"] = {
      {"status", to_string(plan.status)},
      {"steps", static_cast<int>(plan.steps.size())},
      {"duration", plan.end_effector_path.empty() ? 0.0 : plan.end_effector_path.back().t}};
  j["plant"] = plant_object(result, task.plant);
  j["sensor"] =
      std::visit([](const auto& sensor) { return sensor_object(sensor); }, task.sensor_model());
  j["driven_by"] = result.driven_by_joints() ? "joint_trajectory" : "end_effector_path";
  // A moving base (issue 21): what drove the base end; left out with a fixed clamp.
  if (task.problem.base_moves()) j["base_driven_by"] = base_driven_by(result);
  j["plant_solves"] = result.plant.solves;
  Json runs = Json::array();
  for (const ValidationRun& run : result.runs) runs.push_back(run_object(run));
  j["runs"] = std::move(runs);
  return io_detail::format_json(j);
}

}  // namespace rodshape
