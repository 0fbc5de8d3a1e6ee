// shape_controller.hpp: the paper's stated next step, as a real robot's loop runs it. The plan is
// carried out waypoint by waypoint; at each waypoint (a checkpoint) the arm rests, and the
// controller is handed what the sensors saw (update(), in the pattern of Ruckig's online
// update(input, output)): it estimates the rod's state (estimate_state: base wrench and,
// optionally, a stiffness scale, the weight's factor and the grasp offset) and makes the rest of
// the plan again from the estimated equilibrium with the updated model (plan() with
// InitialState::equilibrium and as many steps as remain, of which the first `horizon` are
// optimised: the later ones are re-planned at later checkpoints anyway). An estimate that does not
// differ from the plan's state by more than the markers' noise (`significance`) changes nothing:
// the plan goes on (its next step re-planned from the plan's own state if it was made before the
// last correction). The static parameters (weight, stiffness scale, grasp offset) are estimated
// recursively (`fuse`): each estimate's posterior is the next one's prior, and each estimate is
// tested against what the plan assumes, so the checkpoints' information adds up while estimates
// within the noise still change nothing. Two guards: an estimate the model cannot explain
// (`max_residual`) is not used, and a re-plan whose step is a coiled optimum, with much more energy
// than the step it replaces (`max_energy_ratio`), is refused: the path stays gentle. The
// controller knows no plant: sim/closed_loop.hpp drives one with it. With a moving base (issue 21)
// the rod's clamp is where the base gripper is at the checkpoint: the estimate is made with the
// clamp there, and the re-plan starts from it (its problem's rod.clamp, the moving base kept).
#pragma once

#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "rodshape/core/pose.hpp"
#include "rodshape/feedback/closed_loop_options.hpp"
#include "rodshape/feedback/cloud_measurement.hpp"
#include "rodshape/feedback/controller_beliefs.hpp"
#include "rodshape/feedback/marker_measurement.hpp"
#include "rodshape/feedback/planned_waypoint.hpp"
#include "rodshape/optimisation/workspace.hpp"
#include "rodshape/trajectory/plan_options.hpp"
#include "rodshape/trajectory/plan_problem.hpp"
#include "rodshape/trajectory/plan_result.hpp"

namespace rodshape {

/// One checkpoint: what was estimated and what was done with it.
struct Checkpoint {
  double t = 0.0;    // s
  int waypoint = 0;  // 1 … n - 1: the waypoint just reached
  StateEstimate estimate;
  Pose grasp_offset;         // believed after this checkpoint (identity unless estimated)
  bool consistent = false;   // converged and residual ≤ max_residual: the model explains the data
  bool significant = false;  // the estimate differs from the plan beyond noise (see significance)
  bool replanned = false;
  std::string message;  // the re-plan's brief, or why the plan was kept
  /// What the estimate was made from: the markers seen (averaged over the rest) or the points of
  /// the rest's pooled cloud; 0 until a driver says.
  int points = 0;
  /// The RMS distance from the estimated centreline to the real rod's (sim/shape_error.hpp,
  /// centreline_rms): a truth only a simulation knows, filled by its driver; NaN otherwise.
  double shape_rms = std::numeric_limits<double>::quiet_NaN();
};

/// Where the arm is when the controller is updated: at rest at the waypoint it was driven to
/// (ShapeController::remaining().front()).
struct ArmState {
  Pose end_effector;  // world_T_ee, commanded
  /// With a moving base (PlanProblem::moving_base): the base gripper's commanded pose (world); the
  /// rod's clamp is there · inverse(base_T_ee), and the estimate and the re-plan start from it.
  /// Absent: the waypoint's planned base pose (PlannedWaypoint::base_end_effector).
  std::optional<Pose> base_end_effector{};
};

/// What update() decided.
struct ControllerOutput {
  Checkpoint checkpoint;  // what was estimated, and what was done with it and why
  /// The waypoints still ahead (the next one first): the plan's, or the corrected ones.
  std::vector<PlannedWaypoint> remaining;
  /// The rest of the plan was made again (the arm is to follow `remaining`'s new poses).
  bool recalculated() const { return checkpoint.replanned; }
  /// Why: the re-plan's brief, or why the plan was kept.
  const std::string& reason() const { return checkpoint.message; }
};

class ShapeController {
 public:
  /// Controls the carrying out of `plan` (of `problem`, made with `planning`: the re-plans'
  /// options). Throws InputError for options out of range (ClosedLoopOptions::validate) and for a
  /// plan with no step to carry out.
  ShapeController(const PlanProblem& problem,
                  const PlanResult& plan,
                  const PlanOptions& planning,
                  const ClosedLoopOptions& options = {});

