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
  /// Runge–Kutta steps per interval (1 ≤ substeps ≤ kMaxSubsteps): the nodes stay at s_i, each
  /// interval is crossed in `substeps` steps of L / (N substeps).
  int substeps = 1;
  static constexpr int kMaxSubsteps = 4096;
  /// Upper bound on intervals (docs/limits.md, "Sizes"): memory and time are linear in the nodes,
  /// about 2.7 kB and, for one equilibrium of the band, 11 µs per node (100,000 intervals: 1.1 s,
  /// 290 MB, a 49 MB result file).
  static constexpr int kMaxIntervals = 100'000;

  int nodes() const { return intervals + 1; }
  double step() const { return properties.length / intervals; }

  /// Throws InputError naming the field: properties, loads finite, clamp rotation orthonormal
  /// (within 1e-6), 1 ≤ intervals ≤ kMaxIntervals, 1 ≤ substeps ≤ kMaxSubsteps.
  void validate() const;
};

}  // namespace rodshape
