// distributed_load.hpp: the distributed force f and moment l of n' = -f, m' = -p' × n - l.
// Both are constant along s and given in the world frame.
#pragma once

#include <Eigen/Core>

namespace rodshape {

struct DistributedLoad {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();   // f, N/m
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();  // l, N·m/m

  /// Weight: f = ρ A g.
  static DistributedLoad gravity(double mass_per_length, const Eigen::Vector3d& g) {
    return {mass_per_length * g, Eigen::Vector3d::Zero()};
  }
};

}  // namespace rodshape
