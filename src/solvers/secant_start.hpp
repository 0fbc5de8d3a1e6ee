// secant_start.hpp (private): a solve started from a solved neighbour's Jacobian estimate, as the
// continuation substeps of follow_equilibrium do, instead of an integration with derivatives.
#pragma once

#include <optional>

#include "rodshape/core/clamped_rod.hpp"
#include "rodshape/solvers/shooting_solver.hpp"
#include "rodshape/solvers/tip_condition.hpp"

namespace rodshape::detail {

/// In: when `valid`, B ≈ dr/dw at the guess (the last solve's estimate at its root) and, when
/// known without integrating, the residual at the guess. Out: after a converged direct solve,
/// `valid` with B the estimate at its root (the exact Jacobian there, or its Broyden updates in
/// the endgame), the residual cleared, and the root's distance from Euler's point when there was
/// one (≈ ½ w'' dσ², the next substep's second-order term on a schedule of equal steps); else not
/// valid.
struct SecantStart {
  Matrix6d jacobian = Matrix6d::Zero();
  std::optional<Vector6d> residual_at_guess;
  std::optional<Vector6d> euler_error;
  bool valid = false;
};

/// solve_equilibrium() that, when `secant` is valid and gives the residual at the guess, starts
/// from the predictor's point guess - B⁻¹ r (+ the last Euler error) where its residual is smaller
/// than at the guess (the tangent of the path of roots, at no integration's cost); else as
/// solve_equilibrium().
/// A converged status is confirmed as always.
ShootingResult solve_equilibrium(const ClampedRod& rod,
                                 const TipCondition& tip,
                                 const BaseWrench& guess,
                                 const ShootingOptions& options,
                                 SecantStart* secant);

}  // namespace rodshape::detail
