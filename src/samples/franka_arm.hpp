// franka_arm.hpp: a bundled Franka arm with its published acceleration and jerk limits set, each
// joint's from its number (fr3_joint4: joint 4), so that a part of the chain gets its joints' own.
#pragma once

#include <array>
#include <string>

#include "rodshape/robot/arm_model.hpp"
#include "rodshape/samples/franka_limits.hpp"

namespace rodshape::samples::detail {

inline ArmModel with_franka_limits(const ArmModel& arm,
                                   const FrankaJointLimits& limits,
                                   const std::string& source) {
  const int n = arm.joints();
  Eigen::VectorXd acceleration(n), jerk(n);
  for (int i = 0; i < n; ++i) {
    const std::string& name = arm.joint_info()[static_cast<std::size_t>(i)].name;
    const int k = name.empty() ? 0 : name.back() - '1';  // the bundled URDFs' own names
    acceleration(i) = limits.acceleration.at(static_cast<std::size_t>(k));
    jerk(i) = limits.jerk.at(static_cast<std::size_t>(k));
  }
  return arm.with_motion_limits(acceleration, jerk, source);
}

}  // namespace rodshape::samples::detail
