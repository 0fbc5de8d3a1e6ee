// solve_status.hpp: how an iterative solve ended. Never collapsed to a bool.
#pragma once

#include <string>

namespace rodshape {

enum class SolveStatus {
  NotRun,          // solve() was not called
  Converged,       // the residual met the tolerance
  IterationLimit,  // max_iterations reached first
  Diverged,        // the residual or the iterate became non-finite, or grew without bound
  Singular,        // the Jacobian lost rank and no step reduced the residual
  NonFinite,       // the residual looked converged but the shape is not finite (NaN or ±inf)
  DiscretisationTooCoarse,  // the residual met the tolerance but the integration error estimate
                            // exceeds the tolerance, even with the most sub-steps allowed
};

std::string to_string(SolveStatus status);

}  // namespace rodshape
