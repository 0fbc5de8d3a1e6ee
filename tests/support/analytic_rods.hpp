// analytic_rods.hpp: closed-form rods the tests compare the integrator and the solvers with, and
// the error model of the integrator that the tolerances are derived from. Independent of rodshape's
// own math on purpose (its own rotation formulas, its own elliptic integrals): an oracle must not
// share the code under test.
//
//  * constant_curvature_pose: a rod whose body-frame curvature u and strain v are constant along s
//    (an end moment along a principal axis, pure torsion, an axial force, or a precurved rod under
//    no load): R(s) = exp(s û), p(s) = s J_l(s u) v, with J_l the left Jacobian of SO(3).
//  * cantilever_elastica: the inextensible cantilever under a dead tip load perpendicular to the
//    undeformed rod, solved with incomplete elliptic integrals (Bisshopp and Drucker 1945), written
//    here with Carlson's symmetric integrals R_F and R_D.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace rodshape::testing {

inline constexpr double kEps = std::numeric_limits<double>::epsilon();

// ---- error model of the integrator --------------------------------------------------------------
//
// One classical RK4 step per interval, h = L/N. For a solution whose derivatives scale with a
// curvature κ (the k-th derivative of the tangent is O(κ^k)), the local error is O(h (κh)⁴) per
// step, and the global error O((κh)⁴) times the length it accumulates over:
//  * orientation: for constant u the quaternion equation q' = ½ q ⊗ (0, u) is linear, RK4 returns
//  the
//    degree-4 Taylor polynomial of exp(½hû) and the angle per step is short by (κh)⁵/1920 (expand
//    arg(1 - x²/2 + x⁴/24 + i(x - x³/6)) = x - x⁵/120, x = κh/2): κL (κh)⁴/1920 over the rod;
//  * position: that angle lag moves the rest of the rod by ≤ L times the angle, and the quadrature
//  of
//    p' = R v adds an error of the same order (Simpson-like, ≈ L κ⁴ h⁴/2880).
// So |p_N(L) - p(L)| ≲ L (1 + κL) (κh)⁴ / 1000. We allow C = 1/100 — ten times that constant, to
// cover loaded rods whose curvature varies along s (κ is then the largest curvature) — plus a
// round-off floor of 16 N ε (N steps, each rounding a few operations on O(1) numbers; linear
// accumulation is the worst case). A bug (wrong sign, wrong stiffness, a lower-order step) shows
// as an error of order (κh)² or O(1), far above this.
inline double rk4_error_bound(double length, double kappa_max, int intervals) {
  const double h = length / intervals;
  const double kh = kappa_max * h;
  return length * ((1.0 + kappa_max * length) * std::pow(kh, 4) / 100.0 + 16.0 * intervals * kEps);
}

/// Same model for an angle (rad): κL (κh)⁴ / 1920 per the expansion above, with the factor 10
/// margin and the round-off floor.
inline double rk4_angle_error_bound(double length, double kappa_max, int intervals) {
  const double h = length / intervals;
  const double kh = kappa_max * h;
  return kappa_max * length * std::pow(kh, 4) / 192.0 + 16.0 * intervals * kEps;
}

// ---- rods of constant strain --------------------------------------------------------------------

/// J_l(φ) = I + (1 - cos|φ|)/|φ|² φ̂ + (|φ| - sin|φ|)/|φ|³ φ̂², with Taylor series below 1e-3
/// (truncation error |φ|⁴/720 relative, below 1e-15).
inline Eigen::Matrix3d left_jacobian(const Eigen::Vector3d& phi) {
  const double a2 = phi.squaredNorm();
  const double a = std::sqrt(a2);
  Eigen::Matrix3d phi_hat;
  phi_hat << 0.0, -phi.z(), phi.y(), phi.z(), 0.0, -phi.x(), -phi.y(), phi.x(), 0.0;
  const double c1 = a < 1e-3 ? 0.5 - a2 / 24.0 + a2 * a2 / 720.0 : (1.0 - std::cos(a)) / a2;
  const double c2 =
      a < 1e-3 ? 1.0 / 6.0 - a2 / 120.0 + a2 * a2 / 5040.0 : (a - std::sin(a)) / (a2 * a);
  return Eigen::Matrix3d::Identity() + c1 * phi_hat + c2 * phi_hat * phi_hat;
}

struct AnalyticPose {
  Eigen::Vector3d position;
  Eigen::Matrix3d rotation;
};

