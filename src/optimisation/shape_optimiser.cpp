#include "rodshape/optimisation/shape_optimiser.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include "optimisation/ipopt_adapter.hpp"
#include "optimisation/unconstrained_newton.hpp"
#include "validation.hpp"

namespace rodshape {

void ShapeOptimiserOptions::validate() const {
  detail::require_count("ShapeOptimiserOptions.max_iterations", max_iterations, 0, kMaxIterations);
  detail::require_positive("ShapeOptimiserOptions.tolerance", tolerance);
  detail::require_positive("ShapeOptimiserOptions.constraint_tolerance", constraint_tolerance);
  detail::require_count("ShapeOptimiserOptions.multi_starts", multi_starts, 0, kMaxMultiStarts);
  if (print_level < 0 || print_level > 12)
    throw InputError("ShapeOptimiserOptions.print_level",
                     " = " + std::to_string(print_level) + " must be in [0, 12]");
}

bool ipopt_available() { return true; }

namespace {

using detail::IpoptRun;
using detail::IpoptSession;
using detail::unconstrained_newton;
using detail::unconstrained_newton_serves;
using detail::uses_finite_difference_hessian;

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
  IpoptRun run;
  SolveStatus status = SolveStatus::NotRun;  // run.status, judged on the problem as posed
  double violation = 0.0;
  double cost = 0.0;
  double energy = 0.0;
  int start_index = 0;
};

/// The box F is evaluated in (ShapeOptimiserOptions::confine_to_scale): the rod's scale, widened
/// to twice the start where the start lies outside it.
std::optional<WrenchBounds> admissible_box(const ShapeProblem& problem,
                                           const Vector6d& start,
                                           const ShapeOptimiserOptions& options) {
  if (!options.confine_to_scale) return std::nullopt;
  WrenchBounds box = WrenchBounds::from_scale(problem.rod());
  box.upper = box.upper.cwiseMax(2.0 * start.cwiseAbs());
  box.lower = -box.upper;
  return box;
}

/// With a moving base, the start x = (w_b, ξ) of each start's world wrench at the reference pose.
std::vector<Vector12d> moving_starts(const ShapeProblem& problem,
                                     const std::vector<Vector6d>& starts) {
  std::vector<Vector12d> x;
  x.reserve(starts.size());
  for (const Vector6d& w : starts)
    x.push_back(problem.variables_at_reference(Wrench::from_vector(w)));
  return x;
}

/// Whether a moving base's start is solved by the dense Newton over w_b alone, the base pose
/// eliminated (ShapeProblem::eliminate_base_pose): no rows, no finite bound on w_b, a shape that
/// moves rigidly with the base (rigid_alignment_applies) and the differenced Hessian.
bool eliminated_newton_serves(const ShapeProblem& problem, bool finite_difference_hessian) {
  const Vector12d lower = problem.variable_lower(), upper = problem.variable_upper();
  return finite_difference_hessian && problem.constraint_count() == 0 &&
         problem.rigid_alignment_applies() && !lower.head<6>().array().isFinite().any() &&
         !upper.head<6>().array().isFinite().any();
}

/// The dense Newton over w_b with ξ = ξ*(w_b); the run's x = (w_b, ξ*) and w its world wrench.
IpoptRun eliminated_newton(ShapeProblem& problem,
                           const Vector12d& start,
                           const ShapeOptimiserOptions& options) {
  const Vector6d units = problem.rod().properties.bending_wrench_units();
  std::optional<WrenchBounds> box = admissible_box(problem, start.head<6>(), options);
  if (box) {  // in w̃ = w_b / D
    box->lower.array() /= units.array();
    box->upper.array() /= units.array();
  }
  problem.eliminate_base_pose(true);
  IpoptRun run = unconstrained_newton(problem, start.head<6>().cwiseQuotient(units), options, box,
                                      detail::HessianModel::Sr1UntilBacktrack);
  problem.evaluate(run.w);  // ξ*(w_b) at the final iterate
  const bool aligned = std::isfinite(problem.cost());
  run.x = problem.evaluated_variables();
  problem.eliminate_base_pose(false);
  if (!aligned) run.status = SolveStatus::NonFinite;
  run.w = problem.world_wrench(run.x).to_vector();
  return run;
}

StartResult run_start(IpoptSession& session,
                      ShapeProblem& problem,
                      const Vector6d& start,
                      const ShapeOptimiserOptions& options,
                      const Vector12d* moving_start = nullptr) {
  StartResult result;
  if (moving_start) {
    // Where the dense Newton over w_b does not converge (a start far down the moving base's flat
    // valley), IPOPT from the same start.
    const bool newton = eliminated_newton_serves(problem, session.finite_difference_hessian());
    if (newton) result.run = eliminated_newton(problem, *moving_start, options);
    if (!newton || result.run.status != SolveStatus::Converged)
      result.run = session.run(problem, *moving_start,
                               admissible_box(problem, moving_start->head<6>(), options));
    problem.evaluate_with_base(result.run.x);
  } else if (unconstrained_newton_serves(problem, session.finite_difference_hessian())) {
    result.run =
        unconstrained_newton(problem, start, options, admissible_box(problem, start, options));
    problem.evaluate(result.run.w);
  } else {
    result.run = session.run(problem, start, admissible_box(problem, start, options));
    // Judge the final iterate ourselves, on the problem as posed.
    problem.evaluate(result.run.w);
  }
  result.violation = problem.constraint_violation();  // ours, not IPOPT's (scaled, relaxed)
  result.cost = problem.cost();
  result.energy = problem.breakdown().energy;
  result.status = result.run.status;
  // "Converged" promises a feasible point: IPOPT's own test runs on the relaxed bounds, and an
  // acceptable point could in principle slip through, so our measure has the last word.
  if (result.status != SolveStatus::Converged) return result;
  if (!std::isfinite(result.cost) || !std::isfinite(result.violation))
    result.status = SolveStatus::NonFinite;
  else if (!(result.violation <= options.constraint_tolerance))
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

std::string describe(const StartResult& r, int starts, const ShapeOptimiserOptions& options) {
  std::ostringstream out;
  out.precision(3);
  out << r.run.details.solver << " " << r.run.details.application_status_name << " after "
      << r.run.details.iterations << " iterations";
  if (starts > 1) out << " (start " << r.start_index + 1 << " of " << starts << ")";
  out << "; F = " << r.cost << ", max constraint violation " << r.violation;
  if (r.status == SolveStatus::ConstraintViolated)
    out << " exceeds ShapeOptimiserOptions.constraint_tolerance = " << options.constraint_tolerance;
  if (r.status == SolveStatus::NonFinite)
    out << "; the shape is not finite (NaN or infinite values)";
  if (r.run.details.beyond_scale)
    out << "; stopped: the optimum lies beyond the rod's scale (a base moment over 4π EI/L, two "
           "full turns, or a force over half the axial or shear stiffness: "
           "ShapeOptimiserOptions.confine_to_scale)";
  return out.str();
}

}  // namespace

ShapeResult optimise_shape(ShapeProblem& problem,
                           const BaseWrench& guess,
                           const ShapeOptimiserOptions& options) {
  options.validate();
  const Vector6d w0 = guess.to_vector();
  detail::require_finite("guess", w0);

  ShapeResult solution;
  IpoptSession& session =
      IpoptSession::for_this_thread(options, uses_finite_difference_hessian(options, problem));
  if (const auto& failure = session.initialisation_failure()) {
    solution.status = failure->status;
    solution.message = "IPOPT initialisation failed: " + failure->details.application_status_name;
    solution.ipopt = failure->details;
    return solution;
  }

  ClampedRod at_start = problem.rod();
  if (problem.base_moves()) at_start.clamp = problem.base_motion()->reference;
  const std::vector<Vector6d> starts = starts_from(w0, at_start, options.multi_starts);
  const std::vector<Vector12d> moving =
      problem.base_moves() ? moving_starts(problem, starts) : std::vector<Vector12d>{};
  std::vector<StartResult> results;
  results.reserve(starts.size());
  for (std::size_t k = 0; k < starts.size(); ++k) {
    results.push_back(
        run_start(session, problem, starts[k], options, moving.empty() ? nullptr : &moving[k]));
    results.back().start_index = static_cast<int>(k);
  }
  const StartResult& best = results[pick_best(results)];

  if (problem.base_moves())
    problem.evaluate_with_base(best.run.x);  // the rod's clamp is then the optimum's base pose
  else
    problem.evaluate(best.run.w);
  solution.status = best.status;
  solution.message = describe(best, static_cast<int>(starts.size()), options);
  solution.base_wrench = Wrench::from_vector(best.run.w);
  solution.configuration = problem.configuration();
  solution.cost = problem.breakdown();
  solution.max_constraint_violation = best.violation;
  if (options.assess_stability && std::isfinite(best.cost)) {
    // Released grasp components leave the tip partly free: their tip stiffness is tested too.
    solution.stability =
        assess_stability(problem.rod(), solution.configuration,
                         GraspedTip{solution.configuration.tip(), problem.grasp().released});
  }
  solution.ipopt = best.run.details;
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
