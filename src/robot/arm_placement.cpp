// arm_placement.cpp: frames of an arm placed in the world (see arm_placement.hpp).
#include "rodshape/robot/arm_placement.hpp"

namespace rodshape {

Pose flange_target(const ArmPlacement& placement, const Pose& world_T_ee) {
  return compose(compose(inverse(placement.world_T_base), world_T_ee),
                 inverse(placement.flange_T_ee));
}

Pose end_effector_pose(const ArmModel& arm,
                       const ArmPlacement& placement,
                       const Eigen::VectorXd& q) {
  return compose(compose(placement.world_T_base, arm.forward_kinematics(q)), placement.flange_T_ee);
}

}  // namespace rodshape
