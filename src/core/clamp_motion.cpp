// clamp_motion.cpp: a configuration carried rigidly with its clamp (clamp_motion.hpp).
#include "rodshape/core/clamp_motion.hpp"

#include <cassert>

namespace rodshape {

namespace {

/// Q D Bᵀ for a derivative D = [d/dn(0) | d/dm(0)] of a world-frame vector, B = blockdiag(Q, Q).
Matrix36d world_derivative(const Eigen::Matrix3d& Q, const Matrix36d& D) {
  Matrix36d out;
  out.leftCols<3>().noalias() = Q * D.leftCols<3>() * Q.transpose();
  out.rightCols<3>().noalias() = Q * D.rightCols<3>() * Q.transpose();
  return out;
}

/// D Bᵀ for a derivative of a body-frame quantity.
Matrix36d body_derivative(const Eigen::Matrix3d& Q, const Matrix36d& D) {
  Matrix36d out;
  out.leftCols<3>().noalias() = D.leftCols<3>() * Q.transpose();
  out.rightCols<3>().noalias() = D.rightCols<3>() * Q.transpose();
  return out;
}

}  // namespace

void move_with_clamp(const RodConfiguration& c,
                     const Pose& from,
                     const Pose& to,
                     RodConfiguration& out) {
  assert(&c != &out);
  const int nodes = c.nodes();
  out.resize(nodes, c.derivatives);
  const Eigen::Matrix3d Q = to.rotation * from.rotation.transpose();
  for (int i = 0; i < nodes; ++i) {
    out.p[i] = to.position + Q * (c.p[i] - from.position);
    out.R[i] = Q * c.R[i];
    out.n[i] = Q * c.n[i];
    out.m[i] = Q * c.m[i];
  }
  out.s = c.s;
  out.v = c.v;
  out.u = c.u;
  out.energy = c.energy;
  if (c.derivatives == Derivatives::None) return;
  if (c.derivatives == Derivatives::AllNodes) {
    for (int i = 0; i < nodes; ++i) {
      out.dp_dw[i] = world_derivative(Q, c.dp_dw[i]);
      out.dtheta_dw[i] = body_derivative(Q, c.dtheta_dw[i]);
      out.dn_dw[i] = world_derivative(Q, c.dn_dw[i]);
      out.dm_dw[i] = world_derivative(Q, c.dm_dw[i]);
    }
  }
  out.tip_dp_dw = world_derivative(Q, c.tip_dp_dw);
  out.tip_dtheta_dw = body_derivative(Q, c.tip_dtheta_dw);
  out.tip_dn_dw = world_derivative(Q, c.tip_dn_dw);
  out.tip_dm_dw = world_derivative(Q, c.tip_dm_dw);
  out.denergy_dw.head<3>() = c.denergy_dw.head<3>() * Q.transpose();
  out.denergy_dw.tail<3>() = c.denergy_dw.tail<3>() * Q.transpose();
}

}  // namespace rodshape
