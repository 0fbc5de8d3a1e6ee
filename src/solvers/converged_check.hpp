// converged_check.hpp (private): the last word on "converged" at the end of solve_equilibrium.
#pragma once

#include <optional>

#include "rodshape/core/clamped_rod.hpp"
#include "rodshape/solvers/shooting_solver.hpp"
#include "rodshape/solvers/tip_condition.hpp"

namespace rodshape::detail {

/// A converged `solution` of `rod` and `tip` stays converged only if its configuration is finite,
/// its residual (recomputed from it) is within options.residual_tolerance, and its integration
/// error estimate within options.integration_tolerance. Where the estimate is too large, the
/// equilibrium is solved again from the solution's wrench with more sub-steps per interval, up to
/// options.max_substeps. Otherwise the status says why: NonFinite, DiscretisationTooCoarse, or
/// the failed re-solve's status. `integration_error`: the configuration's estimate when the solve
/// already made it (integration_error_estimate()'s value, from the same two integrations).
void confirm_converged(const ClampedRod& rod,
                       const TipCondition& tip,
                       const ShootingOptions& options,
                       ShootingResult& solution,
                       std::optional<double> integration_error = std::nullopt);

}  // namespace rodshape::detail
