// planned_waypoint.hpp: a waypoint of the plan still ahead of the shape controller: where the arm
// is commanded to, the base wrench the plan expects there (the estimator's prior) and the planned
// shape's elastic energy (what a re-planned step is held against) and, with a moving base, where
// the base gripper is commanded to.
#pragma once

#include "rodshape/core/pose.hpp"
#include "rodshape/core/wrench.hpp"
#include "rodshape/trajectory/plan_result.hpp"

namespace rodshape {

struct PlannedWaypoint {
  Pose end_effector;
  BaseWrench wrench;
  double energy = 0.0;  // J
  /// The base gripper's pose (PlanStep::base_end_effector; used with a moving base only).
  Pose base_end_effector{};
};

/// The waypoint a plan's step ends at.
inline PlannedWaypoint planned_waypoint(const PlanStep& step) {
  return {step.end_effector, step.solution.base_wrench, step.solution.configuration.energy,
          step.base_end_effector};
}

}  // namespace rodshape
