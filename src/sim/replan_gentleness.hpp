// replan_gentleness.hpp (private): the waypoints ahead of the closed loop, and whether a re-plan
// of them keeps the path gentle. Correcting the model changes a step's elastic energy by about the
// correction (tens of percent); a re-planned step with much more energy than the step it replaces
// is another, coiled optimum of that step's problem, and the rod would be bent through it
// (ClosedLoopOptions::max_energy_ratio).
#pragma once

#include <string>
#include <vector>

#include "rodshape/core/pose.hpp"
#include "rodshape/core/wrench.hpp"
#include "rodshape/trajectory/plan_result.hpp"

namespace rodshape::closed_loop_detail {

/// A waypoint still ahead of the closed loop: the commanded pose, the planned base wrench there
/// (the estimator's prior) and the planned shape's elastic energy (what a re-planned step is held
/// against).
struct PlannedWaypoint {
  Pose end_effector;
  BaseWrench wrench;
  double energy = 0.0;  // J
};

inline PlannedWaypoint planned_waypoint(const PlanStep& step) {
  return {step.end_effector, step.solution.base_wrench, step.solution.configuration.energy};
}

/// Empty when every re-planned step k (of `steps`, as far as `replaced` goes) has an energy
/// E_k ≤ ratio · max(replaced[k].energy, start_energy), start_energy being the energy of the state
/// the re-plan starts from; else why the first that has more is refused.
std::string not_gentle(const std::vector<PlanStep>& steps,
                       double start_energy,
                       const std::vector<PlannedWaypoint>& replaced,
                       double ratio);

}  // namespace rodshape::closed_loop_detail
