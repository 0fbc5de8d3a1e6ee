// arm_replanning.hpp (private): the plan carried out by an arm. The arm's reach joins the
// workspace Ws (a shell for its wrist point, robot/arm_reach.hpp); every planned end-effector pose
// (the initial one, then one per step) is checked by exact inverse kinematics, seeded from the pose
// before it; when a pose has no IK solution the plan is made again with the shell tightened past
// that pose's wrist distance (its outer radius pulled in when the pose was far out, its inner
// radius pushed out when it was close in), up to max_replans times; then the joint trajectory
// follows the path, and a sample without IK solution there tightens the shell the same way.
#pragma once

#include "plan_stages.hpp"
#include "rodshape/trajectory/plan.hpp"

namespace rodshape::detail {

/// Stages 2–7 of the plan from the initial equilibrium (plan() without an arm).
PlanResult plan_rod(const PlanProblem& problem,
                    const PlanOptions& options,
                    const plan_stages::InitialEquilibrium& initial);

/// plan() with problem.arm: the reach shell, plan_rod, the IK checks and the re-plans, the joint
/// trajectory. Throws InputError for a workspace that already has a reach shell while use_reach
/// is set, and an initial tip pose outside the arm's reach shell.
PlanResult plan_with_arm(const PlanProblem& problem, const PlanOptions& options);

}  // namespace rodshape::detail
