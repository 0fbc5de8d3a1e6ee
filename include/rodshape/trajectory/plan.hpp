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

/// The time plan() is expected to take, s, on the machine docs/limits.md was measured on (2 cores,
/// Release), for a plan that needs no refinement nor re-plan: rod intervals × steps × (1.5e-4 s ×
/// (1 + multi_starts) × (target points + 30) / 40 + 1.4e-6 s × tracking_substeps when tracking).
/// Within a factor of about 2 of the bundled plans and of the measurements in docs/limits.md.
double estimated_plan_seconds(const PlanProblem& problem, const PlanOptions& options);

/// The most estimated_plan_seconds() that plan() accepts: each size has its own bound, and this
/// bounds their product (1000 steps × 100 starts × 5000 intervals would take years).
inline constexpr double kMaxEstimatedPlanSeconds = 300.0;

/// Throws InputError, saying the estimate and the sizes it comes from, when
/// estimated_plan_seconds() exceeds kMaxEstimatedPlanSeconds. plan() calls it before any work.
void check_plan_cost(const PlanProblem& problem, const PlanOptions& options);

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
