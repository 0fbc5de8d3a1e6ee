// unconstrained_newton.cpp: Newton's method with IPOPT's inertia correction and Armijo line search
// for a ShapeProblem without rows or bounds (see the header for what is kept from IPOPT and why).
#include "optimisation/unconstrained_newton.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <limits>

namespace rodshape::detail {

namespace {

// IPOPT's defaults for the options named in the header.
constexpr double kMaxGradient = 100.0;                // nlp_scaling_max_gradient
constexpr double kMinScaling = 1e-8;                  // nlp_scaling_min_value
constexpr double kDualInfeasibilityTol = 1.0;         // dual_inf_tol (unscaled)
constexpr double kAcceptableTol = 1e-6;               // acceptable_tol
constexpr int kAcceptableIterations = 15;             // acceptable_iter
constexpr double kDivergingIterates = 1e20;           // diverging_iterates_tol
constexpr double kFirstPerturbation = 1e-4;           // first_hessian_perturbation
constexpr double kPerturbationDecrease = 1.0 / 3.0;   // perturb_dec_fact
constexpr double kPerturbationIncreaseFirst = 100.0;  // perturb_inc_fact_first
constexpr double kPerturbationIncrease = 8.0;         // perturb_inc_fact
constexpr double kMinPerturbation = 1e-20;            // min_hessian_perturbation
constexpr double kMaxPerturbation = 1e40;             // max_hessian_perturbation
constexpr double kArmijo = 1e-8;                      // eta_phi
constexpr double kBacktrack = 0.5;                    // alpha_red_factor
/// NlpOutcome::kMaxRefusals: refused trial points after which the optimum lies beyond the rod's
/// scale (ipopt_nlp.hpp; IPOPT's run is stopped by the intermediate callback).
constexpr int kMaxRefusals = 20;
constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

/// The unknowns, F and ∇F at the current iterate.
struct Iterate {
  Vector6d w;
  double cost = 0.0;
  Vector6d gradient;
};

class Newton {
 public:
  Newton(ShapeProblem& problem, const std::optional<WrenchBounds>& admissible)
      : problem_(problem), admissible_(admissible) {}

  int refusals() const { return refusals_; }

  /// F and ∇F at w, or false when w is refused (outside the admissible box) or either is not
  /// finite (IPOPT's eval_f / eval_grad_f returning false).
  bool evaluate(const Vector6d& w, Iterate& at) {
    if (admissible_ && ((w.array() < admissible_->lower.array()).any() ||
                        (w.array() > admissible_->upper.array()).any())) {
      ++refusals_;
      return false;
    }
    problem_.evaluate(w);
    at.w = w;
    at.cost = problem_.cost();
    at.gradient = problem_.cost_gradient();
    return std::isfinite(at.cost) && at.gradient.allFinite();
  }

  /// The model B of ∇²F: differenced at `at` (false when a gradient is not finite), or updated by
  /// the SR1 formula with the step just taken from `from` to `to`.
  bool difference_model(const Iterate& at) {
    differenced_ = hessian(at, model_);
    return differenced_;
  }
  void update_model(const Iterate& from, const Iterate& to) {
    sr1_update(to.w - from.w, to.gradient - from.gradient, model_);
    differenced_ = false;
  }
  const Matrix6d& model() const { return model_; }
  /// Whether the model is a fresh difference, not yet updated.
  bool model_differenced() const { return differenced_; }

  /// ∇²F by forward differences of ∇F, symmetrised, with ShapeNlp::eval_h's steps
  /// h_j = √ε max(|w_j|, unit_j) (the bending wrench units); false when a gradient is not finite.
  bool hessian(const Iterate& at, Matrix6d& H) {
    const Vector6d units = problem_.rod().properties.bending_wrench_units();
    for (int j = 0; j < 6; ++j) {
      const double h = std::sqrt(kEpsilon) * std::max(std::abs(at.w[j]), units[j]);
      Vector6d shifted = at.w;
      shifted[j] += h;
      problem_.evaluate(shifted);
      if (!problem_.cost_gradient().allFinite()) return false;
      H.col(j) = (problem_.cost_gradient() - at.gradient) / h;
    }
    H = 0.5 * (H + H.transpose()).eval();
    return true;
  }

