// clamped_rod.hpp: everything that fixes the shape once the base wrench is known: the rod, its
// distributed load, the clamp pose at s = 0 and the discretisation.
#pragma once

#include "rodshape/core/distributed_load.hpp"
#include "rodshape/core/pose.hpp"
#include "rodshape/core/rod_properties.hpp"

namespace rodshape {

struct ClampedRod {
  RodProperties properties;
  DistributedLoad load;
  Pose clamp;           // world_T_base: p(0), R(0)
  int intervals = 100;  // N: N + 1 nodes s_i = i L / N

  int nodes() const { return intervals + 1; }
  double step() const { return properties.length / intervals; }

  /// Throws InputError naming the field: properties, loads finite, clamp rotation orthonormal
  /// (within 1e-6), intervals ≥ 1.
  void validate() const;
};

}  // namespace rodshape
