// cosserat_ode.hpp (private): the right-hand side of the static Cosserat rod (paper, "system of
// differential equations") and of its variational equations, in the coordinates the integrator
// steps: y = (q, p, n, m, e) with the orientation as a quaternion q = (w, x) and e the energy so far.
//
//   R = R(q/|q|) = I + (2/|q|²)(w x̂ + x̂²)
//   v = K_tra⁻¹ Rᵀ n + ṽ  (Kirchhoff: v = ṽ),   u = K_rot⁻¹ Rᵀ m + ũ         constitutive law
//   p' = R v,   q' = ½ q ⊗ (0, u)   (⇔ R' = R û),   n' = -f,   m' = -p' × n - l
//   e' = ½ ΔvᵀK_traΔv + ½ ΔuᵀK_rotΔu = ½ n̄ᵀK_tra⁻¹n̄ + ½ m̄ᵀK_rot⁻¹m̄,  n̄ = Rᵀn, m̄ = Rᵀm
//
// Tangents are stored transposed, one row per base-wrench direction (6 × 14), so that each state
// component's derivative is a contiguous 6-vector and the six directions share SIMD lanes.
#pragma once

#include <Eigen/Core>

#include "rodshape/core/clamped_rod.hpp"

namespace rodshape::detail {

using OdeState = Eigen::Matrix<double, 14, 1>;       // (q, p, n, m, e)
using OdeTangent = Eigen::Matrix<double, 6, 14>;     // row j: d(state)/dw_j
using Matrix63d = Eigen::Matrix<double, 6, 3>;
using Vector6 = Eigen::Matrix<double, 6, 1>;

/// Offsets of each quantity in OdeState (and columns of OdeTangent).
struct Slot {
  static constexpr int q = 0, p = 4, n = 7, m = 10, e = 13;
};

/// The ODE's constants, taken once per integration from the rod.
struct CosseratOde {
  Eigen::Vector3d C_tra;  // K_tra⁻¹ (diagonal)
  Eigen::Vector3d C_rot;  // K_rot⁻¹ (diagonal)
  Eigen::Vector3d v_rest, u_rest, f, l;
  bool extensible;        // Cosserat: shear and extension; Kirchhoff: v = ṽ

