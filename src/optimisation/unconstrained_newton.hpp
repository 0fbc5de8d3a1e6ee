// unconstrained_newton.hpp (private): the iteration IPOPT performs on min_w F(w) when the problem
// has no constraint rows and no finite wrench bounds, done directly on the 6 unknowns. Without
// rows or bounds IPOPT's interior-point method reduces to Newton's method with a line search:
// no barrier, no slacks, the filter reduces to Armijo's condition on F, and its KKT system is the
// Hessian alone, perturbed by δ I until positive definite (its inertia correction). Doing the same
// here leaves out IPOPT's per-iteration overhead (its timing of every task by getrusage, its
// vector and matrix objects, their allocations): on the paper's experiment that overhead was about
// a third of a plan's time (BENCHMARKS.md, issue 26).
//
// Kept from IPOPT, so that optima agree to the tolerance and results read the same:
//   * the scaled problem: F is multiplied by s_f = min(1, 100 / |∇F(w0)|_∞) (gradient-based
//     scaling, nlp_scaling_max_gradient), bounded below by 1e-8 (nlp_scaling_min_value);
//   * the stopping test: s_f |∇F|_∞ ≤ tol and |∇F|_∞ ≤ 1 (IPOPT's tol and dual_inf_tol); 15
//     iterations in a row within 1e-6 (acceptable_tol, acceptable_iter) stop at an acceptable
//     point;
//   * the first Hessian: forward differences of the exact gradient (as ShapeNlp::eval_h);
//   * the inertia correction: δ = 0 first, then 1e-4 (or a third of the last δ) growing ×100 (×8
//     after a first δ) until the Cholesky factorisation succeeds, giving up past 1e40
//     (first_hessian_perturbation, perturb_dec_fact, perturb_inc_fact(_first), max_hessian_
//     perturbation);
//   * the line search: α = 1, halved until s_f F decreases by 1e-8 α s_f ∇Fᵀd (eta_phi,
//     alpha_red_factor), a failed evaluation (non-finite, or refused outside the admissible box)
//     counting as a rejected trial;
//   * the iteration count, the statuses and their names (IpoptDetails::application_status_name):
//     Solve_Succeeded, Solved_To_Acceptable_Level, Maximum_Iterations_Exceeded,
//     User_Requested_Stop (beyond the rod's scale, NlpOutcome::kMaxRefusals refusals),
//     Diverging_Iterates (|w|_∞ > 1e20), Invalid_Number_Detected (F or a derivative non-finite at
//     an accepted point or in the Hessian), Error_In_Step_Computation (no δ up to 1e40 made the
//     Hessian positive definite); when the line search finds no decrease before the step falls
//     below round-off (at the noise floor of F, where Σ dist can leave |∇F| a little above tol),
//     IPOPT's restoration phase returns the last acceptable iterate (scaled |∇F|_∞ ≤ 1e-6) as
//     Solved_To_Acceptable_Level, and so does this; without one, Search_Direction_Becomes_Too_Small
//     (IPOPT's restoration has nothing to restore without rows).
//
// Not kept: IPOPT differences the Hessian at every iteration (6 more integrations with all-node
// derivatives, 6/7 of an iteration's cost). Here the differenced Hessian of the first iteration
// is carried on by symmetric rank-one (SR1) updates from each accepted step's change of the
// exact gradient, and differenced again only when a step from the updated model finds no
// decrease. On the paper's experiment (BENCHMARKS.md, branch hess) that is 7 Hessians in place
// of 46 and about 160 integrations in place of 360 for the same optima; the iterations are more
// (superlinear, not quadratic, convergence: 79 against 46). SR1, not BFGS: the Hessian is
// indefinite away from the optimum and BFGS's positive definite model needed more integrations
// (damped BFGS 220, SR1 187, refreshed when |∇F| fell by less than half: both about 290).
#pragma once

#include <optional>

#include "optimisation/ipopt_adapter.hpp"
#include "rodshape/optimisation/shape_optimiser.hpp"
#include "rodshape/optimisation/shape_problem.hpp"

namespace rodshape::detail {

/// Whether unconstrained_newton() serves `problem`: a fixed clamp, no constraint rows, no finite
/// wrench bound, and the differenced Hessian (ShapeOptimiserOptions::hessian).
bool unconstrained_newton_serves(const ShapeProblem& problem, bool finite_difference_hessian);

/// The symmetric rank-one update of the Hessian model B with the step s and the change of
/// gradient y (Nocedal and Wright, Numerical Optimization, eq. 6.24): B + r rᵀ / (rᵀs), r = y - B
/// s, so that B s = y afterwards (the secant equation). Left out when |rᵀs| ≤ 1e-8 |s| |r| (their
/// eq. 6.26: the update would be huge or undefined) or not finite.
void sr1_update(const Vector6d& s, const Vector6d& y, Matrix6d& B);

/// The Hessian model of the iterations:
/// - Sr1Updated (the default): differenced once, then SR1-updated after every step.
/// - Sr1UntilBacktrack: SR1-updated after a full Newton step, differenced anew at the next iterate
///   after a step the line search shortened (the model was poor along it). The moving base's
///   eliminated problem, whose reduced F is flat along the base's motion: plain SR1 ended a step
///   of tests/python's two-Panda task at the iteration limit; this one completes it, and
///   BM_PlanTwoArms took 230 ms instead of 257-322 ms differencing at every iteration.
/// - DifferencedEveryIteration: as IPOPT does.
enum class HessianModel { Sr1Updated, Sr1UntilBacktrack, DifferencedEveryIteration };

/// Minimises F from `start` (F not evaluated outside `admissible`, when given; `start` lies
/// inside). The result reads as an IPOPT run's (IpoptDetails::solver says which solver it was);
/// the problem is left evaluated at some iterate. The iterations do not allocate.
IpoptRun unconstrained_newton(ShapeProblem& problem,
                              const Vector6d& start,
                              const ShapeOptimiserOptions& options,
                              const std::optional<WrenchBounds>& admissible = std::nullopt,
                              HessianModel hessian_model = HessianModel::Sr1Updated);

}  // namespace rodshape::detail
