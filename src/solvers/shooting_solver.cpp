#include "rodshape/solvers/shooting_solver.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <unsupported/Eigen/LevenbergMarquardt>

#include "converged_check.hpp"
#include "rodshape/core/physical_bounds.hpp"
#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/core/so3.hpp"
#include "rodshape/error.hpp"
#include "rodshape/solvers/follow_equilibrium.hpp"
#include "rodshape/solvers/shooting_residual.hpp"
#include "secant_start.hpp"
#include "step_doubling.hpp"
#include "validation.hpp"

#include "overloaded.hpp"

namespace rodshape {

void ShootingOptions::validate() const {
  detail::require_count("ShootingOptions.max_iterations", max_iterations, 1, kMaxIterations);
  detail::require_positive("ShootingOptions.residual_tolerance", residual_tolerance);
  detail::require_count("ShootingOptions.max_continuation_steps", max_continuation_steps, 1,
                        kMaxContinuationSteps);
  if (!(integration_tolerance > 0.0))  // +inf is allowed: it turns the accuracy check off
    throw InputError("ShootingOptions.integration_tolerance",
                     " = " + detail::format_value(integration_tolerance) + " must be > 0");
  if (max_substeps < 1 || max_substeps > ClampedRod::kMaxSubsteps)
    throw InputError("ShootingOptions.max_substeps",
                     " = " + std::to_string(max_substeps) + " must be in [1, " +
                         std::to_string(ClampedRod::kMaxSubsteps) + "]");
  strain_limits.validate("ShootingOptions.strain_limits");
}

std::string ShootingSummary::brief() const {
  std::ostringstream out;
  out << to_string(status) << " in " << iterations << " iterations";
  if (chord_steps > 0) out << " + " << chord_steps << " chord steps";
  out << " (" << integrations << " integrations, " << jacobian_evaluations << " with derivatives";
  if (continuation_steps > 0) out << ", " << continuation_steps << " continuation steps";
  if (substeps > 1) out << ", " << substeps << " sub-steps per interval";
  out << "), |r| = ";
  out.precision(3);
  out << residual_norm;
  return out.str();
}

namespace {

using detail::Overloaded;

void validate_tip(const TipCondition& tip) {
  std::visit(Overloaded{
                 [](const FreeTip& t) {
                   require_magnitude_at_most("FreeTip.wrench.force", t.wrench.force,
                                             bounds::kMaxForce, "N");
                   require_magnitude_at_most("FreeTip.wrench.moment", t.wrench.moment,
                                             bounds::kMaxForce, "N*m");
                 },
                 [](const ClampedTip& t) {
                   detail::require_pose("ClampedTip.pose", t.pose);
                   require_magnitude_at_most("ClampedTip.pose.position", t.pose.position,
                                             bounds::kMaxPosition, "m");
                 },
                 [](const GraspedTip& t) {
                   detail::require_pose("GraspedTip.pose", t.pose);
                   require_magnitude_at_most("GraspedTip.pose.position", t.pose.position,
                                             bounds::kMaxPosition, "m");
                   if (std::all_of(t.released.begin(), t.released.end(), [](bool r) { return r; }))
                     throw InputError("GraspedTip.released",
                                      " releases all six axes: the grasp would hold nothing; a "
                                      "tip held by nothing is a free tip (FreeTip)");
                 },
             },
             tip);
}

/// Row scales that make the residual dimensionless for Levenberg–Marquardt's trust region:
/// positions / L, angles as they are, forces · L²/EI, moments · L/EI.
Vector6d residual_row_scale(const ClampedRod& rod, const TipCondition& tip) {
  const double L = rod.properties.length;
  const Vector6d units = rod.properties.bending_wrench_units();
  const double force = 1.0 / units(0), moment = 1.0 / units(3);
  Vector6d scale;
  std::visit(Overloaded{
                 [&](const FreeTip&) { scale << force, force, force, moment, moment, moment; },
                 [&](const ClampedTip&) { scale << 1 / L, 1 / L, 1 / L, 1, 1, 1; },
                 [&](const GraspedTip& t) {
                   for (int i = 0; i < 3; ++i) {
                     scale[i] = t.released[i] ? force : 1 / L;
                     scale[3 + i] = t.released[3 + i] ? moment : 1.0;
                   }
                 },
             },
             tip);
  return scale;
}

/// The coarse stage's rod: the comparison rod (steps twice as long), its steps doubled again
/// (comparison_rod()) while it keeps at least kMinGlobalSteps Runge–Kutta steps. At h = L/20
/// RK4's error on a rod bent into a full loop (κh ≈ 0.31) is of order (κh)⁴/5! ≈ 1e-4 relative,
/// far inside the chord threshold (kChordThreshold, 1e-2), so the rod's endgame starts where its
/// steps converge; where it does not, Levenberg–Marquardt on the rod itself takes over
/// (solve_direct()). A comparison rod with fewer steps is the stage of the chord steps only.
constexpr int kMinGlobalSteps = 20;
/// Runge–Kutta steps along the rod.
int rk4_steps(const ClampedRod& rod) { return rod.intervals * rod.substeps; }
ClampedRod global_rod(const detail::ComparisonRod& compared) {
  ClampedRod rod = compared.rod;
  while (true) {
    const detail::ComparisonRod coarser = detail::comparison_rod(rod);
    if (!coarser.coarse || rk4_steps(coarser.rod) < kMinGlobalSteps) return rod;
    rod = coarser.rod;
  }
}

/// The coarse stage: the rod with steps two or more times as long (`stage`, global_rod()), that
/// much cheaper an integration, where a solve's global phase runs (coarse_phase()) and the chord
/// steps go down to the root of that coarser discretisation before the rod's own residual
/// finishes. When `stage` is the accuracy check's comparison rod (`compared`, steps twice as
/// long), the last coarse integration is kept: when the solve ends at its wrench, it is the
/// check's comparison run (step_doubling_error()), which then costs no integration.
struct CoarseStage {
  detail::ComparisonRod compared;
  ClampedRod stage;
  RodConfiguration work;  // integrate(compared.rod, w, Derivatives::None) when `holds`
  Vector6d w = Vector6d::Zero();
  bool holds = false;

