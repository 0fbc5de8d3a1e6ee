// commanded_path.cpp: the arm's forward kinematics along its joint trajectory (commanded_path.hpp).
#include "rodshape/sim/commanded_path.hpp"

#include "rodshape/robot/arm_placement.hpp"

namespace rodshape {

bool drives_joints(const PlanProblem& problem, const PlanResult& plan) {
  return problem.arm && plan.arm && plan.arm->joints.complete();  // complete: ≥ 1 sample
}

std::vector<TimedPose> hand_poses(const PlanArm& arm, const JointTrajectoryResult& joints) {
  std::vector<TimedPose> path;
  path.reserve(joints.t.size());
  for (std::size_t k = 0; k < joints.t.size(); ++k)
    path.push_back({joints.t[k], end_effector_pose(arm.model, arm.placement, joints.q[k])});
  return path;
}

std::vector<TimedPose> commanded_path(const PlanProblem& problem, const PlanResult& plan) {
  if (!drives_joints(problem, plan)) return plan.end_effector_path;
  return hand_poses(*problem.arm, plan.arm->joints);
}

bool drives_base_joints(const PlanProblem& problem, const PlanResult& plan) {
  return problem.moving_base && problem.base_arm && plan.base_arm &&
         plan.base_arm->joints.complete();
}

std::vector<TimedPose> commanded_base_path(const PlanProblem& problem, const PlanResult& plan) {
  if (!problem.moving_base) return {};
  if (!drives_base_joints(problem, plan)) return plan.base_end_effector_path;
  return hand_poses(*problem.base_arm, plan.base_arm->joints);
}

BaseGripperPath commanded_base(const PlanProblem& problem, const PlanResult& plan) {
  BaseGripperPath base;
  if (!problem.moving_base) return base;
  base.base_to_end_effector = problem.moving_base->grasp.tip_to_end_effector;
  base.path = commanded_base_path(problem, plan);
  return base;
}

}  // namespace rodshape
