#include "rodshape/optimisation/shape_optimizer.hpp"

#include <IpIpoptApplication.hpp>
#include <IpSolveStatistics.hpp>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include "optimisation/ipopt_adapter.hpp"
#include "validation.hpp"

namespace rodshape {

void ShapeOptimizerOptions::validate() const {
  if (max_iterations < 0)
    throw InputError("ShapeOptimizerOptions.max_iterations",
                     " = " + std::to_string(max_iterations) + " must be >= 0");
  detail::require_positive("ShapeOptimizerOptions.tolerance", tolerance);
  detail::require_positive("ShapeOptimizerOptions.constraint_tolerance", constraint_tolerance);
  if (multi_starts < 0)
    throw InputError("ShapeOptimizerOptions.multi_starts",
                     " = " + std::to_string(multi_starts) + " must be >= 0");
  if (print_level < 0 || print_level > 12)
    throw InputError("ShapeOptimizerOptions.print_level",
                     " = " + std::to_string(print_level) + " must be in [0, 12]");
}

bool ipopt_available() { return true; }

namespace {

/// IPOPT's ApplicationReturnStatus → SolveStatus. The raw status is kept in IpoptDetails.
///   Solve_Succeeded, Solved_To_Acceptable_Level    → Converged (then checked against our own
///   Feasible_Point_Found (square problems only)       constraint violation, see below)
///   Maximum_Iterations_Exceeded, _CpuTime_Exceeded → IterationLimit
///   Diverging_Iterates                             → Diverged  (|w| grew without bound)
///   Invalid_Number_Detected                        → Diverged  (F, g or a derivative non-finite)
///   Infeasible_Problem_Detected                    → Infeasible (a stationary point of the
///                                                    constraint violation: no step reduces it)
///   Restoration_Failed                             → Infeasible (the feasibility restoration
///                                                    found no step that reduces the violation)
///   Error_In_Step_Computation                      → Singular  (the KKT matrix stayed singular
///                                                    despite IPOPT's regularisation)
///   Search_Direction_Becomes_Too_Small             → Singular  (no step changes w any more
///                                                    although the tolerances are not met)
///   Not_Enough_Degrees_Of_Freedom                  → Singular  (more equality rows than the 6
///                                                    unknowns: dg/dw cannot have full row rank)
///   User_Requested_Stop, Invalid_Problem_Definition, Invalid_Option, Unrecoverable_Exception,
///   NonIpopt_Exception_Thrown, Insufficient_Memory, Internal_Error
///                                                  → Diverged  (the solve broke down; the
///                                                    message names IPOPT's status)
/// A Converged run whose final w violates a constraint or a wrench bound by more than
/// ShapeOptimizerOptions::constraint_tolerance (our measure, ShapeProblem::constraint_violation)
/// becomes ConstraintViolated.
SolveStatus map_status(Ipopt::ApplicationReturnStatus status) {
  switch (status) {
    case Ipopt::Solve_Succeeded:
    case Ipopt::Solved_To_Acceptable_Level:
    case Ipopt::Feasible_Point_Found:
      return SolveStatus::Converged;
    case Ipopt::Maximum_Iterations_Exceeded:
    case Ipopt::Maximum_CpuTime_Exceeded:
      return SolveStatus::IterationLimit;
    case Ipopt::Infeasible_Problem_Detected:
    case Ipopt::Restoration_Failed:
      return SolveStatus::Infeasible;
    case Ipopt::Error_In_Step_Computation:
    case Ipopt::Search_Direction_Becomes_Too_Small:
    case Ipopt::Not_Enough_Degrees_Of_Freedom:
      return SolveStatus::Singular;
    case Ipopt::Diverging_Iterates:
    case Ipopt::Invalid_Number_Detected:
    case Ipopt::User_Requested_Stop:
    case Ipopt::Invalid_Problem_Definition:
    case Ipopt::Invalid_Option:
    case Ipopt::Unrecoverable_Exception:
    case Ipopt::NonIpopt_Exception_Thrown:
    case Ipopt::Insufficient_Memory:
    case Ipopt::Internal_Error:
      return SolveStatus::Diverged;
  }
  return SolveStatus::Diverged;
}

/// The guess, then `count` extra starts, deterministic. Bending moments are the components of m(0)
/// across the clamp's tangent, i.e. along the clamp frame's x and y axes R0 e_x, R0 e_y. In order:
///   1. the guess with both bending moments flipped (the mirror shape),
///   2. the guess × 0.5,  3. the guess × 2,
///   4. the guess with m_x flipped,  5. with m_y flipped,
///   6… the guess plus a bending moment of size m_c · {1, 0.5, 2} (cycling) about the direction at
///      k × the golden angle in the clamp's x–y plane, m_c = max(EIx, EIy) (π/2) / L being the end
///      moment that bends the unloaded rod through a quarter turn.
/// A start equal to one already listed (e.g. 1–5 from a zero guess) is skipped.
std::vector<Vector6d> starts_from(const Vector6d& guess, const ClampedRod& rod, int count) {
  std::vector<Vector6d> starts{guess};
  const std::size_t wanted = static_cast<std::size_t>(count) + 1;
  const auto add = [&](const Vector6d& w) {
    if (starts.size() >= wanted) return;
    for (const Vector6d& s : starts)
      if ((s - w).lpNorm<Eigen::Infinity>() <= 1e-12 * (1.0 + w.lpNorm<Eigen::Infinity>())) return;
    starts.push_back(w);
  };
  const Eigen::Matrix3d& R0 = rod.clamp.rotation;
  const Eigen::Vector3d m_local = R0.transpose() * guess.tail<3>();
  const auto with_local_moment = [&](const Eigen::Vector3d& m) {
    Vector6d w = guess;
    w.tail<3>() = R0 * m;
    return w;
  };
  add(with_local_moment({-m_local.x(), -m_local.y(), m_local.z()}));
  add(0.5 * guess);
  add(2.0 * guess);
  add(with_local_moment({-m_local.x(), m_local.y(), m_local.z()}));
  add(with_local_moment({m_local.x(), -m_local.y(), m_local.z()}));
  const RodProperties& props = rod.properties;
  const double m_c =
      std::max(props.K_rot.x(), props.K_rot.y()) * (std::numbers::pi / 2.0) / props.length;
  const double golden_angle = std::numbers::pi * (3.0 - std::sqrt(5.0));
  constexpr double kScales[] = {1.0, 0.5, 2.0};
  for (int k = 0; starts.size() < wanted; ++k) {
    const double phi = k * golden_angle;
    const double size = m_c * kScales[k % 3];
    add(with_local_moment(m_local + size * Eigen::Vector3d(std::cos(phi), std::sin(phi), 0.0)));
  }
  return starts;
}

/// One IPOPT run and what we make of it.
struct StartResult {
  Ipopt::ApplicationReturnStatus application_status = Ipopt::Internal_Error;
  detail::NlpOutcome outcome;
  SolveStatus status = SolveStatus::NotRun;
  int iterations = 0;
  double violation = 0.0;
  double cost = 0.0;
  double energy = 0.0;
  int start_index = 0;
};

StartResult run_start(Ipopt::IpoptApplication& app,
                      ShapeProblem& problem,
                      const Vector6d& start,
                      const ShapeOptimizerOptions& options) {
  StartResult result;
  auto* nlp = new detail::ShapeNlp(problem, start,
                                   detail::uses_finite_difference_hessian(options, problem));
  const Ipopt::SmartPtr<Ipopt::TNLP> owner = nlp;
  result.application_status = app.OptimizeTNLP(owner);
  result.outcome = nlp->outcome();
  const Ipopt::SmartPtr<Ipopt::SolveStatistics> statistics = app.Statistics();
  result.iterations =
      Ipopt::IsValid(statistics) ? statistics->IterationCount() : result.outcome.iterations;

  // Judge the final iterate ourselves, on the problem as posed.
  const Vector6d& w = result.outcome.w;
  problem.evaluate(w);
  result.violation = problem.constraint_violation();  // ours, not IPOPT's (scaled, relaxed)
  result.cost = problem.cost();
  result.energy = problem.breakdown().energy;
  result.status = map_status(result.application_status);
  // "Converged" promises a feasible point: IPOPT's own test runs on the relaxed bounds, and an
  // acceptable point could in principle slip through, so our measure has the last word.
  if (result.status == SolveStatus::Converged &&
      !(result.violation <= options.constraint_tolerance && std::isfinite(result.cost)))
    result.status = SolveStatus::ConstraintViolated;
  return result;
}

/// Among converged starts, the one of least F; F = W1 E / L + W2 Σ dist, so among shapes that fit
/// the target equally well the least elastic energy wins (the paper's use of E), while a flatter
/// shape that misses the points does not. Ties in F (within 1e-9·max(1, |F|)) go to the least E.
/// Without any converged start, the guess's run is returned: its status says what went wrong.
std::size_t pick_best(const std::vector<StartResult>& results) {
  std::size_t best = 0;
  bool found = false;
  for (std::size_t k = 0; k < results.size(); ++k) {
    const StartResult& r = results[k];
    if (r.status != SolveStatus::Converged) continue;
    if (!found) {
      best = k;
      found = true;
      continue;
    }
    const StartResult& b = results[best];
    const double tie = 1e-9 * std::max(1.0, std::abs(b.cost));
    if (r.cost < b.cost - tie || (std::abs(r.cost - b.cost) <= tie && r.energy < b.energy))
      best = k;
  }
  return best;
}

std::string describe(const StartResult& r, int starts, const ShapeOptimizerOptions& options) {
  std::ostringstream out;
  out.precision(3);
  out << "IPOPT " << detail::application_status_name(r.application_status) << " after "
      << r.iterations << " iterations";
  if (starts > 1) out << " (start " << r.start_index + 1 << " of " << starts << ")";
  out << "; F = " << r.cost << ", max constraint violation " << r.violation;
  if (r.status == SolveStatus::ConstraintViolated)
    out << " exceeds ShapeOptimizerOptions.constraint_tolerance = " << options.constraint_tolerance;
  return out.str();
}

}  // namespace

ShapeResult optimise_shape(ShapeProblem& problem,
                           const BaseWrench& guess,
                           const ShapeOptimizerOptions& options) {
  options.validate();
  const Vector6d w0 = guess.to_vector();
  detail::require_finite("guess", w0);

  ShapeResult solution;
  Ipopt::SmartPtr<Ipopt::IpoptApplication> app = IpoptApplicationFactory();
  detail::apply_options(*app->Options(), options,
                        detail::uses_finite_difference_hessian(options, problem));
  // "" skips IPOPT's options file: an ipopt.opt in the working directory must not change results.
  const Ipopt::ApplicationReturnStatus init = app->Initialize("");
  if (init != Ipopt::Solve_Succeeded) {
    solution.status = SolveStatus::Diverged;
    solution.message = "IPOPT initialisation failed: " + detail::application_status_name(init);
    solution.ipopt.application_status = static_cast<int>(init);
    solution.ipopt.application_status_name = detail::application_status_name(init);
    return solution;
  }

  const std::vector<Vector6d> starts = starts_from(w0, problem.rod(), options.multi_starts);
  std::vector<StartResult> results;
  results.reserve(starts.size());
  for (std::size_t k = 0; k < starts.size(); ++k) {
    results.push_back(run_start(*app, problem, starts[k], options));
    results.back().start_index = static_cast<int>(k);
  }
  const StartResult& best = results[pick_best(results)];

  problem.evaluate(best.outcome.w);
  solution.status = best.status;
  solution.message = describe(best, static_cast<int>(starts.size()), options);
  solution.base_wrench = Wrench::from_vector(best.outcome.w);
  solution.configuration = problem.configuration();
  solution.cost = problem.breakdown();
  solution.max_constraint_violation = best.violation;
  if (options.assess_stability && std::isfinite(best.cost))
    solution.stability = assess_stability(problem.rod(), solution.configuration);
  solution.ipopt.application_status = static_cast<int>(best.application_status);
  solution.ipopt.application_status_name = detail::application_status_name(best.application_status);
  solution.ipopt.iterations = best.iterations;
  solution.ipopt.objective = best.outcome.objective;
  solution.ipopt.constraint_multipliers = best.outcome.constraint_multipliers;
  solution.ipopt.lower_bound_multipliers = best.outcome.lower_bound_multipliers;
  solution.ipopt.upper_bound_multipliers = best.outcome.upper_bound_multipliers;
  solution.starts_tried = static_cast<int>(starts.size());
  return solution;
}

std::string ShapeResult::brief() const {
  std::ostringstream out;
  out.precision(3);
  out << to_string(status) << ": max distance " << 1e3 * cost.max_distance << " mm, energy "
      << cost.energy << " J; " << message;
  return out.str();
}

}  // namespace rodshape