/// Pose at arc length s of a rod clamped at (p0, R0) whose body-frame strains v and curvature u are
/// constant: R(s) = R0 exp(s û), p(s) = p0 + R0 s J_l(s u) v.
inline AnalyticPose constant_strain_pose(double s,
                                         const Eigen::Vector3d& u,
                                         const Eigen::Vector3d& v = Eigen::Vector3d::UnitZ(),
                                         const Eigen::Vector3d& p0 = Eigen::Vector3d::Zero(),
                                         const Eigen::Matrix3d& R0 = Eigen::Matrix3d::Identity()) {
  const Eigen::Vector3d phi = s * u;
  const double angle = phi.norm();
  const Eigen::Matrix3d R_rel = angle > 0.0
                                    ? Eigen::AngleAxisd(angle, phi / angle).toRotationMatrix()
                                    : Eigen::Matrix3d::Identity();
  return {p0 + R0 * (s * left_jacobian(phi) * v), R0 * R_rel};
}

// ---- elliptic integrals (Carlson 1995, "Numerical computation of real or complex elliptic
// integrals", Numer. Algorithms 10:13–26: duplication theorem, then the series to fifth order)
// ------

/// R_F(x, y, z) = ½ ∫₀^∞ dt / √((t+x)(t+y)(t+z)). Duplication until the arguments agree to 1e-3
/// relative; the series' first neglected term is O(1e-3⁶) = 1e-18.
inline double carlson_rf(double x, double y, double z) {
  for (int i = 0; i < 200; ++i) {
    const double mean = (x + y + z) / 3.0;
    const double spread = std::max({std::abs(mean - x), std::abs(mean - y), std::abs(mean - z)});
    if (spread <= 1e-3 * mean) {
      const double X = (mean - x) / mean, Y = (mean - y) / mean, Z = -(X + Y);
      const double E2 = X * Y - Z * Z, E3 = X * Y * Z;
      return (1.0 - E2 / 10.0 + E3 / 14.0 + E2 * E2 / 24.0 - 3.0 * E2 * E3 / 44.0) /
             std::sqrt(mean);
    }
    const double sx = std::sqrt(x), sy = std::sqrt(y), sz = std::sqrt(z);
    const double lambda = sx * sy + sx * sz + sy * sz;
    x = 0.25 * (x + lambda);
    y = 0.25 * (y + lambda);
    z = 0.25 * (z + lambda);
  }
  return std::numeric_limits<double>::quiet_NaN();
}

/// R_D(x, y, z) = (3/2) ∫₀^∞ dt / ((t+z) √((t+x)(t+y)(t+z))).
inline double carlson_rd(double x, double y, double z) {
  double sum = 0.0;
  double factor = 1.0;  // 4^-m
  for (int i = 0; i < 200; ++i) {
    const double mean = (x + y + 3.0 * z) / 5.0;
    const double spread = std::max({std::abs(mean - x), std::abs(mean - y), std::abs(mean - z)});
    if (spread <= 1e-3 * mean) {
      const double X = (mean - x) / mean, Y = (mean - y) / mean, Z = -(X + Y) / 3.0;
      const double E2 = X * Y - 6.0 * Z * Z;
      const double E3 = (3.0 * X * Y - 8.0 * Z * Z) * Z;
      const double E4 = 3.0 * (X * Y - Z * Z) * Z * Z;
      const double E5 = X * Y * Z * Z * Z;
      const double series = 1.0 - 3.0 * E2 / 14.0 + E3 / 6.0 + 9.0 * E2 * E2 / 88.0 -
                            3.0 * E4 / 22.0 - 9.0 * E2 * E3 / 52.0 + 3.0 * E5 / 26.0;
      return 3.0 * sum + factor * series / (mean * std::sqrt(mean));
    }
    const double sx = std::sqrt(x), sy = std::sqrt(y), sz = std::sqrt(z);
    const double lambda = sx * sy + sx * sz + sy * sz;
    sum += factor / (sz * (z + lambda));
    factor *= 0.25;
    x = 0.25 * (x + lambda);
    y = 0.25 * (y + lambda);
    z = 0.25 * (z + lambda);
  }
  return std::numeric_limits<double>::quiet_NaN();
}

/// F(φ, k) = ∫₀^φ dϑ / √(1 - k² sin²ϑ), 0 ≤ φ ≤ π/2, 0 ≤ k < 1.
inline double elliptic_f(double phi, double k) {
  const double s = std::sin(phi), c = std::cos(phi);
  return s * carlson_rf(c * c, 1.0 - k * k * s * s, 1.0);
}

