// sim_sections.cpp: the plant and sensor sections of a plan task (docs/task-file.md, "validate").
#include "io/sim_sections.hpp"

#include "io/task_sections.hpp"

#include <optional>
#include <string_view>
#include <vector>

namespace rodshape::io_detail {

namespace {

void read_number_into(const YamlField& parent, const char* key, double& value) {
  if (const YamlField field = parent.get(key); field.present()) value = field.number();
}

StiffnessFactors read_stiffness_factors(const YamlField& factors) {
  factors.expect_mapping({"EA", "GA", "EIx", "EIy", "GJ"});
  StiffnessFactors result;
  read_number_into(factors, "EA", result.EA);
  read_number_into(factors, "GA", result.GA);
  read_number_into(factors, "EIx", result.EIx);
  read_number_into(factors, "EIy", result.EIy);
  read_number_into(factors, "GJ", result.GJ);
  return result;
}

}  // namespace

PlantModel read_plant_section(const YamlField& plant) {
  plant.expect_mapping({"stiffness_scale", "stiffness_factors", "length", "mass_per_length",
                        "gravity", "rest_curvature", "grasp_offset"});
  PlantModel model;
  read_number_into(plant, "stiffness_scale", model.stiffness_scale);
  if (const YamlField factors = plant.get("stiffness_factors"); factors.present())
    model.factors = read_stiffness_factors(factors);
  if (const YamlField length = plant.get("length"); length.present())
    model.length = length.number();
  if (const YamlField mass = plant.get("mass_per_length"); mass.present())
    model.mass_per_length = mass.number();
  if (const YamlField gravity = plant.get("gravity"); gravity.present())
    model.gravity = gravity.vector3();
  if (const YamlField curvature = plant.get("rest_curvature"); curvature.present())
    model.rest_curvature = curvature.vector3();
  if (const YamlField offset = plant.get("grasp_offset"); offset.present())
    model.grasp_offset = read_pose(offset);
  plant.located([&] { model.validate(); });
  return model;
}

Eigen::Vector3d read_planner_gravity(const YamlField& root) {
  if (const YamlField gravity = root.get("gravity"); gravity.present()) return gravity.vector3();
  return Eigen::Vector3d::Zero();
}

namespace {

/// `wrench_noise {force, moment}`: the wrist sensor's noise (absent: no wrist sensor).
std::optional<WristNoise> read_wrench_noise(const YamlField& sensor) {
  const YamlField wrench = sensor.get("wrench_noise");
  if (!wrench.present()) return std::nullopt;
  wrench.expect_mapping({"force", "moment"});
  WristNoise noise;
  read_number_into(wrench, "force", noise.force);
  read_number_into(wrench, "moment", noise.moment);
  return noise;
}

MarkerSensorModel read_marker_sensor(const YamlField& sensor) {
  sensor.expect_mapping(
      {"kind", "markers", "noise", "dropout", "frame_rate", "camera", "wrench_noise"},
      {{"depth", "sensor.depth is the depth camera's section: it needs sensor.kind: depth"}});
  MarkerSensorModel model;
  if (const YamlField markers = sensor.get("markers"); markers.present())
    model.markers = markers.integer();
  if (const YamlField noise = sensor.get("noise"); noise.present()) {
    noise.expect_mapping({"in_plane", "depth"});
    read_number_into(noise, "in_plane", model.in_plane_noise);
    read_number_into(noise, "depth", model.depth_noise);
  }
  read_number_into(sensor, "dropout", model.dropout);
  read_number_into(sensor, "frame_rate", model.frame_rate);
  if (const YamlField camera = sensor.get("camera"); camera.present())
    model.camera = read_pose(camera);
  model.wrist = read_wrench_noise(sensor);
  sensor.located([&] { model.validate(); });
  return model;
}

/// `[first, second]`: a list of two numbers.
void read_pair_into(const YamlField& parent, const char* key, double& first, double& second) {
  const YamlField pair = parent.get(key);
  if (!pair.present()) return;
  const std::vector<YamlField> values = pair.elements();
  if (values.size() != 2) pair.fail(pair.path() + " must be a list of two numbers");
  first = values[0].number();
  second = values[1].number();
}

/// `sensor.depth`: resolution [w, h], field_of_view [x, y] (degrees), range [min, max] (m),
/// points, noise {a0, a1, a2, incidence, lateral_pixels}, outliers.
void read_depth_camera(const YamlField& depth, DepthSensorModel& model) {
  depth.expect_mapping({"resolution", "field_of_view", "range", "points", "noise", "outliers"});
  if (const YamlField resolution = depth.get("resolution"); resolution.present()) {
    const std::vector<YamlField> values = resolution.elements();
    if (values.size() != 2)
      resolution.fail(resolution.path() + " must be a list of two whole numbers [width, height]");
    model.width = values[0].integer();
    model.height = values[1].integer();
  }
  read_pair_into(depth, "field_of_view", model.fov_x_deg, model.fov_y_deg);
  read_pair_into(depth, "range", model.min_range, model.max_range);
  if (const YamlField points = depth.get("points"); points.present())
    model.points = points.integer();
  if (const YamlField noise = depth.get("noise"); noise.present()) {
    noise.expect_mapping({"a0", "a1", "a2", "incidence", "lateral_pixels"});
    read_number_into(noise, "a0", model.noise.a0);
    read_number_into(noise, "a1", model.noise.a1);
    read_number_into(noise, "a2", model.noise.a2);
    read_number_into(noise, "incidence", model.noise.incidence);
    read_number_into(noise, "lateral_pixels", model.noise.lateral_pixels);
  }
  read_number_into(depth, "outliers", model.outliers);
}

DepthSensorModel read_depth_sensor(const YamlField& sensor) {
  static constexpr std::string_view kMarkerKey =
      "a marker camera's key, not allowed with sensor.kind: depth (the depth camera's keys go "
      "under sensor.depth)";
  sensor.expect_mapping({"kind", "depth", "frame_rate", "camera", "wrench_noise"},
                        {{"markers", kMarkerKey}, {"noise", kMarkerKey}, {"dropout", kMarkerKey}});
  DepthSensorModel model;
  if (const YamlField depth = sensor.get("depth"); depth.present()) read_depth_camera(depth, model);
  read_number_into(sensor, "frame_rate", model.frame_rate);
  if (const YamlField camera = sensor.get("camera"); camera.present())
    model.camera = read_pose(camera);
  model.wrist = read_wrench_noise(sensor);
  sensor.located([&] { model.validate(); });
  return model;
}

}  // namespace

SensorModel read_sensor_section(const YamlField& sensor) {
  SensorKind kind = SensorKind::Markers;
  if (const YamlField field = sensor.get("kind"); field.present())
    kind = *value_of(kSensorKindNames, field.choice({"markers", "depth"}));
  if (kind == SensorKind::Depth) return read_depth_sensor(sensor);
  return read_marker_sensor(sensor);
}

ClosedLoopOptions read_closed_loop_section(const YamlField& loop) {
  loop.expect_mapping({"estimate_stiffness", "gravity", "estimate_grasp_offset", "replan",
                       "checkpoint_frames", "tip_position_sigma", "tip_rotation_sigma",
                       "prior_sigma", "horizon", "significance", "fuse", "max_residual",
                       "max_energy_ratio"});
  ClosedLoopOptions options;
  if (const YamlField offset = loop.get("estimate_grasp_offset"); offset.present())
    options.estimate_grasp_offset = offset.boolean();
  if (const YamlField estimate = loop.get("estimate_stiffness"); estimate.present())
    options.estimation.estimate_stiffness = estimate.boolean();
  if (const YamlField gravity = loop.get("gravity"); gravity.present())
    options.estimation.gravity = gravity.vector3();
  if (const YamlField replan = loop.get("replan"); replan.present())
    options.replan = replan.boolean();
  if (const YamlField fuse = loop.get("fuse"); fuse.present()) options.fuse = fuse.boolean();
  read_number_into(loop, "tip_position_sigma", options.estimation.tip_position_sigma);
  read_number_into(loop, "tip_rotation_sigma", options.estimation.tip_rotation_sigma);
  read_number_into(loop, "prior_sigma", options.estimation.prior_sigma);
  read_number_into(loop, "significance", options.significance);
  read_number_into(loop, "max_residual", options.max_residual);
  read_number_into(loop, "max_energy_ratio", options.max_energy_ratio);
  if (const YamlField frames = loop.get("checkpoint_frames"); frames.present())
    options.checkpoint_frames = frames.integer();
  if (const YamlField horizon = loop.get("horizon"); horizon.present())
    options.horizon = horizon.integer();
  loop.located([&] { options.validate(); });
  return options;
}

}  // namespace rodshape::io_detail
