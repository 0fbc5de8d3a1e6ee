// wrist_wrench.hpp (private to the sim area): what a wrist force/torque sensor measures of a plant
// frame: the rod's wrench on the gripper, −n(L), −m(L) about the end effector and in its frame,
// with the sensor's Gaussian noise. The marker and depth cameras share it.
#pragma once

#include <random>

#include "rodshape/core/wrench.hpp"
#include "rodshape/feedback/marker_measurement.hpp"
#include "rodshape/sim/plant.hpp"

namespace rodshape::sim_detail {

/// The noisy wrist wrench of `frame`: six draws of `normal` (force k, moment k, k = 0, 1, 2).
Wrench measured_wrist_wrench(const PlantFrame& frame,
                             const WristNoise& noise,
                             std::mt19937_64& random,
                             std::normal_distribution<double>& normal);

}  // namespace rodshape::sim_detail
