// marker_sensor.cpp: markers on the plant's curve, seen with noise in the camera's frame.
#include "rodshape/sim/marker_sensor.hpp"

#include <utility>

#include "rodshape/optimisation/curve_distance.hpp"

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
  if (model_.wrist) {
    // The rod's wrench on the gripper, -n(L), -m(L), in the end-effector frame.
    const Pose& ee = frame.end_effector;  // where the gripper is (the grasp may be off)
    const Wrench tip = frame.configuration.tip_wrench();
    Wrench w;
    w.force = -(ee.rotation.transpose() * tip.force);
    w.moment =
        -(ee.rotation.transpose() *
          (tip.moment + (frame.configuration.tip().position - ee.position).cross(tip.force)));
    for (int k = 0; k < 3; ++k) {
      w.force(k) += model_.wrist->force * normal_(random_);
      w.moment(k) += model_.wrist->moment * normal_(random_);
    }
    seen.wrist = w;
  }
  return seen;
}

}  // namespace rodshape
