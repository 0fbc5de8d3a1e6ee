// optimisation_fixtures.hpp: an independent cubic Hermite evaluator (the brute-force oracle must
// not share curve_distance.cpp's code) and the central finite-difference error model the gradient
// tests derive their tolerances from. The paper's rubber band (rubber_band()) and the wrench scales
// (wrench_scale()) come from tests/support/solver_fixtures.hpp.
//
// FD error model (as tests/core/test_integrator_derivatives.cpp). In the scaled variable
// ξ_j = w_j / S_j (S = EI/L² for forces, EI/L for moments, so that ξ ~ 1 bends the rod by ~1 rad),
// a central difference of an output of size F errs by
//     |FD - ∂f/∂ξ_j| ≤ η² M₃ / 6 + δ / η,   M₃ = |∂³f/∂ξ³| ≤ μ F,   δ = 16 N ε F,
// with μ = 10 (trigonometric-like dependence on ξ, with margin) and δ the round-off of one
// evaluation (N RK4 steps; the projection's Newton iteration converges to round-off in t, and the
// distance is stationary in t, so it adds only O(ε F)). η = (3δ/M₃)^(1/3) minimises the sum; for
// N = 20 that is η ≈ 2.8e-5 and a bound ≈ 3.8e-9 F.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "rodshape/core/rod_configuration.hpp"
#include "support/solver_fixtures.hpp"

namespace rodshape::testing {

struct FdModel {
  double eta = 0.0;    // step in ξ
  double bound = 0.0;  // |FD - ∂f/∂ξ| per unit F
};

/// `mu` bounds the relative third derivative in ξ (10 for the rod's own quantities; a distance to
/// an obstacle curved at radius R, reached by nodes that a unit ξ moves by about L, has about
/// (L/R)² more).
inline FdModel central_difference_model(int intervals, double kMu = 10.0) {
  const double delta = 16.0 * intervals * std::numeric_limits<double>::epsilon();
  FdModel model;
  model.eta = std::cbrt(3.0 * delta / kMu);
  model.bound = model.eta * model.eta * kMu / 6.0 + delta / model.eta;
  return model;
}

/// The Hermite curve on interval i at t ∈ [0, 1], in the basis-function form (h00, h10, h01, h11).
inline Eigen::Vector3d hermite_point(const RodConfiguration& c, int i, double t) {
  const double h = c.s[i + 1] - c.s[i];
  const double h00 = (1.0 + 2.0 * t) * (1.0 - t) * (1.0 - t), h10 = t * (1.0 - t) * (1.0 - t);
  const double h01 = t * t * (3.0 - 2.0 * t), h11 = t * t * (t - 1.0);
  return h00 * c.p[i] + h10 * h * (c.R[i] * c.v[i]) + h01 * c.p[i + 1] +
         h11 * h * (c.R[i + 1] * c.v[i + 1]);
}

/// Brute force: min over `per_interval` + 1 samples of every interval. It is ≥ the true distance to
/// the Hermite curve and exceeds it by at most half the sample spacing along the curve.
inline double brute_force_distance(const RodConfiguration& c,
                                   const Eigen::Vector3d& point,
                                   int per_interval) {
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i + 1 < c.nodes(); ++i)
    for (int k = 0; k <= per_interval; ++k)
      best = std::min(best,
                      (hermite_point(c, i, static_cast<double>(k) / per_interval) - point).norm());
  return best;
}

/// "1.234e-07": for RecordProperty, which std::to_string would round to 0.000000.
inline std::string scientific(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3e", value);
  return buffer;
}

}  // namespace rodshape::testing