  bool stage_is_compared() const {
    return stage.intervals == compared.rod.intervals && stage.substeps == compared.rod.substeps;
  }
};

/// The shooting residual as Eigen's Levenberg–Marquardt sees it. Every evaluation integrates with
/// tip derivatives and keeps the Jacobian, so that df() at an accepted point costs nothing (and
/// so does operator() at the cached point, e.g. minimizeInit() at the Euler predictor's point).
class ShootingProblem : public Eigen::DenseFunctor<double> {
 public:
  ShootingProblem(const ClampedRod& rod,
                  const TipCondition& tip,
                  RodConfiguration& work,
                  CoarseStage* coarse)
      : Eigen::DenseFunctor<double>(6, 6),
        rod_(rod),
        tip_(tip),
        work_(work),
        coarse_(coarse),
        row_scale_(residual_row_scale(rod, tip)),
        units_(rod.properties.bending_wrench_units()) {}

  int operator()(const InputType& w, ValueType& f) {
    if (!has_cache_ || Vector6d(w) != w_cached_) evaluate(w);
    // A non-finite shape is a very bad point, not an error: the trust region shrinks.
    if (residual_.allFinite()) {
      f = row_scale_.cwiseProduct(residual_);
    } else {
      f.setConstant(6, 1e150);
    }
    return 0;
  }

  int df(const InputType& w, JacobianType& J) {
    if (!has_cache_ || Vector6d(w) != w_cached_) evaluate(w);
    J = row_scale_.asDiagonal() * jacobian_;
    return 0;
  }

  /// The unscaled residual at w (re-using the last evaluation when it was at w).
  const Vector6d& residual_at(const Vector6d& w) {
    if (!has_cache_ || w != w_cached_) evaluate(w);
    return residual_;
  }
  int integrations() const { return integrations_; }
  /// Whether B ≈ dr/dw has full rank in the units of the trust region (rows scaled as the residual,
  /// columns in bending units): rank-revealing LU with Eigen's threshold (pivots above 6 ε times
  /// the largest). A Newton step along a direction the residual does not see (a Kirchhoff rod's
  /// axial force while it is straight) would otherwise be round-off amplified, not a step.
  bool invertible(const Matrix6d& B) const {
    return Eigen::FullPivLU<Matrix6d>(row_scale_.asDiagonal() * B * units_.asDiagonal())
        .isInvertible();
  }
  /// ||diag(row_scale) r||_∞: the residual in the units of the trust region.
  double scaled_norm(const Vector6d& r) const {
    return row_scale_.cwiseProduct(r).lpNorm<Eigen::Infinity>();
  }

  /// The cached evaluation (w, r, J), to come back to after a failed chord endgame.
  struct Snapshot {
    Vector6d w, r;
    Matrix6d J;
    bool valid;
  };
  Snapshot snapshot() const { return {w_cached_, residual_, jacobian_, has_cache_}; }
  void restore(const Snapshot& snap) {
    w_cached_ = snap.w, residual_ = snap.r, jacobian_ = snap.J, has_cache_ = snap.valid;
  }
  int jacobian_evaluations() const { return jacobian_evaluations_; }
  /// True when the work configuration holds integrate(rod, w, derivatives)'s values, bit for bit:
  /// the last integration was a chord step's (every node, no derivatives) at w and None is asked.
  /// The evaluations with derivatives store the tip only (Output::Tip).
  bool work_holds(const Vector6d& w, Derivatives derivatives) const {
    return integrations_ > 0 && derivatives == Derivatives::None &&
           work_derivatives_ == Derivatives::None && work_w_ == w;
  }

