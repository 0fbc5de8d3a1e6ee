// commanded_path.hpp: the end-effector poses the arm really commands. With an arm, a plan's hand
// follows its joint trajectory, so the poses are the arm's forward kinematics at the trajectory's
// samples and times (re-timed when slowed):
//   world_T_ee(t_k) = world_T_base · FK(q_k) · flange_T_ee.
// They equal the planned end-effector path to the IK tolerance (IkOptions: 1e-10 m and rad).
// With a moving base (issue 21) the base gripper's commanded poses are found the same way from the
// base arm's joint trajectory, else they are the plan's base_end_effector_path.
#pragma once

#include <vector>

#include "rodshape/sim/plant.hpp"
#include "rodshape/trajectory/end_effector_path.hpp"
#include "rodshape/trajectory/joint_trajectory.hpp"
#include "rodshape/trajectory/plan_problem.hpp"
#include "rodshape/trajectory/plan_result.hpp"

namespace rodshape {

/// Whether `plan` has an arm's complete joint trajectory (and `problem` the arm) to drive a plant.
bool drives_joints(const PlanProblem& problem, const PlanResult& plan);

/// The end-effector pose of `arm` at every sample of `joints`, at the samples' times.
std::vector<TimedPose> hand_poses(const PlanArm& arm, const JointTrajectoryResult& joints);

/// hand_poses() of the plan's joint trajectory when drives_joints(), else the plan's end-effector
/// path.
std::vector<TimedPose> commanded_path(const PlanProblem& problem, const PlanResult& plan);

/// Whether `plan` has the base arm's complete joint trajectory (and `problem` a moving base held
/// by that arm) to drive the plant's base.
bool drives_base_joints(const PlanProblem& problem, const PlanResult& plan);

/// The base gripper's commanded poses: empty with a fixed clamp (no moving_base); the base arm's
/// hand_poses() when drives_base_joints(); else the plan's base_end_effector_path (empty until a
/// plan fills it: the base then stays clamped at rod.clamp).
std::vector<TimedPose> commanded_base_path(const PlanProblem& problem, const PlanResult& plan);

/// The plant's base drive: commanded_base_path() with the base grasp's base_T_ee.
BaseGripperPath commanded_base(const PlanProblem& problem, const PlanResult& plan);

}  // namespace rodshape
