#include "rodshape/trajectory/shape_plan.hpp"

#include <algorithm>
#include <limits>
#include <sstream>

#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/error.hpp"
#include "rodshape/optimisation/shape_problem.hpp"
#include "rodshape/solvers/shooting_solver.hpp"
#include "rodshape/solvers/stability.hpp"

namespace rodshape {

void PlanOptions::validate() const {
  if (steps < 1) throw InputError("trajectory.steps = " + std::to_string(steps) + " must be >= 1");
  if (max_refinements < 0)
    throw InputError("trajectory.max_refinements = " + std::to_string(max_refinements) +
                     " must be >= 0");
  if (tracking_substeps < 1)
    throw InputError("trajectory.tracking_substeps = " + std::to_string(tracking_substeps) +
                     " must be >= 1");
  optimizer.validate();
  end_effector.validate();
}

std::string to_string(PlanStatus status) {
  switch (status) {
    case PlanStatus::Complete:
      return "complete";
    case PlanStatus::Partial:
      return "partial";
    case PlanStatus::Infeasible:
      return "infeasible";
  }
  return "unknown";
}

namespace {

std::string format_point(const Eigen::Vector3d& p) {
  std::ostringstream out;
  out.precision(4);
  out << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return out.str();
}

/// The condition the gripper imposes while it moves: the tip held at a pose, with the components
/// the grasp cannot transmit released.
TipCondition held_tip(const Pose& tip, const Grasp& grasp) {
  if (std::none_of(grasp.zero_wrench.begin(), grasp.zero_wrench.end(), [](bool b) { return b; }))
    return ClampedTip{tip};
  return GraspedTip{tip, grasp.zero_wrench};
}

/// Largest distance between corresponding nodes of two configurations of the same rod.
double node_deviation(const RodConfiguration& a, const RodConfiguration& b) {
  double worst = 0.0;
  for (int i = 0; i < a.nodes(); ++i) worst = std::max(worst, (a.p[i] - b.p[i]).norm());
  return worst;
}

/// One step's optimum. The workspace and the strain limits are inequalities that are inactive for
/// most steps, and even an inactive one changes the interior-point path (its barrier term is
/// comparable to the small shape cost at first; from the straight rod, a box of ±1 m sent IPOPT
/// to a coiled rod). So the step is solved first without them (`unconstrained` holds the grasp
/// rows only); when the optimum respects them it is also a local optimum of the full problem, else
/// the full problem is solved from there.
ShapeSolution optimise_step(const PlanRequest& request,
                            const ShapeTarget& target,
                            ShapeProblem& unconstrained,
                            const BaseWrench& start,
                            const ShapeOptimizerOptions& options) {
  ShapeSolution solution = optimise_shape(unconstrained, start, options);
  const bool has_inequalities = !request.workspace.unbounded() || request.limits.max_curvature ||
                                request.limits.max_axial_strain;
  if (!has_inequalities) return solution;
  ShapeProblem full(request.rod, target, request.workspace, request.grasp, request.limits,
                    request.wrench_bounds);
  if (solution.converged()) {
    // The inequalities hold at the unconstrained optimum: it is a local optimum of the full
    // problem too, with multipliers 0.
    full.evaluate(solution.base_wrench.to_vector());
    if (full.constraint_violation() <= options.constraint_tolerance) return solution;
  }
  // Violated: the full problem, from the step's start (the warm start), and failing that from the
  // unconstrained optimum.
  ShapeSolution constrained = optimise_shape(full, start, options);
  if (!constrained.converged() && solution.converged())
    constrained = optimise_shape(full, solution.base_wrench, options);
  return constrained;
}

}  // namespace

namespace {

/// The equilibrium followed from one waypoint to the next.
struct SegmentTracking {
  bool jump = false;
  double deviation = 0.0;  // on arrival, from the planned shape
  BaseWrench arrived;      // the tracked base wrench on arrival
  std::string note;
};

/// Follows the equilibrium along the commanded end-effector path from `from` (with base wrench
/// `w`) to `step`'s waypoint in options.tracking_substeps continuation steps, and compares it on
/// arrival with the planned shape: farther than 1 mm, or unstable, is a jump.
SegmentTracking track_segment(const PlanRequest& request,
                              const PlanOptions& options,
                              const Pose& from,
                              BaseWrench w,
                              const PlanStep& step,
                              int waypoint) {
  constexpr double kJumpDeviation = 1e-3;  // m
  ShootingOptions shooting;
  shooting.continuation = false;  // a failure here is what we want to see, not to repair
  shooting.output_derivatives = Derivatives::None;
  const Pose ee_T_tip = inverse(request.grasp.tip_to_end_effector);
  SegmentTracking segment;
  RodConfiguration arrived;
  for (int j = 1; j <= options.tracking_substeps; ++j) {
    const double sigma = static_cast<double>(j) / options.tracking_substeps;
    const Pose tip = compose(interpolate(from, step.end_effector, sigma), ee_T_tip);
    // On arrival the stability test needs every node's derivatives: the solver's last
    // integration gives them.
    if (j == options.tracking_substeps) shooting.output_derivatives = Derivatives::AllNodes;
    ShootingSolution tracked =
        solve_equilibrium(request.rod, held_tip(tip, request.grasp), w, shooting);
    if (!tracked.summary.converged()) {
      segment.jump = true;
      segment.deviation = std::numeric_limits<double>::infinity();
      segment.note = "the equilibrium could not be followed towards waypoint " +
                     std::to_string(waypoint) + " at " + std::to_string(sigma) + " of the way (" +
                     tracked.summary.brief() + ")";
      return segment;
    }
    w = tracked.base_wrench;
    arrived = std::move(tracked.configuration);
  }
  segment.arrived = w;
  // On arrival the tracked rod should be the planned equilibrium; otherwise it jumped to another
  // branch on the way (snap-through).
  segment.deviation = node_deviation(arrived, step.solution.configuration);
  if (segment.deviation > kJumpDeviation) {
    segment.jump = true;
    segment.note = "on arrival at waypoint " + std::to_string(waypoint) + " the tracked rod is " +
                   std::to_string(segment.deviation) +
                   " m from the planned shape: it jumped to another equilibrium";
    return segment;
  }
  const StabilityReport stability = assess_stability(request.rod, arrived);
  if (!stability.stable && !stability.degenerate) {
    segment.jump = true;
    segment.note =
        "the tracked equilibrium at waypoint " + std::to_string(waypoint) + " is unstable";
  }
  return segment;
}

void record(TrackingReport& report, const SegmentTracking& segment, int step_index) {
  report.performed = true;
  report.arrival_deviation.push_back(segment.deviation);
  report.max_deviation = std::max(report.max_deviation, segment.deviation);
  if (segment.jump && !report.jump) {
    report.jump = true;
    report.jump_step = step_index;
    report.note = segment.note;
  }
}

}  // namespace

TrackingReport track_plan(const PlanRequest& request,
                          const PlanOptions& options,
                          const ShapePlan& plan) {
  TrackingReport report;
  report.performed = true;
  Pose from = compose(plan.initial_configuration.tip(), request.grasp.tip_to_end_effector);
  BaseWrench w = plan.initial_wrench;
  for (std::size_t k = 0; k < plan.steps.size() && !report.jump; ++k) {
    const SegmentTracking segment =
        track_segment(request, options, from, w, plan.steps[k], static_cast<int>(k) + 1);
    record(report, segment, static_cast<int>(k));
    w = segment.arrived;
    from = plan.steps[k].end_effector;
  }
  if (!report.jump) report.note = "the rod follows the plan";
  return report;
}

ShapePlan plan_shape(const PlanRequest& request, const PlanOptions& options) {
  options.validate();
  request.rod.validate();
  request.target.validate();
  request.workspace.validate();
  request.limits.validate();

  ShapePlan plan;
  // 1. The initial configuration: held at the initial tip pose, or at rest.
  if (request.initial_tip) {
    ShootingOptions shooting;
    const ShootingSolution initial =
        solve_equilibrium(request.rod, held_tip(*request.initial_tip, request.grasp), {}, shooting);
    if (!initial.summary.converged())
      throw InputError("initial.tip: no equilibrium holds the rod there (" +
                       initial.summary.brief() + ")");
    plan.initial_wrench = initial.base_wrench;
    plan.initial_configuration = initial.configuration;
  } else {
    plan.initial_configuration = integrate(request.rod, BaseWrench{}, Derivatives::AllNodes);
  }
  const Pose initial_tip = plan.initial_configuration.tip();
  if (!request.workspace.contains(initial_tip, 1e-9)) {
    std::string reason =
        "workspace excludes the initial tip at " + format_point(initial_tip.position);
    if (const auto& reach = request.workspace.reach) {
      const double r = reach->distance(initial_tip);
      if (r > reach->outer_radius || r < reach->inner_radius)
        reason += " (its reach point is " + std::to_string(r) +
                  " m from the reach centre, outside [" + std::to_string(reach->inner_radius) +
                  ", " + std::to_string(reach->outer_radius) + "] m)";
    }
    throw InputError(reason);
  }
  const Pose initial_end_effector = compose(initial_tip, request.grasp.tip_to_end_effector);

  // 2. Is the target within reach at all?
  const TargetFeasibility feasibility =
      check_feasibility(request.target, request.rod, request.limits.max_axial_strain.value_or(0.0));
  if (!feasibility.feasible) {
    plan.status = PlanStatus::Infeasible;
    plan.message = feasibility.reason;
    return plan;
  }

  // 3. p_init on the initial shape; the objective set of fraction f is p_init + f (p_obj - p_init),
  //    f = i / n_inter for the n_inter steps (the last is p_obj itself).
  plan.initial_points =
      project_onto_initial_shape(plan.initial_configuration, request.target.points);
  const auto set_at = [&](double f) {
    return objective_set(plan.initial_points, request.target.points, f);
  };
  struct Pending {
    double fraction;
    PointSet points;
    bool inserted;
  };
  std::vector<Pending> pending;
  for (int i = 1; i <= options.steps; ++i) {  // as intermediate_targets() makes them
    const double f = static_cast<double>(i) / options.steps;
    pending.push_back({f, set_at(f), false});
  }

  // 4. One optimal shape per set, each warm-started from the last (see optimise_step). From the
  //    third step on, the secant extrapolation of the last two optima is tried as well (the sets
  //    move on straight lines, so the optima move smoothly) and the start of lower cost is kept.
  //    Each new waypoint is tracked from the last; where the rod would jump, a step is inserted
  //    halfway and the segment planned again.
  BaseWrench w = plan.initial_wrench, w_before = plan.initial_wrench;
  double f_last = 0.0, f_before = 0.0;
  Pose from = initial_end_effector;
  BaseWrench tracked_w = plan.initial_wrench;
  bool tracking = options.track_between_waypoints;
  plan.status = PlanStatus::Complete;
  for (std::size_t next = 0; next < pending.size();) {
    const Pending& set = pending[next];
    ShapeTarget target = request.target;
    target.points = set.points;
    ShapeProblem problem(request.rod, target, Workspace{}, request.grasp, StrainLimits{},
                         request.wrench_bounds);
    BaseWrench start = w;
    if (plan.steps.size() >= 2) {
      const double ratio = (set.fraction - f_last) / (f_last - f_before);
      const Vector6d secant = w.to_vector() + ratio * (w.to_vector() - w_before.to_vector());
      problem.evaluate(w.to_vector());
      const double cost_at_last = problem.cost();
      problem.evaluate(secant);
      if (problem.cost() < cost_at_last) start = Wrench::from_vector(secant);
    }
    ShapeSolution solution = optimise_step(request, target, problem, start, options.optimizer);
    const int number = static_cast<int>(plan.steps.size()) + 1;
    if (!solution.converged()) {
      plan.status = PlanStatus::Partial;
      plan.failed_step = static_cast<int>(plan.steps.size());
      plan.message = "step " + std::to_string(number) + " (fraction " +
                     std::to_string(set.fraction) + " of the way) failed: " + solution.message;
      break;
    }
    const Pose end_effector =
        compose(solution.configuration.tip(), request.grasp.tip_to_end_effector);
    PlanStep step{set.fraction, set.inserted, set.points, std::move(solution), end_effector};
    if (tracking) {
      const SegmentTracking segment =
          track_segment(request, options, from, tracked_w, step, number);
      if (segment.jump && plan.tracking.refinements < options.max_refinements) {
        // Plan the segment again through a set halfway (from the same last optimum).
        const double half = 0.5 * (f_last + set.fraction);
        pending.insert(pending.begin() + static_cast<std::ptrdiff_t>(next),
                       {half, set_at(half), true});
        ++plan.tracking.refinements;
        continue;
      }
      record(plan.tracking, segment, static_cast<int>(plan.steps.size()));
      if (segment.jump) tracking = false;  // past a jump, following the plan means nothing
      tracked_w = segment.arrived;
      from = end_effector;
    }
    w_before = w;
    f_before = f_last;
    w = step.solution.base_wrench;
    f_last = set.fraction;
    plan.steps.push_back(std::move(step));
    ++next;
  }
  if (plan.status == PlanStatus::Complete)
    plan.message = "complete: " + std::to_string(plan.steps.size()) + " steps";
  if (plan.tracking.performed && !plan.tracking.jump)
    plan.tracking.note = plan.tracking.refinements > 0
                             ? "the rod follows the plan (" +
                                   std::to_string(plan.tracking.refinements) +
                                   " steps inserted where it would have jumped)"
                             : "the rod follows the plan";

  // 5. The timed end-effector path through the waypoints.
  std::vector<Pose> waypoints{initial_end_effector};
  for (const PlanStep& step : plan.steps) waypoints.push_back(step.end_effector);
  plan.end_effector_path = time_parameterize(waypoints, options.end_effector);

  return plan;
}

}  // namespace rodshape
