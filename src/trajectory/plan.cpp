// plan.cpp: plan(), the one entry point of planning: the problem's checks, the stages in order
// (plan_stages.hpp) and, with an arm, the re-plan loop around them (arm_replanning.hpp).
#include "rodshape/trajectory/plan.hpp"

#include <algorithm>
#include <iomanip>
#include <sstream>

#include "arm_replanning.hpp"
#include "plan_stages.hpp"
#include "rodshape/error.hpp"
#include "target_behind_clamp.hpp"
#include "validation.hpp"

namespace rodshape {

void PlanOptions::validate() const {
  detail::require_count("PlanOptions.steps", steps, 1, kMaxSteps);
  detail::require_count("PlanOptions.horizon", horizon, 0, steps);
  detail::require_count("PlanOptions.max_refinements", max_refinements, 0, kMaxRefinements);
  detail::require_count("PlanOptions.tracking_substeps", tracking_substeps, 1,
                        kMaxTrackingSubsteps);
  optimiser.validate();
  end_effector.validate();
  arm.validate();
}

void PlanProblem::validate() const {
  rod.validate();
  detail::require_count("PlanProblem.rod.intervals", rod.intervals, 1, kMaxIntervals);
  target.validate();
  workspace.validate();
  limits.validate();
  validity.validate("PlanProblem.validity");
  if (initial.kind == InitialState::Kind::HeldTip)
    detail::require_pose("PlanProblem.initial.tip", initial.tip);
  if (initial.kind == InitialState::Kind::Equilibrium) {
    detail::require_finite("PlanProblem.initial.base_wrench.force", initial.base_wrench.force);
    detail::require_finite("PlanProblem.initial.base_wrench.moment", initial.base_wrench.moment);
  }
}

std::string to_string(ObjectiveInterpolation interpolation) {
  switch (interpolation) {
    case ObjectiveInterpolation::Shape:
      return "shape";
    case ObjectiveInterpolation::ArcLength:
      return "arc_length";
    case ObjectiveInterpolation::Projection:
      return "projection";
  }
  return "unknown";
}

std::string to_string(PlanStatus status) {
  switch (status) {
    case PlanStatus::Complete:
      return "complete";
    case PlanStatus::SnapThrough:
      return "snap_through";
    case PlanStatus::Partial:
      return "partial";
    case PlanStatus::Infeasible:
      return "infeasible";
  }
  return "unknown";
}

std::string PlanResult::brief(int steps_requested) const {
  std::ostringstream out;
  const int completed = static_cast<int>(steps.size());
  out << to_string(status) << " plan, " << completed << (completed == 1 ? " step (" : " steps (")
      << steps_requested << " requested";
  if (horizon > 0) out << ", a horizon of " << horizon;
  if (tracking.refinements > 0)
    out << ", " << tracking.refinements << " inserted where the rod would jump";
  out << ")";
  if (completed > 0) {
    const ShapeCostBreakdown& cost = steps.back().solution.cost;
    out << ", final max distance " << std::setprecision(3) << cost.max_distance * 1e3
        << " mm, energy " << std::setprecision(3) << cost.energy << " J";
  }
  if (tracking.performed) {
    out << "; tracked peak energy " << std::setprecision(3) << tracking.peak_energy << " J";
    if (completed > 0) {
      const double initial = initial_configuration.energy;
      const double final = steps.back().solution.configuration.energy;
      const double larger = std::max(initial, final);
      if (larger > 0.0)
        out << " (" << std::fixed << std::setprecision(2) << tracking.peak_energy / larger
            << std::defaultfloat << "× the larger end energy)";
    }
    if (tracking.jump) out << "; tracking: " << tracking.note;
  }
  if (arm && arm->shell) {
    out << "; reach shell " << std::setprecision(3) << arm->shell->inner_radius << "–"
        << arm->shell->outer_radius << " m";
    if (!arm->replans.empty()) out << " (" << arm->replans.size() << " re-plans)";
  }
  if (arm && arm->joints.complete()) {
    out << "; joint trajectory: " << arm->joints.t.size() << " samples, " << std::setprecision(4)
        << arm->joints.duration() << " s";
    if (arm->joints.slowed) out << " (slowed ×" << arm->joints.slowdown << ")";
  }
  return out.str();
}

namespace detail {

namespace {

using namespace plan_stages;

/// Where the steps loop stands: the sets to plan, the tracked rod, the warm-start history.
struct StepLoop {
  ObjectivePath path;
  std::vector<ObjectiveSet> pending;
  StepHistory history;
  Pose from;             // the last waypoint (the tracked rod's end-effector pose)
  BaseWrench tracked;    // the tracked rod's base wrench there
  bool tracking = true;  // false past a jump: following the plan then means nothing
};

/// Steps 3–6: one optimal shape per objective set, each warm-started from the last and tracked
/// from the last waypoint; where the rod would jump, a set halfway is inserted and the segment
/// planned again. Returns false when a step's optimisation fails (the plan is then Partial).
bool plan_steps(const PlanProblem& problem,
                const PlanOptions& options,
                StepLoop& loop,
                PlanResult& result) {
  for (std::size_t next = 0; next < loop.pending.size();) {
    const ObjectiveSet& set = loop.pending[next];
    ShapeTarget target = problem.target;
    target.points = set.points;
    ShapeProblem unconstrained(problem.rod, target, Workspace{}, problem.grasp, StrainLimits{},
                               problem.wrench_bounds);
    const BaseWrench start = warm_start(unconstrained, loop.history, set.fraction);
    ShapeResult solution = optimise_step(problem, target, unconstrained, start, options.optimiser);
    const int number = static_cast<int>(result.steps.size()) + 1;
    if (!solution.converged()) {
      result.status = PlanStatus::Partial;
      result.failed_step = static_cast<int>(result.steps.size());
      result.message = "step " + std::to_string(number) + " (fraction " +
                       std::to_string(set.fraction) + " of the way) failed: " + solution.message;
      return false;
    }
    const Pose end_effector =
        compose(solution.configuration.tip(), problem.grasp.tip_to_end_effector);
    PlanStep step{set.fraction, set.inserted, set.points, std::move(solution), end_effector};
    if (loop.tracking) {
      const SegmentTracking segment =
          track_segment(problem, options, loop.from, loop.tracked, step, number);
      if (segment.jump && result.tracking.refinements < options.max_refinements) {
        const ObjectiveSet half = halfway_set(loop.path, loop.history.f_last, set);
        loop.pending.insert(loop.pending.begin() + static_cast<std::ptrdiff_t>(next), half);
        ++result.tracking.refinements;
        continue;
      }
      record(result.tracking, segment, static_cast<int>(result.steps.size()));
      if (segment.jump) loop.tracking = false;
      loop.tracked = segment.arrived;
      loop.from = end_effector;
    }
    loop.history.push(step.solution.base_wrench, set.fraction);
    result.steps.push_back(std::move(step));
    ++next;
  }
  return true;
}

/// The tracking's closing note.
std::string tracking_note(const TrackingResult& tracking) {
  if (tracking.refinements == 0) return "the rod follows the plan";
  return "the rod follows the plan (" + std::to_string(tracking.refinements) +
         " steps inserted where it would have jumped)";
}

}  // namespace

PlanResult plan_rod(const PlanProblem& problem,
                    const PlanOptions& options,
                    const plan_stages::InitialEquilibrium& initial) {
  PlanResult result;
  result.initial_wrench = initial.wrench;
  result.initial_configuration = initial.configuration;
  result.initial_stable_search = initial.stable_search;
  const Pose initial_end_effector =
      compose(initial.configuration.tip(), problem.grasp.tip_to_end_effector);
  // 2. Is the target within reach at all?
  result.feasibility =
      check_feasibility(problem.target, problem.rod, problem.limits.max_axial_strain.value_or(0.0));
  if (!result.feasibility.feasible) {
    result.status = PlanStatus::Infeasible;
    result.message = result.feasibility.reason;
    return result;
  }
  // 3. p_init on the initial shape, and the sets.
  result.initial_points =
      plan_stages::initial_points(problem, options, initial, result.feasibility);
  StepLoop loop;
  loop.path = {problem.rod.clamp.position, result.initial_points, problem.target.points,
               options.interpolation};
  loop.pending = objective_sets(loop.path, options.steps);
  if (options.planned_steps() < options.steps) {  // a receding horizon: the first sets only
    loop.pending.resize(static_cast<std::size_t>(options.planned_steps()));
    result.horizon = options.planned_steps();
  }
  loop.history.last = loop.history.before = initial.wrench;
  loop.from = initial_end_effector;
  loop.tracked = initial.wrench;
  loop.tracking = options.track_between_waypoints;
  // 4–6. The steps.
  result.status = PlanStatus::Complete;
  if (plan_steps(problem, options, loop, result))
    result.message = "complete: " + std::to_string(result.steps.size()) + " steps";
  if (result.tracking.performed && !result.tracking.jump)
    result.tracking.note = tracking_note(result.tracking);
  if (result.status == PlanStatus::Complete && result.tracking.jump) {
    result.status = PlanStatus::SnapThrough;
    result.message = "the rod would not follow the plan towards waypoint " +
                     std::to_string(result.tracking.jump_step + 1) + ": " + result.tracking.note;
  }
  if (result.status == PlanStatus::Partial || result.status == PlanStatus::SnapThrough)
    result.message += plan_stages::behind_clamp_note(problem);  // why, for a target behind it
  // 7. The timed end-effector path through the waypoints.
  result.end_effector_path =
      time_waypoints(initial_end_effector, result.steps, options.end_effector);
  return result;
}

}  // namespace detail

double estimated_plan_seconds(const PlanProblem& problem, const PlanOptions& options) {
  const double intervals = problem.rod.intervals;
  const double points = static_cast<double>(problem.target.points.size());
  const double optimise = 1.5e-4 * (1.0 + options.optimiser.multi_starts) * (points + 30.0) / 40.0;
  const double track = options.track_between_waypoints ? 1.4e-6 * options.tracking_substeps : 0.0;
  return intervals * options.planned_steps() * (optimise + track);
}

void check_plan_cost(const PlanProblem& problem, const PlanOptions& options) {
  const double seconds = estimated_plan_seconds(problem, options);
  if (seconds <= kMaxEstimatedPlanSeconds) return;
  std::ostringstream out;
  out.precision(2);
  out << "the plan would take about " << seconds
      << " s, estimated from PlanOptions.steps = " << options.planned_steps()
      << ", ShapeOptimiserOptions.multi_starts = " << options.optimiser.multi_starts << ", "
      << problem.rod.nodes() << " rod nodes, " << problem.target.points.size()
      << " ShapeTarget.points";
  if (options.track_between_waypoints)
    out << " and PlanOptions.tracking_substeps = " << options.tracking_substeps;
  out << "; at most " << detail::format_value(kMaxEstimatedPlanSeconds)
      << " s (docs/limits.md): lower one of them";
  throw InputError(out.str());
}

PlanResult plan(const PlanProblem& problem, const PlanOptions& options) {
  options.validate();
  problem.validate();
  check_plan_cost(problem, options);
  if (problem.arm) return detail::plan_with_arm(problem, options);
  return detail::plan_rod(problem, options, plan_stages::initial_equilibrium(problem));
}

TrackingResult track_plan(const PlanProblem& problem,
                          const PlanOptions& options,
                          const PlanResult& result) {
  TrackingResult tracking;
  tracking.performed = true;
  Pose from = compose(result.initial_configuration.tip(), problem.grasp.tip_to_end_effector);
  BaseWrench w = result.initial_wrench;
  for (std::size_t k = 0; k < result.steps.size() && !tracking.jump; ++k) {
    const plan_stages::SegmentTracking segment = plan_stages::track_segment(
        problem, options, from, w, result.steps[k], static_cast<int>(k) + 1);
    plan_stages::record(tracking, segment, static_cast<int>(k));
    w = segment.arrived;
    from = result.steps[k].end_effector;
  }
  if (!tracking.jump) tracking.note = "the rod follows the plan";
  return tracking;
}

}  // namespace rodshape