  /// The residual at w from a forward integration without derivatives (a chord step's check).
  const Vector6d& residual_without_jacobian(const Vector6d& w) {
    integrate(rod_, Wrench::from_vector(w), work_, Derivatives::None);
    work_w_ = w, work_derivatives_ = Derivatives::None;
    residual_ = shooting_residual(tip_, work_);
    has_cache_ = false;  // residual_ is at w, jacobian_ is not
    ++integrations_;
    return residual_;
  }

  bool has_coarse_stage() const { return coarse_ != nullptr; }
  /// The residual at w of the coarse stage's rod (CoarseStage), without derivatives.
  const Vector6d& coarse_residual(const Vector6d& w) {
    integrate(coarse_->stage, Wrench::from_vector(w), coarse_->work, Derivatives::None);
    coarse_->w = w, coarse_->holds = coarse_->stage_is_compared();
    residual_ = shooting_residual(tip_, coarse_->work);
    has_cache_ = false;
    ++integrations_;
    return residual_;
  }

 private:
  /// r and J need the tip only: the shape's other nodes and the energy are not stored.
  void evaluate(const Vector6d& w) {
    integrate(rod_, Wrench::from_vector(w), work_, Derivatives::Tip, Output::Tip);
    work_w_ = w, work_derivatives_ = Derivatives::Tip;
    shooting_residual(tip_, work_, residual_, jacobian_);
    w_cached_ = w;
    has_cache_ = true;
    ++integrations_;
    ++jacobian_evaluations_;
  }

