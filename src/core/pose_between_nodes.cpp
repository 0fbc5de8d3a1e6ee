#include "rodshape/core/pose_between_nodes.hpp"

#include <Eigen/Geometry>
#include "rk4_step.hpp"

namespace rodshape {

namespace {

using detail::NodeState;
using detail::Slot;

/// Re-enters the integration at node i: y from the stored node, the tangent from the stored
/// derivatives (δq = ½ q ⊗ (0, θ) for each direction).
NodeState node_state(const RodConfiguration& c, int i) {
  NodeState state;
  const Eigen::Quaterniond q(c.R[i]);
  state.y << q.w(), q.x(), q.y(), q.z(), c.p[i], c.n[i], c.m[i], 0.0;
  state.Y.setZero();
  for (int j = 0; j < 6; ++j) {
    const Eigen::Vector3d theta = c.dtheta_dw[i].col(j);
    const Eigen::Quaterniond dq =
        q * Eigen::Quaterniond(0.0, 0.5 * theta.x(), 0.5 * theta.y(), 0.5 * theta.z());
    state.Y(j, Slot::q) = dq.w();
    state.Y.block<1, 3>(j, Slot::q + 1) = dq.vec().transpose();
  }
  state.Y.middleCols<3>(Slot::p) = c.dp_dw[i].transpose();
  state.Y.middleCols<3>(Slot::n) = c.dn_dw[i].transpose();
  state.Y.middleCols<3>(Slot::m) = c.dm_dw[i].transpose();
  return state;
}

}  // namespace

PoseDerivatives pose_between_nodes(const ClampedRod& rod,
                                   const RodConfiguration& c,
                                   int i,
                                   double s) {
  const detail::CosseratOde ode(rod);
  NodeState state = node_state(c, i);
  const int steps = rod.substeps;
  const double h = (s - c.s[i]) / steps;
  detail::OdePoint start;
  detail::Matrix63d theta;
  for (int k = 0; k < steps; ++k) detail::rk4_step<true>(ode, h, state, start, theta);
  const Eigen::Vector4d q = state.y.segment<4>(Slot::q);
  const double q_scale = 2.0 / q.squaredNorm();
  PoseDerivatives out;
  out.pose = {state.y.segment<3>(Slot::p), detail::rotation_of(q, q_scale)};
  out.dp_dw = state.Y.middleCols<3>(Slot::p).transpose();
  out.dtheta_dw = detail::body_rotation_tangent(q, q_scale, state.Y).transpose();
  return out;
}

}  // namespace rodshape
