// wrist_wrench.cpp: the rod's wrench on the gripper, in the end-effector frame, with noise.
#include "wrist_wrench.hpp"

namespace rodshape::sim_detail {

Wrench measured_wrist_wrench(const PlantFrame& frame,
                             const WristNoise& noise,
                             std::mt19937_64& random,
                             std::normal_distribution<double>& normal) {
  const Pose& ee = frame.end_effector;  // where the gripper is (the grasp may be off)
  const Wrench tip = frame.configuration.tip_wrench();
  Wrench w;
  w.force = -(ee.rotation.transpose() * tip.force);
  w.moment = -(ee.rotation.transpose() *
               (tip.moment + (frame.configuration.tip().position - ee.position).cross(tip.force)));
  for (int k = 0; k < 3; ++k) {
    w.force(k) += noise.force * normal(random);
    w.moment(k) += noise.moment * normal(random);
  }
  return w;
}

}  // namespace rodshape::sim_detail
