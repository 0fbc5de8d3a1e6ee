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

}  // namespace rodshape
