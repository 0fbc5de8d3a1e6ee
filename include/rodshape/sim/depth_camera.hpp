// depth_camera.hpp: the simulated depth camera (the paper's Kinect v2): what a pinhole camera of a
// DepthSensorModel (feedback/cloud_measurement.hpp) sees of the rod's surface, as an unordered
// cloud in the world frame, with no correspondence to arc lengths.
//
// The surface is the circle of radius r swept along the plant's centreline (each segment between
// nodes a capsule of radius r). Each pixel's centre ray is cast against the capsules whose image
// it lies in (a z-buffer: the nearest wins, so the rod hides itself), then against the occluders
// (the scene's obstacles, the arm's link capsules): a pixel whose ray meets one first sees no rod.
// Depths z (along the camera's +z) outside [min_range, max_range] are not reported. Of the visible
// pixels, `points` are kept at random (all when fewer), each measured with the DepthNoiseModel:
// its depth z + σ_z(z, θ) ε (θ the incidence angle between the ray and the surface's normal) and
// its pixel moved by lateral_pixels · ε' in u and v, then back-projected. A fraction `outliers` of
// the kept points are flying pixels (a time-of-flight camera's mixed pixels at an edge): the ray of
// a pixel on the rod's silhouette, at a depth drawn uniformly in [z, z + kFlyingDepth]. Seeded: the
// same seed and frames give the same clouds, bit for bit. Memory: the z-buffer, 12 bytes a pixel
// per thread that draws (2.6 MB at 512 × 424), whatever the number of cameras.
#pragma once

#include <cstdint>
#include <random>
#include <vector>

#include "rodshape/core/obstacle.hpp"
#include "rodshape/feedback/cloud_measurement.hpp"
#include "rodshape/sim/plant.hpp"
#include "rodshape/trajectory/plan_problem.hpp"

namespace rodshape {

/// What may hide the rod from the camera besides the rod itself, world frame.
struct DepthOccluders {
  std::vector<Obstacle> obstacles;     // the scene's
  std::vector<CapsuleObstacle> links;  // the arm's link capsules where the arm stands
};

/// The arm's link capsules in the world at joint positions q (ArmModel::link_capsules()).
std::vector<CapsuleObstacle> arm_link_capsules(const PlanArm& arm, const Eigen::VectorXd& q);

class DepthCamera {
 public:
  static constexpr double kFlyingDepth = 0.2;  // m, how far behind the rod a flying pixel may lie
  /// Throws InputError when the model is not valid (DepthSensorModel::validate).
  DepthCamera(DepthSensorModel model, std::uint64_t seed);
  /// The cloud of `frame`'s rod of radius `rod_radius` (> 0), and the wrist wrench when the model
  /// has a wrist sensor.
  CloudFrame observe(const PlantFrame& frame,
                     double rod_radius,
                     const DepthOccluders& occluders = {});
  const DepthSensorModel& model() const { return model_; }
  /// The pixels that saw the rod in the last frame, before subsampling.
  int visible_pixels() const { return static_cast<int>(visible_.size()); }

 private:
  struct Hit {
    int pixel = 0;
    double t = 0.0;  // along the pixel's unit ray, camera frame
    int segment = 0;
  };
  Eigen::Vector3d ray(int pixel) const;
  void render_rod(const std::vector<Eigen::Vector3d>& nodes, double radius);
  void hide_occluded(const DepthOccluders& occluders, const Pose& camera_T_world);
  bool on_silhouette(int pixel) const;
  Eigen::Vector3d measure(const Hit& hit, const std::vector<Eigen::Vector3d>& nodes, double radius);
  Eigen::Vector3d flying_pixel(const Hit& hit);

  DepthSensorModel model_;
  double fx_, fy_, cx_, cy_;
  std::mt19937_64 random_;
  std::normal_distribution<double> normal_{0.0, 1.0};
  std::uniform_real_distribution<double> uniform_{0.0, 1.0};
  /// Per pixel: the nearest hit's t (+inf where none) and its segment; the pixels it holds a hit
  /// for. One per thread, clean between frames (12 bytes a pixel of the largest image drawn).
  struct ZBuffer;
  ZBuffer* z_ = nullptr;      // the thread's, during observe()
  std::vector<Hit> visible_;  // the last frame's visible pixels, in pixel order
};

}  // namespace rodshape
