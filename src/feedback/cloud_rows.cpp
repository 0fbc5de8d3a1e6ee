// cloud_rows.cpp: the point-to-surface rows of a cloud (cloud_rows.hpp, cloud_estimator.hpp).
#include "cloud_rows.hpp"

#include <algorithm>
#include <cmath>

#include "centreline_index.hpp"
#include "rodshape/feedback/cloud_estimator.hpp"
#include "rodshape/optimisation/curve_distance.hpp"

namespace rodshape::feedback_detail {

namespace {

/// One point's distance to the model's surface, d = |x - Γ(s)| - ρ, its unit direction from the
/// centreline, and the projection.
struct SurfaceDistance {
  double d = 0.0;
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();
  CurveProjection projection;
};

SurfaceDistance surface_distance(double radius,
                                 const CentrelineIndex& index,
                                 const Eigen::Vector3d& x) {
  SurfaceDistance out;
  out.projection = index.project(x);
  const CurveProjection& p = out.projection;
  if (p.distance > 0.0) out.direction = (x - p.closest) / p.distance;
  out.d = p.distance - radius;
  return out;
}

}  // namespace

CauchyRow cauchy_row(double z, double scale) {
  const double c = scale;
  const double q = z * z / (c * c);
  if (q < 1e-12) return {z, 1.0};  // r = z (1 - q/4 + …): the loss is quadratic here
  const double value = std::copysign(c * std::sqrt(std::log1p(q)), z);
  return {value, z / ((1.0 + q) * value)};
}

double cauchy_weight(double z) { return 1.0 / (1.0 + z * z / (kCauchyScale * kCauchyScale)); }

PointNoise::PointNoise(const DepthSensorModel& sensor, double floor)
    : camera_(sensor.camera),
      noise_(sensor.noise),
      min_range_(sensor.min_range),
      max_range_(sensor.max_range),
      focal_(0.5 * (sensor.focal_x() + sensor.focal_y())),
      floor_(floor) {}

double PointNoise::along(const Eigen::Vector3d& x, const Eigen::Vector3d& direction) const {
  const Eigen::Vector3d from_camera = x - camera_.position;
  const double depth =
      std::clamp((camera_.rotation.transpose() * from_camera).z(), min_range_, max_range_);
  const double norm = from_camera.norm();
  const double cosine = norm > 0.0 ? std::min(std::abs(direction.dot(from_camera)) / norm, 1.0)
                                   : 1.0;  // of θ, the ray's angle to the surface's normal
  const double axial = std::max(noise_.axial_sigma(depth, std::acos(cosine)), 0.0);
  const double lateral = noise_.lateral_pixels * depth / focal_;
  const double cos2 = cosine * cosine;
  const double variance = axial * axial * cos2 + lateral * lateral * (1.0 - cos2);
  return std::max(std::sqrt(variance), floor_);
}

CloudRows::CloudRows(const CloudFrame& seen,
                     double radius,
                     const DepthSensorModel& sensor,
                     const EstimationOptions& options,
                     double scale)
    : points_(seen.points),
      radius_(radius),
      noise_(sensor, options.min_cloud_sigma),
      scale_(scale) {}

void CloudRows::evaluate(const ClampedRod& rod,
                         const RodConfiguration& configuration,
                         Eigen::VectorXd& r,
                         Eigen::MatrixXd* J,
                         int row) const {
  const CentrelineIndex index(configuration);
  for (const Eigen::Vector3d& x : points_) {
    const SurfaceDistance s = surface_distance(radius_, index, x);
    const double sigma = noise_.along(x, s.direction);
    const CauchyRow row_of = cauchy_row(s.d / sigma, scale_);
    r(row) = row_of.value;
    if (J)  // dd/dw = -n̂ᵀ dΓ(s_k)/dw (envelope), σ and ρ held
      J->block<1, 6>(row, 0) =
          (row_of.slope / sigma) * distance_gradient(rod, configuration, s.projection, x);
    ++row;
  }
}

std::vector<double> CloudRows::weighted_distances(const RodConfiguration& configuration) const {
  const CentrelineIndex index(configuration);
  std::vector<double> z;
  z.reserve(points_.size());
  for (const Eigen::Vector3d& x : points_) {
    const SurfaceDistance s = surface_distance(radius_, index, x);
    z.push_back(s.d / noise_.along(x, s.direction));
  }
  return z;
}

double CloudRows::outlier_fraction(const RodConfiguration& configuration) const {
  if (points_.empty()) return 0.0;
  int outliers = 0;
  for (const double z : weighted_distances(configuration))
    if (cauchy_weight(z) < kOutlierWeight) ++outliers;
  return static_cast<double>(outliers) / static_cast<double>(points_.size());
}

void CloudRows::finish(const ClampedRod& /*rod*/,
                       const RodConfiguration& configuration,
                       int total_rows,
                       StateEstimate& estimate) const {
  estimate.points = rows();
  if (points_.empty() || !std::isfinite(estimate.chi2)) return;
  double robust = 0.0, plain = 0.0;
  int outliers = 0;
  for (const double z : weighted_distances(configuration)) {
    robust += std::pow(cauchy_row(z, scale_).value, 2);
    if (cauchy_weight(z) < kOutlierWeight)
      ++outliers;
    else
      plain += z * z;
  }
  estimate.outliers = outliers;
  const int kept_rows = total_rows - outliers;
  if (kept_rows > 0)
    estimate.residual = std::sqrt(std::max(estimate.chi2 - robust + plain, 0.0) / kept_rows);
}

}  // namespace rodshape::feedback_detail
