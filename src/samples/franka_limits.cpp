#include "rodshape/samples/franka_limits.hpp"

namespace rodshape::samples {

const FrankaJointLimits& panda_joint_limits() {
  static const FrankaJointLimits limits{
      {-2.8973, -1.7628, -2.8973, -3.0718, -2.8973, -0.0175, -2.8973},
      {2.8973, 1.7628, 2.8973, -0.0698, 2.8973, 3.7525, 2.8973},
      {2.1750, 2.1750, 2.1750, 2.1750, 2.6100, 2.6100, 2.6100},
      {15.0, 7.5, 10.0, 12.5, 15.0, 20.0, 20.0},
      {7500.0, 3750.0, 5000.0, 6250.0, 7500.0, 10000.0, 10000.0}};
  return limits;
}

const FrankaJointLimits& fr3_joint_limits() {
  static const FrankaJointLimits limits{
      {-2.7437, -1.7837, -2.9007, -3.0421, -2.8065, 0.5445, -3.0159},
      {2.7437, 1.7837, 2.9007, -0.1518, 2.8065, 4.5169, 3.0159},
      {2.62, 2.62, 2.62, 2.62, 5.26, 4.18, 5.26},
      {10.0, 10.0, 10.0, 10.0, 10.0, 10.0, 10.0},
      {5000.0, 5000.0, 5000.0, 5000.0, 5000.0, 5000.0, 5000.0}};
  return limits;
}

}  // namespace rodshape::samples
