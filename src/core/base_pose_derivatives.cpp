#include "rodshape/core/base_pose_derivatives.hpp"

#include <cassert>

#include "load_tangent.hpp"
#include "rodshape/core/so3.hpp"

namespace rodshape {

namespace {

/// Replaces a point's load derivatives d = [dx/df | dx/dl] (3 × 6, column-major) by its clamp-pose
/// derivatives [translation·I | rigid + dx/df [f]× + dx/dl [l]×], `rigid` column-major. [f]× is
/// spelled out: column k of dx/df [f]× is dx/df (f × e_k), with f × e_0 = (0, f2, -f1),
/// f × e_1 = (-f2, 0, f0), f × e_2 = (f1, -f0, 0). Without a load (loaded = false) d is not read.
/// Plain scalars: Eigen's 3 × 3 temporaries cost several times this (store-forwarding stalls).
inline void to_pose_columns(bool translation,
                            const double (&rigid)[9],
                            const Eigen::Vector3d& f,
                            const Eigen::Vector3d& l,
                            bool loaded,
                            Matrix36d& derivative) {
  double* const d = derivative.data();
  double turn[9];
  for (int r = 0; r < 3; ++r) {
    double t0 = rigid[r], t1 = rigid[r + 3], t2 = rigid[r + 6];
    if (loaded) {
      const double F0 = d[r], F1 = d[r + 3], F2 = d[r + 6];
      const double L0 = d[r + 9], L1 = d[r + 12], L2 = d[r + 15];
      t0 += f[2] * F1 - f[1] * F2 + l[2] * L1 - l[1] * L2;
      t1 += f[0] * F2 - f[2] * F0 + l[0] * L2 - l[2] * L0;
      t2 += f[1] * F0 - f[0] * F1 + l[1] * L0 - l[0] * L1;
    }
    turn[r] = t0, turn[r + 3] = t1, turn[r + 6] = t2;
  }
  const double one = translation ? 1.0 : 0.0;
  for (int k = 0; k < 9; ++k) d[k] = 0.0;
  d[0] = d[4] = d[8] = one;
  for (int k = 0; k < 9; ++k) d[9 + k] = turn[k];
}

/// -[a]×, column-major: the rigid part δφ × a = -[a]× δφ.
inline void minus_hat(const Eigen::Vector3d& a, double (&out)[9]) {
  out[0] = 0.0, out[1] = -a[2], out[2] = a[1];
  out[3] = a[2], out[4] = 0.0, out[5] = -a[0];
  out[6] = -a[1], out[7] = a[0], out[8] = 0.0;
}

}  // namespace

void base_pose_derivatives(const ClampedRod& rod,
                           const RodConfiguration& c,
                           RodConfiguration& out) {
  assert(&c != &out);
  assert(c.nodes() == rod.nodes());
  const Eigen::Vector3d& f = rod.load.force;
  const Eigen::Vector3d& l = rod.load.moment;
  const bool loaded = f != Eigen::Vector3d::Zero() || l != Eigen::Vector3d::Zero();
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

  const Eigen::Vector3d& p0 = rod.clamp.position;
  const int nodes = out.nodes();
  for (int i = 0; i < nodes; ++i) {
    double rigid[9];
    minus_hat(out.p[i] - p0, rigid);
    to_pose_columns(true, rigid, f, l, loaded, out.dp_dw[i]);
    const double* const R = out.R[i].data();  // Rᵀ, column-major
    for (int r = 0; r < 3; ++r)
      for (int k = 0; k < 3; ++k) rigid[r + 3 * k] = R[k + 3 * r];
    to_pose_columns(false, rigid, f, l, loaded, out.dtheta_dw[i]);
    minus_hat(out.n[i], rigid);
    to_pose_columns(false, rigid, f, l, loaded, out.dn_dw[i]);
    minus_hat(out.m[i], rigid);
    to_pose_columns(false, rigid, f, l, loaded, out.dm_dw[i]);
  }
  out.tip_dp_dw = out.dp_dw[nodes - 1];
  out.tip_dtheta_dw = out.dtheta_dw[nodes - 1];
  out.tip_dn_dw = out.dn_dw[nodes - 1];
  out.tip_dm_dw = out.dm_dw[nodes - 1];
  // dE/dξ = [0 | dE/df [f]× + dE/dl [l]×]
  const Eigen::Matrix<double, 1, 6> dE = out.denergy_dw;
  out.denergy_dw.setZero();
  if (loaded) {
    out.denergy_dw(3) = f[2] * dE(1) - f[1] * dE(2) + l[2] * dE(4) - l[1] * dE(5);
    out.denergy_dw(4) = f[0] * dE(2) - f[2] * dE(0) + l[0] * dE(5) - l[2] * dE(3);
    out.denergy_dw(5) = f[1] * dE(0) - f[0] * dE(1) + l[1] * dE(3) - l[0] * dE(4);
  }
}

RodConfiguration base_pose_derivatives(const ClampedRod& rod, const RodConfiguration& c) {
  RodConfiguration out;
  base_pose_derivatives(rod, c, out);
  return out;
}

}  // namespace rodshape
