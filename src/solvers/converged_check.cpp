#include "converged_check.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "rodshape/solvers/integration_error.hpp"
#include "rodshape/solvers/shooting_residual.hpp"
#include "validation.hpp"

namespace rodshape::detail {

namespace {

/// False (with the status set) when the configuration or its residual is not finite, or the
/// residual is above the tolerance; else refreshes residual_norm from the configuration.
bool confirm_residual(const TipCondition& tip,
                      const ShootingOptions& options,
                      ShootingResult& solution) {
  ShootingSummary& summary = solution.summary;
  const Vector6d r = shooting_residual(tip, solution.configuration);
  if (!solution.configuration.finite() || !r.allFinite()) {
    summary.status = SolveStatus::NonFinite;
    summary.message =
        "the shape is not finite (NaN or infinite values) although the residual looked "
        "converged: the load bends the rod more than its discretisation can integrate";
    summary.residual_norm = std::numeric_limits<double>::quiet_NaN();
    return false;
  }
  summary.residual_norm = r.lpNorm<Eigen::Infinity>();
  if (summary.residual_norm > options.residual_tolerance) {
    summary.status = SolveStatus::Diverged;
    summary.message =
        "the returned configuration's residual |r| = " + format_value(summary.residual_norm) +
        " exceeds ShootingOptions.residual_tolerance";
    return false;
  }
  return true;
}

/// The next sub-step count: RK4's error falls as substeps⁻⁴, so aim at a quarter of the
/// tolerance; at least double, in powers of two, at most max_substeps.
int next_substeps(int substeps, double error, double tolerance, int max_substeps) {
  const double factor = std::pow(4.0 * error / tolerance, 0.25);  // +inf for a non-finite error
  long next = 2L * substeps;
  while (next < max_substeps && !(next >= substeps * factor)) next *= 2;
  return static_cast<int>(std::min<long>(next, max_substeps));
}

void add_counts(ShootingSummary& total, const ShootingSummary& part) {
  total.iterations += part.iterations;
  total.chord_steps += part.chord_steps;
  total.integrations += part.integrations;
  total.jacobian_evaluations += part.jacobian_evaluations;
  total.continuation_steps += part.continuation_steps;
}

}  // namespace

void confirm_converged(const ClampedRod& rod,
                       const TipCondition& tip,
                       const ShootingOptions& options,
                       ShootingResult& solution,
                       std::optional<double> integration_error) {
  ShootingSummary& summary = solution.summary;
  summary.substeps = rod.substeps;
  if (!summary.converged() || !confirm_residual(tip, options, solution)) return;
  if (!std::isfinite(options.integration_tolerance)) return;  // the check is off

  ClampedRod refined = rod;
  while (true) {
    if (integration_error) {  // the solve's own (its integrations are counted)
      summary.integration_error = *integration_error;
      integration_error.reset();
    } else {
      summary.integration_error =
          integration_error_estimate(refined, solution.base_wrench, solution.configuration);
      summary.integrations += 1;  // one, at half the steps (at twice them when counts are odd)
    }
    if (summary.integration_error <= options.integration_tolerance) return;
    if (refined.substeps >= options.max_substeps) {
      summary.status = SolveStatus::DiscretisationTooCoarse;
      summary.message = "the integration error estimate " +
                        format_value(summary.integration_error) +
                        " exceeds ShootingOptions.integration_tolerance = " +
                        format_value(options.integration_tolerance) + " with " +
                        std::to_string(refined.substeps) +
                        " sub-steps per interval (ShootingOptions.max_substeps): use more nodes or "
                        "a larger max_substeps";
      return;
    }
    refined.substeps = next_substeps(refined.substeps, summary.integration_error,
                                     options.integration_tolerance, options.max_substeps);
    // The re-solve starts from the equilibrium just found, which the finer steps move by about
    // the error estimate: a direct solve, without the check (this loop is it) and without the
    // continuation from rest, which would retrace the whole path at `substeps` times the cost and
    // could end on another equilibrium than the one being checked (in the test suite and the
    // examples, none of the 16 re-solves that fell back to it converged). Its iterations are
    // bounded apart, as they cost `substeps` times a solve's (of 51,000 re-solves there, all
    // but 4 of those that converged took at most 30; BENCHMARKS.md).
    ShootingOptions inner = options;
    inner.integration_tolerance = std::numeric_limits<double>::infinity();
    inner.continuation = false;
    inner.max_iterations = std::min(options.max_iterations, ShootingOptions::kRefinementIterations);
    ShootingResult again = solve_equilibrium(refined, tip, solution.base_wrench, inner);
    add_counts(summary, again.summary);
    summary.substeps = refined.substeps;
    solution.base_wrench = again.base_wrench;
    solution.configuration = std::move(again.configuration);
    if (!again.summary.converged()) {
      summary.status = again.summary.status;
      summary.residual_norm = again.summary.residual_norm;
      summary.message = "with " + std::to_string(refined.substeps) +
                        " sub-steps per interval (the integration error asked for them): " +
                        again.summary.message;
      return;
    }
    if (!confirm_residual(tip, options, solution)) return;
  }
}

}  // namespace rodshape::detail
