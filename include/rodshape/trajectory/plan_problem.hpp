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
  std::optional<PlanArm> arm;
  /// Throws InputError naming the field (rod, target, workspace, limits, wrench bounds, scene;
  /// "PlanProblem.rod.intervals" above kMaxIntervals; the clamp inside an obstacle).
  void validate() const;
};

}  // namespace rodshape
