// moving_base_plan.hpp (private): plan() when the base end is held by a moving gripper (issue 21,
// PlanProblem::moving_base). The stages of plan_stages.hpp with the base pose among each step's
// variables (ShapeProblem::move_base): the feasibility of the target without a fixed clamp, the
// sets by aligned_objective_set, each step optimised about the last step's base pose, the rod
// tracked with both ends moving, refinements halfway, and both ends timed on one clock.
#pragma once

#include "plan_stages.hpp"
#include "rodshape/trajectory/plan.hpp"

namespace rodshape::detail {

/// Stages 2–7 with a moving base (interpolation Shape, ArcLength or Projection; Auto is Shape).
PlanResult plan_moving_base(const PlanProblem& problem,
                            const PlanOptions& options,
                            const plan_stages::InitialEquilibrium& initial);

/// The feasibility of the target for a rod whose base may go anywhere: check_feasibility from a
/// virtual clamp on the chain's line before p_1 (at the distance of the initial base from p_1,
/// shortened to what the reach leaves over the chain p_1 → … → p_n; at p_1 itself when that fails),
/// so that the arc lengths of the points start there.
FeasibilityResult free_base_feasibility(const PlanProblem& problem);

}  // namespace rodshape::detail
