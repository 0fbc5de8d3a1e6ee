// surface_cloud.hpp: a synthetic depth-camera cloud of a rod's equilibrium for the cloud
// estimator's tests and benchmark (not the simulated camera, sim/): points drawn uniformly in arc
// length and around the tube of the section's circumscribed radius (the surface the estimator
// fits), kept where the surface faces the camera, a window of
// the length left out (occlusion), Gaussian noise from DepthSensorModel's model (axial along the
// camera's ray, lateral across it) and a fraction of outliers drawn uniformly in a box around
// the rod. Seeded: the same arguments give the same cloud.
#pragma once

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "rodshape/core/rod_configuration.hpp"
#include "rodshape/core/so3.hpp"
#include "rodshape/feedback/cloud_measurement.hpp"
#include "rodshape/optimisation/curve_distance.hpp"

namespace rodshape::testing {

struct CloudRecipe {
  int points = 500;
  double occluded_from = 0.0, occluded_to = 0.0;  // fractions of L left out, [from, to)
  double outliers = 0.0;                          // fraction of the points replaced
  bool noise = true;                              // the sensor's noise drawn
  unsigned seed = 1;
};

/// The section's frame at arc length s: the nodes' rotations interpolated on SO(3).
inline Eigen::Matrix3d frame_at(const RodConfiguration& c, double s) {
  const auto upper = std::upper_bound(c.s.begin(), c.s.end(), s);
  const int i = std::clamp(static_cast<int>(upper - c.s.begin()) - 1, 0, c.nodes() - 2);
  const double t = (s - c.s[i]) / (c.s[i + 1] - c.s[i]);
  return c.R[i] * exp_so3(t * log_so3(c.R[i].transpose() * c.R[i + 1]));
}

/// The cloud of `shape` (its surface the tube of `radius` about the centreline) as `sensor` sees
/// it, world frame.
inline CloudFrame surface_cloud(const RodConfiguration& shape,
                                double radius,
                                const DepthSensorModel& sensor,
                                const CloudRecipe& recipe) {
  std::mt19937 random(recipe.seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::normal_distribution<double> gauss(0.0, 1.0);
  const double length = shape.length();
  const double focal = 0.5 * (sensor.focal_x() + sensor.focal_y());
  CloudFrame frame;
  while (static_cast<int>(frame.points.size()) < recipe.points) {
    const double s = length * uniform(random);
    if (s >= recipe.occluded_from * length && s < recipe.occluded_to * length) continue;
    const Eigen::Matrix3d R = frame_at(shape, s);
    const double phi = 2.0 * std::numbers::pi * uniform(random);
    const Eigen::Vector3d normal = R * Eigen::Vector3d(std::cos(phi), std::sin(phi), 0.0);
    const Eigen::Vector3d x = curve_point(shape, s) + radius * normal;
    const Eigen::Vector3d ray = (x - sensor.camera.position).normalized();
    if (normal.dot(ray) >= 0.0) continue;  // the far side: hidden
    Eigen::Vector3d noisy = x;
    if (recipe.noise) {
      const double z = (sensor.camera.rotation.transpose() * (x - sensor.camera.position)).z();
      const Eigen::Vector3d a = ray.unitOrthogonal(), b = ray.cross(a);
      const double lateral = sensor.noise.lateral_pixels * z / focal;
      noisy += sensor.noise.axial_sigma(z) * gauss(random) * ray +
               lateral * (gauss(random) * a + gauss(random) * b);
    }
    frame.points.push_back(noisy);
  }
  // Outliers: uniform in the rod's bounding box grown by 5 cm.
  Eigen::Vector3d lo = shape.p.front(), hi = shape.p.front();
  for (const Eigen::Vector3d& p : shape.p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  lo.array() -= 0.05;
  hi.array() += 0.05;
  const int outliers = static_cast<int>(std::lround(recipe.outliers * recipe.points));
  for (int k = 0; k < outliers; ++k) {
    Eigen::Vector3d& x = frame.points[static_cast<std::size_t>(k)];  // the points are in no order
    for (int j = 0; j < 3; ++j) x(j) = lo(j) + (hi(j) - lo(j)) * uniform(random);
  }
  return frame;
}

/// The RMS distance between two configurations' nodes (the same arc lengths).
inline double centreline_rms(const RodConfiguration& a, const RodConfiguration& b) {
  double sum = 0.0;
  for (int i = 0; i < a.nodes(); ++i) sum += (a.p[i] - b.p[i]).squaredNorm();
  return std::sqrt(sum / a.nodes());
}

}  // namespace rodshape::testing
