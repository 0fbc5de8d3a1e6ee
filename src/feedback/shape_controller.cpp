// shape_controller.cpp: at each checkpoint, an estimate and perhaps a re-plan of the rest
// (shape_controller.hpp).
#include "rodshape/feedback/shape_controller.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "replan_gentleness.hpp"
#include "rodshape/error.hpp"
#include "rodshape/feedback/cloud_estimator.hpp"
#include "rodshape/trajectory/plan.hpp"

namespace rodshape {

namespace {

void ensure_waypoint_ahead(const std::vector<PlannedWaypoint>& remaining) {
  if (remaining.size() < 2)
    throw InputError("ShapeController.update",
                     ": the arm is at the plan's last waypoint; nothing is left to control");
}

}  // namespace

void ClosedLoopOptions::validate() const {
  estimation.validate();
  if (!std::isfinite(significance))
    throw InputError("ClosedLoopOptions.significance", " must be finite");
  if (!(max_residual > 0.0) || !std::isfinite(max_residual))
    throw InputError("ClosedLoopOptions.max_residual", " must be finite and > 0");
  if (!(max_energy_ratio >= 1.0) || !std::isfinite(max_energy_ratio))
    throw InputError("ClosedLoopOptions.max_energy_ratio", " must be finite and >= 1");
  if (horizon < 0 || horizon > PlanOptions::kMaxSteps)
    throw InputError("ClosedLoopOptions.horizon", " = " + std::to_string(horizon) +
                                                      " must be in [0, " +
                                                      std::to_string(PlanOptions::kMaxSteps) + "]");
  if (checkpoint_frames < 1 || checkpoint_frames > 1000)
    throw InputError("ClosedLoopOptions.checkpoint_frames",
                     " = " + std::to_string(checkpoint_frames) + " must be in [1, 1000]");
  if (!(grasp_offset_position_sigma > 0.0) || !std::isfinite(grasp_offset_position_sigma))
    throw InputError("ClosedLoopOptions.grasp_offset_position_sigma", " must be finite and > 0");
  if (!(grasp_offset_rotation_sigma > 0.0) || !std::isfinite(grasp_offset_rotation_sigma))
    throw InputError("ClosedLoopOptions.grasp_offset_rotation_sigma", " must be finite and > 0");
}

ShapeController::ShapeController(const PlanProblem& problem,
                                 const PlanResult& plan,
                                 const PlanOptions& planning,
                                 const ClosedLoopOptions& options)
    : problem_(problem), planning_(planning), options_(options) {
  options_.validate();
  if (plan.end_effector_path.empty() || plan.steps.empty())
    throw InputError("PlanResult.steps", ": the plan has no step to carry out");
  if (plan.arm) shell_ = plan.arm->shell;
  if (plan.base_arm) base_shell_ = plan.base_arm->shell;
  clamp_now_ = problem_.rod.clamp;
  // A plan without a base path (one made before plan() moved the base) holds it at rod.clamp.
  base_moves_ = problem_.moving_base.has_value() && !plan.base_end_effector_path.empty();
  for (const PlanStep& step : plan.steps) remaining_.push_back(planned_waypoint(step));
  fresh_ = static_cast<int>(plan.steps.size());
}

ControllerOutput ShapeController::update(const MarkerMeasurement& measurement,
                                         const ArmState& arm) {
  ensure_waypoint_ahead(remaining_);
  measurement.sensor.validate();
  return update_with(measurement.frame.t, arm,
                     [&](const ClampedRod& model, const Pose& tip, const Pose& end_effector,
                         const StatePrior& prior, const EstimationOptions& options,
                         const StateHypothesis& hypothesis) {
                       return estimate_state(model, tip, end_effector, measurement.frame,
                                             measurement.sensor, prior, options, hypothesis);
                     });
}

ControllerOutput ShapeController::update(const CloudMeasurement& measurement, const ArmState& arm) {
  ensure_waypoint_ahead(remaining_);
  measurement.sensor.validate();
  return update_with(measurement.frame.t, arm,
                     [&](const ClampedRod& model, const Pose& tip, const Pose& end_effector,
                         const StatePrior& prior, const EstimationOptions& options,
                         const StateHypothesis& hypothesis) {
                       return estimate_state_from_cloud(model, tip, end_effector, measurement.frame,
                                                        measurement.sensor, prior, options,
                                                        hypothesis);
                     });
}

/// The checkpoint at time t: the estimate by `estimator`, judged, and the plan kept or made again.
ControllerOutput ShapeController::update_with(double t,
                                              const ArmState& arm,
                                              const Estimator& estimator) {
  const BaseWrench planned = remaining_.front().wrench;
  if (base_moves_)  // the clamp where the base gripper is now
    clamp_now_ = compose(arm.base_end_effector.value_or(remaining_.front().base_end_effector),
                         inverse(problem_.moving_base->grasp.tip_to_end_effector));
  remaining_.erase(remaining_.begin());
  fresh_ = std::max(0, fresh_ - 1);
  ControllerOutput output;
  Checkpoint& c = output.checkpoint;
  c.t = t;
  c.waypoint = ++waypoint_;
  estimate(c, estimator, arm.end_effector, planned);
  if (options_.replan && c.significant)
    replan(c, c.estimate.base_wrench);
  else if (options_.replan && fresh_ == 0) {  // the next step was planned with other beliefs
    const std::string kept = c.message;
    replan(c, planned);
    c.message = kept +
                "; the next step, made before the last correction, made again from the plan's "
                "state: " +
                c.message;
  }
  output.remaining = remaining_;
  return output;
}

/// The estimate from the measurement, judged (consistent, significant) and taken into the beliefs.
void ShapeController::estimate(Checkpoint& c,
                               const Estimator& estimator,
                               const Pose& end_effector,
                               const BaseWrench& planned) {
  // The tip where the gripper is believed to hold it.
  const Pose commanded = compose(end_effector, inverse(problem_.grasp.tip_to_end_effector));
  c.estimate = estimator(rod_now(), compose(commanded, beliefs_.fused.offset), end_effector,
                         beliefs_.prior(planned), beliefs_.estimation(options_, commanded),
                         beliefs_.hypothesis(planned));
  c.consistent = unexplained(c.estimate, options_.max_residual).empty();
  c.significant = c.consistent && significant(c.estimate);
  if (c.consistent && (c.significant || options_.fuse))
    beliefs_.take(c.estimate, commanded, options_);
  if (c.significant) beliefs_.acting = beliefs_.fused;  // the rod is not as the plan believes
  c.grasp_offset = beliefs_.acting.offset;
  c.message = kept_message(c);
}

ClampedRod ShapeController::rod_now() const {
  ClampedRod rod = problem_.rod;
  rod.clamp = clamp_now_;
  return rod;
}

/// Why an estimate not acted on was not.
std::string ShapeController::kept_message(const Checkpoint& c) const {
  if (c.significant) return "plan kept";
  if (!c.estimate.converged()) return "plan kept: " + c.estimate.message;
  if (!c.consistent)
    return "plan kept: " + unexplained(c.estimate, options_.max_residual) +
           "; the estimate is not used";
  return "plan kept: the estimate is within the noise of the plan's state";
}

/// The fit's drop of χ² from the plan's state beyond k + significance · √(2k).
bool ShapeController::significant(const StateEstimate& e) const {
  if (options_.significance < 0.0) return true;
  const double k = e.parameters;
  return e.prior_chi2 - e.chi2 > k + options_.significance * std::sqrt(2.0 * k);
}

/// The remaining steps made again from the equilibrium of `from` with the beliefs so far (the
/// first `horizon` of them optimised; those are then fresh).
void ShapeController::replan(Checkpoint& c, const BaseWrench& from) {
  PlanProblem rest = problem_;
  // With a moving base the rest starts where the base is now (its clamp; the base keeps moving).
  rest.rod = estimated_rod(rod_now(), beliefs_.acting.stiffness_scale, beliefs_.acting.load_factor,
                           options_.estimation.gravity);
  rest.initial = InitialState::equilibrium(from);
  // Commanded end-effector poses that put the real tip (commanded · offset) where the plan wants.
  rest.grasp.tip_to_end_effector =
      compose(inverse(beliefs_.acting.offset), problem_.grasp.tip_to_end_effector);
  // The arm's own planning (its reach, IK checks and joints) is not re-run; its reach shell is
  // kept in the workspace, and each segment's joints are solved as the arm gets there.
  rest.arm.reset();
  if (shell_) rest.workspace.reach = shell_;
  rest.base_arm.reset();  // the same for the base arm: its shell kept in the base's workspace
  if (rest.moving_base && base_shell_) rest.moving_base->workspace.reach = base_shell_;
  PlanOptions options = planning_;
  options.steps = static_cast<int>(remaining_.size());
  options.horizon = std::min(options_.horizon, options.steps);
  // Untracked re-plans are faster; in a scene plan() needs the tracking, which checks the rod
  // clear of it between waypoints (without it every re-plan in a scene was refused).
  options.track_between_waypoints = !rest.scene.empty();
  try {
    const PlanResult again = plan(rest, options);
    c.message = again.brief();
    if (again.status != PlanStatus::Complete) return;
    if (const std::string coiled = feedback_detail::not_gentle(
            again.steps, again.initial_configuration.energy, remaining_, options_.max_energy_ratio);
        !coiled.empty()) {
      c.message = "plan kept: " + coiled + " (" + c.message + ")";
      return;
    }
    // The first steps re-planned; those beyond the re-plan's horizon are kept until their turn.
    // A re-plan that did not move the base (no base path: the base held at rest.rod.clamp) keeps
    // the base gripper where it is now.
    const bool base_stays = rest.moving_base && again.base_end_effector_path.empty();
    for (std::size_t k = 0; k < again.steps.size() && k < remaining_.size(); ++k) {
      remaining_[k] = planned_waypoint(again.steps[k]);
      if (base_stays)
        remaining_[k].base_end_effector =
            compose(clamp_now_, rest.moving_base->grasp.tip_to_end_effector);
    }
    fresh_ = static_cast<int>(again.steps.size());
    c.replanned = true;
  } catch (const InputError& error) {
    c.message = std::string("plan kept: the re-plan was refused: ") + error.what();
  }
}

}  // namespace rodshape
