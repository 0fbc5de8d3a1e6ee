// cloud_measurement.hpp: what a depth camera (the paper's Kinect v2) measures of the rod: an
// unordered point cloud on the rod's surface, with no correspondence to arc lengths, and
// optionally the wrist wrench. A pinhole camera of `width` × `height` pixels and the given fields
// of view sees the section swept along the centreline, occluded by the scene, the arm and the rod
// itself; each point's depth noise grows with the distance (axial σ(z) = a0 + a1 z + a2 z², z the
// depth along the camera's +z) and its lateral noise is a fixed number of pixels (σ = px · z / f).
// The cloud estimator weighs points by this noise (feedback/cloud_estimator.hpp); the simulated
// camera draws it (sim/depth_camera.hpp).
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "rodshape/core/pose.hpp"
#include "rodshape/core/wrench.hpp"
#include "rodshape/feedback/marker_measurement.hpp"

namespace rodshape {

/// The depth camera's noise, after Fankhauser et al. 2015 ("Kinect v2 for mobile robot
/// navigation: evaluation and modeling", ICAR), whose indoor axial model is
/// σ_z(z, θ) = 1.5 − 0.5 z + 0.3 z² + 0.1 z^{3/2} θ² / (π/2 − θ)² mm (z in m, θ the angle between
/// the viewing ray and the surface's normal): axial σ_z(z) = a0 + a1 z + a2 z² (m, z the depth
/// along the camera's +z) plus the incidence term `incidence` · z^{3/2} θ² / (π/2 − θ)² (θ at most
/// kMaxIncidence), along the viewing ray; lateral σ = lateral_pixels · z / f across it (0.8 px, the
/// Kinect's lateral noise of Nguyen et al. 2012 away from grazing angles).
struct DepthNoiseModel {
  static constexpr double kMaxIncidence = 1.4835298641951802;  // rad, 85°
  double a0 = 1.5e-3, a1 = -0.5e-3, a2 = 0.3e-3;               // m, m/m, m/m²
  double incidence = 0.1e-3;    // m/m^{3/2}, the θ term's coefficient
  double lateral_pixels = 0.8;  // px
  /// σ_z(z) = a0 + a1 z + a2 z², the noise of a surface facing the camera (θ = 0).
  double axial_sigma(double z) const { return a0 + a1 * z + a2 * z * z; }
  /// σ_z(z, θ): σ_z(z) + incidence · z^{3/2} θ² / (π/2 − θ)², θ clamped to [0, kMaxIncidence].
  double axial_sigma(double z, double theta) const;
};

struct DepthSensorModel {
  static constexpr int kMaxResolution = 4096;    // pixels per side
  static constexpr int kMaxPoints = 100000;      // points per frame after subsampling
  static constexpr double kMaxFrameRate = 1000;  // Hz
  int width = 512, height = 424;                 // pixels
  double fov_x_deg = 70.6, fov_y_deg = 60.0;     // full fields of view, degrees, (0, 180)
  double min_range = 0.5, max_range = 4.5;       // m, depths the camera reports
  int points = 500;                              // points per frame after subsampling, ≥ 1
  DepthNoiseModel noise;
  double outliers = 0.0;     // fraction of a frame's points replaced by outliers, [0, 1)
  double frame_rate = 30.0;  // Hz, (0, kMaxFrameRate]
  /// world_T_camera; looks along its local +z, image x right, y down. Default as the markers'.
  Pose camera{Eigen::Vector3d(0.0, -1.0, 0.15),
              (Eigen::Matrix3d() << 1, 0, 0, 0, 0, 1, 0, -1, 0).finished()};
  std::optional<WristNoise> wrist;  // absent: no wrist sensor
  /// Focal lengths in pixels: f_x = (width / 2) / tan(fov_x / 2), likewise f_y.
  double focal_x() const;
  double focal_y() const;
  /// Throws InputError naming the field ("DepthSensorModel.points = 0 must be in [1, 100000]").
  void validate() const;
};

/// One cloud (possibly several frames of a rest put together): points in the world frame, and the
/// wrist wrench (the rod's wrench on the gripper, -n(L), -m(L), in the end-effector frame).
struct CloudFrame {
  double t = 0.0;
  std::vector<Eigen::Vector3d> points;
  std::optional<Wrench> wrist;
  /// The wrist wrench's noise is divided by √frames (averaged over the rest); each point keeps the
  /// sensor's single-frame noise.
  int frames = 1;
};

/// What the shape controller is handed from a depth camera: a cloud and the sensor that took it.
struct CloudMeasurement {
  CloudFrame frame;
  DepthSensorModel sensor;
};

}  // namespace rodshape
