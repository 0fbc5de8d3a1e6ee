#include "rodshape/trajectory/shape_plan.hpp"

#include <algorithm>
#include <sstream>

#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/error.hpp"
#include "rodshape/optimisation/shape_problem.hpp"
#include "rodshape/solvers/shooting_solver.hpp"
#include "rodshape/solvers/stability.hpp"

namespace rodshape {

void PlanOptions::validate() const {
  if (steps < 1) throw InputError("trajectory.steps = " + std::to_string(steps) + " must be >= 1");
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

/// world_T_a · a_T_b.
Pose compose(const Pose& world_T_a, const Pose& a_T_b) {
  return {world_T_a.position + world_T_a.rotation * a_T_b.position,
          world_T_a.rotation * a_T_b.rotation};
}

/// (world_T_b · (a_T_b)⁻¹) = world_T_a.
Pose remove_offset(const Pose& world_T_b, const Pose& a_T_b) {
  const Eigen::Matrix3d R = world_T_b.rotation * a_T_b.rotation.transpose();
  return {world_T_b.position - R * a_T_b.position, R};
}

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
    full.evaluate(solution.base_wrench.to_vector());
    const Eigen::VectorXd& g = full.constraints();
    const double tolerance = options.constraint_tolerance;
    const bool respected =  // the inequalities hold: their multipliers are 0 ((g -
                            // full.constraint_upper()).array() <= tolerance).all() &&
        ((full.constraint_lower() - g).array() <= tolerance).all();
    if (respected)
      return optimise_shape(full, solution.base_wrench, options);  // multipliers, stability
  }
  return optimise_shape(full, solution.converged() ? solution.base_wrench : start, options);
}

}  // namespace

TrackingReport track_plan(const PlanRequest& request,
                          const PlanOptions& options,
                          const ShapePlan& plan) {
  TrackingReport report;
  report.performed = true;
  constexpr double kJumpDeviation = 1e-3;  // m: arrival farther than this from the plan is a jump
  ShootingOptions shooting;
  shooting.continuation = false;  // a failure here is what we want to see, not to repair
  shooting.output_derivatives = Derivatives::Tip;

  Pose from = compose(plan.initial_configuration.tip(), request.grasp.tip_to_end_effector);
  BaseWrench w = plan.initial_wrench;
  for (std::size_t k = 0; k < plan.steps.size() && !report.jump; ++k) {
    const PlanStep& step = plan.steps[k];
    ShootingSolution tracked;
    for (int j = 1; j <= options.tracking_substeps; ++j) {
      const double sigma = static_cast<double>(j) / options.tracking_substeps;
      const Pose ee = interpolate(from, step.end_effector, sigma);
      const Pose tip = remove_offset(ee, request.grasp.tip_to_end_effector);
      tracked = solve_equilibrium(request.rod, held_tip(tip, request.grasp), w, shooting);
      if (!tracked.summary.converged()) {
        report.jump = true;
        report.jump_step = static_cast<int>(k);
        report.note = "the equilibrium could not be followed towards waypoint " +
                      std::to_string(k + 1) + " at " + std::to_string(sigma) + " of the way (" +
                      tracked.summary.brief() + ")";
        break;
      }
      w = tracked.base_wrench;
    }
    if (report.jump) break;
    // On arrival the tracked rod should be the planned equilibrium; otherwise it jumped to
    // another branch on the way (snap-through).
    const RodConfiguration arrived = integrate(request.rod, w, Derivatives::AllNodes);
    const double deviation = node_deviation(arrived, step.solution.configuration);
    report.arrival_deviation.push_back(deviation);
    report.max_deviation = std::max(report.max_deviation, deviation);
    const StabilityReport stability = assess_stability(request.rod, arrived);
    if (deviation > kJumpDeviation || (!stability.stable && !stability.degenerate)) {
      report.jump = true;
      report.jump_step = static_cast<int>(k);
      report.note =
          deviation > kJumpDeviation
              ? "on arrival at waypoint " + std::to_string(k + 1) + " the tracked rod is " +
                    std::to_string(deviation) +
                    " m from the planned shape: it jumped to another equilibrium"
              : "the tracked equilibrium at waypoint " + std::to_string(k + 1) + " is unstable";
    }
    from = step.end_effector;
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
  const Eigen::Vector3d initial_tip = plan.initial_configuration.p.back();
  if (!request.workspace.contains(initial_tip, 1e-9))
    throw InputError("workspace excludes the initial tip at " + format_point(initial_tip));

  // 2. Is the target within reach at all?
  const TargetFeasibility feasibility =
      check_feasibility(request.target, request.rod, request.limits.max_axial_strain.value_or(0.0));
  if (!feasibility.feasible) {
    plan.status = PlanStatus::Infeasible;
    plan.message = feasibility.reason;
    return plan;
  }

  // 3. p_init on the initial shape, and the n_inter objective sets to p_obj.
  plan.initial_points =
      project_onto_initial_shape(plan.initial_configuration, request.target.points);
  const std::vector<PointSet> sets =
      intermediate_targets(plan.initial_points, request.target.points, options.steps);

  // 4. One optimal shape per set, each warm-started from the last (see optimise_step). From the
  //    third step on, the
  //    secant w_k + (w_k - w_{k-1}) is tried as well (the sets move on straight lines, so the
  //    optima move smoothly) and the start of lower cost is kept.
  BaseWrench w = plan.initial_wrench, w_before = plan.initial_wrench;
  plan.status = PlanStatus::Complete;
  for (int i = 0; i < options.steps; ++i) {
    ShapeTarget target = request.target;
    target.points = sets[i];
    ShapeProblem problem(request.rod, target, Workspace{}, request.grasp, StrainLimits{},
                         request.wrench_bounds);
    BaseWrench start = w;
    if (i >= 2) {
      const Vector6d secant = 2.0 * w.to_vector() - w_before.to_vector();
      problem.evaluate(w.to_vector());
      const double cost_at_last = problem.cost();
      problem.evaluate(secant);
      if (problem.cost() < cost_at_last && problem.constraints().allFinite())
        start = Wrench::from_vector(secant);
    }
    ShapeSolution solution = optimise_step(request, target, problem, start, options.optimizer);
    if (!solution.converged()) {
      plan.status = PlanStatus::Partial;
      plan.failed_step = i;
      plan.message = "step " + std::to_string(i + 1) + " of " + std::to_string(options.steps) +
                     " failed: " + solution.message;
      break;
    }
    w_before = w;
    w = solution.base_wrench;
    const Pose end_effector =
        compose(solution.configuration.tip(), request.grasp.tip_to_end_effector);
    plan.steps.push_back({sets[i], std::move(solution), end_effector});
  }
  if (plan.status == PlanStatus::Complete)
    plan.message = "complete: " + std::to_string(options.steps) + " steps";

  // 5. The timed end-effector path through the waypoints.
  std::vector<Pose> waypoints{
      compose(plan.initial_configuration.tip(), request.grasp.tip_to_end_effector)};
  for (const PlanStep& step : plan.steps) waypoints.push_back(step.end_effector);
  plan.end_effector_path = time_parameterize(waypoints, options.end_effector);

  // 6. Does the rod follow the plan between the waypoints?
  if (options.track_between_waypoints && !plan.steps.empty())
    plan.tracking = track_plan(request, options, plan);
  return plan;
}

}  // namespace rodshape
