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

/// σ̇ and σ̈ limits of one end's segment from `a` to `b` (infinite for no motion):
///   σ̇_max = min(v_max/d, ω_max/φ), σ̈_max = min(a_max/d, α_max/φ).
struct SigmaLimits {
  double v = std::numeric_limits<double>::infinity();
  double a = std::numeric_limits<double>::infinity();
  bool moves = false;
};

SigmaLimits sigma_limits(const Pose& a, const Pose& b, const EndEffectorLimits& limits) {
  const double d = (b.position - a.position).norm();
  const double phi = Eigen::AngleAxisd(a.rotation.transpose() * b.rotation).angle();
  SigmaLimits sigma;
  if (d == 0.0 && phi == 0.0) return sigma;
  const double inf = std::numeric_limits<double>::infinity();
  sigma.v = std::min(d > 0 ? limits.max_linear_speed / d : inf,
                     phi > 0 ? limits.max_angular_speed / phi : inf);
  sigma.a = std::min(d > 0 ? limits.max_linear_acceleration / d : inf,
                     phi > 0 ? limits.max_angular_acceleration / phi : inf);
  sigma.moves = true;
  return sigma;
}

/// The profile of the segment from `a` to `b`; nullopt when there is no motion (no time).
std::optional<Trapezoid> segment_profile(const Pose& a,
                                         const Pose& b,
                                         const EndEffectorLimits& limits) {
  const SigmaLimits sigma = sigma_limits(a, b, limits);
  if (!sigma.moves) return std::nullopt;
  return Trapezoid(sigma.v, sigma.a);
}

/// The one profile of a segment of two ends: the tighter of both ends' σ̇ and σ̈ limits; nullopt
/// when neither end moves.
std::optional<Trapezoid> two_end_profile(const std::vector<Pose>& tip,
                                         const std::vector<Pose>& base,
                                         std::size_t k,
                                         const EndEffectorLimits& tip_limits,
                                         const EndEffectorLimits& base_limits) {
  const SigmaLimits t = sigma_limits(tip[k - 1], tip[k], tip_limits);
  const SigmaLimits b = sigma_limits(base[k - 1], base[k], base_limits);
  if (!t.moves && !b.moves) return std::nullopt;
  return Trapezoid(std::min(t.v, b.v), std::min(t.a, b.a));
}

/// The duration and sample count of the segments' profiles (profile_of(k) for k = 1 … n - 1).
template <typename ProfileOf>
PathSize size_of(std::size_t n, const EndEffectorLimits& limits, ProfileOf&& profile_of) {
  PathSize size;
  for (std::size_t k = 1; k < n; ++k) {
    const std::optional<Trapezoid> profile = profile_of(k);
    if (!profile) continue;
    size.duration += profile->duration();
    size.samples += std::floor(profile->duration() * limits.sample_rate) + 1.0;
  }
  return size;
}

void check_size(const PathSize& size, const EndEffectorLimits& limits) {
  if (!(size.samples <= EndEffectorLimits::kMaxSamples))
    throw InputError(
        "EndEffectorLimits",
        ": the end-effector path would have " + count(size.samples) + " samples (duration " +
            detail::format_value(size.duration) +
            " s at EndEffectorLimits.sample_rate = " + detail::format_value(limits.sample_rate) +
            " Hz); at most " + count(EndEffectorLimits::kMaxSamples) +
            ": raise the speed or acceleration limits, or lower EndEffectorLimits.sample_rate");
}

/// The sampling of n waypoints' segments: emit(t, k, σ) for every sample on the global grid
/// t = j / rate strictly inside segment k (k = 1 … n - 1), then emit(t_end, k, nullopt) at its
/// end (the waypoint itself, exactly).
template <typename ProfileOf, typename Emit>
void sample_segments(std::size_t n,
                     const EndEffectorLimits& limits,
                     ProfileOf&& profile_of,
                     Emit&& emit) {
  const double dt = 1.0 / limits.sample_rate;
  double t0 = 0.0;
  for (std::size_t k = 1; k < n; ++k) {
    const std::optional<Trapezoid> segment = profile_of(k);
    if (!segment) continue;  // no motion, no time
    const Trapezoid& profile = *segment;
    const double T = profile.duration();
    // Samples on the global grid t = j / rate strictly inside the segment, then its end exactly.
    for (auto j = static_cast<long long>(std::floor(t0 * limits.sample_rate)) + 1;; ++j) {
      const double t = j * dt;
      if (t >= t0 + T - 1e-12) break;
      if (t <= t0 + 1e-12) continue;
      emit(t, k, std::optional<double>(profile.sigma(t - t0)));
    }
    t0 += T;
    emit(t0, k, std::optional<double>());
  }
}

}  // namespace

