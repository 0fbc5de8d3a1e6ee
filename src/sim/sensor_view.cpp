// sensor_view.cpp: the marker camera or the depth camera seen through one interface by the
// drivers; a rest's frames put together (sensor_view.hpp).
#include "sensor_view.hpp"

#include <cmath>
#include <optional>
#include <utility>

namespace rodshape::sim_detail {

SensorView::SensorView(MarkerSensor& sensor, double length) : sensor_(&sensor), length_(length) {}

SensorView::SensorView(DepthCamera& camera, const PlanProblem& problem)
    : sensor_(&camera), rod_radius_(problem.scene.rod_radius) {
  occluders_.obstacles = problem.scene.obstacles;
}

double SensorView::frame_rate() const {
  return std::visit([](const auto* sensor) { return sensor->model().frame_rate; }, sensor_);
}

ShapeError SensorView::see(const PlantFrame& frame,
                           const PlanProblem& problem,
                           const Eigen::Vector3d& clamp,
                           std::vector<CapsuleObstacle> links) {
  ShapeError error;
  if (auto* const* markers = std::get_if<MarkerSensor*>(&sensor_)) {
    markers_ = (*markers)->observe(frame, length_);
    error = shape_error(problem.target.points, clamp, markers_, frame.configuration,
                        (*markers)->model().camera);
  } else {
    DepthCamera& camera = *std::get<DepthCamera*>(sensor_);
    occluders_.links = std::move(links);
    cloud_ = camera.observe(frame, rod_radius_, occluders_);
    error = shape_error(problem.target.points, cloud_, frame.configuration, camera.model().camera,
                        rod_radius_);
  }
  if (resting_) add_to_rest();
  return error;
}

void SensorView::start_rest() {
  resting_ = true;
  rest_frames_ = 0;
  marker_sum_.assign(markers_.markers.size(), Eigen::Vector3d::Zero());
  marker_count_.assign(markers_.markers.size(), 0);
  pooled_ = CloudFrame{};
  wrist_sum_ = Wrench{};
  rest_start_ = markers_;
  add_to_rest();  // the frame the arm arrived with is the rest's first
}

void SensorView::add_to_rest() {
  ++rest_frames_;
  if (sees_cloud()) {
    pooled_.points.insert(pooled_.points.end(), cloud_.points.begin(), cloud_.points.end());
    if (cloud_.wrist) {
      wrist_sum_.force += cloud_.wrist->force;
      wrist_sum_.moment += cloud_.wrist->moment;
    }
    return;
  }
  for (std::size_t j = 0; j < marker_sum_.size(); ++j)
    if (markers_.markers[j]) {
      marker_sum_[j] += *markers_.markers[j];
      ++marker_count_[j];
    }
}

MarkerMeasurement SensorView::rest_markers() const {
  // The first frame's time and wrist wrench (the controller is handed the rest's end time).
  MarkerMeasurement measurement{rest_start_, std::get<MarkerSensor*>(sensor_)->model()};
  for (std::size_t j = 0; j < marker_sum_.size(); ++j)
    measurement.frame.markers[j] =
        marker_count_[j] > 0 ? std::optional<Eigen::Vector3d>(marker_sum_[j] / marker_count_[j])
                             : std::nullopt;
  const double root_n = std::sqrt(static_cast<double>(rest_frames_));
  measurement.sensor.in_plane_noise /= root_n;
  measurement.sensor.depth_noise /= root_n;
  return measurement;
}

CloudMeasurement SensorView::rest_cloud() const {
  CloudMeasurement measurement{pooled_, std::get<DepthCamera*>(sensor_)->model()};
  measurement.frame.t = cloud_.t;
  measurement.frame.frames = rest_frames_;
  if (cloud_.wrist) {
    const double n = static_cast<double>(rest_frames_);
    measurement.frame.wrist = Wrench{wrist_sum_.force / n, wrist_sum_.moment / n};
  }
  return measurement;
}

}  // namespace rodshape::sim_detail
