// cloud_rows.cpp: the point-to-surface rows of a cloud (cloud_rows.hpp, cloud_estimator.hpp).
#include "cloud_rows.hpp"

#include <algorithm>
#include <cmath>

#include "centreline_index.hpp"
#include "rodshape/core/so3.hpp"
#include "rodshape/feedback/cloud_estimator.hpp"
#include "rodshape/optimisation/curve_distance.hpp"

namespace rodshape::feedback_detail {

namespace {

/// The section's frame at (interval i, t): R_i exp(t log(R_iᵀ R_{i+1})).
Eigen::Matrix3d section_frame(const RodConfiguration& c, const CurveProjection& at) {
  const std::size_t i = static_cast<std::size_t>(at.interval);
  if (i + 1 >= c.R.size()) return c.R[i];
  return c.R[i] * exp_so3(at.t * log_so3(c.R[i].transpose() * c.R[i + 1]));
}

/// The section's radius in the direction `a` (section frame, unit): a circle's radius, or the
/// distance from the centre to a rectangle's boundary along a's part in the section's plane,
/// scaled by that part's length (past an end cap, a points along the tangent: radius → 0).
double radius_towards(const CrossSection& section, const Eigen::Vector3d& a) {
  const double in_plane = std::hypot(a.x(), a.y());
  if (section.shape == CrossSection::Shape::Circle) return section.radius * in_plane;
  const double reach =
      std::max(std::abs(a.x()) / (0.5 * section.width), std::abs(a.y()) / (0.5 * section.height));
  return reach > 0.0 ? in_plane / reach : 0.0;
}

/// One point's distance to the model's surface, d = |x - Γ(s)| - ρ, its unit direction from the
/// centreline, and the projection.
struct SurfaceDistance {
  double d = 0.0;
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();
  CurveProjection projection;
};

SurfaceDistance surface_distance(const ClampedRod& rod,
                                 const RodConfiguration& c,
                                 const CentrelineIndex& index,
                                 const Eigen::Vector3d& x) {
  SurfaceDistance out;
  out.projection = index.project(x);
  const CurveProjection& p = out.projection;
  if (p.distance > 0.0) out.direction = (x - p.closest) / p.distance;
  const bool at_end =
      (p.interval == 0 && p.t == 0.0) || (p.interval == c.nodes() - 2 && p.t == 1.0);
  const CrossSection& section = *rod.properties.section;
  double radius = 0.0;  // a point on the centreline: d = its distance, 0
  if (section.shape == CrossSection::Shape::Circle && !at_end) {
    radius = section.radius;
  } else if (p.distance > 0.0) {
    Eigen::Vector3d a = section_frame(c, p).transpose() * out.direction;
    if (!at_end) a = Eigen::Vector3d(a.x(), a.y(), 0.0).normalized();  // a ⟂ Γ' here
    radius = radius_towards(section, a);
  }
  out.d = p.distance - radius;
  return out;
}

}  // namespace

CauchyRow cauchy_row(double z) {
  constexpr double c = kCauchyScale;
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
  const double axial = std::max(noise_.axial_sigma(depth), 0.0);
  const double lateral = noise_.lateral_pixels * depth / focal_;
  const double norm = from_camera.norm();
  const double cos2 = norm > 0.0 ? std::pow(direction.dot(from_camera) / norm, 2) : 1.0;
  const double variance = axial * axial * cos2 + lateral * lateral * (1.0 - cos2);
  return std::max(std::sqrt(variance), floor_);
}

CloudRows::CloudRows(const CloudFrame& seen,
                     const DepthSensorModel& sensor,
                     const EstimationOptions& options)
    : points_(seen.points), noise_(sensor, options.min_cloud_sigma) {}

void CloudRows::evaluate(const ClampedRod& rod,
                         const RodConfiguration& configuration,
                         Eigen::VectorXd& r,
                         Eigen::MatrixXd* J,
                         int row) const {
  const CentrelineIndex index(configuration);
  for (const Eigen::Vector3d& x : points_) {
    const SurfaceDistance s = surface_distance(rod, configuration, index, x);
    const double sigma = noise_.along(x, s.direction);
    const CauchyRow row_of = cauchy_row(s.d / sigma);
    r(row) = row_of.value;
    if (J)  // dd/dw = -n̂ᵀ dΓ(s_k)/dw (envelope), σ and ρ held
      J->block<1, 6>(row, 0) =
          (row_of.slope / sigma) * distance_gradient(rod, configuration, s.projection, x);
    ++row;
  }
}

std::vector<double> CloudRows::weighted_distances(const ClampedRod& rod,
                                                  const RodConfiguration& configuration) const {
  const CentrelineIndex index(configuration);
  std::vector<double> z;
  z.reserve(points_.size());
  for (const Eigen::Vector3d& x : points_) {
    const SurfaceDistance s = surface_distance(rod, configuration, index, x);
    z.push_back(s.d / noise_.along(x, s.direction));
  }
  return z;
}

void CloudRows::finish(const ClampedRod& rod,
                       const RodConfiguration& configuration,
                       int total_rows,
                       StateEstimate& estimate) const {
  estimate.points = rows();
  if (points_.empty() || !std::isfinite(estimate.chi2)) return;
  double robust = 0.0, plain = 0.0;
  int outliers = 0;
  for (const double z : weighted_distances(rod, configuration)) {
    robust += std::pow(cauchy_row(z).value, 2);
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
