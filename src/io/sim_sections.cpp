// sim_sections.cpp: the plant and sensor sections of a plan task (docs/task-file.md, "validate").
#include "io/sim_sections.hpp"

#include "io/task_sections.hpp"

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

MarkerSensorModel read_sensor_section(const YamlField& sensor) {
  sensor.expect_mapping({"markers", "noise", "dropout", "frame_rate", "camera", "wrench_noise"});
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
  if (const YamlField wrench = sensor.get("wrench_noise"); wrench.present()) {
    wrench.expect_mapping({"force", "moment"});
    WristNoise noise;
    read_number_into(wrench, "force", noise.force);
    read_number_into(wrench, "moment", noise.moment);
    model.wrist = noise;
  }
  sensor.located([&] { model.validate(); });
  return model;
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
