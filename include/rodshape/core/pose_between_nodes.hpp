// pose_between_nodes.hpp: the pose at an arc length between two nodes and its derivatives with
// respect to the base wrench, re-entering the integration at the node before it (the stability
// test refines conjugate points with it).
#pragma once

#include "rodshape/core/clamped_rod.hpp"
#include "rodshape/core/pose.hpp"
#include "rodshape/core/rod_configuration.hpp"
#include "rodshape/core/wrench.hpp"

namespace rodshape {

struct PoseDerivatives {
  Pose pose;                                // p(s), R(s)
  Matrix36d dp_dw = Matrix36d::Zero();      // dp(s)/dw, world frame
  Matrix36d dtheta_dw = Matrix36d::Zero();  // body-frame angle: δR = R θ̂, θ = dtheta_dw δw
};

/// From node i of `configuration` (integrated from `rod` with Derivatives::AllNodes) to s ≥ s_i
/// in rod.substeps Runge–Kutta steps of (s - s_i) / substeps, the method of integrate(), with the
/// variational equations through the same stages: at s = s_{i+1} it reproduces node i+1 up to
/// round-off. Meant for s within one or two intervals of s_i.
PoseDerivatives pose_between_nodes(const ClampedRod& rod,
                                   const RodConfiguration& configuration,
                                   int i,
                                   double s);

}  // namespace rodshape
