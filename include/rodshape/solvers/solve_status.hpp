// solve_status.hpp: how an iterative solve ended, one vocabulary for every solver (shooting,
// shape optimisation, inverse kinematics). Never collapsed to a bool; the raw status of an external
// solver (IPOPT's ApplicationReturnStatus) is kept beside it in the solver's own details.
#pragma once

#include <string>

#include "rodshape/enum_names.hpp"

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
  NonFinite,           // the residual looked converged but the shape is not finite (NaN, ±inf)
  DiscretisationTooCoarse,  // the residual met the tolerance but the integration error estimate
                            // exceeds its tolerance, even with the most sub-steps allowed
};
/// The names of SolveStatus, in its order (to_string; the results' "status").
inline constexpr EnumNames<SolveStatus, 10> kSolveStatusNames = {{
    {SolveStatus::NotRun, "not_run"},
    {SolveStatus::Converged, "converged"},
    {SolveStatus::IterationLimit, "iteration_limit"},
    {SolveStatus::Diverged, "diverged"},
    {SolveStatus::Singular, "singular"},
    {SolveStatus::Infeasible, "infeasible"},
    {SolveStatus::ConstraintViolated, "constraint_violated"},
    {SolveStatus::OutOfReach, "out_of_reach"},
    {SolveStatus::NonFinite, "non_finite"},
    {SolveStatus::DiscretisationTooCoarse, "discretisation_too_coarse"},
}};

std::string to_string(SolveStatus status);

}  // namespace rodshape
