// marker_measurement.hpp: what a marker camera and a wrist force/torque sensor measure of the rod,
// with their noise. A camera (the paper's Kinect v2) tracks m markers at evenly spaced arc lengths
// on the rod, with Gaussian noise of separate in-plane and depth standard deviations in the
// camera's frame and a dropout probability per marker and frame; optionally a wrist sensor
// measures the wrench the rod applies to the gripper. The state estimator weighs what they measure
// by this noise (state_estimator.hpp); the simulated sensor draws it (sim/marker_sensor.hpp).
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "rodshape/core/pose.hpp"
#include "rodshape/core/wrench.hpp"

namespace rodshape {

/// The standard deviations of the wrist sensor's noise.
struct WristNoise {
  double force = 0.0;   // N
  double moment = 0.0;  // N·m
};

struct MarkerSensorModel {
  static constexpr int kMaxMarkers = 1000;
  static constexpr double kMaxFrameRate = 1000.0;  // Hz
  /// Markers at s_j = (j + 1) L / m, j = 0 … m - 1 (the last at the tip), 2 ≤ m ≤ kMaxMarkers.
  int markers = 10;
  double in_plane_noise = 1e-3;  // m, σ along the camera's x and y (a Kinect v2 at ~1 m)
  double depth_noise = 3e-3;     // m, σ along the camera's z
  double dropout = 0.0;          // probability that a marker is not seen in a frame, [0, 1]
  double frame_rate = 30.0;      // Hz, (0, kMaxFrameRate]
  /// world_T_camera; the camera looks along its local +z. Default: 1 m from the clamp along -y,
  /// looking along +y, its image plane the world's x–z plane (where the bundled plans bend).
  Pose camera{Eigen::Vector3d(0.0, -1.0, 0.15),
              (Eigen::Matrix3d() << 1, 0, 0, 0, 0, 1, 0, -1, 0).finished()};
  std::optional<WristNoise> wrist;  // absent: no wrist sensor
  /// Throws InputError naming the field ("MarkerSensorModel.markers = 1 must be >= 2", …).
  void validate() const;
  /// The markers' arc lengths on a rod of length L.
  std::vector<double> arc_lengths(double length) const;
};

/// One frame: each marker's measured position in the world (absent when it dropped out) and the
/// wrist wrench (the rod's wrench on the gripper, -n(L), -m(L), in the end-effector frame).
struct SensorFrame {
  double t = 0.0;
  std::vector<std::optional<Eigen::Vector3d>> markers;
  std::optional<Wrench> wrist;
  int visible() const;
};

/// What the shape controller is handed: a frame (its markers possibly averaged over a rest, its
/// time when it is handed over) and the sensor that measured it, whose noise weighs it (averaged
/// over n frames, divide the noise by √n).
struct MarkerMeasurement {
  SensorFrame frame;
  MarkerSensorModel sensor;
};

/// A point in the camera's image plane (orthographic: its camera-frame x and y), m.
Eigen::Vector2d image_point(const Pose& camera, const Eigen::Vector3d& world_point);

}  // namespace rodshape
