// closed_loop_options.hpp: the shape controller's options (shape_controller.hpp): how it
// estimates, when it acts on an estimate, its guards, and how it re-plans.
#pragma once

#include "rodshape/feedback/state_estimator.hpp"

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
  /// averaged, dividing the noise by √checkpoint_frames (the driver does this: sim/closed_loop.hpp
  /// in simulation). 1 ≤ checkpoint_frames ≤ 1000.
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

}  // namespace rodshape
