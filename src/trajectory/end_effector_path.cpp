#include "rodshape/trajectory/end_effector_path.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "rodshape/error.hpp"
#include "validation.hpp"

namespace rodshape {

void EndEffectorLimits::validate() const {
  detail::require_positive("EndEffectorLimits.max_linear_speed", max_linear_speed);
  detail::require_positive("EndEffectorLimits.max_angular_speed", max_angular_speed);
  detail::require_positive("EndEffectorLimits.max_linear_acceleration", max_linear_acceleration);
  detail::require_positive("EndEffectorLimits.max_angular_acceleration", max_angular_acceleration);
  detail::require_positive("EndEffectorLimits.sample_rate", sample_rate);
}

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

std::vector<TimedPose> time_parameterize(const std::vector<Pose>& waypoints,
                                         const EndEffectorLimits& limits) {
  limits.validate();
  if (waypoints.empty()) throw InputError("time_parameterize: no waypoints");
  std::vector<TimedPose> path{{0.0, waypoints.front()}};
  const double dt = 1.0 / limits.sample_rate;
  double t0 = 0.0;
  for (std::size_t k = 1; k < waypoints.size(); ++k) {
    const Pose& a = waypoints[k - 1];
    const Pose& b = waypoints[k];
    const double d = (b.position - a.position).norm();
    const double phi = Eigen::AngleAxisd(a.rotation.transpose() * b.rotation).angle();
    if (d == 0.0 && phi == 0.0) continue;  // no motion, no time
    const double inf = std::numeric_limits<double>::infinity();
    // σ̇_max = min(v_max/d, ω_max/φ), σ̈_max = min(a_max/d, α_max/φ)
    const double v = std::min(d > 0 ? limits.max_linear_speed / d : inf,
                              phi > 0 ? limits.max_angular_speed / phi : inf);
    const double acc = std::min(d > 0 ? limits.max_linear_acceleration / d : inf,
                                phi > 0 ? limits.max_angular_acceleration / phi : inf);
    const Trapezoid profile(v, acc);
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
