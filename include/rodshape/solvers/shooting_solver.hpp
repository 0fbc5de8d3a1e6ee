// shooting_solver.hpp: solve the clamped rod's boundary-value problem for the unknown base wrench
// w = (n(0), m(0)) with Levenberg–Marquardt on the exact Jacobian (Eigen's MINPACK port, trust
// region in bending units), ending with Newton and chord steps near the root, warm-started from a
// guess, and with continuation of the boundary condition from the unloaded rod when the direct
// solve fails. Where the accuracy check compares with steps twice as long, the global phase runs
// on those (half the cost of an integration) and only the endgame's checks on the rod itself.
#pragma once

#include <limits>
#include <string>

#include "rodshape/core/clamped_rod.hpp"
#include "rodshape/core/rod_configuration.hpp"
#include "rodshape/solvers/model_validity.hpp"
#include "rodshape/solvers/solve_status.hpp"
#include "rodshape/solvers/tip_condition.hpp"

namespace rodshape {

struct ShootingOptions {
  /// Upper bounds (docs/limits.md, "Sizes"): an iteration or a continuation step integrates the
  /// rod with its derivatives (about 0.03 s at 100,001 nodes).
  static constexpr int kMaxIterations = 10'000;
  static constexpr int kMaxContinuationSteps = 4096;
  /// The most iterations of each re-solve that the accuracy check asks for (below).
  static constexpr int kRefinementIterations = 30;

  int max_iterations = 100;  // Levenberg–Marquardt iterations (accepted steps) per solve and
                             // stage (the coarse stage's global phase, then the rod's own where
                             // that fails); the endgame adds at most 8 chord steps per attempt
  double residual_tolerance =
      1e-10;  // converged when ||r(w)||_∞ ≤ residual_tolerance (m, rad, N, N·m)
  /// When the direct solve fails, step the boundary condition from the unloaded rod: clamped and
  /// grasped tips move from the rest tip along the screw motion to the target, a free tip's loads
  /// are scaled from 0 (the guess is not used). Steps are halved on failure down to
  /// 1/max_continuation_steps.
  bool continuation = true;
  int max_continuation_steps = 256;
  /// Derivatives stored in the returned configuration.
  Derivatives output_derivatives = Derivatives::AllNodes;
  /// "Converged" also promises accuracy: the step-doubling estimate of the returned
  /// configuration's integration error (integration_error_estimate(): |Δp|/L, rad, |Δm|/(EI/L)) is
  /// at most this. Where it is not, each interval is crossed in more Runge–Kutta sub-steps
  /// (powers of two, at most max_substeps) and the equilibrium solved again (a direct solve from
  /// the last one, in at most min(max_iterations, kRefinementIterations) iterations); past
  /// max_substeps the status is DiscretisationTooCoarse. +inf turns the check off.
  double integration_tolerance = 1e-6;
  int max_substeps = 64;  // 1 ≤ max_substeps ≤ ClampedRod::kMaxSubsteps
  /// Not used by the solver: what a held pose may ask of the model (check_model_validity()).
  ModelValidityLimits strain_limits;

  /// Throws InputError naming the field, e.g. "residual_tolerance = -1 must be > 0".
  void validate() const;
};

struct ShootingSummary {
  SolveStatus status = SolveStatus::NotRun;
  std::string message = "solve_equilibrium() was not called";
  int iterations = 0;    // Levenberg–Marquardt steps, all stages together
  int chord_steps = 0;   // Newton/chord steps of the endgame (not bounded by max_iterations)
  int integrations = 0;  // forward integrations of the rod
  int jacobian_evaluations = 0;  // of which with tip derivatives (about 3× the cost of one without)
  int continuation_steps = 0;    // 0 when the direct solve converged
  double residual_norm = std::numeric_limits<double>::quiet_NaN();  // ||r||_∞ at the end
  /// integration_error_estimate() of the returned configuration (NaN when not converged).
  double integration_error = std::numeric_limits<double>::quiet_NaN();
  /// Runge–Kutta sub-steps per interval of the returned configuration: integrate and test it with
  /// a copy of the rod whose `substeps` is this.
  int substeps = 1;

  bool converged() const { return status == SolveStatus::Converged; }
  /// One line: "converged in 2 iterations + 3 chord steps (6 integrations, 3 with derivatives),
  /// |r| = 3.1e-13".
  std::string brief() const;
};

struct ShootingResult {
  ShootingSummary summary;
  BaseWrench base_wrench;          // the last iterate (the solution when converged)
  RodConfiguration configuration;  // integrated at base_wrench, with options.output_derivatives
  std::string brief() const { return summary.brief(); }
};

/// The time a solve may take at worst, s, on the machine docs/limits.md was measured on: the sum
/// of two parts fitted to the slowest of 40 solves that fail or barely converge on the band with
/// 100,000 intervals (free tips loaded up to 1e4 N and N·m, held tips out of reach):
///  * the direct solve and the continuation's attempts: at most 13.4 integrations with
///    derivatives per allowed iteration measured, each 2.9e-7 s per interval:
///    16 × max_iterations × intervals × 2.9e-7 s (100 iterations: 39.5 s measured, 46 s estimated);
///  * the accuracy check's re-solves with 2, 4, ... max_substeps sub-steps, each a direct solve of
///    at most ShootingOptions::kRefinementIterations iterations: 2.0e-5 s × max_substeps ×
///    intervals (64: 102 s measured, 128 s estimated).
/// A solve that converges takes a small part of it (0.3–12 s there).
double estimated_failing_solve_seconds(const ClampedRod& rod, const ShootingOptions& options);

/// The most estimated_failing_solve_seconds() that solve_equilibrium() accepts: rod.intervals,
/// max_iterations and max_substeps each have their own bound, and this bounds their products
/// (100,000 intervals with 4096 sub-steps would take hours).
inline constexpr double kMaxEstimatedSolveSeconds = 300.0;

/// Throws InputError naming max_iterations or max_substeps (whichever costs more), with the
/// estimate, when estimated_failing_solve_seconds() exceeds kMaxEstimatedSolveSeconds.
void check_solve_cost(const ClampedRod& rod, const ShootingOptions& options);

/// Solves the equilibrium of `rod` with `tip` at s = L, starting from `guess`.
/// Throws InputError for bad input (rod, tip condition, options, check_solve_cost()); a solve that
/// does not converge is reported in the summary's status, never thrown.
ShootingResult solve_equilibrium(const ClampedRod& rod,
                                 const TipCondition& tip,
                                 const BaseWrench& guess = {},
                                 const ShootingOptions& options = {});

}  // namespace rodshape
