// solver_fixtures.hpp: the rods, scales and helpers the solver tests share.
//
//  * rubber_band(): the paper's rubber band (L = 0.29 m, 0.02 × 0.02 m section, E = 3.2e6 Pa, ν =
//  0.5):
//    EIx = EIy = 0.04 N·m², GJ = 0.028 N·m², GA = G·A = 426.67 N, EA = E·A = 1280 N.
//  * wrench_scale(): the bending units of the unknown, S = (EI/L² ×3, EI/L ×3). A scaled wrench
//    ξ = w / S of order 1 bends the rod by about 1 rad.
//  * residual_jacobian(): the exact Jacobian dr/dw from the integrator's tip derivatives.
//  * inverse_inf_norm(): ||J⁻¹||_∞ (the induced ∞-norm, max row sum of |J⁻¹|), the factor that
//  turns
//    a residual error into a wrench error: ||Δw||_∞ ≤ ||J⁻¹||_∞ ||Δr||_∞ to first order.
//  * Seed and count of random sweeps from RODSHAPE_TEST_SEED and RODSHAPE_TEST_COUNT.
#pragma once

#include <Eigen/LU>
#include <Eigen/SVD>
#include <cstdlib>
#include <limits>
#include <string>

#include "rodshape/core/clamped_rod.hpp"
#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/samples/rubber_band.hpp"
#include "rodshape/solvers/shooting_residual.hpp"
#include "rodshape/solvers/tip_condition.hpp"

namespace rodshape::testing {

inline constexpr double kBandLength = 0.29;      // m
inline constexpr double kBandEI = 0.04;          // N·m², EIx = EIy = E·w⁴/12
inline constexpr double kBandGJ = 0.028;         // N·m²
inline constexpr double kBandEA = 3.2e6 * 4e-4;  // 1280 N
inline constexpr double kBandGA = 3.2e6 / (2.0 * (1.0 + 0.5)) * 4e-4;  // 426.67 N
inline constexpr double kBandMassPerLength = 1392.0 * 4e-4;  // ρA, kg/m (ρ of natural rubber)

/// The paper's rubber band, clamped at the origin with the identity rotation, weightless (the
/// library's sample; the constants above are its values, for the tests' oracles).
inline ClampedRod rubber_band(ConstitutiveModel model = ConstitutiveModel::Cosserat,
                              int intervals = 100) {
  return samples::rubber_band(model, intervals);
}

inline double mean_bending_stiffness(const ClampedRod& rod) {
  return 0.5 * (rod.properties.K_rot.x() + rod.properties.K_rot.y());
}

/// S = (EI/L², EI/L², EI/L², EI/L, EI/L, EI/L): forces and moments that bend the rod by ~1 rad.
inline Vector6d wrench_scale(const ClampedRod& rod) {
  const double L = rod.properties.length, EI = mean_bending_stiffness(rod);
  Vector6d S;
  S << Eigen::Vector3d::Constant(EI / (L * L)), Eigen::Vector3d::Constant(EI / L);
  return S;
}

/// The exact Jacobian dr/dw (and the residual) of `tip` at `w`.
inline Matrix6d residual_jacobian(const ClampedRod& rod,
                                  const TipCondition& tip,
                                  const BaseWrench& w,
                                  Vector6d* residual = nullptr) {
  const RodConfiguration c = integrate(rod, w, Derivatives::Tip);
  Vector6d r;
  Matrix6d J;
  shooting_residual(tip, c, r, J);
  if (residual) *residual = r;
  return J;
}

/// ||J⁻¹||_∞; +∞ when J is singular to working precision.
inline double inverse_inf_norm(const Matrix6d& J) {
  const Eigen::FullPivLU<Matrix6d> lu(J);
  if (!lu.isInvertible()) return std::numeric_limits<double>::infinity();
  return lu.inverse().cwiseAbs().rowwise().sum().maxCoeff();
}

/// An integer from the environment, or `fallback` when unset or unparsable.
inline long environment_integer(const char* name, long fallback) {
  const char* text = std::getenv(name);
  if (!text || !*text) return fallback;
  char* end = nullptr;
  const long value = std::strtol(text, &end, 10);
  return end && *end == '\0' ? value : fallback;
}

/// Seed of the random sweeps: RODSHAPE_TEST_SEED, default 1.
inline unsigned test_seed() {
  return static_cast<unsigned>(environment_integer("RODSHAPE_TEST_SEED", 1));
}
/// Number of draws of the random sweeps: RODSHAPE_TEST_COUNT, default `fallback`.
inline int test_count(int fallback = 50) {
  const long count = environment_integer("RODSHAPE_TEST_COUNT", fallback);
  return count > 0 ? static_cast<int>(count) : fallback;
}

}  // namespace rodshape::testing