  /// The arm has reached the waypoint ahead (remaining().front()), which is not the last, and
  /// rests there; `measurement` is what the sensors saw of the rod there (its frame's t: now).
  /// Estimates the rod's state and keeps the plan or makes the rest again. Throws InputError when
  /// no waypoint but the last is ahead (nothing is left to control) or for a bad sensor model.
  ControllerOutput update(const MarkerMeasurement& measurement, const ArmState& arm);
  /// The same from a depth camera's cloud (estimate_state_from_cloud, cloud_estimator.hpp). The
  /// gates read the same: an estimate is consistent when the model explains the cloud
  /// (unexplained(): converged, its residual over the inliers, about 1 at the camera's noise, ≤
  /// max_residual, and at most half the points outliers of the robust loss), and significant when
  /// the drop of the robust χ² (Σ of the Cauchy rows, ≈ χ² near the truth) from the plan's state
  /// exceeds k + significance · √(2k), as for markers.
  ControllerOutput update(const CloudMeasurement& measurement, const ArmState& arm);

  /// The waypoints still ahead, the one the arm is driven to first.
  const std::vector<PlannedWaypoint>& remaining() const { return remaining_; }
  const PlanProblem& problem() const { return problem_; }
  const PlanOptions& planning() const { return planning_; }
  const ClosedLoopOptions& options() const { return options_; }
  /// What the controller believes of the rod so far.
  const ControllerBeliefs& beliefs() const { return beliefs_; }

 private:
  /// One sensor's estimator: the state from what it saw, given the held tip's prior pose, the
  /// gripper, the prior, the options and the hypothesis.
  using Estimator = std::function<StateEstimate(const ClampedRod& model,
                                                const Pose& tip,
                                                const Pose& end_effector,
                                                const StatePrior& prior,
                                                const EstimationOptions& options,
                                                const StateHypothesis& hypothesis)>;
  ControllerOutput update_with(double t, const ArmState& arm, const Estimator& estimator);
  void estimate(Checkpoint& c,
                const Estimator& estimator,
                const Pose& end_effector,
                const BaseWrench& planned);
  std::string kept_message(const Checkpoint& c) const;
  /// The planner's rod with its clamp where the base is now (problem().rod with a fixed clamp).
  ClampedRod rod_now() const;
  bool significant(const StateEstimate& e) const;
  void replan(Checkpoint& c, const BaseWrench& from);

  PlanProblem problem_;
  PlanOptions planning_;
  ClosedLoopOptions options_;
  std::vector<PlannedWaypoint> remaining_;
  /// How many of the remaining steps were planned with the beliefs held now (the rest were made
  /// before the last correction, beyond a re-plan's horizon).
  int fresh_ = 0;
  int waypoint_ = 0;                                 // the waypoints reached so far
  std::optional<Workspace::ReachShell> shell_;       // the plan's reach shell
  std::optional<Workspace::ReachShell> base_shell_;  // the base arm's, with a moving base
  bool base_moves_ = false;                          // a moving base with the plan's base path
  Pose clamp_now_;  // the rod's clamp at the last checkpoint (rod.clamp with a fixed clamp)
  ControllerBeliefs beliefs_;  // the model's corrections and the grasp offset so far
};

}  // namespace rodshape
