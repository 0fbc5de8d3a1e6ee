// cosserat_ode.hpp (private): the right-hand side of the static Cosserat rod (paper, "system of
// differential equations") and of its variational equations, in the coordinates the integrator
// steps: y = (q, p, n, m, e) with the orientation as a quaternion q = (w, x) and e the energy so
// far.
//
//   R = R(q/|q|) = I + (2/|q|²)(w x̂ + x̂²)
//   v = K_tra⁻¹ Rᵀ n + ṽ  (Kirchhoff: v = ṽ),   u = K_rot⁻¹ Rᵀ m + ũ         constitutive law
//   p' = R v,   q' = ½ q ⊗ (0, u)   (⇔ R' = R û),   n' = -f,   m' = -p' × n - l
//   e' = ½ ΔvᵀK_traΔv + ½ ΔuᵀK_rotΔu = ½ n̄ᵀK_tra⁻¹n̄ + ½ m̄ᵀK_rot⁻¹m̄,  n̄ = Rᵀn, m̄ = Rᵀm
//
// Tangents are stored transposed, one row per base-wrench direction (6 × 14), so that each state
// component's derivative is a contiguous 6-vector and the six directions share SIMD lanes. The same
// layout carries the six directions of the distributed load (f, l) for the clamp-pose derivatives
// (evaluate_tangent<true>, src/core/load_tangent.hpp).
#pragma once

#include <Eigen/Core>
#include <cstring>
#include <type_traits>

#include "rodshape/core/clamped_rod.hpp"

/// Inlined into every caller, so that it is compiled for the caller's target (the integrator's
/// dispatched clones compile the ODE for AVX2 as well as for the baseline).
#define RODSHAPE_ALWAYS_INLINE __attribute__((always_inline))

namespace rodshape::detail {

using OdeState = Eigen::Matrix<double, 14, 1>;    // (q, p, n, m, e)
using OdeTangent = Eigen::Matrix<double, 6, 14>;  // row j: d(state)/dw_j
using Matrix63d = Eigen::Matrix<double, 6, 3>;

/// Offsets of each quantity in OdeState (and columns of OdeTangent).
struct Slot {
  static constexpr int q = 0, p = 4, n = 7, m = 10, e = 13;
};

/// The ODE's constants, taken once per integration from the rod.
struct CosseratOde {
  Eigen::Vector3d C_tra;  // K_tra⁻¹ (diagonal)
  Eigen::Vector3d C_rot;  // K_rot⁻¹ (diagonal)
  Eigen::Vector3d v_rest, u_rest, f, l;
  Eigen::Vector3d half_C_rot, half_u_rest;  // ½K_rot⁻¹, ½ũ (q' = ½ q ⊗ (0, u))
  bool extensible;                          // Cosserat: shear and extension; Kirchhoff: v = ṽ

