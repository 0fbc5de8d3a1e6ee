// plan_options.hpp: how a plan is made: n_inter, the optimiser, the end-effector speed limits, the
// tracking of the held rod between waypoints and the refinement where it would jump, and (used
// only when the problem has an arm) the reach shell and the re-plans.
#pragma once

#include <optional>
#include <string>

#include "rodshape/enum_names.hpp"
#include "rodshape/optimisation/shape_optimiser.hpp"
#include "rodshape/robot/arm_reach.hpp"
#include "rodshape/trajectory/end_effector_path.hpp"
#include "rodshape/trajectory/joint_trajectory.hpp"

namespace rodshape {

/// With an arm: its reach shell in the workspace, IK checks of every pose, re-plans. The same
/// options serve the base's arm (PlanProblem::base_arm), but for its seed (base_seed).
struct ArmPlanOptions {
  bool use_reach = true;            // add the arm's reach shell to the workspace
  double reach_margin = 0.02;       // m: the shell is [r_min + margin, r_max - margin]
  double replan_tightening = 0.02;  // m: how far past an unreachable pose's wrist distance the
                                    // tightened shell ends
  /// Each re-plan is the whole plan again.
  static constexpr int kMaxReplans = 10;
  int max_replans = 3;  // 0 … kMaxReplans
  /// With a scene: keep the arm's link capsules (ArmModel::link_capsules()) the scene's clearance
  /// away from the obstacles and the rod: IK's null space first, then re-plans with a tighter
  /// shell; a plan still too near has the status collision.
  bool link_clearance = true;
  /// m: IK pushes the links whose gap is below the clearance plus this (IkClearance::influence).
  double link_influence = 0.03;
  ArmReachOptions reach;
  JointTrajectoryOptions joints;  // the first seed and the IK options, for the checks too
  /// The base arm's first IK seed (PlanProblem::base_arm; empty: its default_seed); the IK
  /// options in `joints` serve both arms.
  Eigen::VectorXd base_seed;
  /// Throws InputError naming the field ("ArmPlanOptions.reach_margin" etc.).
  void validate() const;
};

/// Where each objective point starts (p_init), from which the sets move in straight lines to p_obj.
enum class ObjectiveInterpolation {
  /// p_init is the initial rod's point at the arc length the objective point has on the target
  /// curve (FeasibilityResult::arc_lengths), so each point is carried by the same material
  /// point; the chain clamp → p_1 → … → p_n is bent from its initial to its target shape, each
  /// link turned by a fraction of its rotation and its length interpolated
  /// (turned_objective_set): every set is a chain of about the rod's length, and the bending
  /// grows steadily instead of crowding the points together on the way.
  Shape,
  /// p_init by arc length as for Shape, then straight lines to p_obj.
  ArcLength,
  /// The paper's: p_init is the objective point's projection on the initial shape, then straight
  /// lines to p_obj.
  Projection,
  /// The end-effector pose continued: the target's optimum first (the Shape steps' last, solved
  /// without tracking), then the held rod followed along the end effector's straight path (position
  /// on the line, rotation slerped) from the initial pose to that optimum's; the steps are the
  /// followed equilibria at fractions i / n of that path (not optima of objective sets), the last
  /// the target's optimum. Plans the whole way (no horizon).
  Pose,
  /// Shape, and where its tracked peak energy exceeds kGentleRatio × the larger end energy, or it
  /// inserted steps, or it did not complete, also Pose and (without a scene: with one, the sets
  /// lead through the same obstacles, each a detour search) Projection, and where none of these
  /// is within kGentleRatio, Search: the gentlest complete plan that reaches the target
  /// (PlanResult::interpolation says which and what was tried). With a horizon, Shape alone.
  Auto,
  /// A searched path: the target's optimum (as for Pose), then a path of end-effector poses to it
  /// from the initial pose found by the scene's detour search (a random tree over poses, seeded)
  /// with every edge's tracked energy within kGentleRatio × the larger end energy; the steps are
  /// the tree's equilibria (PlanStep::detour), the last the optimum. Plans the whole way (no
  /// horizon); up to a few seconds where no such path exists (detour::kMaxEdges edges).
  Search,
};
/// The names of ObjectiveInterpolation, in its order (to_string; trajectory.interpolation).
inline constexpr EnumNames<ObjectiveInterpolation, 6> kObjectiveInterpolationNames = {{
    {ObjectiveInterpolation::Shape, "shape"},
    {ObjectiveInterpolation::ArcLength, "arc_length"},
    {ObjectiveInterpolation::Projection, "projection"},
    {ObjectiveInterpolation::Pose, "pose"},
    {ObjectiveInterpolation::Auto, "auto"},
    {ObjectiveInterpolation::Search, "search"},
}};
std::string to_string(ObjectiveInterpolation interpolation);

struct PlanOptions {
  /// Upper bounds (docs/limits.md, "Sizes"). A step is one optimisation (about 10 ms for the
  /// 101-node band, 0.7 s for 5,001 nodes) and one tracked segment; a tracking substep one solve
  /// (about 0.15 ms at 101 nodes); a refinement one more step.
  static constexpr int kMaxSteps = 1000;
  static constexpr int kMaxTrackingSubsteps = 1000;
  static constexpr int kMaxRefinements = 100;

