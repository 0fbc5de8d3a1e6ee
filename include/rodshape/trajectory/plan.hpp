// plan.hpp: the paper's trajectory generation, end to end, in one entry point. From the initial
// equilibrium, the objective points move in n_inter steps from their projection on the initial
// shape to the target; each step is an optimal shape (ShapeProblem, IPOPT) warm-started from the
// last. The tip poses of these shapes, composed with the grasp offset, are the end-effector
// waypoints, timed for quasi-static motion. Between waypoints the held rod is followed along the
// commanded path (follow_equilibrium) to check that it follows the plan without a jump; where it
// would jump, a step is inserted. With an arm (PlanProblem::arm), its reach shell is part of the
// workspace, every planned pose is checked by inverse kinematics (re-planning with a tighter shell
// where one has no solution) and the joint trajectory follows the path.
//
// The stages, in src/trajectory/plan_stages.hpp: initial equilibrium, feasibility, objective
// sets, one step's optimisation (warm start included), tracking, refinement, timing; and
// src/trajectory/arm_replanning.hpp for the arm.
#pragma once

#include "rodshape/trajectory/plan_options.hpp"
#include "rodshape/trajectory/plan_problem.hpp"
#include "rodshape/trajectory/plan_result.hpp"

namespace rodshape {

/// Plans. Throws InputError for bad input (including an initial tip outside the workspace or, with
/// an arm, outside its reach shell); an infeasible target, a failed step or an unreachable pose
/// is reported in the result's status and message.
PlanResult plan(const PlanProblem& problem, const PlanOptions& options = {});

/// Follows the held rod along the commanded end-effector path of `result` (waypoint to waypoint,
/// options.tracking_substeps continuation steps each) and compares it on arrival with each
/// planned shape. plan() does this as it goes; this checks a plan made elsewhere.
TrackingResult track_plan(const PlanProblem& problem,
                          const PlanOptions& options,
                          const PlanResult& result);

}  // namespace rodshape