  explicit CosseratOde(const ClampedRod& rod)
      : C_tra(rod.properties.K_tra.cwiseInverse()),
        C_rot(rod.properties.K_rot.cwiseInverse()),
        v_rest(rod.properties.v_rest),
        u_rest(rod.properties.u_rest),
        f(rod.load.force),
        l(rod.load.moment),
        half_C_rot(0.5 * C_rot),
        half_u_rest(0.5 * u_rest),
        extensible(rod.properties.model == ConstitutiveModel::Cosserat) {}
};

/// What one evaluation of the ODE knows beyond y': kept for the tangent and for output.
struct OdePoint {
  Eigen::Matrix3d R;
  Eigen::Vector3d n_body, m_body;  // n̄ = Rᵀn, m̄ = Rᵀm
  Eigen::Vector3d v, u, p_prime;
  double q_scale;  // 2/|q|²
};

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
/// half the instructions of Eigen's packet code. Without Energy, e' = 0 (the caller does not want
/// E).
template <bool Energy = true>
RODSHAPE_ALWAYS_INLINE inline void evaluate(const CosseratOde& ode,
                                            const OdeState& y,
                                            OdeState& dy,
                                            OdePoint& point) {
  const double w = y[0], x = y[1], yq = y[2], z = y[3];
  const double nx = y[Slot::n], ny = y[Slot::n + 1], nz = y[Slot::n + 2];
  const double mx = y[Slot::m], my = y[Slot::m + 1], mz = y[Slot::m + 2];
  const double s = 2.0 / ((w * w + x * x) + (yq * yq + z * z));  // two short sums in parallel
  point.q_scale = s;
  // R = I + s B with B = w x̂ + x̂² (its entries do not wait for the division)
  const double b00 = -(yq * yq + z * z), b01 = x * yq - w * z, b02 = x * z + w * yq;
  const double b10 = x * yq + w * z, b11 = -(x * x + z * z), b12 = yq * z - w * x;
  const double b20 = x * z - w * yq, b21 = yq * z + w * x, b22 = -(x * x + yq * yq);
  const double r00 = 1.0 + s * b00, r01 = s * b01, r02 = s * b02;
  const double r10 = s * b10, r11 = 1.0 + s * b11, r12 = s * b12;
  const double r20 = s * b20, r21 = s * b21, r22 = 1.0 + s * b22;
  double* const R = point.R.data();  // column-major
  R[0] = r00, R[1] = r10, R[2] = r20, R[3] = r01, R[4] = r11, R[5] = r21, R[6] = r02, R[7] = r12,
  R[8] = r22;
  // n̄ = Rᵀn = n + s Bᵀn, m̄ = Rᵀm = m + s Bᵀm: Bᵀn and Bᵀm run beside the division, so that the
  // chain from q to u (which feeds the next stage) is one multiply-add after it rather than a dot
  // product after R.
  const double bn0 = b00 * nx + b10 * ny + b20 * nz;
  const double bn1 = b01 * nx + b11 * ny + b21 * nz;
  const double bn2 = b02 * nx + b12 * ny + b22 * nz;
  const double bm0 = b00 * mx + b10 * my + b20 * mz;
  const double bm1 = b01 * mx + b11 * my + b21 * mz;
  const double bm2 = b02 * mx + b12 * my + b22 * mz;
  const double nb0 = nx + s * bn0, nb1 = ny + s * bn1, nb2 = nz + s * bn2;
  const double mb0 = mx + s * bm0, mb1 = my + s * bm1, mb2 = mz + s * bm2;
  point.n_body[0] = nb0, point.n_body[1] = nb1, point.n_body[2] = nb2;
  point.m_body[0] = mb0, point.m_body[1] = mb1, point.m_body[2] = mb2;
  // Δu = K_rot⁻¹ m̄, u = Δu + ũ;  Δv = K_tra⁻¹ n̄, v = Δv + ṽ (Kirchhoff: v = ṽ)
  const double u0 = ode.C_rot[0] * mb0 + ode.u_rest[0], u1 = ode.C_rot[1] * mb1 + ode.u_rest[1],
               u2 = ode.C_rot[2] * mb2 + ode.u_rest[2];
  double v0 = ode.v_rest[0], v1 = ode.v_rest[1], v2 = ode.v_rest[2];
  if (ode.extensible) {
    v0 += ode.C_tra[0] * nb0;
    v1 += ode.C_tra[1] * nb1;
    v2 += ode.C_tra[2] * nb2;
  }
  point.v[0] = v0, point.v[1] = v1, point.v[2] = v2;
  point.u[0] = u0, point.u[1] = u1, point.u[2] = u2;
  // p' = R v
  const double px = r00 * v0 + r01 * v1 + r02 * v2;
  const double py = r10 * v0 + r11 * v1 + r12 * v2;
  const double pz = r20 * v0 + r21 * v1 + r22 * v2;
  point.p_prime[0] = px, point.p_prime[1] = py, point.p_prime[2] = pz;
  // q' = ½ q ⊗ (0, u) = ½ (-x·u, w u + x × u)
  // with ½u = ½K_rot⁻¹ m̄ + ½ũ: bitwise ½ times u (powers of two scale exactly), one multiply
  // fewer on the chain from q to the next stage's q
  const double hu0 = ode.half_C_rot[0] * mb0 + ode.half_u_rest[0];
  const double hu1 = ode.half_C_rot[1] * mb1 + ode.half_u_rest[1];
  const double hu2 = ode.half_C_rot[2] * mb2 + ode.half_u_rest[2];
  dy[0] = -(x * hu0 + yq * hu1 + z * hu2);
  dy[1] = w * hu0 + yq * hu2 - z * hu1;
  dy[2] = w * hu1 + z * hu0 - x * hu2;
  dy[3] = w * hu2 + x * hu1 - yq * hu0;
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
  // e' = ½ ΔvᵀK_traΔv + ½ ΔuᵀK_rotΔu = ½ n̄ᵀΔv + ½ m̄ᵀΔu, with Δv = v - ṽ and Δu = u - ũ read back,
  // so that each product K⁻¹n̄, K⁻¹m̄ has one use and a multiply-add clone fuses it alike with and
  // without the energy (Output::Tip is bitwise Output::Full at the tip)
  if constexpr (Energy) {
    const double dv0 = v0 - ode.v_rest[0], dv1 = v1 - ode.v_rest[1], dv2 = v2 - ode.v_rest[2];
    const double du0 = u0 - ode.u_rest[0], du1 = u1 - ode.u_rest[1], du2 = u2 - ode.u_rest[2];
    dy[Slot::e] =
        0.5 * (nb0 * dv0 + nb1 * dv1 + nb2 * dv2) + 0.5 * (mb0 * du0 + mb1 * du1 + mb2 * du2);
  } else {
    dy[Slot::e] = 0.0;
  }
}

/// Four and two doubles side by side (GCC and Clang vector extensions; a scalar operand is
/// broadcast). The tangent's six directions go through the same arithmetic, four in one vector and
/// two in another: a 32-byte vector is one AVX register where the code is compiled for AVX2 (the
/// integrator's dispatched clone, rod_integrator.cpp) and two SSE2 registers elsewhere. The lanes
/// never mix, so every direction's result is bitwise that of scalar code in the same order compiled
/// for the same target (the x86-64-v3 clone fuses multiply-adds in both alike).
typedef double Lanes4 __attribute__((vector_size(32)));
typedef double Lanes2 __attribute__((vector_size(16)));

/// lanes = column[j, j + lanes' width) (an out-parameter: returning a 32-byte vector from a
/// function compiled without AVX would change the ABI, which GCC warns about).
template <class V>
RODSHAPE_ALWAYS_INLINE inline void load(V& lanes, const double* column, int j) {
  std::memcpy(&lanes, column + j, sizeof(V));
}

template <class V>
RODSHAPE_ALWAYS_INLINE inline void store(double* column, int j, const V& lanes) {
  std::memcpy(column + j, &lanes, sizeof(V));
}

/// A Runge–Kutta stage of the tangent, Y + a K, formed lanes by lanes where evaluate_tangent
/// reads it: it reads only the δq and δm columns (and δn for the load directions), so the other
/// columns of the stage are never formed, and nothing is stored to be loaded back. Without K, the
/// stage is Y. Bitwise the stage formed whole (the same y + a k per lane).
struct TangentStage {
  const OdeTangent& Y;
  const OdeTangent* K = nullptr;
  double a = 0.0;

