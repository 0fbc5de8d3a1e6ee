// plan.cpp: plan(), the one entry point of planning: the problem's checks, the stages in order
// (plan_stages.hpp) and, with an arm, the re-plan loop around them (arm_replanning.hpp).
#include "rodshape/trajectory/plan.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "arm_replanning.hpp"
#include "detour_search.hpp"
#include "moving_base_plan.hpp"
#include "plan_stages.hpp"
#include "pose_continuation.hpp"
#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/error.hpp"
#include "rodshape/robot/arm_clearance.hpp"
#include "rodshape/solvers/follow_equilibrium.hpp"
#include "scene_stages.hpp"
#include "target_behind_clamp.hpp"
#include "validation.hpp"

namespace rodshape {

namespace {

/// A gripper that transmits no component of the wrench does not hold the rod: nothing it does
/// moves the rod (a plan of a 0 s path that ends where it began).
void require_holds(const std::string& field, const std::array<bool, 6>& released) {
  if (std::all_of(released.begin(), released.end(), [](bool r) { return r; }))
    throw InputError(field,
                     " releases all six components of the wrench: the gripper would not "
                     "hold the rod (keep at least one held)");
}

}  // namespace

void PlanOptions::validate() const {
  detail::require_count("PlanOptions.steps", steps, 1, kMaxSteps);
  detail::require_count("PlanOptions.horizon", horizon, 0, steps);
  detail::require_count("PlanOptions.max_refinements", max_refinements, 0, kMaxRefinements);
  detail::require_count("PlanOptions.tracking_substeps", tracking_substeps, 1,
                        kMaxTrackingSubsteps);
  optimiser.validate();
  end_effector.validate();
  base_end_effector.validate();
  arm.validate();
  detail::require_non_negative("PlanOptions.scene_margin", scene_margin);
  if (scene_margin > kMaxSceneMargin)
    throw InputError("PlanOptions.scene_margin",
                     " = " + detail::format_value(scene_margin) +
                         " must be <= " + detail::format_value(kMaxSceneMargin));
  detail::require_positive("PlanOptions.scene_reach", scene_reach);
  if (reach_tolerance) detail::require_positive("PlanOptions.reach_tolerance", *reach_tolerance);
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
  scene.validate();
  scene.check_clamp(rod.clamp.position);
  require_holds("Grasp.released", grasp.released);
  if (moving_base) moving_base->validate();
  if (base_arm && !moving_base)
    throw InputError("PlanProblem.base_arm",
                     " needs PlanProblem.moving_base (the arm moves the base)");
}

void MovingBase::validate() const {
  workspace.validate();
  require_holds("PlanProblem.moving_base.grasp.released", grasp.released);
  detail::require_non_negative("PlanProblem.moving_base.motion_weight", motion_weight);
  detail::require_pose("PlanProblem.moving_base.grasp.tip_to_end_effector",
                       grasp.tip_to_end_effector);
  for (int i = 0; i < 6; ++i)
    if (std::isnan(wrench_bounds.lower[i]) || std::isnan(wrench_bounds.upper[i]) ||
        wrench_bounds.lower[i] > wrench_bounds.upper[i])
      throw InputError("PlanProblem.moving_base.wrench_bounds",
                       ": component " + std::to_string(i) + " has lower > upper or NaN");
}

std::string to_string(ObjectiveInterpolation interpolation) {
  return std::string(name_of(kObjectiveInterpolationNames, interpolation));
}

std::string to_string(PlanStatus status) { return std::string(name_of(kPlanStatusNames, status)); }

std::string PlanResult::brief() const {
  std::ostringstream out;
  const int completed = static_cast<int>(steps.size());
  out << to_string(status) << " plan, " << completed << (completed == 1 ? " step (" : " steps (")
      << options.steps << " requested";
  if (horizon > 0) out << ", a horizon of " << horizon;
  if (tracking.refinements > 0)
    out << ", " << tracking.refinements << " inserted where the rod would jump";
  out << ")";
  if (std::isfinite(target_distance))  // to the target, not to the last set reached
    out << ", final max distance " << std::setprecision(3) << target_distance * 1e3 << " mm";
  if (completed > 0)
    out << ", energy " << std::setprecision(3) << steps.back().solution.cost.energy << " J";
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
  if (interpolation.tried.size() > 1) {
    out << "; interpolation " << to_string(interpolation.used) << " (";
    for (std::size_t k = 0; k < interpolation.tried.size(); ++k) {
      const InterpolationTrial& trial = interpolation.tried[k];
      out << (k > 0 ? ", " : "") << to_string(trial.scheme) << " " << to_string(trial.status);
      if (std::isfinite(trial.peak_ratio))
        out << " at " << std::fixed << std::setprecision(2) << trial.peak_ratio << std::defaultfloat
            << "×";
    }
    out << ")";
  }
  if (scene && std::isfinite(scene->min_gap)) {
    out << "; least gap to the scene " << std::setprecision(3) << scene->min_gap * 1e3
        << " mm (obstacle " << scene->obstacle_label << ", clearance " << scene->clearance * 1e3
        << " mm)";
  }
  if (scene && scene->robot) {
    out << "; least gap of the arm's links " << std::setprecision(3) << scene->robot->min_gap * 1e3
        << " mm (" << scene->robot->link << ", "
        << (scene->robot->obstacle == kOtherArm ? "the other arm's " + scene->robot->other_link
            : scene->robot->obstacle < 0
                ? std::string("the rod")
                : "obstacle " + (scene->robot->obstacle_name.empty()
                                     ? std::to_string(scene->robot->obstacle)
                                     : "'" + scene->robot->obstacle_name + "'"))
        << ")";
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
  Pose from;                     // the last waypoint (the tracked rod's end-effector pose)
  BaseWrench tracked;            // the tracked rod's base wrench there
  bool tracking = true;          // false past a jump: following the plan then means nothing
  std::vector<double> required;  // with a scene: the gap each obstacle requires
};

/// One step's optimum. With a scene, its optimisation keeps the rod clear of the obstacles near
/// its start and its points; an obstacle the optimum then comes too near to joins them and the
/// step is solved again (a few rounds at most: each adds at least one obstacle). `obstacles` is
/// set to the obstacles its last round kept the rod clear of (the rows of its clearance block).
ShapeResult solve_step(const PlanProblem& problem,
                       const PlanOptions& options,
                       const ShapeTarget& target,
                       ShapeProblem& unconstrained,
                       const BaseWrench& start,
                       const StepLoop& loop,
                       int& obstacles) {
  obstacles = 0;
  if (problem.scene.empty())
    return optimise_step(problem, target, unconstrained, start, options.optimiser);
  return solve_in_scene_rounds(
      problem, options, loop.required, integrate(problem.rod, start, Derivatives::None),
      target.points,
      [&](const Clearance& clearance) {
        return optimise_step(problem, target, unconstrained, start, options.optimiser, clearance);
      },
      obstacles);
}

/// A detour's waypoint as a step of the plan: the equilibrium it reached, with the cost terms of
/// the step it leads to (`problem` is that step's ShapeProblem).
PlanStep detour_step(const detour::Waypoint& waypoint,
                     const ObjectiveSet& set,
                     const PointSet& points,
                     ShapeProblem& problem) {
  ShapeResult solution;
  solution.status = SolveStatus::Converged;
  solution.message = "a detour's waypoint: an equilibrium clear of the scene";
  solution.base_wrench = waypoint.wrench;
  solution.configuration = waypoint.configuration;
  problem.evaluate(waypoint.wrench.to_vector());
  solution.cost = problem.breakdown();
  solution.stability = waypoint.stability;
  return {set.fraction, false, true, points, std::move(solution), waypoint.end_effector};
}

/// The tracking of an edge the detour search followed.
SegmentTracking detour_tracking(const detour::Waypoint& reached, double deviation) {
  SegmentTracking segment;
  segment.deviation = deviation;
  segment.arrived = reached.wrench;
  segment.peak_energy = reached.peak_energy;
  segment.peak_curvature = reached.peak_curvature;
  segment.gap = reached.gap;
  return segment;
}

/// A detour's waypoints `via` appended to the plan as steps (detour: true), each edge's tracking
/// and, with a scene, its least gap recorded.
void append_detour(PlanResult& result,
                   const PlanProblem& problem,
                   const std::vector<detour::Waypoint>& via,
                   const ObjectiveSet& set,
                   const PointSet& points,
                   ShapeProblem& costs) {
  for (const detour::Waypoint& waypoint : via) {
    const int number = static_cast<int>(result.steps.size()) + 1;
    record(result.tracking, detour_tracking(waypoint, 0.0), number - 1);
    if (result.scene) record_gap(result, problem, waypoint.gap, number);
    result.steps.push_back(detour_step(waypoint, set, points, costs));
  }
}

/// Searches a detour to `step` from the last waypoint; when found, appends its waypoints as
/// steps (detour: true) and returns the tracking of the last edge, which arrives at `step` (or at
/// the step optimised again on the branch the rod reaches: `step` is then replaced by it).
std::optional<SegmentTracking> take_detour(const PlanProblem& problem,
                                           const PlanOptions& options,
                                           StepLoop& loop,
                                           const ObjectiveSet& set,
                                           PlanStep& step,
                                           ShapeProblem& step_problem,
                                           PlanResult& result) {
  ShapeTarget target = problem.target;
  target.points = step.objective_points;
  const detour::Reoptimise reoptimise = [&](const BaseWrench& w) -> std::optional<PlanStep> {
    int obstacles = 0;  // the step is counted once, by its first solve
    ShapeResult solution = solve_step(problem, options, target, step_problem, w, loop, obstacles);
    if (!solution.converged()) return std::nullopt;
    const Pose end_effector =
        compose(solution.configuration.tip(), problem.grasp.tip_to_end_effector);
    return PlanStep{step.fraction,         step.inserted,       false,
                    step.objective_points, std::move(solution), end_effector};
  };
  detour::Search found =
      detour::search(problem, options, loop.required, loop.from, loop.tracked, step, reoptimise);
  result.scene->detours.push_back(found.message);
  if (!found.found) return std::nullopt;
  if (found.goal_step) step = std::move(*found.goal_step);
  append_detour(result, problem, found.via, set, step.objective_points, step_problem);
  if (!found.via.empty()) {
    loop.tracked = found.via.back().wrench;
    loop.from = found.via.back().end_effector;
  }
  return detour_tracking(found.goal,
                         node_deviation(found.goal.configuration, step.solution.configuration));
}

/// With a scene, where the steps cannot get past an obstacle (a step's optimisation fails, or the
/// rod would jump or come too near with no refinement left): the last set's optimum, reached by
/// a detour from the last waypoint, and the sets between skipped (the straight sequence of
/// objective sets leads into the obstacle; its end is clear of it). The optimum is tried from a
/// few warm starts (the steps' extrapolation, the last optimum, the tracked rod, the initial rod:
/// they may end in different local optima, on different sides of an obstacle) until a detour
/// reaches one. Returns false when none does; the plan then ends as the failed step says.
bool skip_to_last_set(const PlanProblem& problem,
                      const PlanOptions& options,
                      StepLoop& loop,
                      std::size_t next,
                      PlanResult& result) {
  if (problem.scene.empty() || !options.scene_detour || !loop.tracking ||
      loop.pending.back().detour_tried)
    return false;
  loop.pending.back().detour_tried = true;
  const ObjectiveSet last = loop.pending.back();
  ShapeTarget target = problem.target;
  target.points = scene_stages::clear_of_scene(problem.scene, loop.required, last.points);
  ShapeProblem unconstrained(problem.rod, target, Workspace{}, problem.grasp, StrainLimits{},
                             problem.wrench_bounds);
  const BaseWrench starts[] = {warm_start(unconstrained, loop.history, last.fraction),
                               loop.history.last, loop.tracked, result.initial_wrench};
  std::vector<RodConfiguration> tried;
  for (const BaseWrench& start : starts) {
    int obstacles = 0;
    ShapeResult solution =
        solve_step(problem, options, target, unconstrained, start, loop, obstacles);
    const bool known = std::any_of(tried.begin(), tried.end(), [&](const RodConfiguration& c) {
      return solution.converged() && node_deviation(c, solution.configuration) < 1e-3;
    });
    if (!solution.converged() || known) continue;
    tried.push_back(solution.configuration);
    const Pose end_effector =
        compose(solution.configuration.tip(), problem.grasp.tip_to_end_effector);
    PlanStep step{last.fraction, last.inserted,       false,
                  target.points, std::move(solution), end_effector};
    auto around = take_detour(problem, options, loop, last, step, unconstrained, result);
    if (!around) continue;
    result.scene->obstacles_per_step.push_back(obstacles);  // only the step taken is counted
    record(result.tracking, *around, static_cast<int>(result.steps.size()));
    if (around->gap)
      record_gap(result, problem, *around->gap, static_cast<int>(result.steps.size()) + 1);
    loop.tracked = around->arrived;
    loop.from = step.end_effector;
    loop.history.push(step.solution.base_wrench, last.fraction);
    result.scene->detours.back() +=
        "; to the last objective set (fraction " + std::to_string(last.fraction) + "), the " +
        std::to_string(loop.pending.size() - 1 - next) + " sets before it skipped";
    result.steps.push_back(std::move(step));
    return true;
  }
  return false;
}

/// Steps 3–6: one optimal shape per objective set, each warm-started from the last and tracked
/// from the last waypoint; where the rod would jump, or come nearer to an obstacle than the
/// clearance, a set halfway is inserted and the segment planned again. Returns false when a
/// step's optimisation fails (the plan is then Partial).
bool plan_steps(const PlanProblem& problem,
                const PlanOptions& options,
                StepLoop& loop,
                PlanResult& result) {
  const bool scene = !problem.scene.empty();
  for (std::size_t next = 0; next < loop.pending.size();) {
    const ObjectiveSet& set = loop.pending[next];
    ShapeTarget target = problem.target;
    target.points =
        scene ? scene_stages::clear_of_scene(problem.scene, loop.required, set.points) : set.points;
    // An intermediate set with points inside an obstacle: the straight sequence of sets leads
    // through it, and its optimum would wrap the rod around it; the last set first.
    if (scene && next + 1 < loop.pending.size() && target.points != set.points &&
        skip_to_last_set(problem, options, loop, next, result))
      return true;
    ShapeProblem unconstrained(problem.rod, target, Workspace{}, problem.grasp, StrainLimits{},
                               problem.wrench_bounds);
    const BaseWrench start = warm_start(unconstrained, loop.history, set.fraction);
    int obstacles = 0;
    ShapeResult solution =
        solve_step(problem, options, target, unconstrained, start, loop, obstacles);
    if (scene) result.scene->obstacles_per_step.push_back(obstacles);
    const int number = static_cast<int>(result.steps.size()) + 1;
    if (!solution.converged()) {
      if (skip_to_last_set(problem, options, loop, next, result)) return true;
      result.status = PlanStatus::Partial;
      result.failed_step = static_cast<int>(result.steps.size());
      result.message = "step " + std::to_string(number) + " (fraction " +
                       std::to_string(set.fraction) + " of the way) failed: " + solution.message;
      return false;
    }
    const Pose end_effector =
        compose(solution.configuration.tip(), problem.grasp.tip_to_end_effector);
    PlanStep step{set.fraction,  set.inserted,        false,
                  target.points, std::move(solution), end_effector};
    if (loop.tracking) {
      SegmentTracking segment = track_segment(problem, options, loop.from, loop.tracked, step,
                                              number, scene ? &loop.required : nullptr);
      // Through an obstacle (or still too near after the refinements): a way around, once per set.
      const bool refinable = result.tracking.refinements < options.max_refinements;
      if (segment.collision && options.scene_detour && !set.detour_tried &&
          (segment.gap->gap < 0.0 || !refinable)) {
        loop.pending[next].detour_tried = true;
        if (auto around = take_detour(problem, options, loop, set, step, unconstrained, result))
          segment = std::move(*around);
      }
      if ((segment.jump || segment.collision) && refinable) {
        const ObjectiveSet half = halfway_set(loop.path, loop.history.f_last, set);
        loop.pending.insert(loop.pending.begin() + static_cast<std::ptrdiff_t>(next), half);
        ++result.tracking.refinements;
        continue;
      }
      if ((segment.jump || segment.collision) &&
          skip_to_last_set(problem, options, loop, next, result))
        return true;
      record(result.tracking, segment, static_cast<int>(result.steps.size()));
      if (segment.gap)
        record_gap(result, problem, *segment.gap, static_cast<int>(result.steps.size()) + 1);
      if (segment.collision && result.scene->note.empty()) result.scene->note = segment.note;
      if (segment.jump) loop.tracking = false;
      loop.tracked = segment.arrived;
      loop.from = step.end_effector;  // the planned one, or the detour's goal optimised again
    }
    loop.history.push(step.solution.base_wrench, set.fraction);
    result.steps.push_back(std::move(step));
    ++next;
  }
  return true;
}

}  // namespace

/// Stages 2–7 with objective sets (Shape, ArcLength, Projection).
PlanResult plan_by_sets(const PlanProblem& problem,
                        const PlanOptions& options,
                        const plan_stages::InitialEquilibrium& initial) {
  PlanResult result;
  result.interpolation.used = options.interpolation;
  result.initial_wrench = initial.wrench;
  result.initial_configuration = initial.configuration;
  result.initial_stable_search = initial.stable_search;
  const Pose initial_end_effector =
      compose(initial.configuration.tip(), problem.grasp.tip_to_end_effector);
  // 2. Is the target within reach at all?
  result.feasibility =
      check_feasibility(problem.target, problem.rod, problem.limits.max_axial_strain.value_or(0.0));
  StepLoop loop;
  if (!problem.scene.empty()) {
    plan_stages::start_scene(problem, initial.configuration, loop.required, result);
    if (result.feasibility.feasible) {
      if (const auto blocked =
              scene_stages::target_clear(problem.scene, loop.required, problem.target.points)) {
        result.feasibility.feasible = false;
        result.feasibility.offending_point = blocked->point;
        result.feasibility.reason = blocked->reason;
      }
    }
  }
  if (!result.feasibility.feasible) {
    result.status = PlanStatus::Infeasible;
    result.message = result.feasibility.reason;
    return result;
  }
  // 3. p_init on the initial shape, and the sets.
  result.initial_points =
      plan_stages::initial_points(problem, options, initial, result.feasibility);
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
  plan_stages::settle_status(result);
  plan_stages::settle_reach(result, problem, options);
  if (result.status == PlanStatus::Partial || result.status == PlanStatus::SnapThrough)
    result.message += plan_stages::behind_clamp_note(problem);  // why, for a target behind it
  // 7. The timed end-effector path through the waypoints.
  result.end_effector_path =
      time_waypoints(initial_end_effector, result.steps, options.end_effector);
  return result;
}

namespace {

/// Why a complete plan of another scheme does not replace the Shape plan.
std::string farther_than(const PlanResult& plan, double reach) {
  return "its last step is farther from the target than allowed (" +
         detail::format_value(plan.steps.back().solution.cost.max_distance * 1e3) + " mm > " +
         detail::format_value(reach * 1e3) + " mm)";
}

/// Complete with a tracked peak within kGentleRatio × the larger end energy.
bool gentle_peak(const PlanResult& plan) {
  return plan.complete() && !(plan_stages::peak_ratio(plan) > PlanOptions::kGentleRatio);
}

/// Gentle enough that Auto tries nothing else.
bool gentle(const PlanResult& plan) { return gentle_peak(plan) && plan.tracking.refinements == 0; }

PlanOptions with_interpolation(PlanOptions options, ObjectiveInterpolation scheme) {
  options.interpolation = scheme;
  return options;
}

/// The step `goal` optimised again from the base wrench of another equilibrium at its pose (a
/// local optimum of the same points on the branch the rod reaches); nullopt when that fails.
detour::Reoptimise reoptimised_goal(const PlanProblem& problem,
                                    const PlanOptions& options,
                                    const PlanStep& goal) {
  return [&problem, &options, goal](const BaseWrench& w) -> std::optional<PlanStep> {
    ShapeTarget target = problem.target;
    target.points = goal.objective_points;
    ShapeProblem unconstrained(problem.rod, target, Workspace{}, problem.grasp, StrainLimits{},
                               problem.wrench_bounds);
    StepLoop loop;
    if (!problem.scene.empty())
      loop.required = problem.scene.required_gaps(problem.rod.clamp.position);
    int obstacles = 0;
    ShapeResult solution = solve_step(problem, options, target, unconstrained, w, loop, obstacles);
    if (!solution.converged()) return std::nullopt;
    const Pose end_effector =
        compose(solution.configuration.tip(), problem.grasp.tip_to_end_effector);
    return PlanStep{goal.fraction, false, false, target.points, std::move(solution), end_effector};
  };
}

/// The target's optimum: the given Shape plan's last step, or the Shape sets' (untracked) when it
/// has none; `reference` holds the latter. Where the sets' optimisation fails on the way (an
/// intermediate set of a few points on a helix can pull the optimum beyond the rod's scale) or
/// ends on an optimum off the points (more than 1 % of the rod's length: untracked, the sets can
/// lead to another local optimum), twice as many sets (each a smaller move), and then the target's
/// set alone from the initial rod, where they reach the points (within 1 % of the rod's length):
/// the target's optimum is what Pose and Search need, not the sets' way there.
const PlanResult& optimum_plan(const PlanProblem& problem,
                               const PlanOptions& options,
                               const plan_stages::InitialEquilibrium& initial,
                               const PlanResult* shape_plan,
                               PlanResult& reference) {
  if (shape_plan && !shape_plan->steps.empty() && shape_plan->status != PlanStatus::Partial)
    return *shape_plan;
  PlanOptions untracked = with_interpolation(options, ObjectiveInterpolation::Shape);
  untracked.track_between_waypoints = false;
  reference = plan_by_sets(problem, untracked, initial);
  const double near = 0.01 * problem.rod.properties.length;
  const auto failed = [](const PlanResult& r) {
    return r.status == PlanStatus::Partial || r.steps.empty();
  };
  const auto off_points = [&](const PlanResult& r) {
    return failed(r) || r.steps.back().solution.cost.max_distance > near;
  };
  for (const int steps : {std::min(2 * options.steps, PlanOptions::kMaxSteps), 1}) {
    if (!off_points(reference) || steps == options.steps) break;
    untracked.steps = steps;
    PlanResult finer = plan_by_sets(problem, untracked, initial);
    // an optimum off the points (a target the rod cannot reach) is no goal for Pose or Search
    if (!off_points(finer)) reference = std::move(finer);
  }
  return reference;
}

/// Pose: the target's optimum by the Shape sets (untracked), then the end effector's path to it.
PlanResult plan_by_pose(const PlanProblem& problem,
                        const PlanOptions& options,
                        const plan_stages::InitialEquilibrium& initial,
                        const PlanResult* shape_plan) {
  PlanResult reference;
  shape_plan = &optimum_plan(problem, options, initial, shape_plan, reference);
  const bool reached = shape_plan->status != PlanStatus::Partial &&
                       shape_plan->status != PlanStatus::Infeasible && !shape_plan->steps.empty();
  pose_continuation::Refusal refusal;
  std::optional<PlanResult> result =
      reached ? pose_continuation::plan(
                    problem, options, initial, *shape_plan,
                    reoptimised_goal(problem, options, shape_plan->steps.back()), refusal)
              : std::nullopt;
  if (!result) {  // the reference's status and message, or why the path was not taken
    PlanResult failed = *shape_plan;
    if (reached) {
      failed.status = refusal.status;
      failed.message = refusal.why;
      failed.tracking = TrackingResult{};  // the reference's tracking is not the path's
    }
    failed.interpolation.used = ObjectiveInterpolation::Pose;
    return failed;
  }
  result->interpolation.used = ObjectiveInterpolation::Pose;
  plan_stages::settle_reach(*result, problem, options);
  return std::move(*result);
}

/// Search: the target's optimum (as for Pose), then a path to it from the initial pose found by
/// the detour search with every edge's energy within kGentleRatio × the larger end energy; its
/// equilibria are the steps (detour: true), the last the optimum (or the optimum of the same
/// points on the branch the rod reached, detour::Search::goal_step).
PlanResult plan_by_search(const PlanProblem& problem,
                          const PlanOptions& options,
                          const plan_stages::InitialEquilibrium& initial,
                          const PlanResult* shape_plan) {
  PlanResult reference;
  const PlanResult& optimum = optimum_plan(problem, options, initial, shape_plan, reference);
  PlanResult result = optimum;
  result.interpolation.used = ObjectiveInterpolation::Search;
  result.tracking = TrackingResult{};
  result.end_effector_path.clear();
  if (optimum.status == PlanStatus::Partial || optimum.status == PlanStatus::Infeasible ||
      optimum.steps.empty())
    return result;  // the reference's status and message: no optimum to go to
  result.steps.clear();
  PlanStep goal = optimum.steps.back();
  const Pose from = compose(initial.configuration.tip(), problem.grasp.tip_to_end_effector);
  const std::vector<double> required =
      problem.scene.empty() ? std::vector<double>{}
                            : problem.scene.required_gaps(problem.rod.clamp.position);
  const double cap = PlanOptions::kGentleRatio;
  const detour::Search found =
      detour::search(problem, options, required, from, initial.wrench, goal,
                     reoptimised_goal(problem, options, goal), {cap, cap});
  if (!found.found) {
    result.status = PlanStatus::Partial;
    result.message = "no path found on which the rod stays within " + detail::format_value(cap) +
                     " x the larger end energy: " + found.message;
    return result;
  }
  if (found.goal_step) goal = *found.goal_step;
  ShapeTarget target = problem.target;
  target.points = goal.objective_points;
  ShapeProblem costs(problem.rod, target, Workspace{}, problem.grasp, StrainLimits{},
                     problem.wrench_bounds);
  if (!problem.scene.empty()) {
    result.scene = SceneResult{};
    result.scene->clearance = problem.scene.clearance;
  }
  append_detour(result, problem, found.via, {goal.fraction, goal.objective_points},
                goal.objective_points, costs);
  record(result.tracking,
         detour_tracking(found.goal,
                         node_deviation(found.goal.configuration, goal.solution.configuration)),
         static_cast<int>(result.steps.size()));
  if (result.scene)
    record_gap(result, problem, found.goal.gap, static_cast<int>(result.steps.size()) + 1);
  result.steps.push_back(std::move(goal));
  result.status = PlanStatus::Complete;
  result.message = "complete: " + std::to_string(result.steps.size()) +
                   " steps on a searched path within " + detail::format_value(cap) +
                   " x the larger end energy to the target's optimum";
  result.tracking.note = "the rod follows the plan (a searched path)";
  result.end_effector_path = plan_stages::time_waypoints(from, result.steps, options.end_effector);
  if (!plan_stages::follows_timed_path(problem, result)) {
    result.status = PlanStatus::SnapThrough;
    result.message =
        "the rod cannot follow the searched path: along the timed path's samples it "
        "snaps on the way or arrives elsewhere (the path passes where the "
        "equilibrium's branch divides)";
  }
  plan_stages::settle_reach(result, problem, options);
  return result;
}

/// Appended to an incomplete plan's message when `optimum`'s last step, the target's set, passes
/// within the reach tolerance of the points but has a conjugate point before the tip (the step's
/// assess_stability): held at the clamp and the end effector the rod cannot rest in that shape, so
/// no path to it completes. A helix held so has one after 1.0–1.45 turns whatever its radius and
/// pitch (docs/task-file.md, plan.json `message`): why a 2.5-turn helix has no plan.
void note_unstable_optimum(PlanResult& result,
                           const PlanResult& optimum,
                           const PlanProblem& problem,
                           const PlanOptions& options) {
  if (result.complete() || optimum.status == PlanStatus::Partial ||
      optimum.status == PlanStatus::Infeasible || optimum.steps.empty())
    return;
  const PlanStep& goal = optimum.steps.back();
  const std::optional<StabilityResult>& stability = goal.solution.stability;
  const double length = problem.rod.properties.length;
  if (!(goal.fraction >= 1.0) || !stability || stability->stable || !stability->conjugate_point_s ||
      !(goal.solution.cost.max_distance <= options.reach_tolerance_for(length)))
    return;
  std::ostringstream out;
  out.precision(3);
  out << "; no complete plan ends on the target's optimum: it passes within "
      << goal.solution.cost.max_distance * 1e3 << " mm of the points (" << goal.solution.cost.energy
      << " J) but is unstable held at the clamp and the end effector (a conjugate point at s = "
      << *stability->conjugate_point_s << " m of " << length
      << " m: the rod between the clamp and there can buckle with both ends held, as a helix "
         "does beyond about 1.3 turns)";
  result.message += out.str();
}

InterpolationTrial trial(const PlanResult& plan, ObjectiveInterpolation scheme) {
  return {scheme, plan.status, plan_stages::peak_ratio(plan), plan.complete() ? "" : plan.message};
}

/// Auto: Shape, and when it is not gentle, Pose and Projection, and when none of them is within
/// kGentleRatio, Search; the complete plan with the least peak ratio (the earlier on a tie).
PlanResult gentlest_plan(const PlanProblem& problem,
                         const PlanOptions& options,
                         const plan_stages::InitialEquilibrium& initial) {
  PlanResult best =
      plan_by_sets(problem, with_interpolation(options, ObjectiveInterpolation::Shape), initial);
  std::vector<InterpolationTrial> tried = {trial(best, ObjectiveInterpolation::Shape)};
  if (options.planned_steps() == options.steps && options.track_between_waypoints &&
      !gentle(best)) {
    // With a scene, Pose only: the paper's sets lead through the same obstacles, and each
    // segment they block is another detour search (seconds), for plans that rarely win.
    const int schemes_tried = problem.scene.empty() ? 2 : 1;
    const PlanResult plan_for_optimum = best;  // the Shape plan: its last step is the optimum
    // the target's optimum: the Shape plan's last step, or the untracked sets' where it failed
    PlanResult reference;
    const PlanResult& optimum =
        optimum_plan(problem, options, initial, &plan_for_optimum, reference);
    PlanResult others[2] = {plan_by_pose(problem, options, initial, &optimum), {}};
    if (schemes_tried == 2)
      others[1] = plan_by_sets(
          problem, with_interpolation(options, ObjectiveInterpolation::Projection), initial);
    const ObjectiveInterpolation schemes[] = {ObjectiveInterpolation::Pose,
                                              ObjectiveInterpolation::Projection};
    const double reach = plan_stages::reached_within(best, problem);
    for (int k = 0; k < schemes_tried; ++k) {
      tried.push_back(trial(others[k], schemes[k]));
      if (others[k].complete() && !(others[k].steps.back().solution.cost.max_distance <= reach)) {
        tried.back().note = farther_than(others[k], reach);
        continue;
      }
      const bool better =
          others[k].complete() &&
          (!best.complete() || plan_stages::peak_ratio(others[k]) < plan_stages::peak_ratio(best));
      if (better) best = std::move(others[k]);
    }
    if (!gentle_peak(best)) {  // none gentle: a path searched for within the ratio, to the
      // optimum of the best plan so far (the Shape plan's when none completed)
      PlanResult searched =
          plan_by_search(problem, options, initial, best.complete() ? &best : &optimum);
      tried.push_back(trial(searched, ObjectiveInterpolation::Search));
      if (searched.complete() && !(searched.steps.back().solution.cost.max_distance <= reach))
        tried.back().note = farther_than(searched, reach);
      else if (searched.complete() && (!best.complete() || plan_stages::peak_ratio(searched) <
                                                               plan_stages::peak_ratio(best)))
        best = std::move(searched);
    }
    for (InterpolationTrial& t : tried)
      if (t.scheme != best.interpolation.used && t.note.empty())
        t.note = "not the gentlest complete plan";
    note_unstable_optimum(best, optimum, problem, options);
  }
  best.interpolation.tried = std::move(tried);
  return best;
}

}  // namespace

namespace {

PlanResult plan_by_scheme(const PlanProblem& problem,
                          const PlanOptions& options,
                          const plan_stages::InitialEquilibrium& initial) {
  if (problem.base_moves()) return plan_moving_base(problem, options, initial);
  switch (options.interpolation) {
    case ObjectiveInterpolation::Auto:
      return gentlest_plan(problem, options, initial);
    case ObjectiveInterpolation::Pose: {
      PlanResult result = plan_by_pose(problem, options, initial, nullptr);
      result.interpolation.tried = {trial(result, ObjectiveInterpolation::Pose)};
      note_unstable_optimum(result, result, problem, options);  // a failed path keeps its steps
      return result;
    }
    case ObjectiveInterpolation::Search: {
      PlanResult result = plan_by_search(problem, options, initial, nullptr);
      result.interpolation.tried = {trial(result, ObjectiveInterpolation::Search)};
      return result;
    }
    default: {
      PlanResult result = plan_by_sets(problem, options, initial);
      result.interpolation.tried = {trial(result, options.interpolation)};
      if (options.planned_steps() == options.steps)
        note_unstable_optimum(result, result, problem, options);
      return result;
    }
  }
}

}  // namespace

PlanResult plan_rod(const PlanProblem& problem,
                    const PlanOptions& options,
                    const plan_stages::InitialEquilibrium& initial) {
  PlanResult result = plan_by_scheme(problem, options, initial);
  plan_stages::settle_reach(result, problem, options);  // the failed schemes' distance too
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
  if (!problem.scene.empty() && !options.track_between_waypoints)
    throw InputError("PlanOptions.track_between_waypoints",
                     " must be true with a scene: the rod is checked clear of it between "
                     "waypoints by following it");
  if ((options.interpolation == ObjectiveInterpolation::Pose ||
       options.interpolation == ObjectiveInterpolation::Search) &&
      options.planned_steps() < options.steps)
    throw InputError("PlanOptions.interpolation", " = " + to_string(options.interpolation) +
                                                      " plans the whole way: it cannot be used "
                                                      "with a horizon");
  if (problem.base_moves() && (options.interpolation == ObjectiveInterpolation::Pose ||
                               options.interpolation == ObjectiveInterpolation::Search))
    throw InputError("PlanOptions.interpolation",
                     " = " + to_string(options.interpolation) +
                         " follows the tip alone: with a moving base use shape, arc_length, "
                         "projection or auto (which is shape there)");
  if (options.reach_tolerance && *options.reach_tolerance > problem.rod.properties.length)
    throw InputError("PlanOptions.reach_tolerance",
                     " = " + detail::format_value(*options.reach_tolerance) +
                         " m must be at most the rod's length, " +
                         detail::format_value(problem.rod.properties.length) + " m");
  check_plan_cost(problem, options);
  PlanResult result =
      problem.arm || problem.base_arm
          ? detail::plan_with_arm(problem, options)
          : detail::plan_rod(problem, options, plan_stages::initial_equilibrium(problem));
  if (!problem.base_moves())  // the clamp's pose: the base end effector of every step
    for (PlanStep& step : result.steps) step.base_end_effector = problem.rod.clamp;
  result.options = options;
  return result;
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
