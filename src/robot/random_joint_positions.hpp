// random_joint_positions.hpp (private): joint positions drawn uniformly within an arm's limits, for
// IK restarts and for sampling the arm's reach.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <numbers>
#include <random>

#include "rodshape/robot/arm_model.hpp"

namespace rodshape::detail {

/// Each joint uniform within its limits (a joint without limits: within [-π, π]).
inline Eigen::VectorXd random_joint_positions(const ArmModel& arm, std::mt19937& rng) {
  Eigen::VectorXd q(arm.joints());
  for (int i = 0; i < arm.joints(); ++i) {
    const JointInfo& joint = arm.joint_info()[i];
    const double lo = std::isfinite(joint.lower) ? joint.lower : -std::numbers::pi;
    const double hi = std::isfinite(joint.upper) ? joint.upper : std::numbers::pi;
    q(i) = std::uniform_real_distribution<double>(lo, hi)(rng);
  }
  return q;
}

}  // namespace rodshape::detail