  /// lanes = the stage's column `column`, rows [j, j + lanes' width)
  template <class V>
  RODSHAPE_ALWAYS_INLINE void load(V& lanes, int column, int j) const {
    detail::load(lanes, Y.data() + Y.rows() * column, j);
    if (K != nullptr) {
      V k;
      detail::load(k, K->data() + K->rows() * column, j);
      lanes = lanes + a * k;
    }
  }
};

/// θ: the body-frame rotation of each direction, δR = R θ̂, from the quaternion tangent:
/// θ = 2 vec(q* ⊗ δq)/|q|² = (2/|q|²)(w δx - δw x - x × δx).
inline Matrix63d body_rotation_tangent(const Eigen::Vector4d& q,
                                       double q_scale,
                                       const OdeTangent& Y) {
  const double w = q[0], x0 = q[1], x1 = q[2], x2 = q[3];
  Matrix63d theta;
  for (int j = 0; j < 6; ++j) {
    const double dw = Y(j, Slot::q);
    const double dx0 = Y(j, Slot::q + 1), dx1 = Y(j, Slot::q + 2), dx2 = Y(j, Slot::q + 3);
    theta(j, 0) = q_scale * (w * dx0 - x0 * dw - x1 * dx2 + x2 * dx1);
    theta(j, 1) = q_scale * (w * dx1 - x1 * dw - x2 * dx0 + x0 * dx2);
    theta(j, 2) = q_scale * (w * dx2 - x2 * dw - x0 * dx1 + x1 * dx0);
  }
  return theta;
}

/// θ = (2/|q|²)(w δx - δw x - x × δx) for the lanes' directions (body_rotation_tangent's formula).
template <class V>
RODSHAPE_ALWAYS_INLINE inline void rotation_variation(
    double s, const double* q, const V& qw, const V& q0, const V& q1, const V& q2, V* t) {
  const double w = q[0], x0 = q[1], x1 = q[2], x2 = q[3];
  t[0] = s * (w * q0 - x0 * qw - x1 * q2 + x2 * q1);
  t[1] = s * (w * q1 - x1 * qw - x2 * q0 + x0 * q2);
  t[2] = s * (w * q2 - x2 * qw - x0 * q1 + x1 * q0);
}

/// δq' = ½ (δq ⊗ (0, u) + q ⊗ (0, δu)), stored into the lanes' rows of the q columns of `out`.
template <class V>
RODSHAPE_ALWAYS_INLINE inline void store_quaternion_rate_variation(double* out,
                                                                   int j,
                                                                   const double* q,
                                                                   const Eigen::Vector3d& u,
                                                                   const V& qw,
                                                                   const V& q0,
                                                                   const V& q1,
                                                                   const V& q2,
                                                                   const V* du) {
  const double w = q[0], x0 = q[1], x1 = q[2], x2 = q[3];
  const double u0 = u[0], u1 = u[1], u2 = u[2];
  store(out + 6 * Slot::q, j,
        -0.5 * (u0 * q0 + u1 * q1 + u2 * q2 + x0 * du[0] + x1 * du[1] + x2 * du[2]));
  store(out + 6 * (Slot::q + 1), j,
        0.5 * (u0 * qw + u2 * q1 - u1 * q2 + w * du[0] + x1 * du[2] - x2 * du[1]));
  store(out + 6 * (Slot::q + 2), j,
        0.5 * (u1 * qw + u0 * q2 - u2 * q0 + w * du[1] + x2 * du[0] - x0 * du[2]));
  store(out + 6 * (Slot::q + 3), j,
        0.5 * (u2 * qw + u1 * q0 - u0 * q1 + w * du[2] + x0 * du[1] - x1 * du[0]));
}

/// The load directions' δn terms, read from Y: Rᵀδn and p' × δn.
template <class V>
RODSHAPE_ALWAYS_INLINE inline void load_direction_force_terms(
    const TangentStage& Y, int j, const OdePoint& point, V* rt_dn, V* pp_dn) {
  const Eigen::Matrix3d& R = point.R;
  const double pp0 = point.p_prime[0], pp1 = point.p_prime[1], pp2 = point.p_prime[2];
  V dn0, dn1, dn2;
  Y.load(dn0, Slot::n, j), Y.load(dn1, Slot::n + 1, j), Y.load(dn2, Slot::n + 2, j);
  rt_dn[0] = R(0, 0) * dn0 + R(1, 0) * dn1 + R(2, 0) * dn2;
  rt_dn[1] = R(0, 1) * dn0 + R(1, 1) * dn1 + R(2, 1) * dn2;
  rt_dn[2] = R(0, 2) * dn0 + R(1, 2) * dn1 + R(2, 2) * dn2;
  pp_dn[0] = pp1 * dn2 - pp2 * dn1;
  pp_dn[1] = pp2 * dn0 - pp0 * dn2;
  pp_dn[2] = pp0 * dn1 - pp1 * dn0;
}

/// δm' = n × δp' - p' × δn (- δl for the load directions: j ≥ 3 is δl = e_{j-3}), stored into the
/// lanes' rows of the m columns of `out`.
template <bool LoadForcing, class V>
RODSHAPE_ALWAYS_INLINE inline void store_moment_rate_variation(
    double* out, int j, const double* n, const V* dp, const V* pp_dn) {
  V m0 = n[1] * dp[2] - n[2] * dp[1] - pp_dn[0];
  V m1 = n[2] * dp[0] - n[0] * dp[2] - pp_dn[1];
  V m2 = n[0] * dp[1] - n[1] * dp[0] - pp_dn[2];
  if constexpr (LoadForcing) {
    alignas(16) static constexpr double unit_l0[6] = {0.0, 0.0, 0.0, 1.0, 0.0, 0.0};
    alignas(16) static constexpr double unit_l1[6] = {0.0, 0.0, 0.0, 0.0, 1.0, 0.0};
    alignas(16) static constexpr double unit_l2[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 1.0};
    V dl0, dl1, dl2;
    load(dl0, unit_l0, j), load(dl1, unit_l1, j), load(dl2, unit_l2, j);
    m0 = m0 - dl0, m1 = m1 - dl1, m2 = m2 - dl2;
  }
  store(out + 6 * Slot::m, j, m0);
  store(out + 6 * (Slot::m + 1), j, m1);
  store(out + 6 * (Slot::m + 2), j, m2);
}

/// Y' = dF(y)[Y]: the variational equations. Each direction j (row of Y) is independent; the
/// directions run four and two at a time in SIMD lanes.
/// Base-wrench directions (LoadForcing = false): since f is constant, δn = e_j for the force
/// directions j < 3 and 0 for the moment directions at every s; that is used rather than read from
/// Y. Load directions (LoadForcing = true: j < 3 is δf = e_j, j ≥ 3 is δl = e_{j-3}, started from
/// a zero tangent): δn is read from Y and the load's own terms are added, δn' = -δf and
/// δm' = ... - δl (δe' has none). The base-wrench path's arithmetic is unchanged by the flag.
/// The columns whose rate is zero are not written: δn' (base-wrench directions) and, without
/// Energy, δe' (tangent_update leaves them). Returns θ (see above).
template <bool LoadForcing = false, bool Energy = true>
RODSHAPE_ALWAYS_INLINE inline Matrix63d evaluate_tangent(const CosseratOde& ode,
                                                         const OdeState& y,
                                                         const OdePoint& point,
                                                         const TangentStage& Y,
                                                         OdeTangent& dY) {
  const double s = point.q_scale;
  const Eigen::Matrix3d& R = point.R;
  const double r00 = R(0, 0), r01 = R(0, 1), r02 = R(0, 2);
  const double r10 = R(1, 0), r11 = R(1, 1), r12 = R(1, 2);
  const double r20 = R(2, 0), r21 = R(2, 1), r22 = R(2, 2);
  const double nb0 = point.n_body[0], nb1 = point.n_body[1], nb2 = point.n_body[2];
  const double mb0 = point.m_body[0], mb1 = point.m_body[1], mb2 = point.m_body[2];
  const double v0 = point.v[0], v1 = point.v[1], v2 = point.v[2];
  const double pp0 = point.p_prime[0], pp1 = point.p_prime[1], pp2 = point.p_prime[2];
  const double cr0 = ode.C_rot[0], cr1 = ode.C_rot[1], cr2 = ode.C_rot[2];
  const double ct0 = ode.extensible ? ode.C_tra[0] : 0.0;  // Kirchhoff: δv = 0
  const double ct1 = ode.extensible ? ode.C_tra[1] : 0.0;
  const double ct2 = ode.extensible ? ode.C_tra[2] : 0.0;
  // δe' weights: Δv = K_tra⁻¹ n̄ and Δu = K_rot⁻¹ m̄
  const double ev0 = ct0 * nb0, ev1 = ct1 * nb1, ev2 = ct2 * nb2;
  const double eu0 = cr0 * mb0, eu1 = cr1 * mb1, eu2 = cr2 * mb2;

  double* const out = dY.data();
  Matrix63d theta;

  // Directions j, j + 1, ... side by side, one per lane of V (Lanes4 or Lanes2).
  const auto directions = [&](auto lanes_tag, int j) RODSHAPE_ALWAYS_INLINE {
    using V = typename decltype(lanes_tag)::type;
    V qw, q0, q1, q2, m0, m1, m2, t[3];
    V rt_dn[3]{}, pp_dn[3]{};  // the moment directions 4–5: δn = 0
    Y.load(qw, Slot::q, j), Y.load(q0, Slot::q + 1, j), Y.load(q1, Slot::q + 2, j);
    Y.load(q2, Slot::q + 3, j);
    Y.load(m0, Slot::m, j), Y.load(m1, Slot::m + 1, j), Y.load(m2, Slot::m + 2, j);
    if constexpr (LoadForcing) {
      load_direction_force_terms(Y, j, point, rt_dn, pp_dn);
    } else if constexpr (sizeof(V) == sizeof(Lanes4)) {
      // δn = e_j for the force directions 0–2, 0 for direction 3: Rᵀδn and p' × δn, built in
      // registers (an array of scalars loaded as lanes would wait for its stores)
      rt_dn[0] = V{r00, r10, r20, 0.0}, rt_dn[1] = V{r01, r11, r21, 0.0};
      rt_dn[2] = V{r02, r12, r22, 0.0};
      pp_dn[0] = V{0.0, -pp2, pp1, 0.0}, pp_dn[1] = V{pp2, 0.0, -pp0, 0.0};
      pp_dn[2] = V{-pp1, pp0, 0.0, 0.0};
    }
    rotation_variation(s, y.data(), qw, q0, q1, q2, t);
    const V t0 = t[0], t1 = t[1], t2 = t[2];
    store(theta.data(), j, t0);
    store(theta.data() + 6, j, t1);
    store(theta.data() + 12, j, t2);
    // δn̄ = n̄ × θ + Rᵀδn,  δm̄ = m̄ × θ + Rᵀδm
    const V dnb0 = nb1 * t2 - nb2 * t1 + rt_dn[0];
    const V dnb1 = nb2 * t0 - nb0 * t2 + rt_dn[1];
    const V dnb2 = nb0 * t1 - nb1 * t0 + rt_dn[2];
    const V dmb0 = mb1 * t2 - mb2 * t1 + r00 * m0 + r10 * m1 + r20 * m2;
    const V dmb1 = mb2 * t0 - mb0 * t2 + r01 * m0 + r11 * m1 + r21 * m2;
    const V dmb2 = mb0 * t1 - mb1 * t0 + r02 * m0 + r12 * m1 + r22 * m2;
    // δu = K_rot⁻¹ δm̄;  a = δv - v × θ with δv = K_tra⁻¹ δn̄;  δp' = R a
    const V du[3] = {cr0 * dmb0, cr1 * dmb1, cr2 * dmb2};
    const V a0 = ct0 * dnb0 + v2 * t1 - v1 * t2;
    const V a1 = ct1 * dnb1 + v0 * t2 - v2 * t0;
    const V a2 = ct2 * dnb2 + v1 * t0 - v0 * t1;
    const V dp0 = r00 * a0 + r01 * a1 + r02 * a2;
    const V dp1 = r10 * a0 + r11 * a1 + r12 * a2;
    const V dp2 = r20 * a0 + r21 * a1 + r22 * a2;
    store_quaternion_rate_variation(out, j, y.data(), point.u, qw, q0, q1, q2, du);
    store(out + 6 * Slot::p, j, dp0);
    store(out + 6 * (Slot::p + 1), j, dp1);
    store(out + 6 * (Slot::p + 2), j, dp2);
    const V dp[3] = {dp0, dp1, dp2};
    store_moment_rate_variation<LoadForcing>(out, j, y.data() + Slot::n, dp, pp_dn);
    // δe' = Δvᵀ δn̄ + Δuᵀ δm̄
    if constexpr (Energy)
      store(out + 6 * Slot::e, j,
            ev0 * dnb0 + ev1 * dnb1 + ev2 * dnb2 + eu0 * dmb0 + eu1 * dmb1 + eu2 * dmb2);
  };
  directions(std::type_identity<Lanes4>{}, 0);  // directions 0–3
  directions(std::type_identity<Lanes2>{}, 4);  // directions 4–5
  // δn' = -δf for the load directions (below); the base-wrench directions' δn' = 0 and, without
  // Energy, δe' = 0 are not stored: rk4_step's update leaves those columns of Y as they are.
  if constexpr (LoadForcing) {
    for (int k = Slot::n; k < Slot::n + 3; ++k)
      store(out + 6 * k, 0, Lanes4{}), store(out + 6 * k, 4, Lanes2{});
    for (int k = 0; k < 3; ++k) dY(k, Slot::n + k) = -1.0;  // δn' = -δf
  }
  return theta;
}

}  // namespace rodshape::detail