/// E(φ, k) = ∫₀^φ √(1 - k² sin²ϑ) dϑ.
inline double elliptic_e(double phi, double k) {
  const double s = std::sin(phi), c = std::cos(phi);
  const double q = 1.0 - k * k * s * s;
  return s * carlson_rf(c * c, q, 1.0) - k * k * s * s * s * carlson_rd(c * c, q, 1.0) / 3.0;
}

inline double complete_elliptic_k(double k) { return carlson_rf(0.0, 1.0 - k * k, 1.0); }
inline double complete_elliptic_e(double k) {
  return carlson_rf(0.0, 1.0 - k * k, 1.0) - k * k * carlson_rd(0.0, 1.0 - k * k, 1.0) / 3.0;
}

// ---- the cantilever elastica under a dead tip load --------------------------------------------

/// Tip of an inextensible cantilever of length L, clamped horizontally, under a tip load P that
/// stays perpendicular to the undeformed rod, as fractions of L; α = P L²/EI.
struct CantileverElasticaTip {
  double alpha = 0.0;
  double tip_angle = 0.0;  // θ(L), rad, from the undeformed direction
  double along = 0.0;      // x(L)/L: tip coordinate along the undeformed rod
  double across = 0.0;     // y(L)/L: tip deflection in the load direction ("vertical")
  double shortening() const { return 1.0 - along; }  // (L - x(L))/L ("horizontal displacement")
};

/// EI θ'' = -P cos θ, θ(0) = 0, θ'(L) = 0. With 1 + sin θ = 2k² sin²φ, k² = (1 + sin θ(L))/2 and
/// λ = √(P/EI), ds = dφ / (λ √(1 - k² sin²φ)), so
///   √α = K(k) - F(φ₀, k),  sin φ₀ = 1/(k√2)                              (fixes k),
///   x(L)/L = √(2 sin θ(L) / α),   y(L)/L = 1 - 2 (E(k) - E(φ₀, k)) / √α.
/// k is found by bisection on (1/√2, 1), where the left side grows monotonically from 0 to ∞: to
/// the last bit, so the reference is exact to ~1e-15 (the integrals' own accuracy).
inline CantileverElasticaTip cantilever_elastica(double alpha) {
  const double root_alpha = std::sqrt(alpha);
  auto length_defect = [&](double k) {
    const double phi0 = std::asin(1.0 / (k * std::numbers::sqrt2));
    return complete_elliptic_k(k) - elliptic_f(phi0, k) - root_alpha;
  };
  double lo = 1.0 / std::numbers::sqrt2, hi = 1.0 - 1e-15;
  for (int i = 0; i < 200 && hi - lo > 4.0 * kEps; ++i) {
    const double mid = 0.5 * (lo + hi);
    (length_defect(mid) < 0.0 ? lo : hi) = mid;
  }
  const double k = 0.5 * (lo + hi);
  const double phi0 = std::asin(1.0 / (k * std::numbers::sqrt2));
  CantileverElasticaTip tip;
  tip.alpha = alpha;
  const double sin_tip = 2.0 * k * k - 1.0;
  tip.tip_angle = std::asin(sin_tip);
  tip.along = std::sqrt(2.0 * sin_tip / alpha);
  tip.across = 1.0 - 2.0 * (complete_elliptic_e(k) - elliptic_e(phi0, k)) / root_alpha;
  return tip;
}

/// Published values of the same problem, to the digits printed there: α = PL²/EI, y(L)/L and
/// (L - x(L))/L. Source: Bisshopp and Drucker (1945), "Large deflection of cantilever beams",
/// Quart. Appl. Math. 3:272–275, as tabulated by Bathe and Bolourchi (1979), "Large displacement
/// analysis of three-dimensional beam structures", IJNME 14:961–986 (the α = 1 and α = 2 rows, as
/// quoted in the docstring of a public elastica regression test we found with the search tool; the
/// other rows of the table could not be retrieved, so those α are checked against
/// cantilever_elastica() only, which reproduces these two rows to their last digit).
struct PublishedElasticaRow {
  double alpha, across, shortening;
};
inline constexpr PublishedElasticaRow kBisshoppDruckerRows[] = {
    {1.0, 0.30172, 0.05643},
    {2.0, 0.49346, 0.16064},
};
inline constexpr double kBisshoppDruckerHalfUlp = 0.5e-5;  // half a unit of the last printed digit

}  // namespace rodshape::testing
