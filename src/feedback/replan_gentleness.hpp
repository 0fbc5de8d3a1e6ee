// replan_gentleness.hpp (private): whether a re-plan of the waypoints ahead of the shape
// controller keeps the path gentle. Correcting the model changes a step's elastic energy by about
// the correction (tens of percent); a re-planned step with much more energy than the step it
// replaces is another, coiled optimum of that step's problem, and the rod would be bent through it
// (ClosedLoopOptions::max_energy_ratio, shape_controller.hpp).
#pragma once

#include <string>
#include <vector>

#include "rodshape/feedback/planned_waypoint.hpp"
#include "rodshape/trajectory/plan_result.hpp"

namespace rodshape::feedback_detail {

/// Empty when every re-planned step k (of `steps`, as far as `replaced` goes) has an energy
/// E_k ≤ ratio · max(replaced[k].energy, start_energy), start_energy being the energy of the state
/// the re-plan starts from; else why the first that has more is refused.
std::string not_gentle(const std::vector<PlanStep>& steps,
                       double start_energy,
                       const std::vector<PlannedWaypoint>& replaced,
                       double ratio);

}  // namespace rodshape::feedback_detail
