// arm_replanning.hpp (private): the plan carried out by an arm. The arm's reach joins the
// workspace Ws (a shell for its wrist point, robot/arm_reach.hpp); every planned end-effector pose
// (the initial one, then one per step) is checked by exact inverse kinematics, seeded from the pose
// before it; when a pose has no IK solution the plan is made again with the shell tightened past
// that pose's wrist distance (its outer radius pulled in when the pose was far out, its inner
// radius pushed out when it was close in), up to max_replans times; then the joint trajectory
// follows the path, and a sample without IK solution there tightens the shell the same way.
//
// Two arms (issue 21: PlanProblem::base_arm holds the base end, s = 0): the base arm's shell, for
// its wrist point in the rod's base frame (through base_T_ee = moving_base.grasp), joins
// moving_base.workspace; every step's base end-effector pose and every sample of the base path is
// checked by IK the same way, seeded from the one before, and a pose without solution tightens the
// base arm's shell by the same rule; both arms' re-plans share max_replans. The tip's arm is
// checked first; the base arm's IK then keeps its links off the tip arm's links at each sample
// (the tip's arm does not yield). With both reachable, the joint trajectories are re-timed
// together (retime_together) so that both keep the same times. With link clearance (a scene, or
// two arms) every arm's links keep the clearance from the scene and the rod (the hand holding it
// excepted) and the two arms' links keep the scene's clearance from each other (measured at every
// joint sample; too near: both arms' status collision and the plan's, no re-plan).
#pragma once

#include "plan_stages.hpp"
#include "rodshape/trajectory/plan.hpp"

namespace rodshape::detail {

/// Stages 2–7 of the plan from the initial equilibrium (plan() without an arm).
PlanResult plan_rod(const PlanProblem& problem,
                    const PlanOptions& options,
                    const plan_stages::InitialEquilibrium& initial);

/// plan() with problem.arm and/or problem.base_arm: each arm's reach shell (the tip arm's in
/// problem.workspace, the base arm's in problem.moving_base->workspace), plan_rod, the IK checks
/// of both arms and the re-plans (both arms' re-plans share ArmPlanOptions::max_replans), the
/// joint trajectories (on one clock with two arms) and the links' gaps. Throws InputError for a
/// workspace that already has a reach shell while use_reach is set
/// ("PlanProblem.workspace.reach", "PlanProblem.moving_base.workspace.reach"), an initial tip
/// pose outside the arm's reach shell ("PlanArm") and an initial base pose outside the base
/// arm's ("PlanProblem.rod.clamp").
PlanResult plan_with_arm(const PlanProblem& problem, const PlanOptions& options);

/// The arms' part of a plan made elsewhere (or by hand), without re-plans: the arms prepared as
/// by plan_with_arm (the same InputErrors), every step's and path sample's pose checked by IK,
/// the joint trajectories, the links' gaps; sets result.arm and result.base_arm, the scene
/// result's robot gap and the status collision.
void check_arms(const PlanProblem& problem, const PlanOptions& options, PlanResult& result);

}  // namespace rodshape::detail
