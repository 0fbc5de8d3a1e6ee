// follow_equilibrium.cpp: continuation of the held rod's equilibrium along a path of boundary
// conditions (see follow_equilibrium.hpp).
#include "rodshape/solvers/follow_equilibrium.hpp"

#include "rodshape/core/strain_extremes.hpp"

#include <algorithm>
#include <sstream>

#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/error.hpp"
#include "rodshape/solvers/shooting_residual.hpp"
#include "secant_start.hpp"
#include "validation.hpp"

namespace rodshape {

void FollowOptions::validate() const {
  detail::require_count("FollowOptions.substeps", substeps, 1, kMaxSubsteps);
  detail::require_count("FollowOptions.max_substeps", max_substeps, 1, kMaxSubsteps);
  detail::require_positive("FollowOptions.initial_step", initial_step);
  if (arrival_stability && final_derivatives != Derivatives::AllNodes)
    throw InputError("FollowOptions.arrival_stability",
                     ": the stability test needs final_derivatives = AllNodes");
  shooting.validate();
}

std::string to_string(FollowEvent event) { return std::string(name_of(kFollowEventNames, event)); }

std::string FollowResult::brief() const {
  std::ostringstream out;
  if (followed())
    out << "followed to the end in " << states.size() << " substeps";
  else
    out << to_string(event) << " at sigma = " << sigma << ": " << message;
  out << " (" << total.iterations << " iterations, " << total.integrations << " integrations)";
  return out.str();
}

EquilibriumPath held_tip_path(const Pose& from,
                              const Pose& to,
                              const std::array<bool, 6>& released) {
  const bool grasped = std::any_of(released.begin(), released.end(), [](bool b) { return b; });
  return {[from, to, released, grasped](double sigma) -> TipCondition {
            const Pose pose = interpolate(from, to, sigma);
            if (grasped) return GraspedTip{pose, released};
            return ClampedTip{pose};
          },
          false};
}

EquilibriumPath sampled_tip_path(std::vector<TipCondition> samples) {
  if (samples.size() < 2)
    throw InputError("samples",
                     ": a sampled tip path needs at least 2 samples (the start and one)");
  const double last = static_cast<double>(samples.size() - 1);
  return {[samples = std::move(samples), last](double sigma) {
            const auto k = static_cast<std::size_t>(
                std::clamp(std::lround(sigma * last), 0L, static_cast<long>(last)));
            return samples[k];
          },
          false};
}

double node_deviation(const RodConfiguration& a, const RodConfiguration& b) {
  double worst = 0.0;
  for (int i = 0; i < std::min(a.nodes(), b.nodes()); ++i)
    worst = std::max(worst, (a.p[i] - b.p[i]).norm());
  return worst;
}

namespace {

/// Adds the work counts of one substep's solve to `total`.
void add_substep_counts(ShootingSummary& total, const ShootingSummary& part) {
  total.iterations += part.iterations;
  total.chord_steps += part.chord_steps;
  total.integrations += part.integrations;
  total.jacobian_evaluations += part.jacobian_evaluations;
  ++total.continuation_steps;
  total.status = part.status;
  total.message = part.message;
  total.residual_norm = part.residual_norm;
}

/// The rod at σ: with ramp_loads its distributed load scaled by σ; with clamp_at, its clamp there.
ClampedRod rod_at(const ClampedRod& rod, const EquilibriumPath& path, double sigma) {
  ClampedRod scaled = rod;
  if (path.ramp_loads) {
    scaled.load.force *= sigma;
    scaled.load.moment *= sigma;
  }
  if (path.clamp_at) scaled.clamp = path.clamp_at(sigma);
  return scaled;
}

/// The base wrench w of the equilibrium at σ = `from` as the start of the solve at `to`: with a
/// moving clamp, turned by R(to) R(from)ᵀ, so that it is the same in the base's frame.
BaseWrench carried(const EquilibriumPath& path, double from, double to, const BaseWrench& w) {
  if (!path.clamp_at) return w;
  const Eigen::Matrix3d turn =
      path.clamp_at(to).rotation * path.clamp_at(from).rotation.transpose();
  return {turn * w.force, turn * w.moment};
}

/// One substep: the direct solve at σ from `guess`, with the derivatives `derivatives` (and the
/// last substep's Jacobian estimate when `secant` is given and valid).
ShootingResult solve_at(const ClampedRod& rod,
                        const EquilibriumPath& path,
                        double sigma,
                        const BaseWrench& guess,
                        ShootingOptions shooting,
                        Derivatives derivatives,
                        detail::SecantStart* secant = nullptr) {
  shooting.continuation = false;  // a failure here is what the caller wants to see
  shooting.output_derivatives = derivatives;
  return detail::solve_equilibrium(rod_at(rod, path, sigma), path.tip_at(sigma), guess, shooting,
                                   secant);
}

/// The Euler predictor's data for the substep to σ from the last one (whose root `result` holds):
/// with the rod unchanged along the path (no moving clamp, no ramped load) and the last shape
/// integrated on the rod's own sub-steps, the new tip condition's residual at the last root is
/// that shape's residual, no integration needed; -B⁻¹ r is then the path's tangent dw/dσ Δσ
/// (dr/dw dw + ∂r/∂σ Δσ = 0), the solve's Euler predictor.
void predict(const ClampedRod& rod,
             const EquilibriumPath& path,
             double sigma,
             const FollowResult& result,
             detail::SecantStart& secant) {
  secant.residual_at_guess.reset();
  if (!secant.valid || path.clamp_at || path.ramp_loads || result.states.empty()) return;
  if (result.states.back().solve.substeps != rod.substeps) return;
  secant.residual_at_guess = shooting_residual(path.tip_at(sigma), result.configuration);
}

/// The rod as the solve integrated it (with the sub-steps its accuracy check asked for).
ClampedRod with_substeps(const ClampedRod& rod, const ShootingSummary& solved) {
  ClampedRod copy = rod;
  copy.substeps = solved.substeps;
  return copy;
}

/// Records an accepted substep; false (with the event set) when it is unstable and stability is
/// assessed at every substep.
bool accept(const ClampedRod& rod,
            const EquilibriumPath& path,
            const FollowOptions& options,
            double sigma,
            ShootingResult&& solved,
            FollowResult& result) {
  FollowedState state{sigma,
                      solved.base_wrench,
                      solved.configuration.tip(),
                      solved.configuration.tip_wrench(),
                      solved.configuration.energy,
                      strain_extremes(rod.properties, solved.configuration).max_curvature,
                      solved.summary,
                      std::nullopt};
  if (options.stability_every_substep)
    state.stability = assess_stability(with_substeps(rod_at(rod, path, sigma), solved.summary),
                                       solved.configuration);
  const bool unstable = state.stability && !state.stability->stable && !state.stability->degenerate;
  const bool stopped = options.observer && !options.observer(sigma, solved.configuration);
  result.sigma = sigma;
  result.base_wrench = solved.base_wrench;
  result.configuration = std::move(solved.configuration);
  result.states.push_back(std::move(state));
  if (unstable) {
    result.event = FollowEvent::Unstable;
    result.event_sigma = sigma;
    result.message = "the equilibrium at sigma = " + detail::format_value(sigma) + " is unstable";
  } else if (stopped) {
    result.event = FollowEvent::Stopped;
    result.event_sigma = sigma;
    result.message = "stopped by the observer at sigma = " + detail::format_value(sigma);
  }
  return !unstable && !stopped;
}

/// σ_j = j / substeps; the first failure ends the path.
void follow_fixed(const ClampedRod& rod,
                  const EquilibriumPath& path,
                  const FollowOptions& options,
                  FollowResult& result) {
  const Derivatives every =
      options.stability_every_substep ? Derivatives::AllNodes : Derivatives::None;
  detail::SecantStart secant;         // the Jacobian estimate carried from substep to substep
  const bool carry = !path.clamp_at;  // with a moving clamp w turns, and its Jacobian with it
  for (int j = 1; j <= options.substeps; ++j) {
    const double sigma = static_cast<double>(j) / options.substeps;
    const Derivatives derivatives = j == options.substeps ? options.final_derivatives : every;
    const BaseWrench guess = carried(path, result.sigma, sigma, result.base_wrench);
    predict(rod, path, sigma, result, secant);
    ShootingResult solved =
        solve_at(rod, path, sigma, guess, options.shooting, derivatives, carry ? &secant : nullptr);
    add_substep_counts(result.total, solved.summary);
    if (!solved.summary.converged()) {
      result.event = FollowEvent::Lost;
      result.event_sigma = sigma;
      result.failed_solve = solved.summary;
      result.message =
          "the equilibrium could not be followed at sigma = " + detail::format_value(sigma) + " (" +
          solved.summary.brief() + ")";
      return;
    }
    if (!accept(rod, path, options, sigma, std::move(solved), result)) return;
  }
}

/// Steps doubled after a success and halved after a failure, with a secant predictor.
void follow_adaptive(const ClampedRod& rod,
                     const EquilibriumPath& path,
                     const FollowOptions& options,
                     FollowResult& result) {
  const Derivatives every =
      options.stability_every_substep ? Derivatives::AllNodes : Derivatives::None;
  Vector6d w_solved = result.base_wrench.to_vector(), w_previous = w_solved;
  double t = 0.0, dt = options.initial_step, dt_previous = 0.0;
  const double dt_min = 1.0 / options.max_substeps;
  while (t < 1.0) {
    dt = std::min(dt, 1.0 - t);
    const double t_next = t + dt;
    Vector6d w_step = w_solved;
    if (dt_previous > 0.0) w_step += (w_solved - w_previous) * (dt / dt_previous);  // secant
    const Derivatives derivatives = t_next >= 1.0 ? options.final_derivatives : every;
    ShootingResult solved =
        solve_at(rod, path, t_next, carried(path, t, t_next, Wrench::from_vector(w_step)),
                 options.shooting, derivatives);
    add_substep_counts(result.total, solved.summary);
    if (solved.summary.converged()) {
      w_previous = w_solved;
      w_solved = solved.base_wrench.to_vector();
      dt_previous = dt;
      t = t_next;
      dt *= 2.0;
      if (!accept(rod, path, options, t, std::move(solved), result)) return;
    } else if (dt * 0.5 >= dt_min) {
      dt *= 0.5;
    } else {
      result.event = FollowEvent::Lost;
      result.event_sigma = t_next;
      result.failed_solve = solved.summary;
      result.message =
          "the equilibrium could not be followed beyond sigma = " + detail::format_value(t) + " (" +
          solved.summary.message + ")";
      return;
    }
  }
}

/// After an event on the way: the last followed equilibrium (the start when none was) with
/// final_derivatives, as on arrival (the last accepted substep carried the derivatives of the
/// substeps, and a first substep that failed left none).
void keep_last_equilibrium(const ClampedRod& rod,
                           const EquilibriumPath& path,
                           const FollowOptions& options,
                           FollowResult& result) {
  if (result.configuration.nodes() == rod.nodes() &&
      result.configuration.derivatives == options.final_derivatives)
    return;
  const ClampedRod at = rod_at(rod, path, result.sigma);
  integrate(result.states.empty() ? at : with_substeps(at, result.states.back().solve),
            result.base_wrench, result.configuration, options.final_derivatives);
}

/// On arrival: the expected equilibrium (else another branch), then stable (else unstable).
void check_arrival(const ClampedRod& rod,
                   const FollowOptions& options,
                   const RodConfiguration* expected,
                   double branch_tolerance,
                   FollowResult& result) {
  result.event_sigma = 1.0;
  if (expected) {
    result.arrival_deviation = node_deviation(result.configuration, *expected);
    if (result.arrival_deviation > branch_tolerance) {
      result.event = FollowEvent::OtherBranch;
      result.message = "on arrival the rod is " + detail::format_value(result.arrival_deviation) +
                       " m from the expected equilibrium: it went over to another branch";
      return;
    }
  }
  if (!options.arrival_stability) return;
  result.arrival_stability =
      assess_stability(with_substeps(rod, result.states.back().solve), result.configuration);
  if (!result.arrival_stability->stable && !result.arrival_stability->degenerate) {
    result.event = FollowEvent::Unstable;
    result.message = "the equilibrium on arrival is unstable";
  }
}

}  // namespace

FollowResult follow_equilibrium(const ClampedRod& rod,
                                const EquilibriumPath& path,
                                const BaseWrench& start,
                                const FollowOptions& options,
                                const RodConfiguration* expected,
                                double branch_tolerance) {
  options.validate();
  rod.validate();
  if (!path.tip_at) throw InputError("EquilibriumPath.tip_at", ": no tip condition is given");
  detail::require_finite("start.force", start.force);
  detail::require_finite("start.moment", start.moment);

  FollowResult result;
  result.base_wrench = start;
  result.total.status = SolveStatus::Converged;
  result.total.message = "converged";
  result.message = "followed to the end";
  if (options.adaptive)
    follow_adaptive(rod, path, options, result);
  else
    follow_fixed(rod, path, options, result);
  // Checked invariant: a path followed to the end ends on a finite shape (each accepted solve
  // converged, and converged solves are finite: solve_equilibrium checks it).
  if (result.followed() && !result.configuration.finite()) {
    result.event = FollowEvent::Lost;
    result.event_sigma = result.sigma;
    result.message = "the followed shape is not finite (NaN or infinite values)";
  }
  if (result.followed())
    check_arrival(rod_at(rod, path, 1.0), options, expected, branch_tolerance, result);
  else
    keep_last_equilibrium(rod, path, options, result);
  return result;
}

}  // namespace rodshape
