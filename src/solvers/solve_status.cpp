#include "rodshape/solvers/solve_status.hpp"

namespace rodshape {

std::string to_string(SolveStatus status) {
  switch (status) {
    case SolveStatus::NotRun:
      return "not_run";
    case SolveStatus::Converged:
      return "converged";
    case SolveStatus::IterationLimit:
      return "iteration_limit";
    case SolveStatus::Diverged:
      return "diverged";
    case SolveStatus::Singular:
      return "singular";
    case SolveStatus::Infeasible:
      return "infeasible";
    case SolveStatus::ConstraintViolated:
      return "constraint_violated";
    case SolveStatus::OutOfReach:
      return "out_of_reach";
  }
  return "unknown";
}

}  // namespace rodshape
