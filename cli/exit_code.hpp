// exit_code.hpp: what the rodshape tool's exit status means (also in --help and docs/task-file.md).
#pragma once

namespace rodshape::cli {

enum ExitCode : int {
  kSuccess = 0,
  kInternalError = 1,  // a bug: an exception that is not rodshape's InputError
  kBadInput = 2,       // bad task file, bad command line, output file that cannot be written
                       // or is an input, an infeasible target: nothing written or removed
  kNotConverged = 3,   // the solver did not converge; the result (with its status) is still written
  kPartialPlan = 3,    // plan: a step's optimisation failed; the steps before it are still written
  kNotExplained = 3,   // estimate: the fit did not converge or the model does not explain the
                       // cloud; the result (saying why) is still written
};

}  // namespace rodshape::cli
