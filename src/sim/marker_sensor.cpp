// marker_sensor.cpp: markers on the plant's curve, seen with noise in the camera's frame.
#include "rodshape/sim/marker_sensor.hpp"

#include <utility>

#include "rodshape/optimisation/curve_distance.hpp"
#include "wrist_wrench.hpp"

namespace rodshape {

MarkerSensor::MarkerSensor(MarkerSensorModel model, std::uint64_t seed)
    : model_(std::move(model)), random_(seed) {
  model_.validate();
}

SensorFrame MarkerSensor::observe(const PlantFrame& frame, double length) {
  SensorFrame seen;
  seen.t = frame.t;
  const Eigen::Matrix3d& Rc = model_.camera.rotation;
  // Every draw is made whether or not the marker is seen, so that the noise of one marker does not
  // depend on the dropout of another.
  for (const double s : model_.arc_lengths(length)) {
    const Eigen::Vector3d noise(model_.in_plane_noise * normal_(random_),
                                model_.in_plane_noise * normal_(random_),
                                model_.depth_noise * normal_(random_));
    const bool dropped = uniform_(random_) < model_.dropout;
    if (dropped) {
      seen.markers.emplace_back();
      continue;
    }
    seen.markers.emplace_back(curve_point(frame.configuration, s) + Rc * noise);
  }
  if (model_.wrist)
    seen.wrist = sim_detail::measured_wrist_wrench(frame, *model_.wrist, random_, normal_);
  return seen;
}

}  // namespace rodshape