PathSize path_size(const std::vector<Pose>& waypoints, const EndEffectorLimits& limits) {
  return size_of(waypoints.size(), limits, [&](std::size_t k) {
    return segment_profile(waypoints[k - 1], waypoints[k], limits);
  });
}

std::vector<TimedPose> time_parameterize(const std::vector<Pose>& waypoints,
                                         const EndEffectorLimits& limits) {
  limits.validate();
  if (waypoints.empty()) throw InputError("time_parameterize: no waypoints");
  const PathSize size = path_size(waypoints, limits);
  check_size(size, limits);
  std::vector<TimedPose> path{{0.0, waypoints.front()}};
  path.reserve(static_cast<std::size_t>(size.samples) + 1);
  sample_segments(
      waypoints.size(), limits,
      [&](std::size_t k) { return segment_profile(waypoints[k - 1], waypoints[k], limits); },
      [&](double t, std::size_t k, std::optional<double> sigma) {
        path.push_back(
            {t, sigma ? interpolate(waypoints[k - 1], waypoints[k], *sigma) : waypoints[k]});
      });
  return path;
}

PathSize path_size_together(const std::vector<Pose>& tip_waypoints,
                            const std::vector<Pose>& base_waypoints,
                            const EndEffectorLimits& tip_limits,
                            const EndEffectorLimits& base_limits) {
  if (tip_waypoints.size() != base_waypoints.size())
    throw InputError("path_size_together: " + std::to_string(tip_waypoints.size()) +
                     " tip waypoints but " + std::to_string(base_waypoints.size()) +
                     " base waypoints");
  return size_of(tip_waypoints.size(), tip_limits, [&](std::size_t k) {
    return two_end_profile(tip_waypoints, base_waypoints, k, tip_limits, base_limits);
  });
}

TwoEndPath time_parameterize_together(const std::vector<Pose>& tip_waypoints,
                                      const std::vector<Pose>& base_waypoints,
                                      const EndEffectorLimits& tip_limits,
                                      const EndEffectorLimits& base_limits) {
  tip_limits.validate();
  base_limits.validate();
  if (tip_waypoints.empty()) throw InputError("time_parameterize_together: no waypoints");
  const PathSize size = path_size_together(tip_waypoints, base_waypoints, tip_limits, base_limits);
  check_size(size, tip_limits);
  std::vector<bool> tip_moves(tip_waypoints.size()), base_moves(tip_waypoints.size());
  for (std::size_t k = 1; k < tip_waypoints.size(); ++k) {
    tip_moves[k] = sigma_limits(tip_waypoints[k - 1], tip_waypoints[k], tip_limits).moves;
    base_moves[k] = sigma_limits(base_waypoints[k - 1], base_waypoints[k], base_limits).moves;
  }
  TwoEndPath path;
  path.tip = {{0.0, tip_waypoints.front()}};
  path.base = {{0.0, base_waypoints.front()}};
  path.tip.reserve(static_cast<std::size_t>(size.samples) + 1);
  path.base.reserve(static_cast<std::size_t>(size.samples) + 1);
  sample_segments(
      tip_waypoints.size(), tip_limits,
      [&](std::size_t k) {
        return two_end_profile(tip_waypoints, base_waypoints, k, tip_limits, base_limits);
      },
      [&](double t, std::size_t k, std::optional<double> sigma) {
        // An end that does not move in this segment holds its pose exactly (no round-off of the
        // interpolation).
        const auto at = [&](const std::vector<Pose>& waypoints, bool moves) {
          return sigma && moves ? interpolate(waypoints[k - 1], waypoints[k], *sigma)
                                : waypoints[k];
        };
        path.tip.push_back({t, at(tip_waypoints, tip_moves[k])});
        path.base.push_back({t, at(base_waypoints, base_moves[k])});
      });
  return path;
}

}  // namespace rodshape