  int steps = 7;  // n_inter, 1 … kMaxSteps
  /// A receding horizon: plan only the first `horizon` of the `steps` objective sets (0 … steps;
  /// 0: all of them). The plan then ends at fraction horizon / steps of the way, not at the target;
  /// PlanResult::horizon says so. The closed loop uses it to re-plan only the next waypoint at a
  /// checkpoint (the later ones are re-planned at later checkpoints).
  int horizon = 0;
  /// The steps plan() optimises: steps, or horizon when it cuts them short.
  int planned_steps() const { return horizon > 0 && horizon < steps ? horizon : steps; }
  ObjectiveInterpolation interpolation = ObjectiveInterpolation::Auto;
  /// Auto: a plan whose tracked peak energy is at most this × the larger of its end energies is
  /// gentle (no other scheme is tried).
  static constexpr double kGentleRatio = 1.1;
  ShapeOptimiserOptions optimiser;
  EndEffectorLimits end_effector;
  /// With a moving base: the base gripper's speed and acceleration limits. The two grippers move
  /// on one clock: each segment takes the longer of the two ends' times.
  EndEffectorLimits base_end_effector;
  bool track_between_waypoints = true;
  int tracking_substeps = 10;  // continuation steps from one waypoint to the next (≤ kMax…)
  /// Where the tracked rod does not arrive on the planned shape (a jump), a step is inserted
  /// halfway between the two objective sets and the segment re-planned, at most this many times.
  int max_refinements = 4;
  /// With a scene: each step's optimisation asks of every obstacle its required gap plus this
  /// fraction of the clearance (0 … kMaxSceneMargin), room for the rod between waypoints, which
  /// is checked against the clearance itself.
  double scene_margin = 0.2;
  static constexpr double kMaxSceneMargin = 10.0;
  /// With a scene: a step's optimisation includes the obstacles within this distance of its
  /// start shape or its objective points (m, > 0; obstacles it then comes too near to are added
  /// and the step solved again).
  double scene_reach = 0.1;
  /// With a scene: search a detour where the straight motion between two waypoints drags the rod
  /// through an obstacle (detour_search.hpp); false: such a plan ends in the status Collision.
  bool scene_detour = true;
  ArmPlanOptions arm;  // used when the problem has an arm
  /// Complete means the final shape passes within this distance of every target point (m, > 0,
  /// at most the rod's length); absent: kDefaultReachFraction of the rod's length, the distance
  /// beyond which the planner already takes an optimum to be off the points (plan.cpp,
  /// optimum_plan). A plan whose steps all succeed but whose final shape ends farther is Partial,
  /// with the distance. Not applied with a horizon (such a plan ends short on purpose).
  std::optional<double> reach_tolerance;
  static constexpr double kDefaultReachFraction = 0.01;
  /// The reach tolerance for a rod of length `length`, m.
  double reach_tolerance_for(double length) const {
    return reach_tolerance.value_or(kDefaultReachFraction * length);
  }
  /// Throws InputError naming the field ("PlanOptions.steps", "PlanOptions.max_refinements" etc.).
  void validate() const;
};

}  // namespace rodshape
