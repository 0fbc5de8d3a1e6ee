// plan_problem.hpp: what a plan is asked for (paper, "Optimal trajectory generation"): the clamped
// rod, the target shape (objective points, weights W1, W2), what every step's shape must respect
// (workspace, grasp, strain limits, base-wrench bounds), the equilibrium the rod starts in, and
// optionally the arm that carries the end effector. With an arm, its reach joins the workspace and
// every planned pose is checked by inverse kinematics (see plan.hpp).
#pragma once

#include <optional>

#include "rodshape/core/clamped_rod.hpp"
#include "rodshape/core/pose.hpp"
#include "rodshape/core/rod_configuration.hpp"
#include "rodshape/core/scene.hpp"
#include "rodshape/core/wrench.hpp"
#include "rodshape/optimisation/shape_constraints.hpp"
#include "rodshape/optimisation/shape_target.hpp"
#include "rodshape/optimisation/workspace.hpp"
#include "rodshape/robot/arm_model.hpp"
#include "rodshape/robot/arm_placement.hpp"
#include "rodshape/solvers/model_validity.hpp"

namespace rodshape {

/// The equilibrium the plan starts from. A tip pose alone does not say which equilibrium the rod
/// is in (a held rod may have several); a base wrench does.
struct InitialState {
  enum class Kind {
    Rest,         // the rod at rest: base wrench 0 (with its loads, if any, hanging free)
    HeldTip,      // held at `tip`: the clamped–clamped (or grasped) equilibrium solved from rest
    Equilibrium,  // the equilibrium of `base_wrench`, the tip held where it puts it
  };
  Kind kind = Kind::Rest;
  Pose tip;                // HeldTip
  BaseWrench base_wrench;  // Equilibrium

  static InitialState rest() { return {}; }
  static InitialState held_at(const Pose& tip) { return {Kind::HeldTip, tip, {}}; }
  static InitialState equilibrium(const BaseWrench& w) { return {Kind::Equilibrium, {}, w}; }
  /// The equilibrium of a configuration of the same rod (its n(0), m(0)).
  static InitialState equilibrium(const RodConfiguration& c) {
    return equilibrium(c.base_wrench());
  }
};

/// The arm that holds the rod's tip: its chain (URDF) and where it stands.
struct PlanArm {
  ArmModel model;
  ArmPlacement placement;  // world_T_base, flange_T_ee
};

/// The base end (s = 0) held by a gripper that moves (issue 21), not a fixed clamp. Each step then
/// optimises the base pose too: its variables are the base wrench in the base's frame,
/// w_b = (R(0)ᵀ n(0), R(0)ᵀ m(0)), and the base pose, ξ = (δt, δφ) about the last step's
/// (p(0) + δt, exp([δφ]×) R(0)): 12 in all. The rod's `clamp` is the base's initial pose.
struct MovingBase {
  /// The components of the base wrench, in the base's frame R(0), that the base gripper cannot
  /// transmit (order force x, y, z, moment x, y, z: those of w_b held at 0), and base_T_ee in
  /// `tip_to_end_effector`: the base gripper's pose is world_T_base · base_T_ee.
  Grasp grasp;
  /// Bounds on w_b (the base gripper's wrench, base frame); infinite: WrenchBounds::from_scale.
  WrenchBounds wrench_bounds;
  /// Where the base may go: the set p(0) must stay in (a reach shell bounds the point
  /// p(0) + R(0) t, the base arm's wrist).
  Workspace workspace;
  /// W_b of the energy-free term W_b W2 (|δt|² + L² |δφ|²) / L that each step adds to the cost: the
  /// least motion of the base from the step before, which makes a target that fixes the rod only
  /// up to a rigid motion unique (≥ 0; optimisation/base_motion.hpp).
  double motion_weight = 1e-3;
  /// Throws InputError naming "PlanProblem.moving_base.<field>".
  void validate() const;
};

struct PlanProblem {
  /// Upper bound on rod.intervals for a plan (docs/limits.md, "Sizes"): every step optimises and
  /// tracks the whole rod many times, linear in the intervals; the bundled plans take 2.5–5 s with
  /// 5,000 intervals (the S-curve: 0.12 s with 100, 4.9 s with 5,000, 10 s with 10,000).
  static constexpr int kMaxIntervals = 5'000;

  ClampedRod rod;
  ShapeTarget target;  // the objective points p_obj and the weights W1, W2
  Workspace workspace;
  Grasp grasp;  // the components the grasp cannot transmit, and tip_T_ee
  StrainLimits limits;
  /// What the initial tip (or base wrench) may ask of the model (check_model_validity()).
  ModelValidityLimits validity;
  WrenchBounds wrench_bounds;
  InitialState initial;
  /// The cell's obstacles, kept clear of by every step and between steps (empty: none).
  Scene scene;
  std::optional<PlanArm> arm;  // the arm that holds the tip (s = L)
  /// The base end held by a moving gripper (absent: a fixed clamp at rod.clamp).
  std::optional<MovingBase> moving_base;
  /// The arm that holds the base end (implies moving_base; its reach shell joins
  /// moving_base.workspace, its IK is checked at every pose of the base's path).
  std::optional<PlanArm> base_arm;
  bool base_moves() const { return moving_base.has_value(); }
  /// Throws InputError naming the field (rod, target, workspace, limits, wrench bounds, scene;
  /// "PlanProblem.rod.intervals" above kMaxIntervals; the clamp inside an obstacle).
  void validate() const;
};

}  // namespace rodshape
