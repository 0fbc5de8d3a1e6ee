// closed_loop.hpp: the paper's stated next step. The plan is carried out waypoint by waypoint; at
// each waypoint (a checkpoint) the rod's state is estimated from what the sensors see
// (estimate_state: base wrench and, optionally, a stiffness scale) and the rest of the plan is made
// again from the estimated equilibrium with the updated model (plan() with
// InitialState::equilibrium and as many steps as remain, of which the first `horizon` are
// optimised: the later ones are re-planned at later checkpoints anyway). An estimate that does not
// differ from the plan's state by more than the markers' noise (`significance`) changes nothing:
// the plan goes on (its next step re-planned from the plan's own state if it was made before the
// last correction). The static parameters (weight, stiffness scale, grasp offset) are estimated
// recursively (`fuse`): each estimate's posterior is the next one's prior, and each estimate is
// tested against what the plan assumes, so the checkpoints' information adds up while estimates
// within the noise still change nothing. Two guards: an estimate the model cannot explain
// (`max_residual`) is not used, and a re-plan whose step is a coiled optimum, with much more energy
// than the step it replaces (`max_energy_ratio`), is refused: the path stays gentle.
#pragma once

#include <string>
#include <vector>

#include "rodshape/core/clamped_rod.hpp"
#include "rodshape/sim/marker_sensor.hpp"
#include "rodshape/sim/plant.hpp"
#include "rodshape/sim/shape_error.hpp"
#include "rodshape/sim/state_estimator.hpp"
#include "rodshape/trajectory/plan_options.hpp"
#include "rodshape/trajectory/plan_problem.hpp"
#include "rodshape/trajectory/plan_result.hpp"

namespace rodshape {

struct ClosedLoopOptions {
  EstimationOptions estimation;
  /// Re-plan the remaining steps from each estimate (false: estimate only, the plan unchanged).
  bool replan = true;
  /// Act on an estimate (take its model corrections and re-plan) only when it differs from what
  /// the plan expects by more than noise: when the fit's drop of χ² from the plan's state,
  /// prior_chi2 - chi2, exceeds k + significance · √(2k), k the parameters fitted (the mean of
  /// χ²_k plus `significance` of its standard deviations). Else the plan and the beliefs are kept,
  /// and no estimate noise enters the rest of the path. < 0: act on every estimate.
  double significance = 3.0;
  /// Use an estimate (fuse it, act on it) only when the model explains what the sensors see: its
  /// RMS weighted residual (StateEstimate::residual, about 1 at the sensors' noise) is at most
  /// this. A fit beyond it is a shape the model cannot represent (an unmodelled effect, a local
  /// minimum): acting on its parameters would re-plan for a rod that is not there. > 0.
  double max_residual = 2.0;
  /// A re-plan is taken only when each re-planned step's shape has at most max_energy_ratio × the
  /// elastic energy of the step it replaces (or of the state it starts from, if more). Correcting
  /// the model changes a step's energy by about the correction (tens of percent); a larger rise is
  /// another, coiled optimum of the step, and the path to it would not be gentle. ≥ 1.
  double max_energy_ratio = 1.5;
  /// The steps optimised at a re-plan (PlanOptions::horizon), 0 … PlanOptions::kMaxSteps; 0: all
  /// that remain. The next waypoint is all the arm needs before the next checkpoint, and its step
  /// is the same whatever the horizon (the objective sets towards the target are the same, and the
  /// first step starts from the estimate), so a horizon of 1 gives the same run as re-planning
  /// everything (up to IPOPT's warm start where a stale step is re-planned from the plan's state),
  /// with one optimisation per checkpoint instead of as many as steps remain.
  int horizon = 1;
  /// Also estimate where the gripper really holds the tip: the tip pose is then fitted with the
  /// standard deviations below around the pose believed so far (instead of
  /// estimation.tip_position_sigma around the commanded one), and the re-plans use the corrected
  /// grasp (tip_T_ee = offset⁻¹ · tip_T_ee), so that the commanded poses put the real tip where
  /// the plan wants it.
  bool estimate_grasp_offset = true;
  /// Frames averaged at each checkpoint: the arm rests there (the path is rest to rest at every
  /// waypoint) for checkpoint_frames / frame_rate seconds, and each marker's visible positions are
  /// averaged, dividing the noise by √checkpoint_frames. 1 ≤ checkpoint_frames ≤ 1000.
  int checkpoint_frames = 15;
  /// Recursive estimation of the static parameters (stiffness scale, λ, grasp offset): each
  /// estimate acted on leaves its posterior standard deviations as the next estimate's prior
  /// (instead of the fixed ones of `estimation` and below), so the checkpoints' information adds
  /// up. Assumes the model's form is right: model errors the parameters cannot absorb make the
  /// beliefs over-confident.
  bool fuse = true;
  /// Throws InputError naming the field.
  void validate() const;
  double grasp_offset_position_sigma = 5e-3;  // m
  double grasp_offset_rotation_sigma = 0.05;  // rad
};

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
};

/// A closed-loop run: the plant as driven, what the sensor saw and the errors at each frame, the
/// checkpoints.
struct ClosedLoopRun {
  PlantRun plant;  // its events include the contacts with the plan's scene
  double min_gap = std::numeric_limits<double>::infinity();  // to the plan's scene, m
  std::vector<double> times;                                 // s, one per frame
  std::vector<ShapeError> errors;  // one per frame (the frames themselves are not kept)
  SensorFrame last_seen;           // what the sensor saw at the last frame
  std::vector<Checkpoint> checkpoints;
  /// With an arm (a plan with a complete joint trajectory), each segment is solved by IK from the
  /// arm's joints and the plant follows the hand's poses (commanded_path.hpp). A segment without
  /// an IK solution and the rest of the run follow the end-effector poses: false, and the
  /// checkpoint before it says so.
  bool driven_by_joints = false;
};

/// Carries out `plan` (of `problem`, made with `options`) on `rod` (the real one, held with
/// `grasp_offset`) seen by `sensor`, with a checkpoint at every waypoint but the last.
ClosedLoopRun run_closed_loop(const PlanProblem& problem,
                              const PlanOptions& options,
                              const PlanResult& plan,
                              const ClampedRod& rod,
                              const Pose& grasp_offset,
                              MarkerSensor& sensor,
                              const ClosedLoopOptions& loop = {},
                              const PlantOptions& plant_options = {});

}  // namespace rodshape
