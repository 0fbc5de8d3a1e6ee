// sim_sections.hpp (private to the io area): the readers of the sections a plan task adds for
// `rodshape validate`: plant (the real rod) and sensor (the camera and the wrist sensor). Numbers
// are checked finite here and their ranges by PlantModel::validate and the sensor's validate().
#pragma once

#include "io/yaml_field.hpp"
#include "rodshape/feedback/closed_loop_options.hpp"
#include "rodshape/feedback/marker_measurement.hpp"
#include "rodshape/feedback/sensor_model.hpp"
#include "rodshape/sim/plant_model.hpp"

namespace rodshape::io_detail {

/// `plant`: stiffness_scale, stiffness_factors {EA, GA, EIx, EIy, GJ}, length, mass_per_length,
/// gravity, rest_curvature, grasp_offset (a pose).
PlantModel read_plant_section(const YamlField& plant);

/// The task's top-level `gravity` (zero when absent): the planner's, which the plant's weight
/// replaces (PlantModel::planner_gravity).
Eigen::Vector3d read_planner_gravity(const YamlField& root);

/// `sensor`: kind (markers, the default, or depth), frame_rate, camera (a pose), wrench_noise
/// {force, moment} (absent: no wrist sensor); markers: markers, noise {in_plane, depth}, dropout;
/// depth: depth {resolution, field_of_view, range, points, noise, outliers}. Another kind's key is
/// bad input naming it. Checked by the model's validate(). (`rodshape estimate` reads its task's
/// sensor with it too.)
SensorModel read_sensor_section(const YamlField& sensor);

/// `closed_loop`: estimate_stiffness, replan, tip_position_sigma, tip_rotation_sigma, prior_sigma.
ClosedLoopOptions read_closed_loop_section(const YamlField& loop);

}  // namespace rodshape::io_detail
