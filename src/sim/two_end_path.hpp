// two_end_path.hpp (private to the sim area): both ends' paths on one clock, for a plant driven by
// both ends when a driver (the closed loop) times a segment itself. Each segment is timed by
// time_parameterize() for each end with its own limits; the slower end's profile is the clock and
// the other end moves along its own line and slerp at the same path parameter σ, so that both
// arrive together (each segment takes the longer of the two ends' times).
#pragma once

#include <vector>

#include "rodshape/core/pose.hpp"
#include "rodshape/trajectory/end_effector_path.hpp"

namespace rodshape::sim_detail {

struct TwoEndPath {
  std::vector<TimedPose> tip;   // the tip's end effector
  std::vector<TimedPose> base;  // the base gripper, at the same times sample for sample
};

/// The paths through the waypoints (the same count, at least one each), rest to rest at every
/// waypoint, starting at t = 0.
TwoEndPath time_two_ends(const std::vector<Pose>& tip,
                         const std::vector<Pose>& base,
                         const EndEffectorLimits& tip_limits,
                         const EndEffectorLimits& base_limits);

}  // namespace rodshape::sim_detail
