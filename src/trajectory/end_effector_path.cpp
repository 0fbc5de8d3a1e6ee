#include "rodshape/trajectory/end_effector_path.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "rodshape/error.hpp"
#include "validation.hpp"

namespace rodshape {

namespace {

/// Rest-to-rest trapezoidal profile of σ from 0 to 1 with |σ̇| ≤ v and |σ̈| ≤ a (triangular when
/// v is not reached).
struct Trapezoid {
  double v, a, t_accel, t_cruise;

  Trapezoid(double v_max, double a_max) : a(a_max) {
    if (v_max * v_max / a_max >= 1.0) {  // accelerating to v_max would pass σ = 1/2
      t_accel = std::sqrt(1.0 / a_max);
      v = a_max * t_accel;
      t_cruise = 0.0;
    } else {
      v = v_max;
      t_accel = v_max / a_max;
      t_cruise = (1.0 - v_max * t_accel) / v_max;
    }
  }

  double duration() const { return 2.0 * t_accel + t_cruise; }

  double sigma(double t) const {
    const double T = duration();
    if (t <= 0.0) return 0.0;
    if (t >= T) return 1.0;
    if (t < t_accel) return 0.5 * a * t * t;
    if (t < t_accel + t_cruise) return 0.5 * a * t_accel * t_accel + v * (t - t_accel);
    const double left = T - t;  // decelerating: mirror of the acceleration
    return 1.0 - 0.5 * a * left * left;
  }
};

}  // namespace

namespace {

/// "1e+14".
std::string count(double value) { return detail::format_value(value); }

/// The limits' cost for a reference move of 1 (m or rad) from rest to rest with speed `v` and
/// acceleration `a`: throws when it would take more than kMaxSamples samples, naming the speed or
/// the acceleration, whichever makes it slow.
void check_reference_move(const EndEffectorLimits& limits,
                          double v,
                          double a,
                          const char* speed,
                          const char* acceleration,
                          const char* unit) {
  const Trapezoid profile(v, a);
  const double samples = profile.duration() * limits.sample_rate;
  if (samples <= EndEffectorLimits::kMaxSamples) return;
  // Accelerating to v (v/a) or cruising (1/v): the longer names the culprit.
  const bool by_speed = profile.t_cruise >= profile.t_accel;
  const std::string field = std::string("EndEffectorLimits.") + (by_speed ? speed : acceleration);
  throw InputError(field, " = " + detail::format_value(by_speed ? v : a) + ": a move of 1 " + unit +
                              " from rest to rest would take " +
                              detail::format_value(profile.duration()) + " s, " + count(samples) +
                              " samples at EndEffectorLimits.sample_rate = " +
                              detail::format_value(limits.sample_rate) +
                              " Hz; an end-effector path has at most " +
                              count(EndEffectorLimits::kMaxSamples) + " samples");
}

}  // namespace

void EndEffectorLimits::validate() const {
  detail::require_positive("EndEffectorLimits.max_linear_speed", max_linear_speed);
  detail::require_positive("EndEffectorLimits.max_angular_speed", max_angular_speed);
  detail::require_positive("EndEffectorLimits.max_linear_acceleration", max_linear_acceleration);
  detail::require_positive("EndEffectorLimits.max_angular_acceleration", max_angular_acceleration);
  detail::require_positive("EndEffectorLimits.sample_rate", sample_rate);
  if (sample_rate > kMaxSampleRate)
    throw InputError("EndEffectorLimits.sample_rate",
                     " = " + detail::format_value(sample_rate) +
                         " must be <= " + detail::format_value(kMaxSampleRate));
  check_reference_move(*this, max_linear_speed, max_linear_acceleration, "max_linear_speed",
                       "max_linear_acceleration", "m");
  check_reference_move(*this, max_angular_speed, max_angular_acceleration, "max_angular_speed",
                       "max_angular_acceleration", "rad");
}

namespace {

/// The profile of the segment from `a` to `b`; nullopt when there is no motion (no time).
std::optional<Trapezoid> segment_profile(const Pose& a,
                                         const Pose& b,
                                         const EndEffectorLimits& limits) {
  const double d = (b.position - a.position).norm();
  const double phi = Eigen::AngleAxisd(a.rotation.transpose() * b.rotation).angle();
  if (d == 0.0 && phi == 0.0) return std::nullopt;
  const double inf = std::numeric_limits<double>::infinity();
  // σ̇_max = min(v_max/d, ω_max/φ), σ̈_max = min(a_max/d, α_max/φ)
  const double v = std::min(d > 0 ? limits.max_linear_speed / d : inf,
                            phi > 0 ? limits.max_angular_speed / phi : inf);
  const double acc = std::min(d > 0 ? limits.max_linear_acceleration / d : inf,
                              phi > 0 ? limits.max_angular_acceleration / phi : inf);
  return Trapezoid(v, acc);
}

}  // namespace

PathSize path_size(const std::vector<Pose>& waypoints, const EndEffectorLimits& limits) {
  PathSize size;
  for (std::size_t k = 1; k < waypoints.size(); ++k) {
    const std::optional<Trapezoid> profile =
        segment_profile(waypoints[k - 1], waypoints[k], limits);
    if (!profile) continue;
    size.duration += profile->duration();
    size.samples += std::floor(profile->duration() * limits.sample_rate) + 1.0;
  }
  return size;
}

std::vector<TimedPose> time_parameterize(const std::vector<Pose>& waypoints,
                                         const EndEffectorLimits& limits) {
  limits.validate();
  if (waypoints.empty()) throw InputError("time_parameterize: no waypoints");
  const PathSize size = path_size(waypoints, limits);
  if (!(size.samples <= EndEffectorLimits::kMaxSamples))
    throw InputError(
        "EndEffectorLimits",
        ": the end-effector path would have " + count(size.samples) + " samples (duration " +
            detail::format_value(size.duration) +
            " s at EndEffectorLimits.sample_rate = " + detail::format_value(limits.sample_rate) +
            " Hz); at most " + count(EndEffectorLimits::kMaxSamples) +
            ": raise the speed or acceleration limits, or lower EndEffectorLimits.sample_rate");
  std::vector<TimedPose> path{{0.0, waypoints.front()}};
  path.reserve(static_cast<std::size_t>(size.samples) + 1);
  const double dt = 1.0 / limits.sample_rate;
  double t0 = 0.0;
  for (std::size_t k = 1; k < waypoints.size(); ++k) {
    const Pose& a = waypoints[k - 1];
    const Pose& b = waypoints[k];
    const std::optional<Trapezoid> segment = segment_profile(a, b, limits);
    if (!segment) continue;  // no motion, no time
    const Trapezoid& profile = *segment;
    const double T = profile.duration();
    // Samples on the global grid t = j / rate strictly inside the segment, then its end exactly.
    for (auto j = static_cast<long long>(std::floor(t0 * limits.sample_rate)) + 1;; ++j) {
      const double t = j * dt;
      if (t >= t0 + T - 1e-12) break;
      if (t <= t0 + 1e-12) continue;
      path.push_back({t, interpolate(a, b, profile.sigma(t - t0))});
    }
    t0 += T;
    path.push_back({t0, b});
  }
  return path;
}

}  // namespace rodshape
