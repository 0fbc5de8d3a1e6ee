// arm_placement.hpp: where an arm stands in the world and where its end effector sits on its tip
// link (flange). The IK target of an end-effector pose world_T_ee is
//   base_T_flange = world_T_base⁻¹ · world_T_ee · flange_T_ee⁻¹.
#pragma once

#include <Eigen/Core>

#include "rodshape/core/pose.hpp"
#include "rodshape/robot/arm_model.hpp"

namespace rodshape {

struct ArmPlacement {
  Pose world_T_base;  // identity: the arm's base frame is the world frame
  Pose flange_T_ee;   // identity: the end effector is the tip link's frame
};

/// base_T_flange for the end-effector pose world_T_ee (the IK target of that pose).
Pose flange_target(const ArmPlacement& placement, const Pose& world_T_ee);

/// world_T_ee of the arm at `q`: world_T_base · FK(q) · flange_T_ee.
Pose end_effector_pose(const ArmModel& arm,
                       const ArmPlacement& placement,
                       const Eigen::VectorXd& q);

}  // namespace rodshape
