// moving_base_plan.cpp: the plan with a moving base (see moving_base_plan.hpp).
#include "moving_base_plan.hpp"

#include <algorithm>

#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/core/so3.hpp"
#include "rodshape/error.hpp"
#include "scene_stages.hpp"
#include "validation.hpp"

namespace rodshape::detail {

namespace {

using plan_stages::ObjectiveSet;

/// The stretch a free base's feasibility allows a Cosserat rod without a strain limit.
constexpr double kStretchSlack = 1e-3;

Pose base_of(const RodConfiguration& c) { return {c.p[0], c.R[0]}; }

/// What one step's optimisation knows of the moving base: about `reference`, with or without the
/// base's workspace.
BaseMotion base_motion(const PlanProblem& problem, const Pose& reference, bool with_workspace) {
  const MovingBase& base = *problem.moving_base;
  BaseMotion motion;
  motion.reference = reference;
  motion.released = base.grasp.released;
  motion.wrench_bounds = base.wrench_bounds;
  if (with_workspace) motion.workspace = base.workspace;
  motion.motion_weight = base.motion_weight;
  return motion;
}

/// The step's problem about `reference`: the rod's clamp there, the base's variables on.
ShapeProblem step_problem(const PlanProblem& problem,
                          const ShapeTarget& target,
                          const Pose& reference,
                          bool constrained,
                          const Clearance& clearance = {}) {
  ClampedRod rod = problem.rod;
  rod.clamp = reference;
  ShapeProblem shape = constrained ? ShapeProblem(rod, target, problem.workspace, problem.grasp,
                                                  problem.limits, WrenchBounds{}, clearance)
                                   : ShapeProblem(rod, target, Workspace{}, problem.grasp,
                                                  StrainLimits{}, WrenchBounds{});
  shape.move_base(base_motion(problem, reference, constrained));
  return shape;
}

/// x = (w_b, ξ) of an optimum (its base pose and world wrench) about `problem`'s reference.
Vector12d variables_of(const ShapeProblem& problem, const ShapeResult& solution) {
  const Pose& reference = problem.base_motion()->reference;
  const Pose base = base_of(solution.configuration);
  Vector12d x;
  x << base.rotation.transpose() * solution.base_wrench.force,
      base.rotation.transpose() * solution.base_wrench.moment, base.position - reference.position,
      log_so3(base.rotation * reference.rotation.transpose());
  return x;
}

/// One step's optimum about `reference` from the world wrench `start`: first without the
/// inequalities; when its optimum violates them, the full problem (as plan_stages::optimise_step).
ShapeResult optimise_moving_step(const PlanProblem& problem,
                                 const PlanOptions& options,
                                 const ShapeTarget& target,
                                 const Pose& reference,
                                 const BaseWrench& start,
                                 const Clearance& clearance) {
  ShapeProblem unconstrained = step_problem(problem, target, reference, false);
  ShapeResult solution = optimise_shape(unconstrained, start, options.optimiser);
  const bool has_inequalities =
      !problem.workspace.unbounded() || !problem.moving_base->workspace.unbounded() ||
      problem.limits.max_curvature || problem.limits.max_axial_strain || !clearance.empty();
  if (!has_inequalities) return solution;
  ShapeProblem full = step_problem(problem, target, reference, true, clearance);
  if (solution.converged()) {
    full.evaluate_with_base(variables_of(full, solution));
    if (full.constraint_violation() <= options.optimiser.constraint_tolerance) return solution;
  }
  ShapeResult constrained = optimise_shape(full, start, options.optimiser);
  if (!constrained.converged() && solution.converged()) {
    full.set_base_reference(base_of(solution.configuration));
    constrained = optimise_shape(full, solution.base_wrench, options.optimiser);
  }
  return constrained;
}

/// Where the steps stand.
struct MovingLoop {
  plan_stages::ObjectivePath path;
  std::vector<ObjectiveSet> pending;
  double f_last = 0.0;
  Pose from;               // the last tip waypoint (end effector)
  Pose base;               // the rod's base pose there
  BaseWrench planned;      // the last optimum's world wrench (the next warm start)
  BaseWrench tracked;      // the tracked rod's world wrench there
  RodConfiguration shape;  // the last planned shape
  bool tracking = true;
  std::vector<double> required;
};

/// One step's optimum about the last step's base pose, with the scene's rounds where it has one.
ShapeResult solve_moving_step(const PlanProblem& problem,
                              const PlanOptions& options,
                              const ShapeTarget& target,
                              const MovingLoop& loop,
                              int& obstacles) {
  obstacles = 0;
  if (problem.scene.empty())
    return optimise_moving_step(problem, options, target, loop.base, loop.planned, {});
  return plan_stages::solve_in_scene_rounds(
      problem, options, loop.required, loop.shape, target.points,
      [&](const Clearance& clearance) {
        return optimise_moving_step(problem, options, target, loop.base, loop.planned, clearance);
      },
      obstacles);
}

PlanStep make_step(const PlanProblem& problem,
                   const ObjectiveSet& set,
                   const PointSet& points,
                   ShapeResult&& solution) {
  const Pose tip_ee = compose(solution.configuration.tip(), problem.grasp.tip_to_end_effector);
  const Pose base_ee =
      compose(base_of(solution.configuration), problem.moving_base->grasp.tip_to_end_effector);
  return {set.fraction, set.inserted, false, points, std::move(solution), tip_ee, base_ee};
}

/// Steps 4–6 with a moving base; false when a step's optimisation fails.
bool plan_moving_steps(const PlanProblem& problem,
                       const PlanOptions& options,
                       MovingLoop& loop,
                       PlanResult& result) {
  const bool scene = !problem.scene.empty();
  for (std::size_t next = 0; next < loop.pending.size();) {
    const ObjectiveSet& set = loop.pending[next];
    ShapeTarget target = problem.target;
    target.points =
        scene ? scene_stages::clear_of_scene(problem.scene, loop.required, set.points) : set.points;
    int obstacles = 0;
    ShapeResult solution = solve_moving_step(problem, options, target, loop, obstacles);
    if (scene) result.scene->obstacles_per_step.push_back(obstacles);
    const int number = static_cast<int>(result.steps.size()) + 1;
    if (!solution.converged()) {
      result.status = PlanStatus::Partial;
      result.failed_step = static_cast<int>(result.steps.size());
      result.message = "step " + std::to_string(number) + " (fraction " +
                       std::to_string(set.fraction) + " of the way) failed: " + solution.message;
      return false;
    }
    PlanStep step = make_step(problem, set, target.points, std::move(solution));
    if (loop.tracking) {
      const plan_stages::SegmentTracking segment =
          plan_stages::track_segment(problem, options, loop.from, loop.tracked, step, number,
                                     scene ? &loop.required : nullptr, &loop.base);
      if ((segment.jump || segment.collision) &&
          result.tracking.refinements < options.max_refinements) {
        const ObjectiveSet half = plan_stages::halfway_set(loop.path, loop.f_last, set);
        loop.pending.insert(loop.pending.begin() + static_cast<std::ptrdiff_t>(next), half);
        ++result.tracking.refinements;
        continue;
      }
      plan_stages::record(result.tracking, segment, static_cast<int>(result.steps.size()));
      if (segment.gap)
        plan_stages::record_gap(result, problem, *segment.gap,
                                static_cast<int>(result.steps.size()) + 1);
      if (segment.collision && result.scene->note.empty()) result.scene->note = segment.note;
      if (segment.jump) loop.tracking = false;
      loop.tracked = segment.arrived;
    }
    loop.from = step.end_effector;
    loop.base = base_of(step.solution.configuration);
    loop.planned = step.solution.base_wrench;
    loop.shape = step.solution.configuration;
    loop.f_last = set.fraction;
    result.steps.push_back(std::move(step));
    ++next;
  }
  return true;
}

/// Throws InputError when the base's workspace excludes the initial base pose.
void require_base_in_workspace(const PlanProblem& problem) {
  const Workspace& workspace = problem.moving_base->workspace;
  if (workspace.contains(problem.rod.clamp, 1e-9)) return;
  throw InputError("PlanProblem.moving_base.workspace",
                   " excludes the initial base pose at " +
                       format_point(problem.rod.clamp.position) + " (PlanProblem.rod.clamp)");
}

/// 7. Both ends' paths on one clock.
void time_both_ends(const PlanProblem& problem,
                    const PlanOptions& options,
                    const RodConfiguration& initial,
                    PlanResult& result) {
  std::vector<Pose> tip{compose(initial.tip(), problem.grasp.tip_to_end_effector)};
  std::vector<Pose> base{compose(base_of(initial), problem.moving_base->grasp.tip_to_end_effector)};
  for (const PlanStep& step : result.steps) {
    tip.push_back(step.end_effector);
    base.push_back(step.base_end_effector);
  }
  TwoEndPath path =
      time_parameterize_together(tip, base, options.end_effector, options.base_end_effector);
  result.end_effector_path = std::move(path.tip);
  result.base_end_effector_path = std::move(path.base);
}

}  // namespace

FeasibilityResult free_base_feasibility(const PlanProblem& problem) {
  const PointSet& points = problem.target.points;
  // A Cosserat rod's own equilibria are stretched by their tension (the band's by ~2e-4): points
  // taken from one may make a chain a little longer than L, which a fixed clamp's check allows for
  // no better; 1e-3 of slack for them, none for an inextensible Kirchhoff rod.
  const double slack =
      problem.rod.properties.model == ConstitutiveModel::Cosserat ? kStretchSlack : 0.0;
  const double strain = std::max(problem.limits.max_axial_strain.value_or(0.0), slack);
  const double reach = problem.rod.properties.length * (1.0 + strain);
  double chain = 0.0;
  for (std::size_t i = 1; i < points.size(); ++i) chain += (points[i] - points[i - 1]).norm();
  const Eigen::Vector3d& first = points.front();
  Eigen::Vector3d back = first - problem.rod.clamp.position;  // towards p_1 from before it
  if (points.size() > 1 && (points[1] - first).norm() > 0.0) back = points[1] - first;
  const double lead =
      std::clamp(std::min((first - problem.rod.clamp.position).norm(), reach - chain), 0.0, reach);
  FeasibilityResult feasibility;
  for (double before : {lead, 0.0}) {
    ClampedRod virtual_clamp = problem.rod;
    virtual_clamp.clamp.position =
        back.norm() > 0.0 ? Eigen::Vector3d(first - before * back.normalized()) : first;
    feasibility = check_feasibility(problem.target, virtual_clamp, strain);
    if (feasibility.feasible) return feasibility;
  }
  return feasibility;
}

PlanResult plan_moving_base(const PlanProblem& problem,
                            const PlanOptions& options,
                            const plan_stages::InitialEquilibrium& initial) {
  require_base_in_workspace(problem);
  PlanResult result;
  result.interpolation.used = options.interpolation == ObjectiveInterpolation::Auto
                                  ? ObjectiveInterpolation::Shape
                                  : options.interpolation;
  result.initial_wrench = initial.wrench;
  result.initial_configuration = initial.configuration;
  result.initial_stable_search = initial.stable_search;
  result.feasibility = free_base_feasibility(problem);
  MovingLoop loop;
  if (!problem.scene.empty())
    plan_stages::start_scene(problem, initial.configuration, loop.required, result);
  if (!result.feasibility.feasible) {
    result.status = PlanStatus::Infeasible;
    result.message = result.feasibility.reason;
    return result;
  }
  PlanOptions sets_options = options;
  sets_options.interpolation = result.interpolation.used;
  result.initial_points =
      plan_stages::initial_points(problem, sets_options, initial, result.feasibility);
  loop.path = {problem.rod.clamp.position, result.initial_points, problem.target.points,
               result.interpolation.used, true};
  loop.pending = plan_stages::objective_sets(loop.path, options.steps);
  if (options.planned_steps() < options.steps) {
    loop.pending.resize(static_cast<std::size_t>(options.planned_steps()));
    result.horizon = options.planned_steps();
  }
  loop.from = compose(initial.configuration.tip(), problem.grasp.tip_to_end_effector);
  loop.base = problem.rod.clamp;
  loop.planned = loop.tracked = initial.wrench;
  loop.shape = initial.configuration;
  loop.tracking = options.track_between_waypoints;
  result.status = PlanStatus::Complete;
  if (plan_moving_steps(problem, options, loop, result))
    result.message =
        "complete: " + std::to_string(result.steps.size()) + " steps, the base moving with the tip";
  plan_stages::settle_status(result);
  plan_stages::settle_reach(result, problem, options);
  time_both_ends(problem, options, initial.configuration, result);
  result.interpolation.tried = {{result.interpolation.used, result.status,
                                 plan_stages::peak_ratio(result),
                                 result.complete() ? "" : result.message}};
  return result;
}

}  // namespace rodshape::detail
