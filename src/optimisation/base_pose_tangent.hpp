// base_pose_tangent.hpp (private, temporary until core's base_pose_derivatives lands): the
// derivatives of every node's state with respect to the base pose ξ = (δt, δφ) at a fixed
// body-frame base wrench, for a rod without distributed loads, where a turn of the base turns the
// whole rod rigidly about p(0):
//   δp_i = δt + δφ × (p_i - p0),  δθ_i = R_iᵀ δφ,  δn_i = δφ × n_i,  δm_i = δφ × m_i,  δE = 0.
#pragma once

#include "rodshape/core/clamped_rod.hpp"
#include "rodshape/core/rod_configuration.hpp"
#include "rodshape/core/so3.hpp"
#include "rodshape/error.hpp"

namespace rodshape::detail {

inline void base_pose_tangent(const ClampedRod& rod, const RodConfiguration& c,
                              RodConfiguration& out) {
  if (!rod.load.force.isZero() || !rod.load.moment.isZero())
    throw InputError("PlanProblem.moving_base", ": not yet with a distributed load");
  const int n = c.nodes();
  out.resize(n, Derivatives::AllNodes);
  out.s = c.s;
  out.p = c.p;
  out.R = c.R;
  out.n = c.n;
  out.m = c.m;
  out.v = c.v;
  out.u = c.u;
  out.energy = c.energy;
  const Eigen::Vector3d& p0 = c.p[0];
  for (int i = 0; i < n; ++i) {
    out.dp_dw[i].leftCols<3>().setIdentity();
    out.dp_dw[i].rightCols<3>() = -hat(c.p[i] - p0);
    out.dtheta_dw[i].leftCols<3>().setZero();
    out.dtheta_dw[i].rightCols<3>() = c.R[i].transpose();
    out.dn_dw[i].leftCols<3>().setZero();
    out.dn_dw[i].rightCols<3>() = -hat(c.n[i]);
    out.dm_dw[i].leftCols<3>().setZero();
    out.dm_dw[i].rightCols<3>() = -hat(c.m[i]);
  }
  out.tip_dp_dw = out.dp_dw[n - 1];
  out.tip_dtheta_dw = out.dtheta_dw[n - 1];
  out.tip_dn_dw = out.dn_dw[n - 1];
  out.tip_dm_dw = out.dm_dw[n - 1];
  out.denergy_dw.setZero();
}

}  // namespace rodshape::detail
