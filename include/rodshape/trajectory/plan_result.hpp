// plan_result.hpp: what plan() returns: the initial equilibrium, one optimal shape per step with
// its end-effector waypoint, the timed end-effector path, the tracking of the held rod along it
// and, with an arm, the reach, the IK checks, the re-plans and the joint trajectory.
#pragma once

#include <Eigen/Core>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "rodshape/core/pose.hpp"
#include "rodshape/core/rod_configuration.hpp"
#include "rodshape/core/scene.hpp"
#include "rodshape/enum_names.hpp"
#include "rodshape/optimisation/shape_optimiser.hpp"
#include "rodshape/optimisation/workspace.hpp"
#include "rodshape/robot/arm_reach.hpp"
#include "rodshape/trajectory/end_effector_path.hpp"
#include "rodshape/trajectory/intermediate_targets.hpp"
#include "rodshape/trajectory/joint_trajectory.hpp"
#include "rodshape/trajectory/plan_options.hpp"

namespace rodshape {

/// Complete: every step succeeded, the tracked rod follows the plan (when tracked) and the final
/// shape passes within PlanOptions::reach_tolerance of every target point (without a horizon).
/// SnapThrough: every step succeeded, but the tracked rod would jump between two waypoints even
/// after the refinements allowed (TrackingResult says where and the energy released): a plan
/// defect, not a success. Partial: a step's optimisation failed, or the final shape ends farther
/// than the reach tolerance from a target point (PlanResult::target_distance). Infeasible: no step
/// was tried. Collision: every step succeeded, but the tracked rod comes nearer to an obstacle of
/// the scene than the clearance even after the refinements allowed (SceneResult says where).
enum class PlanStatus { Complete, SnapThrough, Partial, Infeasible, Collision };
/// The names of PlanStatus, in its order (to_string; plan.json's "status").
inline constexpr EnumNames<PlanStatus, 5> kPlanStatusNames = {{
    {PlanStatus::Complete, "complete"},
    {PlanStatus::SnapThrough, "snap_through"},
    {PlanStatus::Partial, "partial"},
    {PlanStatus::Infeasible, "infeasible"},
    {PlanStatus::Collision, "collision"},
}};
std::string to_string(PlanStatus status);

struct PlanStep {
  double fraction = 1.0;  // the objective set is p_init + fraction (p_obj - p_init)
  bool inserted = false;  // a refinement step, inserted where the tracked rod jumped
  /// A step of a detour around the scene's obstacles (an equilibrium the search went through, not
  /// an optimal shape: its solution's cost is that of the step it leads to).
  bool detour = false;
  PointSet objective_points;
  ShapeResult solution;  // the optimal shape of this step (configuration, cost, stability, IPOPT)
  Pose end_effector;     // world_T_tip · tip_T_ee
  /// The base gripper's pose: world_T_base · base_T_ee (MovingBase::grasp); with a fixed clamp,
  /// the clamp's pose, the same at every step.
  Pose base_end_effector = {};
};

/// The equilibrium tracked along the commanded path between waypoints, against the plan.
struct TrackingResult {
  bool performed = false;
  /// Per step k: the largest distance between the tracked rod on arrival at waypoint k and the
  /// planned shape k, over the nodes, m.
  std::vector<double> arrival_deviation;
  double max_deviation = 0.0;
  /// A jump: the tracked equilibrium lost stability, the continuation failed, or the rod arrived
  /// on another equilibrium than the planned one (snap-through).
  bool jump = false;
  int jump_step = -1;   // the waypoint being approached when it happened
  int refinements = 0;  // steps inserted by plan() to avoid jumps
  /// At the jump: the energy of the planned shape at the waypoint minus that of the equilibrium
  /// the rod went to (J; > 0: released in the snap). Unknown (nullopt) when the rod was lost on the
  /// way, or without a jump.
  std::optional<double> energy_released;
  /// Gentleness: the largest elastic energy (J) and bending curvature |(u_x, u_y)| (1/m) of the
  /// tracked rod over every substep of every segment (0 when not tracked).
  double peak_energy = 0.0;
  double peak_curvature = 0.0;
  std::string note;
  std::string brief() const { return note; }
};

/// With a scene and an arm with collision geometry: the least gap between the arm's link capsules
/// and the scene's obstacles or the rod (the hand holding it excepted) over the joint trajectory's
/// samples, and where. With two arms (PlanProblem::arm and base_arm, with or without a scene): the
/// least over both arms' links against the scene and the rod and over the pairs of one link of
/// each arm (obstacle = kOtherArm, -2: `link` is the tip arm's, `other_link` the base arm's).
struct RobotGapResult {
  double min_gap = std::numeric_limits<double>::infinity();  // m
  double margin = std::numeric_limits<double>::infinity();   // min_gap - its required gap
  int sample = -1;                                           // the joint trajectory's sample
  double t = 0.0;                                            // its time, s
  int step = -1;              // the waypoint it moves towards (0: the initial pose)
  std::string arm = "tip";    // whose link: "tip" (PlanProblem::arm) or "base" (base_arm)
  std::string link;           // the capsule's label ("panda_link4", "panda_link8 (hand)")
  int obstacle = -1;          // index into Scene::obstacles; -1: the rod; -2: the other arm
  std::string other_link;     // obstacle = -2: the base arm's capsule's label
  std::string obstacle_name;  // its name (empty: unnamed, or the rod)
  std::string note;           // "link panda_link4, obstacle 'shelf', gap 3.2 mm (required 5 mm)"
  bool clear() const { return margin >= -SceneGap::kTolerance; }
};

/// With a scene: the least gap between the rod's surface and an obstacle over every tracked
/// substep of every segment (and the initial shape), and where it was.
struct SceneResult {
  double clearance = 0.0;  // m, Scene::clearance
  /// The least gap, m: of the (segment, obstacle) pair with the least margin over its required gap
  /// (the clearance, or a clamp mount's own gap; see scene.hpp).
  double min_gap = std::numeric_limits<double>::infinity();
  double margin = std::numeric_limits<double>::infinity();  // min_gap - its required gap
  int step = -1;      // the step whose segment (from the waypoint before) holds it; 0: initial
  double s = 0.0;     // arc length along the rod, m
  int obstacle = -1;  // index into Scene::obstacles
  std::string obstacle_label;  // the name, or the index
  /// Obstacles each step's optimisation kept the rod clear of (rows of its clearance block).
  std::vector<int> obstacles_per_step;
  std::string note;  // where the rod first came too near, when it did
  /// Each detour search: what it found ("detour of 2 waypoints (…)") or why not.
  std::vector<std::string> detours;
  /// With an arm that has collision geometry (ArmPlanOptions::link_clearance).
  std::optional<RobotGapResult> robot;
  /// Clear within the tracked rod's accuracy (SceneGap's).
  static constexpr double kTolerance = SceneGap::kTolerance;
  bool clear() const { return margin >= -kTolerance; }
};

enum class ArmPlanStatus {
  Reachable,    // every planned pose and every path sample has an IK solution
  Unreachable,  // a pose or a sample has none, after the re-plans allowed (message: which)
  Collision,    // every sample has one, but a link comes nearer to the scene or the rod than the
                // clearance, after the re-plans allowed (message: the step, link, obstacle, gap)
  NotChecked,   // the plan has no end-effector path (infeasible target)
};
/// The names of ArmPlanStatus, in its order (to_string; plan.json's robot "status").
inline constexpr EnumNames<ArmPlanStatus, 4> kArmPlanStatusNames = {{
    {ArmPlanStatus::Reachable, "reachable"},
    {ArmPlanStatus::Unreachable, "unreachable"},
    {ArmPlanStatus::Collision, "collision"},
    {ArmPlanStatus::NotChecked, "not_checked"},
}};
std::string to_string(ArmPlanStatus status);

/// One re-plan: which pose had no IK solution and the shell it led to.
struct Replan {
  std::string reason;           // the pose (step or path sample) and the IK's message
  double wrist_distance = 0.0;  // |w - c| of that pose, m
  Workspace::ReachShell shell;  // the shell of the next plan
};

/// The arm's part of a plan.
struct ArmPlanResult {
  ArmPlanStatus status = ArmPlanStatus::NotChecked;
  std::string message;
  std::optional<ArmReach> reach;               // the arm's reach (ArmPlanOptions::use_reach)
  std::optional<Workspace::ReachShell> shell;  // the shell the last plan was made with
  std::vector<Replan> replans;
  /// Joint positions of the initial end-effector pose and then of each step's, as far as the
  /// check got (IK seeded from the one before).
  std::vector<Eigen::VectorXd> waypoint_q;
  JointTrajectoryResult joints;  // along the plan's end_effector_path
  bool reachable() const { return status == ArmPlanStatus::Reachable; }
  std::string brief() const { return to_string(status) + ": " + message; }
};

/// One way from the initial shape to the target that plan() tried (PlanOptions::interpolation).
struct InterpolationTrial {
  ObjectiveInterpolation scheme = ObjectiveInterpolation::Shape;
  PlanStatus status = PlanStatus::Infeasible;
  /// The tracked peak energy over the larger of the initial and final energies (NaN when the plan
  /// did not reach the target, partial or infeasible, or was not tracked).
  double peak_ratio = std::numeric_limits<double>::quiet_NaN();
  std::string note;  // why it was not taken (empty for the one used)
};

/// Which way made the plan: the scheme used and, with Auto, every scheme tried.
struct InterpolationResult {
  ObjectiveInterpolation used = ObjectiveInterpolation::Shape;
  std::vector<InterpolationTrial> tried;
};

struct PlanResult {
  PlanStatus status = PlanStatus::Infeasible;
  std::string message;
  int failed_step = -1;  // the step whose optimisation failed (Partial), else -1
  /// With PlanOptions::horizon: the steps planned (of the sets towards the target), else 0. A
  /// Complete plan with a horizon ends short of the target, on purpose.
  int horizon = 0;
  FeasibilityResult feasibility;  // of the target, for this rod (Infeasible: why not)
  BaseWrench initial_wrench;
  RodConfiguration initial_configuration;
  /// When the rod starts held at a tip pose whose cold solve was unstable: what the search for a
  /// stable equilibrium did (seek_stable_equilibrium's message); the plan starts from the stable
  /// one when found.
  std::optional<std::string> initial_stable_search;
  PointSet initial_points;      // p_init: the objective points projected on the initial shape
  std::vector<PlanStep> steps;  // the steps that succeeded
  std::vector<TimedPose> end_effector_path;
  /// With a moving base: the base gripper's path on the same clock (the same times as
  /// end_effector_path, sample for sample); empty with a fixed clamp.
  std::vector<TimedPose> base_end_effector_path;
  TrackingResult tracking;
  InterpolationResult interpolation;
  std::optional<SceneResult> scene;       // when the problem has a scene
  std::optional<ArmPlanResult> arm;       // when the problem has an arm
  std::optional<ArmPlanResult> base_arm;  // when the problem has a base arm (PlanProblem::base_arm)

  /// The largest distance from the final shape (the last step's, or the initial one without
  /// steps) to a target point (ShapeTarget::points, not an intermediate set), m, and that point.
  double target_distance = std::numeric_limits<double>::quiet_NaN();
  int target_point = -1;
  /// The reach tolerance the plan was judged with (PlanOptions::reach_tolerance_for), m.
  double reach_tolerance = std::numeric_limits<double>::quiet_NaN();
  /// What the plan was asked: the options plan() was called with (options.steps: the steps
  /// requested; the scheme used is interpolation.used).
  PlanOptions options;

  bool complete() const { return status == PlanStatus::Complete; }
  /// One line: "complete plan, 7 steps (7 requested), final max distance 0.37 mm, energy 0.25 J"
  /// (the steps requested: options.steps) and, where they apply, the tracking's jump, the reach
  /// shell and the joint trajectory.
  std::string brief() const;
};

}  // namespace rodshape
