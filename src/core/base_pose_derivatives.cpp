#include "rodshape/core/base_pose_derivatives.hpp"

#include <cassert>

#include "load_tangent.hpp"
#include "rodshape/core/so3.hpp"

namespace rodshape {

namespace {

/// [I | -[r]× + D] (with_translation) or [0 | B + D].
Matrix36d pose_columns(const Eigen::Matrix3d& rotation_block,
                       const Eigen::Matrix3d& load_block,
                       bool with_translation) {
  Matrix36d d;
  if (with_translation) {
    d.leftCols<3>().setIdentity();
  } else {
    d.leftCols<3>().setZero();
  }
  d.rightCols<3>() = rotation_block + load_block;
  return d;
}

/// D = dx/df [f]× + dx/dl [l]× from the load derivatives (columns 0–2 f, 3–5 l).
Eigen::Matrix3d load_turn(const Matrix36d& d_load,
                          const Eigen::Matrix3d& f_hat,
                          const Eigen::Matrix3d& l_hat) {
  return d_load.leftCols<3>() * f_hat + d_load.rightCols<3>() * l_hat;
}

/// Replaces the load derivatives of one point (p, θ, n, m: `d_*`) by the clamp-pose derivatives.
void to_pose_derivatives(const Eigen::Vector3d& p_rel,
                         const Eigen::Matrix3d& R,
                         const Eigen::Vector3d& n,
                         const Eigen::Vector3d& m,
                         const Eigen::Matrix3d& f_hat,
                         const Eigen::Matrix3d& l_hat,
                         bool loaded,
                         Matrix36d& dp,
                         Matrix36d& dtheta,
                         Matrix36d& dn,
                         Matrix36d& dm) {
  const Eigen::Matrix3d zero = Eigen::Matrix3d::Zero();
  dp = pose_columns(-hat(p_rel), loaded ? load_turn(dp, f_hat, l_hat) : zero, true);
  dtheta = pose_columns(R.transpose(), loaded ? load_turn(dtheta, f_hat, l_hat) : zero, false);
  dn = pose_columns(-hat(n), loaded ? load_turn(dn, f_hat, l_hat) : zero, false);
  dm = pose_columns(-hat(m), loaded ? load_turn(dm, f_hat, l_hat) : zero, false);
}

}  // namespace

void base_pose_derivatives(const ClampedRod& rod,
                           const RodConfiguration& c,
                           RodConfiguration& out) {
  assert(&c != &out);
  assert(c.nodes() == rod.nodes());
  const Eigen::Vector3d& f = rod.load.force;
  const Eigen::Vector3d& l = rod.load.moment;
  const bool loaded = !f.isZero(0.0) || !l.isZero(0.0);
  if (loaded) {
    // The derivatives with respect to (f, l) into out's derivative arrays (and its state, which
    // c's replaces below).
    detail::integrate_load_tangent(rod, c.base_wrench(), out);
  } else {
    out.resize(c.nodes(), Derivatives::AllNodes);
  }
  // c's state (equal sizes: no allocation).
  out.s = c.s;
  out.p = c.p;
  out.R = c.R;
  out.n = c.n;
  out.m = c.m;
  out.v = c.v;
  out.u = c.u;
  out.energy = c.energy;

  const Eigen::Matrix3d f_hat = hat(f);
  const Eigen::Matrix3d l_hat = hat(l);
  const Eigen::Vector3d& p0 = rod.clamp.position;
  for (int i = 0; i < out.nodes(); ++i)
    to_pose_derivatives(out.p[i] - p0, out.R[i], out.n[i], out.m[i], f_hat, l_hat, loaded,
                        out.dp_dw[i], out.dtheta_dw[i], out.dn_dw[i], out.dm_dw[i]);
  const int tip = out.nodes() - 1;
  to_pose_derivatives(out.p[tip] - p0, out.R[tip], out.n[tip], out.m[tip], f_hat, l_hat, loaded,
                      out.tip_dp_dw, out.tip_dtheta_dw, out.tip_dn_dw, out.tip_dm_dw);
  Eigen::Matrix<double, 1, 6> denergy = Eigen::Matrix<double, 1, 6>::Zero();
  if (loaded) {
    denergy.rightCols<3>() =
        out.denergy_dw.leftCols<3>() * f_hat + out.denergy_dw.rightCols<3>() * l_hat;
  }
  out.denergy_dw = denergy;
}

RodConfiguration base_pose_derivatives(const ClampedRod& rod, const RodConfiguration& c) {
  RodConfiguration out;
  base_pose_derivatives(rod, c, out);
  return out;
}

}  // namespace rodshape