  explicit CosseratOde(const ClampedRod& rod)
      : C_tra(rod.properties.K_tra.cwiseInverse()),
        C_rot(rod.properties.K_rot.cwiseInverse()),
        v_rest(rod.properties.v_rest),
        u_rest(rod.properties.u_rest),
        f(rod.load.force),
        l(rod.load.moment),
        extensible(rod.properties.model == ConstitutiveModel::Cosserat) {}
};

/// What one evaluation of the ODE knows beyond y': kept for the tangent and for output.
struct OdePoint {
  Eigen::Matrix3d R;
  Eigen::Vector3d n_body, m_body;  // n̄ = Rᵀn, m̄ = Rᵀm
  Eigen::Vector3d v, u, p_prime;
  double q_scale;                  // 2/|q|²
};

/// a × d for each row d of D.
inline Matrix63d cross_rows(const Eigen::Vector3d& a, const Matrix63d& D) {
  Matrix63d out;
  out.col(0) = a.y() * D.col(2) - a.z() * D.col(1);
  out.col(1) = a.z() * D.col(0) - a.x() * D.col(2);
  out.col(2) = a.x() * D.col(1) - a.y() * D.col(0);
  return out;
}

/// R(q/|q|), exactly orthonormal for any q ≠ 0.
inline Eigen::Matrix3d rotation_of(const Eigen::Vector4d& q, double q_scale) {
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  const double s = q_scale;
  Eigen::Matrix3d R;
  R << 1.0 - s * (y * y + z * z), s * (x * y - w * z), s * (x * z + w * y),  //
      s * (x * y + w * z), 1.0 - s * (x * x + z * z), s * (y * z - w * x),   //
      s * (x * z - w * y), s * (y * z + w * x), 1.0 - s * (x * x + y * y);
  return R;
}

/// y' = F(y); fills `point` with R, n̄, m̄, v, u, p'. Written in scalars: on 3-vectors this is about
/// half the instructions of Eigen's packet code.
inline void evaluate(const CosseratOde& ode, const OdeState& y, OdeState& dy, OdePoint& point) {
  const double w = y[0], x = y[1], yq = y[2], z = y[3];
  const double nx = y[Slot::n], ny = y[Slot::n + 1], nz = y[Slot::n + 2];
  const double mx = y[Slot::m], my = y[Slot::m + 1], mz = y[Slot::m + 2];
  const double s = 2.0 / (w * w + x * x + yq * yq + z * z);
  point.q_scale = s;
  // R = R(q/|q|)
  const double r00 = 1.0 - s * (yq * yq + z * z), r01 = s * (x * yq - w * z), r02 = s * (x * z + w * yq);
  const double r10 = s * (x * yq + w * z), r11 = 1.0 - s * (x * x + z * z), r12 = s * (yq * z - w * x);
  const double r20 = s * (x * z - w * yq), r21 = s * (yq * z + w * x), r22 = 1.0 - s * (x * x + yq * yq);
  point.R << r00, r01, r02, r10, r11, r12, r20, r21, r22;
  // n̄ = Rᵀn, m̄ = Rᵀm
  const double nb0 = r00 * nx + r10 * ny + r20 * nz;
  const double nb1 = r01 * nx + r11 * ny + r21 * nz;
  const double nb2 = r02 * nx + r12 * ny + r22 * nz;
  const double mb0 = r00 * mx + r10 * my + r20 * mz;
  const double mb1 = r01 * mx + r11 * my + r21 * mz;
  const double mb2 = r02 * mx + r12 * my + r22 * mz;
  point.n_body = {nb0, nb1, nb2};
  point.m_body = {mb0, mb1, mb2};
  // Δu = K_rot⁻¹ m̄, u = Δu + ũ;  Δv = K_tra⁻¹ n̄, v = Δv + ṽ (Kirchhoff: v = ṽ)
  const double du0 = ode.C_rot[0] * mb0, du1 = ode.C_rot[1] * mb1, du2 = ode.C_rot[2] * mb2;
  const double u0 = du0 + ode.u_rest[0], u1 = du1 + ode.u_rest[1], u2 = du2 + ode.u_rest[2];
  double v0 = ode.v_rest[0], v1 = ode.v_rest[1], v2 = ode.v_rest[2];
  double e_tra = 0.0;
  if (ode.extensible) {
    const double dv0 = ode.C_tra[0] * nb0, dv1 = ode.C_tra[1] * nb1, dv2 = ode.C_tra[2] * nb2;
    v0 += dv0;
    v1 += dv1;
    v2 += dv2;
    e_tra = 0.5 * (nb0 * dv0 + nb1 * dv1 + nb2 * dv2);
  }
  point.v = {v0, v1, v2};
  point.u = {u0, u1, u2};
  // p' = R v
  const double px = r00 * v0 + r01 * v1 + r02 * v2;
  const double py = r10 * v0 + r11 * v1 + r12 * v2;
  const double pz = r20 * v0 + r21 * v1 + r22 * v2;
  point.p_prime = {px, py, pz};
  // q' = ½ q ⊗ (0, u) = ½ (-x·u, w u + x × u)
  dy[0] = -0.5 * (x * u0 + yq * u1 + z * u2);
  dy[1] = 0.5 * (w * u0 + yq * u2 - z * u1);
  dy[2] = 0.5 * (w * u1 + z * u0 - x * u2);
  dy[3] = 0.5 * (w * u2 + x * u1 - yq * u0);
  dy[Slot::p] = px;
  dy[Slot::p + 1] = py;
  dy[Slot::p + 2] = pz;
  // n' = -f
  dy[Slot::n] = -ode.f[0];
  dy[Slot::n + 1] = -ode.f[1];
  dy[Slot::n + 2] = -ode.f[2];
  // m' = -p' × n - l
  dy[Slot::m] = -(py * nz - pz * ny) - ode.l[0];
  dy[Slot::m + 1] = -(pz * nx - px * nz) - ode.l[1];
  dy[Slot::m + 2] = -(px * ny - py * nx) - ode.l[2];
  // e' = ½ ΔvᵀK_traΔv + ½ ΔuᵀK_rotΔu
  dy[Slot::e] = e_tra + 0.5 * (mb0 * du0 + mb1 * du1 + mb2 * du2);
}

/// θ: the body-frame rotation of each direction, δR = R θ̂, from the quaternion tangent:
/// θ = 2 vec(q* ⊗ δq)/|q|² = (2/|q|²)(w δx - δw x - x × δx).
inline Matrix63d body_rotation_tangent(const Eigen::Vector4d& q,
                                       double q_scale,
                                       const OdeTangent& Y) {
  const Eigen::Vector3d x = q.tail<3>();
  const Matrix63d dX = Y.middleCols<3>(Slot::q + 1);
  return q_scale * (q[0] * dX - Y.col(Slot::q) * x.transpose() - cross_rows(x, dX));
}

/// Y' = dF(y)[Y]: the variational equations, all six directions at once. Returns θ (see above).
inline Matrix63d evaluate_tangent(const CosseratOde& ode,
                                  const OdeState& y,
                                  const OdePoint& point,
                                  const OdeTangent& Y,
                                  OdeTangent& dY) {
  const Eigen::Vector4d q = y.segment<4>(Slot::q);
  const Eigen::Vector3d n = y.segment<3>(Slot::n);
  const Matrix63d theta = body_rotation_tangent(q, point.q_scale, Y);
  const Matrix63d dN = Y.middleCols<3>(Slot::n);
  const Matrix63d dM = Y.middleCols<3>(Slot::m);

  // δn̄ = n̄ × θ + Rᵀδn,  δm̄ = m̄ × θ + Rᵀδm   (rows: (Rᵀδn)ᵀ = δnᵀR)
  const Matrix63d dn_body = cross_rows(point.n_body, theta) + dN * point.R;
  const Matrix63d dm_body = cross_rows(point.m_body, theta) + dM * point.R;
  // δv = K_tra⁻¹ δn̄ (Kirchhoff: 0),  δu = K_rot⁻¹ δm̄
  const Matrix63d du = dm_body * ode.C_rot.asDiagonal();
  // δp' = R (δv - v × θ)
  Matrix63d dv_body = -cross_rows(point.v, theta);
  if (ode.extensible) dv_body.noalias() += dn_body * ode.C_tra.asDiagonal();
  const Matrix63d dp_prime = dv_body * point.R.transpose();

  // δq' = ½ (δq ⊗ (0, u) + q ⊗ (0, δu))
  const double w = q[0];
  const Eigen::Vector3d x = q.tail<3>();
  const Matrix63d dX = Y.middleCols<3>(Slot::q + 1);
  dY.col(Slot::q) = -0.5 * (dX * point.u + du * x);
  dY.middleCols<3>(Slot::q + 1) =
      0.5 * (Y.col(Slot::q) * point.u.transpose() - cross_rows(point.u, dX) + w * du +
             cross_rows(x, du));
  dY.middleCols<3>(Slot::p) = dp_prime;
  dY.middleCols<3>(Slot::n).setZero();  // f is constant
  // δm' = n × δp' - p' × δn
  dY.middleCols<3>(Slot::m) = cross_rows(n, dp_prime) - cross_rows(point.p_prime, dN);
  // δe' = Δvᵀ δn̄ + Δuᵀ δm̄
  Vector6 de = dm_body * ode.C_rot.cwiseProduct(point.m_body);
  if (ode.extensible) de.noalias() += dn_body * ode.C_tra.cwiseProduct(point.n_body);
  dY.col(Slot::e) = de;
  return theta;
}

}  // namespace rodshape::detail
