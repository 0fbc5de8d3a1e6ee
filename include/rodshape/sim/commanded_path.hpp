// commanded_path.hpp: the end-effector poses the arm really commands. With an arm, a plan's hand
// follows its joint trajectory, so the poses are the arm's forward kinematics at the trajectory's
// samples and times (re-timed when slowed):
//   world_T_ee(t_k) = world_T_base · FK(q_k) · flange_T_ee.
// They equal the planned end-effector path to the IK tolerance (IkOptions: 1e-10 m and rad).
#pragma once

#include <vector>

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

}  // namespace rodshape
