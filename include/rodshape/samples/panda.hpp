// The Franka Emika Panda as a sample arm: the kinematic URDF bundled in data/robots/panda.urdf
// (compiled into the library, so an installed program needs no data files), its chain from
// panda_link0 to the flange panda_link8 with Franka's acceleration and jerk limits
// (franka_limits.hpp), and its ready pose. The paper's experiments used this arm.
#pragma once

#include <Eigen/Core>
#include <string_view>

#include "rodshape/robot/arm_model.hpp"

namespace rodshape::samples {

/// The URDF text of data/robots/panda.urdf.
std::string_view panda_urdf();

/// The arm from panda_link0 (its base) to panda_link8 (the flange), 7 revolute joints.
ArmModel panda();

/// The ready pose q = (0, -π/4, 0, -3π/4, 0, π/2, π/4) rad.
Eigen::VectorXd panda_ready_pose();

}  // namespace rodshape::samples
