// sensor_view.hpp (private to the sim area): a run's sensor as the drivers see it (the open loop's
// and the closed loop's): the marker camera or the depth camera, each frame observed, kept as the
// last one seen and measured by the paper's errors (shape_error.hpp), and a rest's frames put
// together for the controller: the markers averaged (their noise divided by √n), a cloud's frames
// pooled (every point keeps one frame's noise; the wrist wrench averaged).
#pragma once

#include <variant>
#include <vector>

#include "rodshape/feedback/cloud_measurement.hpp"
#include "rodshape/feedback/marker_measurement.hpp"
#include "rodshape/sim/depth_camera.hpp"
#include "rodshape/sim/marker_sensor.hpp"
#include "rodshape/sim/shape_error.hpp"
#include "rodshape/trajectory/plan_problem.hpp"

namespace rodshape::sim_detail {

class SensorView {
 public:
  /// The markers of a rod of `length`.
  SensorView(MarkerSensor& sensor, double length);
  /// The depth camera, in `problem`'s scene (its obstacles, the rod's radius: Scene::rod_radius).
  SensorView(DepthCamera& camera, const PlanProblem& problem);

  bool sees_cloud() const { return std::holds_alternative<DepthCamera*>(sensor_); }
  double frame_rate() const;
  /// `frame` seen (the arm's links at `links`, when it has them: they may hide the rod), kept as
  /// the last one seen, and its errors against `problem`'s target (the clamp at `clamp`).
  ShapeError see(const PlantFrame& frame,
                 const PlanProblem& problem,
                 const Eigen::Vector3d& clamp,
                 std::vector<CapsuleObstacle> links = {});
  const SensorFrame& last_markers() const { return markers_; }
  const CloudFrame& last_cloud() const { return cloud_; }

  /// A rest starts with the last frame seen: it and the frames seen until rest_*() are put
  /// together.
  void start_rest();
  /// The rest's markers averaged, the sensor's noise divided by √frames.
  MarkerMeasurement rest_markers() const;
  /// The rest's clouds pooled, its wrist wrenches averaged (CloudFrame::frames).
  CloudMeasurement rest_cloud() const;

 private:
  void add_to_rest();

  std::variant<MarkerSensor*, DepthCamera*> sensor_;
  double length_ = 0.0;
  double rod_radius_ = 0.0;
  DepthOccluders occluders_;
  SensorFrame markers_;
  CloudFrame cloud_;
  bool resting_ = false;
  int rest_frames_ = 0;
  SensorFrame rest_start_;
  std::vector<Eigen::Vector3d> marker_sum_;
  std::vector<int> marker_count_;
  CloudFrame pooled_;
  Wrench wrist_sum_;
};

}  // namespace rodshape::sim_detail
