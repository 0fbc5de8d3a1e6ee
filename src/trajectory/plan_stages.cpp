// plan_stages.cpp: the stages of plan() (see plan_stages.hpp).
#include "plan_stages.hpp"
#include "scene_stages.hpp"

#include <algorithm>
#include <limits>
#include <sstream>

#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/error.hpp"
#include "rodshape/optimisation/curve_distance.hpp"
#include "rodshape/solvers/follow_equilibrium.hpp"
#include "rodshape/solvers/model_validity.hpp"
#include "rodshape/solvers/rod_reach.hpp"
#include "rodshape/solvers/shooting_solver.hpp"
#include "rodshape/solvers/stability.hpp"
#include "rodshape/solvers/stable_equilibrium.hpp"
#include "validation.hpp"

namespace rodshape::plan_stages {

namespace {

bool any(const std::array<bool, 6>& flags) {
  return std::any_of(flags.begin(), flags.end(), [](bool b) { return b; });
}

/// Throws InputError when the workspace excludes the initial tip (with the reach point's distance
/// when the reach shell is what excludes it).
void require_in_workspace(const Workspace& workspace, const Pose& tip, InitialState::Kind initial) {
  if (workspace.contains(tip, 1e-9)) return;
  std::string reason = " excludes the initial tip at " + detail::format_point(tip.position);
  if (const auto& reach = workspace.reach) {
    const double r = reach->distance(tip);
    if (r > reach->outer_radius || r < reach->inner_radius)
      reason += " (its reach point is " + std::to_string(r) +
                " m from the reach centre, outside [" + std::to_string(reach->inner_radius) + ", " +
                std::to_string(reach->outer_radius) + "] m)";
  }
  reason += initial == InitialState::Kind::Rest ? " (the rod at rest; set PlanProblem.initial.tip)"
                                                : " (PlanProblem.initial)";
  throw InputError("PlanProblem.workspace", reason);
}

/// The equilibrium held at `tip`, solved from rest (with continuation).
InitialEquilibrium held_equilibrium(const PlanProblem& problem, const Pose& tip) {
  const TipCondition held = held_tip(tip, problem.grasp);
  check_within_reach(problem.rod, held, problem.validity, "PlanProblem.initial.tip",
                     "PlanProblem.validity");
  ShootingOptions options;
  options.output_derivatives = Derivatives::AllNodes;  // for the stability test
  ShootingResult solved = solve_equilibrium(problem.rod, held, BaseWrench{}, options);
  if (!solved.summary.converged())
    throw InputError("PlanProblem.initial.tip",
                     ": no equilibrium holds the rod there (" + solved.summary.brief() + ")");
  check_model_validity(problem.rod.properties, solved.configuration, problem.validity,
                       "PlanProblem.initial.tip", "PlanProblem.validity");
  // A cold solve may land on an unstable equilibrium the real rod would not rest in.
  ClampedRod at = problem.rod;
  at.substeps = solved.summary.substeps;
  const StabilityResult verdict = assess_stability(at, solved.configuration, held);
  if (verdict.stable) return {solved.base_wrench, solved.configuration, std::nullopt};
  StableEquilibriumResult search =
      seek_stable_equilibrium(problem.rod, held, solved, verdict, options);
  if (search.found) solved = std::move(search.solution);
  return {solved.base_wrench, solved.configuration, search.message};
}

/// The equilibrium of a given base wrench; the released grasp axes must carry no tip wrench.
InitialEquilibrium given_equilibrium(const PlanProblem& problem, const BaseWrench& w) {
  InitialEquilibrium initial{w, integrate(problem.rod, w, Derivatives::AllNodes), std::nullopt};
  const Vector6d tip_wrench = initial.configuration.tip_wrench().to_vector();
  const double tolerance = ShootingOptions{}.residual_tolerance;
  for (int k = 0; k < 6; ++k) {
    if (problem.grasp.released[k] && std::abs(tip_wrench[k]) > tolerance)
      throw InputError("PlanProblem.initial.base_wrench",
                       ": its tip wrench component " + std::to_string(k) + " = " +
                           std::to_string(tip_wrench[k]) +
                           " is one the grasp releases (Grasp.released): not an equilibrium "
                           "of the grasped rod");
  }
  check_model_validity(problem.rod.properties, initial.configuration, problem.validity,
                       "PlanProblem.initial.base_wrench", "PlanProblem.validity");
  return initial;
}

}  // namespace

TipCondition held_tip(const Pose& tip, const Grasp& grasp) {
  if (!any(grasp.released)) return ClampedTip{tip};
  return GraspedTip{tip, grasp.released};
}

EquilibriumPath commanded_segment(const PlanProblem& problem,
                                  const Pose& from,
                                  const Pose& to,
                                  const Pose* base_from,
                                  const Pose* base_to) {
  const Pose ee_T_tip = inverse(problem.grasp.tip_to_end_effector);
  EquilibriumPath path{[from, to, ee_T_tip, grasp = problem.grasp](double sigma) {
                         return held_tip(compose(interpolate(from, to, sigma), ee_T_tip), grasp);
                       },
                       false};
  if (base_from && base_to)
    path.clamp_at = [a = *base_from, b = *base_to](double sigma) {
      return interpolate(a, b, sigma);
    };
  return path;
}

InitialEquilibrium initial_equilibrium(const PlanProblem& problem) {
  InitialEquilibrium initial;
  switch (problem.initial.kind) {
    case InitialState::Kind::Rest:
      initial.configuration = integrate(problem.rod, BaseWrench{}, Derivatives::AllNodes);
      break;
    case InitialState::Kind::HeldTip:
      initial = held_equilibrium(problem, problem.initial.tip);
      break;
    case InitialState::Kind::Equilibrium:
      initial = given_equilibrium(problem, problem.initial.base_wrench);
      break;
  }
  require_in_workspace(problem.workspace, initial.configuration.tip(), problem.initial.kind);
  return initial;
}

PointSet initial_points(const PlanProblem& problem,
                        const PlanOptions& options,
                        const InitialEquilibrium& initial,
                        const FeasibilityResult& feasibility) {
  if (options.interpolation == ObjectiveInterpolation::Projection)
    return project_onto_initial_shape(initial.configuration, problem.target.points);
  if (initial.configuration.derivatives == Derivatives::AllNodes)
    return points_at_arc_lengths(problem.rod, initial.configuration, feasibility.arc_lengths);
  return points_at_arc_lengths(problem.rod,
                               integrate(problem.rod, initial.wrench, Derivatives::AllNodes),
                               feasibility.arc_lengths);
}

PointSet ObjectivePath::at(double fraction) const {
  if (interpolation == ObjectiveInterpolation::Shape && moving_base)
    return aligned_objective_set(clamp, initial, objective, fraction);
  if (interpolation == ObjectiveInterpolation::Shape)
    return turned_objective_set(clamp, initial, objective, fraction);
  return objective_set(initial, objective, fraction);
}

std::vector<ObjectiveSet> objective_sets(const ObjectivePath& path, int steps) {
  std::vector<ObjectiveSet> sets;
  for (int i = 1; i <= steps; ++i) {
    const double f = static_cast<double>(i) / steps;
    sets.push_back({f, path.at(f), false});
  }
  return sets;
}

void StepHistory::push(const BaseWrench& w, double fraction) {
  before = last;
  f_before = f_last;
  last = w;
  f_last = fraction;
  ++steps;
}

BaseWrench warm_start(ShapeProblem& unconstrained, const StepHistory& history, double fraction) {
  if (history.steps < 2) return history.last;
  const Vector6d w = history.last.to_vector();
  const double ratio = (fraction - history.f_last) / (history.f_last - history.f_before);
  const Vector6d secant = w + ratio * (w - history.before.to_vector());
  unconstrained.evaluate(w);
  const double cost_at_last = unconstrained.cost();
  unconstrained.evaluate(secant);
  return unconstrained.cost() < cost_at_last ? Wrench::from_vector(secant) : history.last;
}

ShapeResult optimise_step(const PlanProblem& problem,
                          const ShapeTarget& target,
                          ShapeProblem& unconstrained,
                          const BaseWrench& start,
                          const ShapeOptimiserOptions& options,
                          const Clearance& clearance) {
  ShapeResult solution = optimise_shape(unconstrained, start, options);
  const bool has_inequalities = !problem.workspace.unbounded() || problem.limits.max_curvature ||
                                problem.limits.max_axial_strain || !clearance.empty();
  if (!has_inequalities) return solution;
  ShapeProblem full(problem.rod, target, problem.workspace, problem.grasp, problem.limits,
                    problem.wrench_bounds, clearance);
  if (solution.converged()) {
    // The inequalities hold at the unconstrained optimum: it is a local optimum of the full
    // problem too, with multipliers 0.
    full.evaluate(solution.base_wrench.to_vector());
    if (full.constraint_violation() <= options.constraint_tolerance) return solution;
  }
  // Violated: the full problem, from the step's start (the warm start), and failing that from the
  // unconstrained optimum.
  ShapeResult constrained = optimise_shape(full, start, options);
  if (!constrained.converged() && solution.converged())
    constrained = optimise_shape(full, solution.base_wrench, options);
  return constrained;
}

SegmentTracking track_segment(const PlanProblem& problem,
                              const PlanOptions& options,
                              const Pose& from,
                              const BaseWrench& w,
                              const PlanStep& step,
                              int waypoint,
                              const std::vector<double>* required,
                              const Pose* base_from) {
  constexpr double kJumpDeviation = 1e-3;  // m
  FollowOptions follow;
  follow.substeps = options.tracking_substeps;
  follow.final_derivatives = Derivatives::AllNodes;  // for the stability test on arrival
  follow.arrival_stability = true;
  std::optional<SceneGap> least;
  std::optional<scene_stages::SweptGap> swept;
  ClampedRod start_rod = problem.rod;
  if (base_from) start_rod.clamp = *base_from;
  const Pose base_to =
      step.solution.configuration.nodes() > 0
          ? Pose{step.solution.configuration.p[0], step.solution.configuration.R[0]}
          : problem.rod.clamp;
  if (required != nullptr) {
    swept.emplace(problem.scene, *required, integrate(start_rod, w, Derivatives::None).p);
    follow.observer = [&](double, const RodConfiguration& c) {
      const SceneGap gap = swept->add(c.p);
      if (!least || gap.margin < least->margin) least = gap;
      return true;
    };
  }
  const FollowResult followed =
      follow_equilibrium(start_rod,
                         commanded_segment(problem, from, step.end_effector, base_from,
                                           base_from ? &base_to : nullptr),
                         w, follow, &step.solution.configuration, kJumpDeviation);
  SegmentTracking segment;
  segment.jump = !followed.followed();
  segment.gap = least;
  segment.collision = least && !least->clear();
  for (const FollowedState& state : followed.states) {
    segment.peak_energy = std::max(segment.peak_energy, state.energy);
    segment.peak_curvature = std::max(segment.peak_curvature, state.max_curvature);
  }
  if (followed.event == FollowEvent::Lost) {
    segment.deviation = std::numeric_limits<double>::infinity();
    segment.note = "the equilibrium could not be followed towards waypoint " +
                   std::to_string(waypoint) + " at " + std::to_string(followed.event_sigma) +
                   " of the way (" + followed.failed_solve.brief() + ")";
    return segment;
  }
  segment.arrived = followed.base_wrench;
  segment.deviation = followed.arrival_deviation;
  if (followed.event == FollowEvent::OtherBranch) {
    segment.energy_released = step.solution.configuration.energy - followed.configuration.energy;
    segment.note = "on arrival at waypoint " + std::to_string(waypoint) + " the tracked rod is " +
                   std::to_string(segment.deviation) +
                   " m from the planned shape: it jumped to another equilibrium (" +
                   std::to_string(*segment.energy_released) + " J released)";
  } else if (followed.event == FollowEvent::Unstable)
    segment.note =
        "the tracked equilibrium at waypoint " + std::to_string(waypoint) + " is unstable";
  if (segment.collision && segment.note.empty()) {
    const Obstacle& obstacle = problem.scene.obstacles[static_cast<std::size_t>(least->obstacle)];
    std::ostringstream out;
    out.precision(3);
    out << "on the way to waypoint " << waypoint << " the rod comes within " << least->gap * 1e3
        << " mm of obstacle " << obstacle.label(least->obstacle)
        << " at s = " << (least->segment + least->t) * problem.rod.step() << " m (required "
        << (least->gap - least->margin) * 1e3 << " mm, " << -least->margin * 1e3
        << " mm nearer than that)";
    segment.note = out.str();
  }
  return segment;
}

void record(TrackingResult& tracking, const SegmentTracking& segment, int step_index) {
  tracking.performed = true;
  tracking.arrival_deviation.push_back(segment.deviation);
  tracking.max_deviation = std::max(tracking.max_deviation, segment.deviation);
  tracking.peak_energy = std::max(tracking.peak_energy, segment.peak_energy);
  tracking.peak_curvature = std::max(tracking.peak_curvature, segment.peak_curvature);
  if (segment.jump && !tracking.jump) {
    tracking.jump = true;
    tracking.jump_step = step_index;
    tracking.energy_released = segment.energy_released;
    tracking.note = segment.note;
  }
}

ObjectiveSet halfway_set(const ObjectivePath& path, double f_last, const ObjectiveSet& set) {
  const double half = 0.5 * (f_last + set.fraction);
  return {half, path.at(half), true};
}

void record_gap(PlanResult& result, const PlanProblem& problem, const SceneGap& gap, int step) {
  SceneResult& scene = *result.scene;
  if (!(gap.margin < scene.margin)) return;
  scene.min_gap = gap.gap;
  scene.margin = gap.margin;
  scene.step = step;
  scene.s = (gap.segment + gap.t) * problem.rod.step();
  scene.obstacle = gap.obstacle;
  scene.obstacle_label =
      problem.scene.obstacles[static_cast<std::size_t>(gap.obstacle)].label(gap.obstacle);
}

void start_scene(const PlanProblem& problem,
                 const RodConfiguration& initial,
                 std::vector<double>& required,
                 PlanResult& result) {
  required = problem.scene.required_gaps(problem.rod.clamp.position);
  result.scene = SceneResult{};
  result.scene->clearance = problem.scene.clearance;
  const SceneGap gap = problem.scene.least_gap(initial.p, required);
  record_gap(result, problem, gap, 0);
  if (!result.scene->clear()) {
    std::ostringstream out;
    out.precision(3);
    out << ": the initial rod comes within " << gap.gap * 1e3 << " mm of obstacle "
        << result.scene->obstacle_label << " at s = " << result.scene->s << " m (required "
        << (gap.gap - gap.margin) * 1e3 << " mm, " << -gap.margin * 1e3 << " mm nearer than that)";
    throw InputError("PlanProblem.initial", out.str());
  }
}

ShapeResult solve_in_scene_rounds(const PlanProblem& problem,
                                  const PlanOptions& options,
                                  const std::vector<double>& required,
                                  const RodConfiguration& start_shape,
                                  const PointSet& points,
                                  const std::function<ShapeResult(const Clearance&)>& solve,
                                  int& obstacles) {
  constexpr int kMaxRounds = 4;
  const double margin = options.scene_margin * problem.scene.clearance;
  std::vector<int> forced;
  for (int round = 1;; ++round) {
    const Clearance clearance = scene_stages::step_clearance(
        problem.scene, required, start_shape, points, options.scene_reach, margin, forced);
    ShapeResult solution = solve(clearance);
    const std::vector<int> violated =
        solution.converged() ? scene_stages::violated_obstacles(problem.scene, required,
                                                                solution.configuration, clearance)
                             : std::vector<int>{};
    if (violated.empty() || round == kMaxRounds) {
      obstacles = static_cast<int>(clearance.scene.obstacles.size());
      return solution;
    }
    forced.insert(forced.end(), violated.begin(), violated.end());
  }
}

void settle_status(PlanResult& result) {
  const TrackingResult& tracking = result.tracking;
  if (tracking.performed && !tracking.jump)
    result.tracking.note = tracking.refinements == 0
                               ? "the rod follows the plan"
                               : "the rod follows the plan (" +
                                     std::to_string(tracking.refinements) +
                                     " steps inserted where it would have jumped)";
  if (result.status == PlanStatus::Complete && tracking.jump) {
    result.status = PlanStatus::SnapThrough;
    result.message = "the rod would not follow the plan towards waypoint " +
                     std::to_string(tracking.jump_step + 1) + ": " + tracking.note;
  }
  if (result.status == PlanStatus::Complete && result.scene && !result.scene->clear()) {
    result.status = PlanStatus::Collision;
    result.message = "the rod would not stay clear of the scene: " + result.scene->note;
  }
}

void settle_reach(PlanResult& result, const PlanProblem& problem, const PlanOptions& options) {
  const RodConfiguration& final_shape = result.steps.empty()
                                            ? result.initial_configuration
                                            : result.steps.back().solution.configuration;
  result.reach_tolerance = options.reach_tolerance_for(problem.rod.properties.length);
  result.target_distance = 0.0;
  result.target_point = -1;
  if (final_shape.p.empty()) return;  // no initial equilibrium (an input error before any step)
  std::vector<IntervalBall> balls;
  interval_balls(final_shape, balls);
  for (std::size_t k = 0; k < problem.target.points.size(); ++k) {
    const double d = project_onto_curve(final_shape, problem.target.points[k], balls).distance;
    if (d > result.target_distance || result.target_point < 0) {
      result.target_distance = d;
      result.target_point = static_cast<int>(k);
    }
  }
  if (result.status != PlanStatus::Complete || result.horizon > 0 ||
      !(result.target_distance > result.reach_tolerance))
    return;
  std::ostringstream out;
  out.precision(3);
  out << "every step succeeded (" << result.steps.size() << "), but the final shape passes "
      << result.target_distance * 1e3 << " mm from target point " << result.target_point
      << ", beyond the reach tolerance of " << result.reach_tolerance * 1e3 << " mm";
  result.status = PlanStatus::Partial;
  result.message = out.str();
}

std::vector<TimedPose> time_waypoints(const Pose& initial_end_effector,
                                      const std::vector<PlanStep>& steps,
                                      const EndEffectorLimits& limits) {
  std::vector<Pose> waypoints{initial_end_effector};
  for (const PlanStep& step : steps) waypoints.push_back(step.end_effector);
  return time_parameterize(waypoints, limits);
}

/// 8. The held rod followed along the timed path's samples, one solve each (what a robot moving at
/// that rate does, and what an independent replay checks), in pieces of at most
/// FollowOptions::kMaxSubsteps: it must arrive on the last step.
/// The path's own substeps can pass a point where the branch divides (a fold, or a bifurcation the
/// path passes near) one way and the samples another: such a path is no plan.
bool follows_timed_path(const PlanProblem& problem, const PlanResult& result) {
  std::vector<TipCondition> samples;
  const Pose ee_T_tip = inverse(problem.grasp.tip_to_end_effector);
  for (const TimedPose& sample : result.end_effector_path)
    samples.push_back(plan_stages::held_tip(compose(sample.pose, ee_T_tip), problem.grasp));
  FollowOptions fine;
  fine.final_derivatives = Derivatives::None;
  BaseWrench w = result.initial_wrench;
  for (std::size_t first = 0; first + 1 < samples.size();) {
    const std::size_t last =
        std::min(samples.size() - 1, first + static_cast<std::size_t>(FollowOptions::kMaxSubsteps));
    fine.substeps = static_cast<int>(last - first);
    const bool arrival = last == samples.size() - 1;
    const FollowResult piece = follow_equilibrium(
        problem.rod,
        sampled_tip_path(
            std::vector<TipCondition>(samples.begin() + first, samples.begin() + last + 1)),
        w, fine, arrival ? &result.steps.back().solution.configuration : nullptr, 1e-3);
    if (!piece.followed()) return false;
    w = piece.base_wrench;
    first = last;
  }
  return true;
}

double peak_ratio(const PlanResult& plan) {
  const bool reached = plan.status != PlanStatus::Partial && plan.status != PlanStatus::Infeasible;
  if (!reached || plan.steps.empty() || !plan.tracking.performed) return std::nan("");
  const double larger =
      std::max(plan.initial_configuration.energy, plan.steps.back().solution.configuration.energy);
  return larger > 0.0 ? plan.tracking.peak_energy / larger : std::nan("");
}

double reached_within(const PlanResult& shape, const PlanProblem& problem) {
  const double length = problem.rod.properties.length;
  const bool reached =
      shape.status != PlanStatus::Partial && shape.status != PlanStatus::Infeasible;
  if (!reached || shape.steps.empty()) return 0.01 * length;
  return std::max(1.05 * shape.steps.back().solution.cost.max_distance + 1e-4,
                  kNearTarget * length);
}

}  // namespace rodshape::plan_stages
