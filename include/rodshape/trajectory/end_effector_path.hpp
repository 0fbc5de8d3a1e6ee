// end_effector_path.hpp: from end-effector waypoints to a timed path that is slow enough for the
// statics to hold. Between waypoints the position moves on a line and the orientation by slerp,
// both driven by one path parameter σ ∈ [0, 1] with a trapezoidal profile (rest to rest at every
// waypoint: the plan's shapes are equilibria, so the arm stops on each). A segment's σ̇ and σ̈
// limits are the tighter of the linear and the angular ones:
//   σ̇_max = min(v_max / d, ω_max / φ),   σ̈_max = min(a_max / d, α_max / φ),
// with d the segment's length and φ its rotation angle.
#pragma once

#include <vector>

#include "rodshape/core/pose.hpp"

namespace rodshape {

struct EndEffectorLimits {
  double max_linear_speed = 0.02;         // v_max, m/s (quasi-static default)
  double max_angular_speed = 0.2;         // ω_max, rad/s
  double max_linear_acceleration = 0.1;   // a_max, m/s²
  double max_angular_acceleration = 1.0;  // α_max, rad/s²
  double sample_rate = 100.0;             // Hz
  /// Throws InputError naming "trajectory.max_linear_speed" etc. (each must be finite and > 0).
  void validate() const;
};

struct TimedPose {
  double t = 0.0;  // s
  Pose pose;
};

/// The path through `waypoints` (at least one), sampled at `sample_rate` plus every waypoint's
/// arrival time exactly. A segment with no motion takes no time.
std::vector<TimedPose> time_parameterize(const std::vector<Pose>& waypoints,
                                         const EndEffectorLimits& limits);

}  // namespace rodshape
