// plan_stages.hpp (private): the stages of plan(), in the order it runs them, each named after what
// the paper's "Optimal trajectory generation" does there:
//   1. initial_equilibrium   the initial shape Γ_0 (rest, a held tip pose, or a given wrench)
//   2. check_feasibility     (optimisation/shape_target.hpp) is the target within reach at all
//   3. objective_sets        p^i = p_init + (i / n_inter)(p_obj - p_init), p_init on Γ_0
//   4. warm_start, optimise_step   each step's optimal shape, warm-started from the last
//   5. track_segment         the held rod followed from one waypoint to the next
//   6. halfway_set           refinement: a set inserted where the tracked rod would jump
//   7. time_waypoints        the end-effector waypoints timed for quasi-static motion
//   8. follows_timed_path    the rod followed along the timed path's samples (Pose, Search)
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "rodshape/core/scene.hpp"
#include "rodshape/optimisation/shape_problem.hpp"
#include "rodshape/solvers/follow_equilibrium.hpp"
#include "rodshape/solvers/tip_condition.hpp"
#include "rodshape/trajectory/plan.hpp"

namespace rodshape::plan_stages {

/// The condition the gripper imposes while it moves: the tip held at a pose, with the components
/// the grasp cannot transmit released.
TipCondition held_tip(const Pose& tip, const Grasp& grasp);

/// The rod held while the end effector moves straight from `from` to `to` (σ ∈ [0, 1]: position
/// interpolated, rotation slerped), the tip at the end effector's pose · (tip_T_ee)⁻¹: what the
/// tracking and the detour search follow.
/// With a moving base, `base_from` and `base_to` are the rod's base poses at the segment's ends:
/// the clamp moves with them (position on the line, rotation slerped, on the same σ).
EquilibriumPath commanded_segment(const PlanProblem& problem,
                                  const Pose& from,
                                  const Pose& to,
                                  const Pose* base_from = nullptr,
                                  const Pose* base_to = nullptr);

/// 1. The equilibrium the rod starts in, with all-node derivatives. Throws InputError when no
/// equilibrium holds the rod at the initial tip pose, when a given wrench loads a released grasp
/// axis, or when the workspace excludes the initial tip.
struct InitialEquilibrium {
  BaseWrench wrench;
  RodConfiguration configuration;
  /// For a held tip whose cold solve was unstable: what the search for a stable one did.
  std::optional<std::string> stable_search;
};
InitialEquilibrium initial_equilibrium(const PlanProblem& problem);

/// 3. The objective set of fraction f: p_init + f (p_obj - p_init). `inserted` marks a refinement.
struct ObjectiveSet {
  double fraction = 1.0;
  PointSet points;
  bool inserted = false;
  bool detour_tried = false;  // a detour around the scene was searched for this set
};
/// p_init: the objective points' starts on the initial shape (PlanOptions::interpolation).
PointSet initial_points(const PlanProblem& problem,
                        const PlanOptions& options,
                        const InitialEquilibrium& initial,
                        const FeasibilityResult& feasibility);
/// The way the objective points go from p_init (f = 0) to p_obj (f = 1).
struct ObjectivePath {
  Eigen::Vector3d clamp = Eigen::Vector3d::Zero();
  PointSet initial, objective;
  ObjectiveInterpolation interpolation = ObjectiveInterpolation::Shape;
  bool moving_base = false;  // Shape with a moving base: aligned_objective_set from `clamp`
  /// Shape: turned_objective_set; else objective_set (straight lines).
  PointSet at(double fraction) const;
};
/// The n_inter sets, f = i / n_inter, i = 1 … n_inter (the last is p_obj itself).
std::vector<ObjectiveSet> objective_sets(const ObjectivePath& path, int steps);

/// 4. The start of a step's optimisation: the last optimum w, or (from the third step on) the
/// secant extrapolation of the last two optima to the new fraction when its cost is lower (the
/// sets move on straight lines, so the optima move smoothly).
struct StepHistory {
  BaseWrench last, before;  // the last two optima (both the initial wrench at first)
  double f_last = 0.0, f_before = 0.0;
  int steps = 0;  // optima so far
  void push(const BaseWrench& w, double fraction);
};
BaseWrench warm_start(ShapeProblem& unconstrained, const StepHistory& history, double fraction);

/// 4. One step's optimum: first without the inequalities (workspace, strain limits), which are
/// inactive for most steps and whose barrier terms would still bend the interior-point path; if
/// its optimum violates them, the full problem from the warm start, then from that optimum.
/// With a scene, `clearance` holds the step's obstacles (scene_stages::step_clearance): a block of
/// the full problem.
ShapeResult optimise_step(const PlanProblem& problem,
                          const ShapeTarget& target,
                          ShapeProblem& unconstrained,
                          const BaseWrench& start,
                          const ShapeOptimiserOptions& options,
                          const Clearance& clearance = {});

/// 5. The held rod followed from the end-effector pose `from` (base wrench `w`) to `step`'s
/// waypoint, and compared on arrival with the planned shape: farther than 1 mm, unstable, or lost
/// on the way is a jump.
struct SegmentTracking {
  bool jump = false;
  double deviation = 0.0;       // on arrival, from the planned shape (∞ when lost on the way)
  BaseWrench arrived;           // the tracked base wrench on arrival
  double peak_energy = 0.0;     // over the followed substeps, J
  double peak_curvature = 0.0;  // over the followed substeps, 1/m
  std::optional<double> energy_released;  // on another branch: planned minus arrived energy, J
  /// With a scene: the least gap over the substeps, and whether it is below the required one.
  std::optional<SceneGap> gap;
  bool collision = false;
  std::string note;
};
/// With `scene` and `required` (Scene::required_gaps), the gap of every substep is measured.
/// With a moving base, `base_from` is the rod's base pose at the start (the clamp moves from it to
/// the step's base pose, its node 0).
SegmentTracking track_segment(const PlanProblem& problem,
                              const PlanOptions& options,
                              const Pose& from,
                              const BaseWrench& w,
                              const PlanStep& step,
                              int waypoint,
                              const std::vector<double>* required = nullptr,
                              const Pose* base_from = nullptr);
/// Adds a segment to the tracking result (its first jump is the result's).
void record(TrackingResult& tracking, const SegmentTracking& segment, int step_index);

/// 6. The set halfway between fraction f_last and `set`'s, to be planned before it.
ObjectiveSet halfway_set(const ObjectivePath& path, double f_last, const ObjectiveSet& set);

/// Keeps the least gap of a tracked segment (step `step`, 1-based; 0: the initial shape) in the
/// plan's scene result, when its margin is less than the one kept.
void record_gap(PlanResult& result, const PlanProblem& problem, const SceneGap& gap, int step);

/// With a scene: the gaps the obstacles require (into `required`), the initial shape's gap kept in
/// the plan's scene result; throws InputError when the rod starts nearer to an obstacle than that.
void start_scene(const PlanProblem& problem,
                 const RodConfiguration& initial,
                 std::vector<double>& required,
                 PlanResult& result);
/// One step's optimum with a scene: `solve` with the clearance of the obstacles near `start_shape`
/// and `points`; an obstacle its optimum then comes too near to joins them and the step is solved
/// again (a few rounds at most: each adds at least one obstacle). `obstacles` is set to the
/// obstacles its last round kept the rod clear of (the rows of its clearance block).
ShapeResult solve_in_scene_rounds(const PlanProblem& problem,
                                  const PlanOptions& options,
                                  const std::vector<double>& required,
                                  const RodConfiguration& start_shape,
                                  const PointSet& points,
                                  const std::function<ShapeResult(const Clearance&)>& solve,
                                  int& obstacles);
/// After the steps: the tracking's note, and Complete turned into SnapThrough when the tracked rod
/// jumped, into Collision when it came too near the scene.
void settle_status(PlanResult& result);
/// The final shape's distance to the target (PlanResult::target_distance, target_point,
/// reach_tolerance), and Complete turned into Partial, with the distance, where it exceeds the
/// reach tolerance (not with a horizon: that plan ends short of the target on purpose).
void settle_reach(PlanResult& result, const PlanProblem& problem, const PlanOptions& options);
/// 7. The timed end-effector path from the initial pose through every step's waypoint.
std::vector<TimedPose> time_waypoints(const Pose& initial_end_effector,
                                      const std::vector<PlanStep>& steps,
                                      const EndEffectorLimits& limits);

/// 8. The held rod followed along `result`'s timed end-effector path, one solve per sample (what a
/// robot moving at that rate does, and what an independent replay checks): it arrives on the last
/// step. A path's own
/// substeps can pass a point where the equilibrium's branch divides (a fold, or a bifurcation the
/// path passes near) one way and the samples another: such a path is no plan.
bool follows_timed_path(const PlanProblem& problem, const PlanResult& result);

/// How near another scheme's last step must come to the target to replace the Shape plan `shape`
/// (which is not gentle when this is asked): the largest distance of an objective point from the
/// rod of its last step, with 5 % + 0.1 mm of slack (another optimiser's end on the same target),
/// and at least kNearTarget of the rod's length (a gentle path may end on the same points' optimum
/// on another branch, a little farther); when `shape` did not reach the target, 1 % of the rod's
/// length (an optimum 10 cm off a point is no plan for it).
/// The tracked peak energy over the larger of the initial and final energies (NaN when the plan
/// did not reach the target, or was not tracked).
double peak_ratio(const PlanResult& plan);

inline constexpr double kNearTarget = 0.0025;
double reached_within(const PlanResult& shape, const PlanProblem& problem);

}  // namespace rodshape::plan_stages
