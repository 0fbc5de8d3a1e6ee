// The Franka Research 3 as a sample arm: the kinematic URDF bundled in data/robots/fr3.urdf
// (compiled into the library), its chain from fr3_link0 to the flange fr3_link8 with Franka's
// acceleration and jerk limits (franka_limits.hpp), and its ready pose.
#pragma once

#include <Eigen/Core>
#include <string_view>

#include "rodshape/robot/arm_model.hpp"

namespace rodshape::samples {

/// The URDF text of data/robots/fr3.urdf.
std::string_view fr3_urdf();

/// The arm from fr3_link0 (its base) to fr3_link8 (the flange), 7 revolute joints.
ArmModel fr3();

/// The ready pose q = (0, −π/4, 0, −3π/4, 0, π/2, π/4) rad, the Panda's (within the FR3's limits).
Eigen::VectorXd fr3_ready_pose();

}  // namespace rodshape::samples
