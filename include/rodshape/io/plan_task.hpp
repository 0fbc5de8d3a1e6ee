// plan_task.hpp: what a plan task file describes: the rod and its clamp (as for `equilibrium`), the
// target shape, the weights of the cost, what the shapes must respect (workspace, grasp, strain
// limits), the initial tip pose, and the options of the optimiser and of the trajectory. See
// docs/task-file.md for the file format. An optional robot section places an arm (URDF) in the
// world; `rodshape plan` then plans with the arm's reach as part of the workspace, checks every
// planned pose by inverse kinematics and computes the joint trajectory (plan_with_arm).
#pragma once

#include <optional>
#include <string>

#include "rodshape/robot/arm_model.hpp"
#include "rodshape/robot/arm_plan.hpp"
#include "rodshape/robot/joint_trajectory.hpp"
#include "rodshape/trajectory/shape_plan.hpp"

namespace rodshape {

/// The task file's `robot` section: the arm (already read from its URDF) and where it stands.
struct PlanRobot {
  std::string urdf;        // the URDF file, resolved against the task file's directory
  ArmModel arm;            // the chain from robot.base_link to robot.tip_link
  ArmPlacement placement;  // robot.base (world_T_base), robot.flange_to_end_effector
  ArmPlanOptions options;  // robot.reach (the reach shell, re-plans); robot.seed in
                           // options.joints.seed (empty: default_seed)
};

struct PlanTask {
  PlanRequest request;  // rod, target (points, weights), workspace, grasp, limits, initial tip
  PlanOptions options;  // trajectory.steps (n_inter), optimizer, end-effector limits, tracking
  std::string source;   // the file name that messages name
  std::optional<PlanRobot> robot;  // the robot section, when the task has one
};

}  // namespace rodshape
