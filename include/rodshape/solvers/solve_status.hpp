// solve_status.hpp: how an iterative solve ended, one vocabulary for every solver (shooting,
// shape optimisation, inverse kinematics). Never collapsed to a bool; the raw status of an external
// solver (IPOPT's ApplicationReturnStatus) is kept beside it in the solver's own details.
#pragma once

#include <string>

namespace rodshape {

enum class SolveStatus {
  NotRun,          // solve() was not called
  Converged,       // the residual met the tolerance
  IterationLimit,  // max_iterations reached first
  Diverged,        // the residual or the iterate became non-finite, or grew without bound
  Singular,        // the Jacobian lost rank and no step reduced the residual (or, in IPOPT, the
                   // step computation failed)
  Infeasible,      // the constraints admit no point (IPOPT: infeasible problem, restoration failed)
  ConstraintViolated,  // the iteration stopped, but the final point violates the constraints by
                       // more than their tolerance (judged on the problem as posed)
  OutOfReach,          // the target is beyond what the solver's unknowns can reach (IK: the arm)
};

std::string to_string(SolveStatus status);

}  // namespace rodshape
