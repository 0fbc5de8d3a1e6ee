// cloud_measurement.cpp: the depth camera's model checked, its focal lengths
// (cloud_measurement.hpp).
#include "rodshape/feedback/cloud_measurement.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "rodshape/core/physical_bounds.hpp"
#include "rodshape/error.hpp"
#include "validation.hpp"

namespace rodshape {
namespace {

void require_int_in(const std::string& field, int value, int lo, int hi) {
  if (value < lo || value > hi)
    throw InputError(field, " = " + std::to_string(value) + " must be in [" + std::to_string(lo) +
                                ", " + std::to_string(hi) + "]");
}

void require_open_interval(const std::string& field, double value, double lo, double hi) {
  detail::require_finite(field, value);
  if (!(value > lo && value < hi))
    throw InputError(field, " = " + detail::format_value(value) + " must be in (" +
                                detail::format_value(lo) + ", " + detail::format_value(hi) + ")");
}

double focal(int pixels, double fov_deg) {
  return 0.5 * pixels / std::tan(0.5 * fov_deg * std::numbers::pi / 180.0);
}

}  // namespace

double DepthNoiseModel::axial_sigma(double z, double theta) const {
  const double angle = std::clamp(theta, 0.0, kMaxIncidence);
  const double grazing = angle / (0.5 * std::numbers::pi - angle);
  return axial_sigma(z) + incidence * z * std::sqrt(z) * grazing * grazing;
}

double DepthSensorModel::focal_x() const { return focal(width, fov_x_deg); }
double DepthSensorModel::focal_y() const { return focal(height, fov_y_deg); }

void DepthSensorModel::validate() const {
  require_int_in("DepthSensorModel.width", width, 1, kMaxResolution);
  require_int_in("DepthSensorModel.height", height, 1, kMaxResolution);
  require_open_interval("DepthSensorModel.fov_x_deg", fov_x_deg, 0.0, 180.0);
  require_open_interval("DepthSensorModel.fov_y_deg", fov_y_deg, 0.0, 180.0);
  detail::require_positive("DepthSensorModel.min_range", min_range);
  require_in_range("DepthSensorModel.max_range", max_range, {0.0, bounds::kMaxPosition, "m"});
  if (!(max_range > min_range))
    throw InputError("DepthSensorModel.max_range",
                     " = " + detail::format_value(max_range) +
                         " must be > min_range = " + detail::format_value(min_range));
  require_int_in("DepthSensorModel.points", points, 1, kMaxPoints);
  detail::require_finite("DepthSensorModel.noise.a0", noise.a0);
  detail::require_finite("DepthSensorModel.noise.a1", noise.a1);
  detail::require_finite("DepthSensorModel.noise.a2", noise.a2);
  // σ_z must be ≥ 0 over the camera's range: a quadratic's least value there is at an end or at
  // its vertex.
  double least = std::min(noise.axial_sigma(min_range), noise.axial_sigma(max_range));
  if (noise.a2 > 0.0) {
    const double vertex = -noise.a1 / (2.0 * noise.a2);
    if (vertex > min_range && vertex < max_range)
      least = std::min(least, noise.axial_sigma(vertex));
  }
  if (least < 0.0)
    throw InputError("DepthSensorModel.noise",
                     ": the axial sigma a0 + a1 z + a2 z^2 is negative within [min_range, "
                     "max_range]");
  require_in_range("DepthSensorModel.noise.a0", noise.a0, {-1.0, 1.0, "m"});
  require_in_range("DepthSensorModel.noise.a1", noise.a1, {-1.0, 1.0, "m/m"});
  require_in_range("DepthSensorModel.noise.a2", noise.a2, {-1.0, 1.0, "m/m^2"});
  detail::require_non_negative("DepthSensorModel.noise.incidence", noise.incidence);
  require_in_range("DepthSensorModel.noise.incidence", noise.incidence, {0.0, 1.0, "m/m^1.5"});
  detail::require_non_negative("DepthSensorModel.noise.lateral_pixels", noise.lateral_pixels);
  require_in_range("DepthSensorModel.noise.lateral_pixels", noise.lateral_pixels,
                   {0.0, 100.0, "px"});
  detail::require_finite("DepthSensorModel.outliers", outliers);
  if (outliers < 0.0 || outliers >= 1.0)
    throw InputError("DepthSensorModel.outliers",
                     " = " + detail::format_value(outliers) + " must be in [0, 1)");
  detail::require_positive("DepthSensorModel.frame_rate", frame_rate);
  if (frame_rate > kMaxFrameRate)
    throw InputError("DepthSensorModel.frame_rate",
                     " = " + detail::format_value(frame_rate) +
                         " must be <= " + detail::format_value(kMaxFrameRate));
  detail::require_pose("DepthSensorModel.camera", camera);
  require_magnitude_at_most("DepthSensorModel.camera.position", camera.position,
                            bounds::kMaxPosition, "m");
  if (wrist) {
    detail::require_non_negative("DepthSensorModel.wrist.force", wrist->force);
    detail::require_non_negative("DepthSensorModel.wrist.moment", wrist->moment);
    require_in_range("DepthSensorModel.wrist.force", wrist->force, {0.0, bounds::kMaxForce, "N"});
    require_in_range("DepthSensorModel.wrist.moment", wrist->moment,
                     {0.0, bounds::kMaxForce, "N*m"});
  }
}

}  // namespace rodshape
