// end_effector_path.hpp: from end-effector waypoints to a timed path that is slow enough for the
// statics to hold. Between waypoints the position moves on a line and the orientation by slerp,
// both driven by one path parameter σ ∈ [0, 1] with a trapezoidal profile (rest to rest at every
// waypoint: the plan's shapes are equilibria, so the arm stops on each). A segment's σ̇ and σ̈
// limits are the tighter of the linear and the angular ones:
//   σ̇_max = min(v_max / d, ω_max / φ),   σ̈_max = min(a_max / d, α_max / φ),
// with d the segment's length and φ its rotation angle.
//
// Two ends on one clock (a moving base, issue 21): the tip's and the base's waypoints pair up
// (waypoint k of each is where that end is at step k), and each segment has ONE profile σ(t) that
// drives both ends, its limits the tighter of the two ends' own ones:
//   σ̇_max = min over both ends of min(v_max/d, ω_max/φ),  likewise σ̈_max,
// each end with its own EndEffectorLimits. So each segment takes at least the longer of the two
// ends' times (more only when one end's speed and the other's acceleration bind), every sample of
// both ends respects that end's limits, both ends start and stop together at every waypoint, and a
// segment where neither end moves takes no time (an end that stays put puts no limit, and holds
// its pose exactly, sample for sample).
#pragma once

#include <vector>

#include "rodshape/core/pose.hpp"

namespace rodshape {

struct EndEffectorLimits {
  /// Upper bounds (docs/limits.md, "Sizes"). A path sample costs about 2.6 µs and 124 bytes of
  /// trajectory.csv, and with an arm one IK (about 20 µs for the Panda): 1e6 samples are a 124 MB
  /// file. 10 kHz is ten times the fastest common robot controller (1 kHz).
  static constexpr double kMaxSampleRate = 10'000.0;
  static constexpr double kMaxSamples = 1e6;

  double max_linear_speed = 0.02;         // v_max, m/s (quasi-static default)
  double max_angular_speed = 0.2;         // ω_max, rad/s
  double max_linear_acceleration = 0.1;   // a_max, m/s²
  double max_angular_acceleration = 1.0;  // α_max, rad/s²
  double sample_rate = 100.0;             // Hz, ≤ kMaxSampleRate
  /// Throws InputError naming "EndEffectorLimits.max_linear_speed" etc.: each must be finite and
  /// > 0, sample_rate ≤ kMaxSampleRate, and a move of 1 m (or of 1 rad) from rest to rest at these
  /// limits may take at most kMaxSamples samples, so that limits such as a speed of 1e-12 m/s are
  /// refused before any planning (the path's own count is checked by time_parameterize()).
  void validate() const;
};

struct TimedPose {
  double t = 0.0;  // s
  Pose pose;
};

/// The duration of the path through `waypoints` and the number of samples time_parameterize()
/// would return (a float: it may be far beyond any integer type), computed without sampling.
struct PathSize {
  double duration = 0.0;  // s
  double samples = 1.0;
};
PathSize path_size(const std::vector<Pose>& waypoints, const EndEffectorLimits& limits);

/// The path through `waypoints` (at least one), sampled at `sample_rate` plus every waypoint's
/// arrival time exactly. A segment with no motion takes no time. Throws InputError (naming
/// EndEffectorLimits, with the count and the duration) before sampling when the path would have
/// more than EndEffectorLimits::kMaxSamples samples.
std::vector<TimedPose> time_parameterize(const std::vector<Pose>& waypoints,
                                         const EndEffectorLimits& limits);

/// The tip's and the base's paths on one clock (see the top of this file): the same sample times,
/// at tip_limits.sample_rate plus every waypoint's arrival exactly (the waypoints themselves).
struct TwoEndPath {
  std::vector<TimedPose> tip;
  std::vector<TimedPose> base;  // base[i].t == tip[i].t for every i
};

/// path_size() of the two ends on one clock (the samples of each end's path). Throws InputError
/// when the two lists differ in length.
PathSize path_size_together(const std::vector<Pose>& tip_waypoints,
                            const std::vector<Pose>& base_waypoints,
                            const EndEffectorLimits& tip_limits,
                            const EndEffectorLimits& base_limits);

/// The two ends' paths through their waypoints (the same count, at least one each), timed
/// together. Throws InputError for invalid limits (either), lists of different lengths, and, as
/// time_parameterize(), a path of more than EndEffectorLimits::kMaxSamples samples. With a base
/// that never moves, tip equals time_parameterize(tip_waypoints, tip_limits).
TwoEndPath time_parameterize_together(const std::vector<Pose>& tip_waypoints,
                                      const std::vector<Pose>& base_waypoints,
                                      const EndEffectorLimits& tip_limits,
                                      const EndEffectorLimits& base_limits);

}  // namespace rodshape
