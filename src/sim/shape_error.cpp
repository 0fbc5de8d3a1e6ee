// shape_error.cpp: point-to-polyline distances for the measured curve, point-to-curve for the
// plant's.
#include "rodshape/sim/shape_error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "rodshape/core/segment.hpp"
#include "rodshape/optimisation/curve_distance.hpp"

namespace rodshape {

template <int D>
double polyline_distance(const std::vector<Eigen::Matrix<double, D, 1>>& polyline,
                         const Eigen::Matrix<double, D, 1>& point) {
  double best = (polyline.front() - point).norm();
  for (std::size_t k = 0; k + 1 < polyline.size(); ++k)
    best = std::min(best, distance_to_segment(point, polyline[k], polyline[k + 1]));
  return best;
}

template double polyline_distance<2>(const std::vector<Eigen::Vector2d>&, const Eigen::Vector2d&);
template double polyline_distance<3>(const std::vector<Eigen::Vector3d>&, const Eigen::Vector3d&);

namespace {

/// The true errors: each p_obj's distance to the plant's curve, their mean and largest.
void add_true_error(ShapeError& error, const PointSet& points, const RodConfiguration& plant) {
  for (const Eigen::Vector3d& p : points) {
    const double d = project_onto_curve(plant, p).distance;
    error.true_error += d;
    error.true_max_distance = std::max(error.true_max_distance, d);
  }
  error.true_error /= static_cast<double>(std::max<std::size_t>(points.size(), 1));
}

}  // namespace

ShapeError shape_error(const PointSet& points,
                       const Eigen::Vector3d& clamp,
                       const SensorFrame& seen,
                       const RodConfiguration& plant,
                       const Pose& camera) {
  // The measured curve: the clamp, then every visible marker (arc-length order).
  std::vector<Eigen::Vector3d> curve{clamp};
  for (const auto& marker : seen.markers)
    if (marker) curve.push_back(*marker);
  std::vector<Eigen::Vector2d> image;
  for (const Eigen::Vector3d& q : curve) image.push_back(image_point(camera, q));

  ShapeError error;
  error.visible_markers = seen.visible();
  for (const Eigen::Vector3d& p : points) {
    error.error_3d += polyline_distance(curve, p);
    error.error_2d += polyline_distance(image, image_point(camera, p));
  }
  const double n = static_cast<double>(std::max<std::size_t>(points.size(), 1));
  error.error_3d /= n;
  error.error_2d /= n;
  add_true_error(error, points, plant);
  if (error.visible_markers == 0) {  // only the clamp: the camera measured nothing of the shape
    error.error_3d = std::numeric_limits<double>::quiet_NaN();
    error.error_2d = std::numeric_limits<double>::quiet_NaN();
  }
  return error;
}

ShapeError shape_error(const PointSet& points,
                       const CloudFrame& seen,
                       const RodConfiguration& plant,
                       const Pose& camera,
                       double radius) {
  ShapeError error;
  error.visible_markers = static_cast<int>(seen.points.size());
  add_true_error(error, points, plant);
  if (seen.points.empty()) {
    error.error_3d = error.error_2d = std::numeric_limits<double>::quiet_NaN();
    return error;
  }
  std::vector<Eigen::Vector2d> image;
  image.reserve(seen.points.size());
  for (const Eigen::Vector3d& q : seen.points) image.push_back(image_point(camera, q));
  for (const Eigen::Vector3d& p : points) {
    double nearest = std::numeric_limits<double>::infinity(), nearest_2d = nearest;
    const Eigen::Vector2d p_image = image_point(camera, p);
    for (std::size_t k = 0; k < image.size(); ++k) {
      nearest = std::min(nearest, (seen.points[k] - p).squaredNorm());
      nearest_2d = std::min(nearest_2d, (image[k] - p_image).squaredNorm());
    }
    error.error_3d += std::max(std::sqrt(nearest) - radius, 0.0);
    error.error_2d += std::max(std::sqrt(nearest_2d) - radius, 0.0);
  }
  const double n = static_cast<double>(std::max<std::size_t>(points.size(), 1));
  error.error_3d /= n;
  error.error_2d /= n;
  return error;
}

double centreline_rms(const RodConfiguration& estimate, const RodConfiguration& plant) {
  if (estimate.p.empty() || plant.p.empty()) return std::numeric_limits<double>::quiet_NaN();
  double sum = 0.0;
  for (const Eigen::Vector3d& p : estimate.p) {
    const double d = project_onto_curve(plant, p).distance;
    sum += d * d;
  }
  return std::sqrt(sum / static_cast<double>(estimate.p.size()));
}

}  // namespace rodshape
