// shape_plan.hpp: the paper's trajectory generation, end to end. From the initial configuration
// (the clamped–clamped equilibrium at the initial tip pose, or the straight rod), the objective
// points are moved in n_inter steps from their projection on the initial shape to the target; each
// step is an optimal shape (ShapeProblem solved by IPOPT) warm-started from the last. The tip poses
// of these shapes, composed with the grasp offset, are the end-effector waypoints; they are timed
// for quasi-static motion. Between waypoints the clamped–clamped equilibrium is tracked along the
// commanded path (continuation) to check that the rod follows the plan without a jump.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "rodshape/core/clamped_rod.hpp"
#include "rodshape/core/pose.hpp"
#include "rodshape/core/rod_configuration.hpp"
#include "rodshape/optimisation/shape_constraints.hpp"
#include "rodshape/optimisation/shape_optimizer.hpp"
#include "rodshape/optimisation/shape_target.hpp"
#include "rodshape/optimisation/workspace.hpp"
#include "rodshape/trajectory/end_effector_path.hpp"
#include "rodshape/trajectory/intermediate_targets.hpp"

namespace rodshape {

/// What a plan is asked for: the rod, the wanted shape and what the shapes must respect.
struct PlanRequest {
  ClampedRod rod;
  ShapeTarget target;  // the objective points p_obj and the weights W1, W2
  Workspace workspace;
  Grasp grasp;
  StrainLimits limits;
  WrenchBounds wrench_bounds;
  /// The tip pose the robot holds at the start; absent: the rod at rest (base wrench 0).
  std::optional<Pose> initial_tip;
};

struct PlanOptions {
  int steps = 7;  // n_inter
  ShapeOptimizerOptions optimizer;
  EndEffectorLimits end_effector;
  bool track_between_waypoints = true;
  int tracking_substeps = 10;  // continuation steps from one waypoint to the next
  /// Where the tracked rod does not arrive on the planned shape (a jump), a step is inserted
  /// halfway between the two objective sets and the segment re-planned, at most this many times.
  int max_refinements = 4;
  /// Throws InputError naming "trajectory.steps", "trajectory.max_refinements" etc.
  void validate() const;
};

enum class PlanStatus { Complete, Partial, Infeasible };
std::string to_string(PlanStatus status);

struct PlanStep {
  double fraction = 1.0;  // the objective set is p_init + fraction (p_obj - p_init)
  bool inserted = false;  // a refinement step, inserted where the tracked rod jumped
  PointSet objective_points;
  ShapeSolution solution;  // the optimal shape of this step (configuration, cost, stability, IPOPT)
  Pose end_effector;       // world_T_tip · tip_T_ee
};

/// The equilibrium tracked along the commanded path between waypoints, against the plan.
struct TrackingReport {
  bool performed = false;
  /// Per step k: the largest distance between the tracked rod on arrival at waypoint k and the
  /// planned shape k, over the nodes, m.
  std::vector<double> arrival_deviation;
  double max_deviation = 0.0;
  /// A jump: the tracked equilibrium lost stability, the continuation failed, or the base wrench
  /// changed discontinuously (snap-through) between two substeps.
  bool jump = false;
  int jump_step = -1;   // the waypoint being approached when it happened
  int refinements = 0;  // steps inserted by plan_shape to avoid jumps
  std::string note;
};

struct ShapePlan {
  PlanStatus status = PlanStatus::Infeasible;
  std::string message;
  int failed_step = -1;  // the step whose optimisation failed (Partial), else -1
  BaseWrench initial_wrench;
  RodConfiguration initial_configuration;
  PointSet initial_points;      // p_init: the objective points projected on the initial shape
  std::vector<PlanStep> steps;  // the steps that succeeded
  std::vector<TimedPose> end_effector_path;
  TrackingReport tracking;
};

/// Tracks the equilibrium along the commanded end-effector path of `plan` (waypoint to waypoint, by
/// continuation in options.tracking_substeps steps, the tip held as the grasp holds it) and
/// compares it on arrival with each planned shape. plan_shape() calls it; it is public so that a
/// plan made elsewhere can be checked.
TrackingReport track_plan(const PlanRequest& request,
                          const PlanOptions& options,
                          const ShapePlan& plan);

/// Plans. Throws InputError for bad input (including a workspace that excludes the initial tip);
/// an infeasible target or a failed step is reported in the plan's status and message.
ShapePlan plan_shape(const PlanRequest& request, const PlanOptions& options = {});

}  // namespace rodshape
