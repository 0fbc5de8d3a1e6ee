// error.hpp: the two kinds of exception rodshape throws. Numerical non-convergence is not one of
// them: it is a status in a result (see solvers/solve_status.hpp).
#pragma once

#include <stdexcept>
#include <string>

namespace rodshape {

/// Base class of every exception rodshape throws.
class RodshapeError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Bad input: the message names the field and the value, e.g. "rod.length = -0.3 must be > 0".
class InputError : public RodshapeError {
 public:
  using RodshapeError::RodshapeError;
};

}  // namespace rodshape