  const ClampedRod& rod_;
  const TipCondition& tip_;
  RodConfiguration& work_;
  CoarseStage* coarse_;  // null: no coarse stage
  Vector6d row_scale_;
  Vector6d units_;  // the unknown's bending units (RodProperties::bending_wrench_units())
  Vector6d w_cached_ = Vector6d::Zero();
  Vector6d residual_ = Vector6d::Zero();
  Matrix6d jacobian_ = Matrix6d::Zero();
  Vector6d work_w_ = Vector6d::Zero();  // where work_ was last integrated, and with what
  Derivatives work_derivatives_ = Derivatives::None;
  bool has_cache_ = false;
  int integrations_ = 0;
  int jacobian_evaluations_ = 0;
};

/// Below this scaled residual (positions 1% of L, angles 0.01 rad) Newton's and quasi-Newton
/// steps take over from Levenberg–Marquardt.
constexpr double kChordThreshold = 1e-2;

/// Quasi-Newton steps from (w, r = r(w)) with B ≈ dr/dw: w ← w - B⁻¹ r, each checked by an
/// integration without derivatives (about a third of the cost of one with them) and accepted when
/// it halves the scaled residual; then B takes Broyden's rank-one update
/// B += (Δr - B Δw) Δwᵀ / (Δwᵀ Δw). Near the root this converges superlinearly without another
/// derivative integration. With a coarse stage (CoarseStage) the steps are checked on its rod in
/// up to kMaxCoarseRounds rounds, each down to its root, where one integration of the rod gives
/// the rod's residual and the next round's offset; a coarse step that fails to halve is checked
/// again on the rod, whose steps then go on. True when ||r||_∞ ≤ tolerance on the rod; false when
/// a step fails first (or after kMaxChordSteps steps). At most kMaxChordSteps + kMaxCoarseRounds +
/// 1 integrations. (w, r, B) end at the last accepted point either way.
bool broyden_steps(ShootingProblem& problem,
                   const ShootingOptions& options,
                   Matrix6d& B,
                   Vector6d& w,
                   Vector6d& r,
                   ShootingSummary& result,
                   const Vector6d* known_offset = nullptr) {
  constexpr int kMaxChordSteps = 8;
  constexpr int kMaxCoarseRounds = 3;
  // The coarse stage steps on r_c(w) + δ, with δ = r(w) − r_c(w) (the two discretisations'
  // difference, which hardly changes near the root) from the last point where both are known;
  // the first round, before any, with δ = 0 and only down to √(tolerance |r|), unless the caller
  // knows δ at w (`known_offset`).
  int coarse_rounds = problem.has_coarse_stage() ? 1 : 0;
  Vector6d offset = known_offset ? *known_offset : Vector6d::Zero();
  double round_tolerance =
      known_offset ? options.residual_tolerance
                   : std::max(options.residual_tolerance,
                              std::sqrt(options.residual_tolerance * r.lpNorm<Eigen::Infinity>()));
  for (int k = 0; k < kMaxChordSteps; ++k) {
    bool coarse = coarse_rounds > 0;
    if (!problem.invertible(B)) return false;
    const Eigen::PartialPivLU<Matrix6d> lu(B);
    const Vector6d step = -lu.solve(r);
    const Vector6d w_next = w + step;
    Vector6d r_next = coarse ? Vector6d(problem.coarse_residual(w_next) + offset)
                             : problem.residual_without_jacobian(w_next);
    ++result.chord_steps;
    const auto halves = [&] {
      return r_next.allFinite() && problem.scaled_norm(r_next) <= 0.5 * problem.scaled_norm(r);
    };
    if (coarse && !halves()) {  // the coarse rod too far from the rod: its own steps from here
      coarse = false, coarse_rounds = 0;
      r_next = problem.residual_without_jacobian(w_next);
    }
    if (!halves()) return false;
    B += (r_next - r - B * step) * step.transpose() / step.squaredNorm();  // Broyden
    w = w_next;
    r = r_next;
    result.residual_norm = r.lpNorm<Eigen::Infinity>();
    if (result.residual_norm > (coarse ? round_tolerance : options.residual_tolerance)) continue;
    if (!coarse) return true;
    // The coarse stage's root: the rod's own residual there, and δ from the two.
    const Vector6d r_coarse = r - offset;
    r = problem.residual_without_jacobian(w);
    if (!r.allFinite()) return false;
    result.residual_norm = r.lpNorm<Eigen::Infinity>();
    if (result.residual_norm <= options.residual_tolerance) return true;
    offset = r - r_coarse;
    coarse_rounds = coarse_rounds < kMaxCoarseRounds ? coarse_rounds + 1 : 0;
    round_tolerance = options.residual_tolerance;
  }
  return false;
}

/// The endgame near a root: Newton's step with the exact Jacobian J(x) at the last accepted point
/// of Levenberg–Marquardt on `lm_problem`, then Broyden's steps (broyden_steps()) on the rod's
/// problem: `rod_problem`, or `lm_problem` itself when null. With a `rod_problem` (the global
/// phase ran on the coarse stage's rod, coarse_phase()) J is the coarse rod's, within the
/// discretisation's O(h⁴) of the rod's, and where x is the coarse rod's root already the rod's
/// residual there gives the discretisations' difference for the steps. Returns true, with x at the
/// root and B the updated Jacobian there, when ||r||_∞ ≤ tolerance; false, with x and
/// `lm_problem`'s cache unchanged, when a step fails to halve the scaled residual first.
bool chord_endgame(ShootingProblem& lm_problem,
                   ShootingProblem* rod_problem,
                   const ShootingOptions& options,
                   Eigen::VectorXd& x,
                   Matrix6d& B,
                   ShootingSummary& result) {
  const ShootingProblem::Snapshot at_x = lm_problem.snapshot();
  ShootingProblem& problem = rod_problem ? *rod_problem : lm_problem;
  B = at_x.J;
  Vector6d w = x;
  Vector6d r = at_x.r;
  std::optional<Vector6d> offset;
  if (rod_problem && r.lpNorm<Eigen::Infinity>() <= options.residual_tolerance) {
    r = problem.residual_without_jacobian(w);
    result.residual_norm = r.lpNorm<Eigen::Infinity>();
    if (result.residual_norm <= options.residual_tolerance) return true;
    offset = r - at_x.r;
  }
  if (r.allFinite() &&
      broyden_steps(problem, options, B, w, r, result, offset ? &*offset : nullptr)) {
    x = w;
    return true;
  }
  lm_problem.restore(at_x);  // Levenberg–Marquardt goes on from x as if nothing happened
  result.residual_norm = at_x.r.lpNorm<Eigen::Infinity>();
  return false;
}

/// The predictor of a continuation substep (detail::SecantStart): from the guess w (the last
/// root) with the residual r of the new tip condition there and B ≈ dr/dw, Euler's step -B⁻¹ r is
/// the path's tangent times the step (dr/dw dw + ∂r/∂σ dσ = 0); the last substep's Euler error
/// (≈ ½ w'' dσ² on equal steps) added makes it of second order. The solve starts from the
/// predicted point when its residual (integrated with derivatives, which Levenberg–Marquardt's
/// first evaluation then re-uses) is smaller than r in the trust region's units; else from w.
/// Returns Euler's point (to measure its error at the root), empty when there is no prediction.
std::optional<Vector6d> predict(ShootingProblem& problem,
                                const detail::SecantStart& start,
                                Vector6d& w) {
  if (!start.residual_at_guess) return std::nullopt;
  const Vector6d& r = *start.residual_at_guess;
  const Eigen::PartialPivLU<Matrix6d> lu(start.jacobian);
  if (!r.allFinite() || !(std::abs(lu.determinant()) > 0.0)) return std::nullopt;
  const Vector6d euler = w - lu.solve(r);
  const Vector6d predicted = start.euler_error ? Vector6d(euler + *start.euler_error) : euler;
  const Vector6d& r_predicted = problem.residual_at(predicted);
  if (r_predicted.allFinite() && problem.scaled_norm(r_predicted) < problem.scaled_norm(r))
    w = predicted;
  return euler;
}

/// Without a predictor, Euler's point w - J⁻¹ r from the exact (r, J) at the guess w (the first
/// evaluation's, no integration): its distance from the root is the Euler error that makes the
/// next substep's predictor of second order. Empty when J is singular or r not finite.
std::optional<Vector6d> euler_point(ShootingProblem& problem, const Vector6d& w) {
  const ShootingProblem::Snapshot at_guess = problem.snapshot();
  if (!at_guess.valid || at_guess.w != w || !at_guess.r.allFinite()) return std::nullopt;
  const Eigen::PartialPivLU<Matrix6d> lu(at_guess.J);
  if (!(std::abs(lu.determinant()) > 0.0)) return std::nullopt;
  return Vector6d(w - lu.solve(at_guess.r));
}

/// Eigen's Levenberg–Marquardt set up for the shooting problem: it stops on our criterion only
/// (||r||_∞ ≤ residual_tolerance, so its own tolerances are 0), and its trust region is measured in
/// bending units of the unknown (forces in EI/L², moments in EI/L), starting at one such unit.
/// Column-norm scaling (MINPACK's default) lets the first step from a straight rod jump to an axial
/// force of order EA/L, because shortening by bending is of second order; the physical scale keeps
/// it to the bending forces that actually move the tip.
void configure(Eigen::LevenbergMarquardt<ShootingProblem>& lm,
               const ClampedRod& rod,
               const ShootingOptions& options) {
  lm.setFtol(0.0);
  lm.setXtol(0.0);
  lm.setGtol(0.0);
  lm.setMaxfev(20 * options.max_iterations);
  lm.setExternalScaling(true);
  lm.diag() = rod.properties.bending_wrench_units().cwiseInverse();
  lm.setFactor(1.0);
}

/// Sets the verdict "converged"; returns true.
bool converged_verdict(ShootingSummary& result) {
  result.status = SolveStatus::Converged;
  result.message = "converged";
  return true;
}

/// Where no Levenberg–Marquardt step reduces |r| any more at x: converged when ||r||_∞ is within
/// the tolerance there (B the Jacobian at x), else a local minimum of |r|² with r ≠ 0, where
/// Jᵀr = 0, so the Jacobian is singular (or the problem has no solution near the guess).
bool stalled(ShootingProblem& problem,
             const ShootingOptions& options,
             const Eigen::VectorXd& x,
             Matrix6d& B,
             ShootingSummary& result) {
  result.residual_norm = problem.residual_at(x).lpNorm<Eigen::Infinity>();
  if (result.residual_norm <= options.residual_tolerance) {
    B = problem.snapshot().J;
    return converged_verdict(result);
  }
  result.status = SolveStatus::Singular;
  result.message = "stalled at |r| = " + detail::format_value(result.residual_norm) +
                   ": the Jacobian is singular there, no step reduces the residual";
  return false;
}

/// Levenberg–Marquardt on `problem` from x (in: guess, out: last iterate), with the chord endgame
/// on `rod_problem` (chord_endgame(); the same problem when null). Returns whether it converged,
/// with B the Jacobian estimate at the root; the status says why not. `euler`, when given,
/// receives Euler's point from the first evaluation unless it holds one already (euler_point()).
/// On the coarse stage's rod (a `rod_problem` given) the coarse residual is never the answer and a
/// stall is not the rod's: it returns false where the endgame fails at the coarse rod's root or
/// the coarse iteration stalls. Each call has max_iterations.
bool levenberg_marquardt(ShootingProblem& problem,
                         ShootingProblem* rod_problem,
                         const ClampedRod& rod,
                         const ShootingOptions& options,
                         Eigen::VectorXd& x,
                         Matrix6d& B,
                         std::optional<Vector6d>* euler,
                         ShootingSummary& result) {
  Eigen::LevenbergMarquardt<ShootingProblem> lm(problem);
  configure(lm, rod, options);
  const bool coarse = rod_problem != nullptr;
  const Vector6d guess = x;
  auto lm_status = lm.minimizeInit(x);
  if (euler && !*euler) *euler = euler_point(problem, guess);
  bool tried_chord_here = false;
  int iterations = 0;  // this call's: each stage has max_iterations
  while (true) {
    const Vector6d& r = problem.residual_at(x);
    result.residual_norm =
        r.allFinite() ? r.lpNorm<Eigen::Infinity>() : std::numeric_limits<double>::infinity();
    if (!coarse && result.residual_norm <= options.residual_tolerance) {
      B = problem.snapshot().J;  // residual_at(x) integrated with derivatives at x
      return converged_verdict(result);
    }
    if (!x.allFinite()) {
      result.status = SolveStatus::Diverged;
      result.message = "the base wrench became non-finite";
      return false;
    }
    if (!tried_chord_here && r.allFinite() && problem.scaled_norm(r) <= kChordThreshold) {
      tried_chord_here = true;
      if (chord_endgame(problem, rod_problem, options, x, B, result))
        return converged_verdict(result);
      if (coarse && result.residual_norm <= options.residual_tolerance) return false;
      continue;
    }
    if (iterations >= options.max_iterations) {
      result.status = SolveStatus::IterationLimit;
      result.message = "reached solver.max_iterations = " + std::to_string(options.max_iterations);
      return false;
    }
    lm_status = lm.minimizeOneStep(x);
    ++iterations;
    ++result.iterations;
    tried_chord_here = false;
    using Eigen::LevenbergMarquardtSpace::Status;
    if (lm_status == Status::TooManyFunctionEvaluation) {
      result.status = SolveStatus::IterationLimit;
      result.message = "too many rejected steps";
      return false;
    }
    if (lm_status != Status::Running) return !coarse && stalled(problem, options, x, B, result);
  }
}

/// The global phase on the coarse stage's rod (CoarseStage): Levenberg–Marquardt from w with the
/// rod's endgame (chord_endgame()), with max_iterations of its own. True, with w at the rod's root
/// and B the estimate there, when that converges; else w is still the guess, from which the rod's
/// own Levenberg–Marquardt starts as if the stage had not been tried: where the coarse
/// discretisation misleads (a rod bent too much for its steps), the solve is no worse than the
/// rod's own, at the cost of the attempt.
bool coarse_phase(ShootingProblem& problem,
                  const ClampedRod& rod,
                  const TipCondition& tip,
                  const ShootingOptions& options,
                  CoarseStage& coarse,
                  Vector6d& w,
                  Matrix6d& B,
                  ShootingSummary& result) {
  RodConfiguration work;
  ShootingProblem on_coarse(coarse.stage, tip, work, nullptr);
  Eigen::VectorXd x = w;
  const bool converged =
      levenberg_marquardt(on_coarse, &problem, rod, options, x, B, nullptr, result);
  result.integrations += on_coarse.integrations();
  result.jacobian_evaluations += on_coarse.jacobian_evaluations();
  if (converged) w = x;
  return converged;
}

/// The direct solve from w (in: guess, out: last iterate): Levenberg–Marquardt with the chord
/// endgame from the predictor's point when a valid `secant` start gives one (predict()); else
/// from w, without `secant` first on the coarse stage's rod when there is one (coarse_phase()).
/// `secant` ends with the Jacobian estimate at the root when the solve converged (see
/// detail::SecantStart). `work_is_output`: true when `work` ends as integrate(rod, w,
/// options.output_derivatives) (the last integration was at the last iterate, with that level), so
/// the caller need not integrate again. `coarse`: the chord steps' coarse stage, or null.
ShootingSummary solve_direct(const ClampedRod& rod,
                             const TipCondition& tip,
                             const ShootingOptions& options,
                             RodConfiguration& work,
                             Vector6d& w,
                             bool& work_is_output,
                             detail::SecantStart* secant,
                             CoarseStage* coarse) {
  ShootingProblem problem(rod, tip, work, coarse);
  ShootingSummary result;
  Matrix6d B;  // the Jacobian estimate at the root, when converged
  std::optional<Vector6d> euler =
      secant && secant->valid ? predict(problem, *secant, w) : std::nullopt;
  if (secant) secant->valid = false;
  bool converged = false;
  // A solve of its own (not a continuation substep, whose first evaluation gives the next
  // substep's predictor) runs its global phase on the coarse stage's rod when that has the steps
  // for it (global_rod()).
  if (coarse && !secant && rk4_steps(coarse->stage) >= kMinGlobalSteps)
    converged = coarse_phase(problem, rod, tip, options, *coarse, w, B, result);
  if (!converged) {
    Eigen::VectorXd x = w;
    levenberg_marquardt(problem, nullptr, rod, options, x, B, secant ? &euler : nullptr, result);
    w = x;
  }
  if (secant && result.converged()) {
    secant->valid = true;
    secant->jacobian = B;
    secant->residual_at_guess.reset();
    secant->euler_error.reset();
    if (euler) secant->euler_error = w - *euler;
  }
  work_is_output = problem.work_holds(w, options.output_derivatives);
  result.integrations += problem.integrations();
  result.jacobian_evaluations += problem.jacobian_evaluations();
  return result;
}

/// The homotopy of the boundary-value problem: at σ = 0 the rod is unloaded and the tip is where
/// the unloaded rod puts it (w = 0 solves it exactly); at σ = 1 it is the problem asked. A held
/// tip moves along the screw motion T(σ) = T_rest exp(σ log(T_rest⁻¹ T_target)), which bends the
/// rod from the start; a straight line from the rest tip would first push a straight rod along its
/// axis, where only its stiff axial compliance answers (and a Kirchhoff rod cannot shorten at all).
/// A free tip's wrench and the distributed load are scaled by σ.
EquilibriumPath continuation_path(const Pose& rest_tip, const TipCondition& tip) {
  const auto screw = [rest_tip](const Pose& target, double t) {
    // ξ = (ρ, φ) = log(T_rest⁻¹ T_target):  φ = log(R_restᵀ R_target),  ρ = J_l(φ)⁻¹ R_restᵀ Δp
    const Eigen::Vector3d phi = log_so3(rest_tip.rotation.transpose() * target.rotation);
    const Eigen::Vector3d rho =
        left_jacobian_so3(phi).inverse() *
        (rest_tip.rotation.transpose() * (target.position - rest_tip.position));
    Pose pose;
    pose.rotation = rest_tip.rotation * exp_so3(t * phi);
    pose.position =
        rest_tip.position + rest_tip.rotation * (left_jacobian_so3(t * phi) * (t * rho));
    return pose;
  };
  return {[tip, screw](double t) {
            return std::visit(Overloaded{
                                  [&](const FreeTip& f) -> TipCondition {
                                    return FreeTip{{t * f.wrench.force, t * f.wrench.moment}};
                                  },
                                  [&](const ClampedTip& c) -> TipCondition {
                                    return ClampedTip{screw(c.pose, t)};
                                  },
                                  [&](const GraspedTip& g) -> TipCondition {
                                    return GraspedTip{screw(g.pose, t), g.released};
                                  },
                              },
                              tip);
          },
          true};
}

/// Continuation from the unloaded rod (adaptive steps in σ, secant predictor) after a failed
/// direct solve; on success w is the solution.
void continue_from_rest(const ClampedRod& rod,
                        const TipCondition& tip,
                        const ShootingOptions& options,
                        ShootingSummary& summary,
                        Vector6d& w) {
  ClampedRod unloaded = rod;
  unloaded.load.force *= 0.0;
  unloaded.load.moment *= 0.0;
  const Pose rest_tip = integrate(unloaded, BaseWrench{}).tip();
  FollowOptions follow;
  follow.shooting = options;
  // The homotopy's intermediate equilibria are only stepping stones: their accuracy check (and its
  // re-solves with up to max_substeps sub-steps at every step) took most of a failing solve's
  // time. The equilibrium at σ = 1 is checked by solve_equilibrium as a direct solve's is. (The
  // check off also leaves out the coarse stage; with it these steps were slower: BENCHMARKS.md.)
  follow.shooting.integration_tolerance = std::numeric_limits<double>::infinity();
  follow.adaptive = true;
  static_assert(ShootingOptions::kMaxContinuationSteps <= FollowOptions::kMaxSubsteps);
  follow.max_substeps = options.max_continuation_steps;
  follow.final_derivatives = Derivatives::None;
  const FollowResult followed =
      follow_equilibrium(rod, continuation_path(rest_tip, tip), BaseWrench{}, follow);
  const ShootingSummary& steps = followed.total;
  summary.iterations += steps.iterations;
  summary.chord_steps += steps.chord_steps;
  summary.integrations += steps.integrations;
  summary.jacobian_evaluations += steps.jacobian_evaluations;
  summary.continuation_steps += steps.continuation_steps;
  if (followed.followed()) {
    summary.status = steps.status;
    summary.message = steps.message;
    summary.residual_norm = steps.residual_norm;
    w = followed.base_wrench.to_vector();
  } else {
    summary.message += "; continuation stopped at t = " + detail::format_value(followed.sigma) +
                       " (" + steps.message + ")";
  }
}

/// out = work, which holds integrate(rod, w, derivatives)'s values (ShootingProblem::work_holds):
/// what integrate() into a fresh configuration gives, bit for bit (tip derivatives that an
/// integration with them left in `work` are zeroed when none are asked for).
void take_as_output(RodConfiguration& work, Derivatives derivatives, RodConfiguration& out) {
  out = std::move(work);
  out.derivatives = derivatives;
  if (derivatives != Derivatives::None) return;
  out.tip_dp_dw.setZero();
  out.tip_dtheta_dw.setZero();
  out.tip_dn_dw.setZero();
  out.tip_dm_dw.setZero();
  out.denergy_dw.setZero();
}

}  // namespace

namespace {

/// The two parts of estimated_failing_solve_seconds() (its comment has the measurements): the
/// iterations of a solve that does not converge, and the accuracy check's re-solves.
double iterations_seconds(const ClampedRod& rod, const ShootingOptions& options) {
  return 16.0 * options.max_iterations * static_cast<double>(rod.intervals) * 2.9e-7;
}
double substeps_seconds(const ClampedRod& rod, const ShootingOptions& options) {
  return 2.0e-5 * options.max_substeps * static_cast<double>(rod.intervals);
}

}  // namespace

double estimated_failing_solve_seconds(const ClampedRod& rod, const ShootingOptions& options) {
  // Not × rod.substeps: the accuracy check's re-solves (with more sub-steps, the same options)
  // must pass this check as the first solve did.
  return iterations_seconds(rod, options) + substeps_seconds(rod, options);
}

void check_solve_cost(const ClampedRod& rod, const ShootingOptions& options) {
  const double seconds = estimated_failing_solve_seconds(rod, options);
  if (seconds <= kMaxEstimatedSolveSeconds) return;
  const bool by_iterations = iterations_seconds(rod, options) >= substeps_seconds(rod, options);
  throw InputError(
      by_iterations ? "ShootingOptions.max_iterations" : "ShootingOptions.max_substeps",
      " = " + std::to_string(by_iterations ? options.max_iterations : options.max_substeps) +
          " with " + std::to_string(rod.nodes()) + " rod nodes: a solve could take about " +
          detail::format_value(std::round(seconds)) + " s (" +
          detail::format_value(std::round(iterations_seconds(rod, options))) +
          " s to fail in ShootingOptions.max_iterations = " +
          std::to_string(options.max_iterations) + ", " +
          detail::format_value(std::round(substeps_seconds(rod, options))) +
          " s for ShootingOptions.max_substeps = " + std::to_string(options.max_substeps) +
          "); at most " + detail::format_value(kMaxEstimatedSolveSeconds) +
          " s (docs/limits.md): lower one of them");
}

ShootingResult solve_equilibrium(const ClampedRod& rod,
                                 const TipCondition& tip,
                                 const BaseWrench& guess,
                                 const ShootingOptions& options) {
  return detail::solve_equilibrium(rod, tip, guess, options, nullptr);
}

ShootingResult detail::solve_equilibrium(const ClampedRod& rod,
                                         const TipCondition& tip,
                                         const BaseWrench& guess,
                                         const ShootingOptions& options,
                                         SecantStart* secant) {
  rod.validate();
  validate_tip(tip);
  options.validate();
  check_solve_cost(rod, options);
  require_magnitude_at_most("guess.force", guess.force, bounds::kMaxForce, "N");
  require_magnitude_at_most("guess.moment", guess.moment, bounds::kMaxForce, "N*m");

  ShootingResult solution;
  ShootingSummary& summary = solution.summary;
  RodConfiguration work;
  work.resize(rod.nodes(), Derivatives::Tip);

  // The coarse stage where the accuracy check will compare with longer steps (CoarseStage).
  std::optional<CoarseStage> coarse;
  if (std::isfinite(options.integration_tolerance)) {
    detail::ComparisonRod compared = detail::comparison_rod(rod);
    if (compared.coarse) {
      coarse.emplace().stage = global_rod(compared);
      coarse->compared = std::move(compared);
    }
  }

  Vector6d w = guess.to_vector();
  bool work_is_output = false;
  summary =
      solve_direct(rod, tip, options, work, w, work_is_output, secant, coarse ? &*coarse : nullptr);

  if (!summary.converged() && options.continuation) {
    continue_from_rest(rod, tip, options, summary, w);
    work_is_output = false;
  }

  solution.base_wrench = Wrench::from_vector(w);
  // The last integration is usually the output asked for (a chord step's, without derivatives):
  // then it is the result, else one more integration makes it.
  // The check's comparison run is the coarse stage's last integration when it was at w.
  std::optional<double> integration_error;
  if (work_is_output) {
    take_as_output(work, options.output_derivatives, solution.configuration);
    if (coarse && coarse->holds && coarse->w == w)
      integration_error =
          detail::step_doubling_error(rod, solution.configuration, coarse->compared, coarse->work);
  } else {
    integrate(rod, solution.base_wrench, solution.configuration, options.output_derivatives);
  }
  // finite, accurate, or a status
  detail::confirm_converged(rod, tip, options, solution, integration_error);
  if (secant && !solution.summary.converged()) secant->valid = false;
  return solution;
}

}  // namespace rodshape