  /// The Newton step d = -(H + δ I)⁻¹ g with IPOPT's choice of δ (header); false when no δ up to
  /// kMaxPerturbation makes H + δ I positive definite.
  bool step(const Matrix6d& H, const Vector6d& g, Vector6d& d) {
    Eigen::LLT<Matrix6d> llt(H);
    double delta = 0.0;
    if (llt.info() != Eigen::Success) {
      delta = last_delta_ == 0.0 ? kFirstPerturbation
                                 : std::max(kMinPerturbation, kPerturbationDecrease * last_delta_);
      const double grow = last_delta_ == 0.0 ? kPerturbationIncreaseFirst : kPerturbationIncrease;
      for (;; delta *= grow) {
        if (delta > kMaxPerturbation) return false;
        llt.compute(H + delta * Matrix6d::Identity());
        if (llt.info() == Eigen::Success) break;
      }
      last_delta_ = delta;
    }
    d = -llt.solve(g);
    return d.allFinite();
  }

 private:
  ShapeProblem& problem_;
  const std::optional<WrenchBounds>& admissible_;
  int refusals_ = 0;
  double last_delta_ = 0.0;  // the last nonzero δ (IPOPT's delta_x_last)
  Matrix6d model_ = Matrix6d::Zero();
  bool differenced_ = false;
};

/// s_f: F scaled so that its gradient at the start is at most kMaxGradient in the max-norm.
double objective_scaling(const Vector6d& gradient) {
  const double largest = gradient.lpNorm<Eigen::Infinity>();
  return largest > kMaxGradient ? std::max(kMinScaling, kMaxGradient / largest) : 1.0;
}

IpoptRun ended(IpoptEnd end, const Iterate& at, int iterations, bool beyond_scale) {
  IpoptRun run = run_ended(end);
  run.details.solver = "dense Newton";
  run.details.iterations = iterations;
  run.details.objective = at.cost;
  run.details.beyond_scale = beyond_scale;
  run.w = at.w;
  return run;
}

enum class Search { Accepted, Refused, TooSmall };

/// IPOPT's backtracking line search on φ = s_f F along d from `at`: α = 1, halved until Armijo's
/// condition holds, compared with a round-off allowance of 10 ε |φ| (IPOPT's Compare_le); the
/// accepted point into `trial`. TooSmall when α d falls below round-off of w first, Refused when
/// the refusals reach kMaxRefusals.
Search line_search(Newton& newton,
                   const Iterate& at,
                   const Vector6d& d,
                   double scaling,
                   Iterate& trial,
                   double& alpha) {
  const double slope = scaling * at.gradient.dot(d);
  const double phi = scaling * at.cost;
  for (alpha = 1.0;; alpha *= kBacktrack) {
    if (alpha * d.lpNorm<Eigen::Infinity>() <=
        10.0 * kEpsilon * (1.0 + at.w.lpNorm<Eigen::Infinity>()))
      return Search::TooSmall;
    if (newton.refusals() >= kMaxRefusals) return Search::Refused;
    if (!newton.evaluate(at.w + alpha * d, trial)) continue;
    if (scaling * trial.cost - phi <= kArmijo * alpha * slope + 10.0 * kEpsilon * std::abs(phi))
      return Search::Accepted;
  }
}

}  // namespace

// Unlike BFGS, SR1 keeps B indefinite where ∇²F is, which the inertia correction then treats as it
// treats the differenced Hessian.
void sr1_update(const Vector6d& s, const Vector6d& y, Matrix6d& B) {
  constexpr double kSr1Skip = 1e-8;
  const Vector6d r = y - B * s;
  const double denominator = r.dot(s);
  if (!std::isfinite(denominator) || std::abs(denominator) <= kSr1Skip * s.norm() * r.norm())
    return;                                          // also r = 0: B s = y already
  B.noalias() += (r * r.transpose()) / denominator;  // r_i r_j = r_j r_i: B stays symmetric
}

bool unconstrained_newton_serves(const ShapeProblem& problem, bool finite_difference_hessian) {
  const WrenchBounds& bounds = problem.wrench_bounds();
  return finite_difference_hessian && !problem.base_moves() && problem.constraint_count() == 0 &&
         !bounds.lower.array().isFinite().any() && !bounds.upper.array().isFinite().any();
}

IpoptRun unconstrained_newton(ShapeProblem& problem,
                              const Vector6d& start,
                              const ShapeOptimiserOptions& options,
                              const std::optional<WrenchBounds>& admissible,
                              HessianModel hessian_model) {
  bool difference_next = true;  // the model at the start is differenced
  Newton newton(problem, admissible);
  Iterate at, trial;
  at.w = start;
  if (!newton.evaluate(start, at)) return ended(IpoptEnd::InvalidNumberDetected, at, 0, false);
  const double scaling = objective_scaling(at.gradient);
  int acceptable = 0;
  std::optional<Iterate> last_acceptable;  // IPOPT's acceptable_iterate_
  for (int iteration = 0;; ++iteration) {
    // IPOPT's order: the intermediate callback, then optimality, acceptability, divergence and
    // the iteration limit.
    if (newton.refusals() >= kMaxRefusals)
      return ended(IpoptEnd::UserRequestedStop, at, iteration, true);
    const double dual = at.gradient.lpNorm<Eigen::Infinity>();
    if (scaling * dual <= options.tolerance && dual <= kDualInfeasibilityTol)
      return ended(IpoptEnd::SolveSucceeded, at, iteration, false);
    acceptable = scaling * dual <= kAcceptableTol ? acceptable + 1 : 0;
    if (acceptable > 0) last_acceptable = at;
    if (acceptable >= kAcceptableIterations)
      return ended(IpoptEnd::SolvedToAcceptableLevel, at, iteration, false);
    if (at.w.lpNorm<Eigen::Infinity>() > kDivergingIterates)
      return ended(IpoptEnd::DivergingIterates, at, iteration, false);
    if (iteration >= options.max_iterations)
      return ended(IpoptEnd::MaximumIterationsExceeded, at, iteration, false);

    // The model: differenced at the start, then SR1-updated or differenced anew (difference_next).
    if (difference_next && !newton.difference_model(at))
      return ended(IpoptEnd::InvalidNumberDetected, at, iteration, false);
    Search search = Search::TooSmall;
    double alpha = 1.0;
    for (;;) {
      Vector6d d;
      const bool stepped = newton.step(scaling * newton.model(), scaling * at.gradient, d);
      if (stepped) search = line_search(newton, at, d, scaling, trial, alpha);
      if ((stepped && search != Search::TooSmall) || newton.model_differenced()) {
        if (!stepped) return ended(IpoptEnd::ErrorInStepComputation, at, iteration, false);
        break;
      }
      // An updated model may point nowhere useful: the step again from a fresh difference.
      if (!newton.difference_model(at))
        return ended(IpoptEnd::InvalidNumberDetected, at, iteration, false);
    }
    if (search == Search::Refused) return ended(IpoptEnd::UserRequestedStop, at, iteration, true);
    if (search == Search::TooSmall)
      return last_acceptable
                 ? ended(IpoptEnd::SolvedToAcceptableLevel, *last_acceptable, iteration, false)
                 : ended(IpoptEnd::SearchDirectionBecomesTooSmall, at, iteration, false);
    // Sr1UntilBacktrack: a step the line search had to shorten says the model is poor there.
    difference_next = hessian_model == HessianModel::DifferencedEveryIteration ||
                      (hessian_model == HessianModel::Sr1UntilBacktrack && alpha < 1.0);
    if (!difference_next) newton.update_model(at, trial);
    at = trial;
  }
}

}  // namespace rodshape::detail
