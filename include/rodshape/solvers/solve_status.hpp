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
};

std::string to_string(SolveStatus status);

}  // namespace rodshape
