// franka_limits.hpp: Franka's published joint limits of the Panda and the FR3, from the tables of
// "Robot and interface specifications" (https://frankaemika.github.io/docs/control_parameters.html;
// frankaemika/docs, commit 1da6bd33e741fbbffafa96e07c6c5cd4b0921055,
// source/control-parameters-joint-panda.csv and control-parameters-joint-fr3.csv). The position
// and velocity limits are also in the bundled URDFs; acceleration and jerk are not (a URDF cannot
// hold them) and are set on the bundled arms by samples::panda() and samples::fr3().
#pragma once

#include <array>

namespace rodshape::samples {

/// One arm's limits per joint (joints 1 … 7): rad, rad/s, rad/s², rad/s³.
struct FrankaJointLimits {
  std::array<double, 7> lower;
  std::array<double, 7> upper;
  std::array<double, 7> velocity;
  std::array<double, 7> acceleration;
  std::array<double, 7> jerk;
};

/// The Panda (Franka Emika Robot, FER): "Limits for Panda".
const FrankaJointLimits& panda_joint_limits();

/// The Franka Research 3: "Limits for Franka Research 3" (not the narrower "position-velocity
/// rectangular limits" the same page suggests for planners, docs/robot.md).
const FrankaJointLimits& fr3_joint_limits();

}  // namespace rodshape::samples
