// pose_continuation.cpp: the Pose plan of pose_continuation.hpp, in stages: follow_path (the held
// rod along the straight end-effector path, the waypoint equilibria kept), path_step (a waypoint
// as a step), then the plan's tracking and timing.
#include "pose_continuation.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/solvers/follow_equilibrium.hpp"
#include "rodshape/solvers/stability.hpp"
#include "scene_stages.hpp"
#include "validation.hpp"

namespace rodshape::pose_continuation {

namespace {

using plan_stages::SegmentTracking;

/// The followed path, cut at the waypoints σ_i = i / n.
struct FollowedPath {
  FollowResult followed;
  std::vector<BaseWrench> waypoint_wrench;  // at σ_1 … σ_n-1
  std::vector<SegmentTracking> segments;  // per waypoint σ_1 … σ_n: peak energy, curvature, gap
  std::optional<SceneGap> least;
};

/// The start of every refusal of a way: "the rod cannot follow <its path> to the target's
/// optimum: ".
std::string cannot_follow(const Way& way) {
  return std::string("the rod cannot follow ") + way.path_name() + " to the target's optimum: ";
}

/// The end effector's waypoints W_0 = `from` … W_n = `to` of the way `way`: with a twist, the
/// tip's poses interpolated from `from`'s to `to`'s with `way.twist` more turn about the rod's
/// tangent at the tip spread along them, T(σ) = interpolate(T_from, T_to · Rz(φ), σ) · Rz(-φσ)
/// (φ = 0: the end effector's straight path's points); along the wrench line, the tip poses of the
/// equilibria whose base wrenches lie on the straight line from `w_from` to `w_to`.
std::vector<Pose> waypoint_poses(const PlanProblem& problem,
                                 const Pose& from,
                                 const Pose& to,
                                 int n,
                                 const Way& way,
                                 const BaseWrench& w_from,
                                 const BaseWrench& w_to) {
  const Pose& tip_T_ee = problem.grasp.tip_to_end_effector;
  const Pose tip_from = compose(from, inverse(tip_T_ee));
  Pose tip_to = compose(to, inverse(tip_T_ee));
  const auto about_tangent = [](double angle) {
    return Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  };
  const double twist = way.twist;
  tip_to.rotation = tip_to.rotation * about_tangent(twist);
  const Vector6d a = w_from.to_vector(), b = w_to.to_vector();
  std::vector<Pose> poses{from};
  for (int i = 1; i < n; ++i) {
    const double sigma = static_cast<double>(i) / n;
    if (way.wrench_line) {
      const RodConfiguration c =
          integrate(problem.rod, Wrench::from_vector(a + sigma * (b - a)), Derivatives::None);
      poses.push_back(compose(c.tip(), tip_T_ee));
      continue;
    }
    if (twist == 0.0) {  // the end effector's straight path
      poses.push_back(interpolate(from, to, sigma));
      continue;
    }
    Pose tip = interpolate(tip_from, tip_to, sigma);
    tip.rotation = tip.rotation * about_tangent(-twist * sigma);
    poses.push_back(compose(tip, tip_T_ee));
  }
  poses.push_back(to);
  return poses;
}

/// The held tip along straight segments between the end effector's waypoints, σ ∈ [i/n, (i+1)/n]
/// on the segment from W_i to W_i+1 (on the straight way they lie on one straight path: that one,
/// as plan_stages::commanded_segment has it).
EquilibriumPath through_waypoints(const PlanProblem& problem,
                                  const std::vector<Pose>& poses,
                                  const Way& way) {
  if (way.straight()) return plan_stages::commanded_segment(problem, poses.front(), poses.back());
  const Pose ee_T_tip = inverse(problem.grasp.tip_to_end_effector);
  const int n = static_cast<int>(poses.size()) - 1;
  return {[poses, n, ee_T_tip, grasp = problem.grasp](double sigma) {
            const double x = std::clamp(sigma, 0.0, 1.0) * n;
            const int i = std::min(n - 1, static_cast<int>(std::floor(x)));
            const Pose ee = interpolate(poses[static_cast<std::size_t>(i)],
                                        poses[static_cast<std::size_t>(i) + 1], x - i);
            return plan_stages::held_tip(compose(ee, ee_T_tip), grasp);
          },
          false};
}

/// The held rod from the initial pose W_0 to `goal`'s W_n through the waypoints `poses` (of
/// `way`), `substeps` per waypoint, arriving on `goal`.
FollowedPath follow_path(const PlanProblem& problem,
                         const std::vector<Pose>& poses,
                         const Way& way,
                         const BaseWrench& w,
                         const PlanStep& goal,
                         int substeps,
                         const std::vector<double>* required,
                         const RodConfiguration& start) {
  const int waypoints = static_cast<int>(poses.size()) - 1;
  FollowedPath path;
  path.segments.resize(static_cast<std::size_t>(waypoints));
  FollowOptions follow;
  follow.substeps = waypoints * substeps;
  follow.final_derivatives = Derivatives::AllNodes;
  follow.arrival_stability = true;
  std::optional<scene_stages::SweptGap> swept;
  if (required) swept.emplace(problem.scene, *required, start.p);
  int substep = 0;
  follow.observer = [&](double, const RodConfiguration& c) {
    SegmentTracking& segment = path.segments[static_cast<std::size_t>(substep / substeps)];
    if (swept) {
      const SceneGap gap = swept->add(c.p);
      if (!segment.gap || gap.margin < segment.gap->margin) segment.gap = gap;
      if (!path.least || gap.margin < path.least->margin) path.least = gap;
      if (!gap.clear()) return false;
    }
    ++substep;
    return true;
  };
  path.followed = follow_equilibrium(problem.rod, through_waypoints(problem, poses, way), w, follow,
                                     &goal.solution.configuration, 1e-3);
  for (std::size_t k = 0; k < path.followed.states.size(); ++k) {
    const FollowedState& state = path.followed.states[k];
    SegmentTracking& segment = path.segments[k / static_cast<std::size_t>(substeps)];
    segment.peak_energy = std::max(segment.peak_energy, state.energy);
    segment.peak_curvature = std::max(segment.peak_curvature, state.max_curvature);
    if ((k + 1) % static_cast<std::size_t>(substeps) == 0 &&
        path.waypoint_wrench.size() + 1 < static_cast<std::size_t>(waypoints))
      path.waypoint_wrench.push_back(state.base_wrench);
  }
  return path;
}

/// The rod arrived at the goal's pose on `arrival`, another equilibrium than the goal's: stable?
bool arrived_stable(const PlanProblem& problem,
                    const RodConfiguration& arrival,
                    const PlanStep& goal) {
  const Pose tip = compose(goal.end_effector, inverse(problem.grasp.tip_to_end_effector));
  return assess_stability(problem.rod, arrival, plan_stages::held_tip(tip, problem.grasp)).stable;
}

/// The equilibrium at waypoint σ as a step: its cost terms those of the objective set `set`
/// (the reference's way), its stability assessed (an unstable waypoint is no place to stop).
PlanStep path_step(const PlanProblem& problem,
                   const plan_stages::ObjectiveSet& set,
                   const BaseWrench& w,
                   const Pose& end_effector,
                   const Way& way) {
  ShapeTarget target = problem.target;
  target.points = set.points;
  ShapeProblem costs(problem.rod, target, Workspace{}, problem.grasp, StrainLimits{},
                     problem.wrench_bounds);
  ShapeResult solution;
  solution.status = SolveStatus::Converged;
  solution.message =
      std::string("an equilibrium on ") + way.path_name() + " to the target's optimum";
  solution.base_wrench = w;
  solution.configuration = integrate(problem.rod, w, Derivatives::AllNodes);
  costs.evaluate(w.to_vector());
  solution.cost = costs.breakdown();
  const Pose tip = compose(end_effector, inverse(problem.grasp.tip_to_end_effector));
  solution.stability = assess_stability(problem.rod, solution.configuration,
                                        plan_stages::held_tip(tip, problem.grasp));
  return {set.fraction, false, false, set.points, std::move(solution), end_effector};
}

/// The held rod from `from` to `goal`'s pose by `way` (waypoint_poses); where it arrives on
/// another stable equilibrium there, `goal` optimised again from it (kMaxReoptimisations at most)
/// and the path followed again. `poses` are the waypoints of the path followed last.
FollowedPath follow_to_goal(const PlanProblem& problem,
                            const plan_stages::InitialEquilibrium& initial,
                            const Pose& from,
                            const Way& way,
                            PlanStep& goal,
                            int waypoints,
                            int substeps,
                            const std::vector<double>* scene_gaps,
                            const detour::Reoptimise& reoptimise,
                            std::vector<Pose>& poses) {
  poses = waypoint_poses(problem, from, goal.end_effector, waypoints, way, initial.wrench,
                         goal.solution.base_wrench);
  FollowedPath path = follow_path(problem, poses, way, initial.wrench, goal, substeps, scene_gaps,
                                  initial.configuration);
  for (int again = 0; again < kMaxReoptimisations && reoptimise &&
                      path.followed.event == FollowEvent::OtherBranch &&
                      arrived_stable(problem, path.followed.configuration, goal);
       ++again) {
    std::optional<PlanStep> there = reoptimise(path.followed.base_wrench);
    if (!there) break;
    goal = std::move(*there);
    poses = waypoint_poses(problem, from, goal.end_effector, waypoints, way, initial.wrench,
                           goal.solution.base_wrench);
    path = follow_path(problem, poses, way, initial.wrench, goal, substeps, scene_gaps,
                       initial.configuration);
  }
  return path;
}

/// Why a path that was not followed to the end is no plan.
Refusal not_followed(const PlanProblem& problem, const FollowedPath& path, const Way& way) {
  const bool scene = path.followed.event == FollowEvent::Stopped;
  const std::string why =
      scene ? "it would come within " + std::to_string(path.least->gap * 1e3) + " mm of obstacle " +
                  problem.scene.obstacles[static_cast<std::size_t>(path.least->obstacle)].label(
                      path.least->obstacle)
            : path.followed.message;
  return {scene ? PlanStatus::Collision : PlanStatus::SnapThrough, cannot_follow(way) + why};
}

/// The path's segments as the plan's tracking (each arriving at its waypoint's equilibrium, the
/// last on the goal) and, with a scene, their least gap.
void record_path(PlanResult& result,
                 const PlanProblem& problem,
                 const FollowedPath& path,
                 const Way& way) {
  if (!problem.scene.empty()) {
    result.scene = SceneResult{};
    result.scene->clearance = problem.scene.clearance;
  }
  for (std::size_t k = 0; k < path.segments.size(); ++k) {
    SegmentTracking segment = path.segments[k];
    const bool last = k + 1 == path.segments.size();
    segment.arrived = last ? path.followed.base_wrench : path.waypoint_wrench[k];
    segment.deviation = last ? path.followed.arrival_deviation : 0.0;
    plan_stages::record(result.tracking, segment, static_cast<int>(k));
    if (result.scene && segment.gap)
      plan_stages::record_gap(result, problem, *segment.gap, static_cast<int>(k) + 1);
  }
  result.tracking.note = std::string("the rod follows the plan (") + way.path_name() + ")";
}

/// The Pose plan along the way `way` (waypoint_poses), or nullopt with `refusal`.
std::optional<PlanResult> plan_along(const PlanProblem& problem,
                                     const PlanOptions& options,
                                     const plan_stages::InitialEquilibrium& initial,
                                     const PlanResult& reference,
                                     const detour::Reoptimise& reoptimise,
                                     const Way& way,
                                     Refusal& refusal) {
  PlanStep goal = reference.steps.back();
  const int n = options.steps;
  const int substeps =
      std::max(1, std::min(options.tracking_substeps, FollowOptions::kMaxSubsteps / n));
  const Pose from = compose(initial.configuration.tip(), problem.grasp.tip_to_end_effector);
  const std::vector<double> required =
      problem.scene.empty() ? std::vector<double>{}
                            : problem.scene.required_gaps(problem.rod.clamp.position);
  std::vector<Pose> poses;
  const FollowedPath path =
      follow_to_goal(problem, initial, from, way, goal, n, substeps,
                     problem.scene.empty() ? nullptr : &required, reoptimise, poses);
  if (!path.followed.followed()) {
    refusal = not_followed(problem, path, way);
    return std::nullopt;
  }
  PlanResult result;
  result.status = PlanStatus::Complete;
  result.message = "complete: " + std::to_string(n) +
                   (way.wrench_line ? " steps through the equilibria whose base wrenches lie on "
                                      "the straight line from the initial rod's to the target's "
                                      "optimum's"
                                    : " steps on the end effector's straight path to the target's "
                                      "optimum");
  if (way.twist != 0.0)
    result.message += ", its tip turned " +
                      detail::format_value(way.twist * 180.0 / std::numbers::pi) +
                      " degrees more about the rod's tangent along the way";
  result.feasibility = reference.feasibility;
  result.initial_wrench = initial.wrench;
  result.initial_configuration = initial.configuration;
  result.initial_stable_search = initial.stable_search;
  result.initial_points = reference.initial_points;
  plan_stages::ObjectivePath sets{problem.rod.clamp.position, reference.initial_points,
                                  problem.target.points, ObjectiveInterpolation::Shape};
  for (int i = 1; i < n; ++i) {
    const double sigma = static_cast<double>(i) / n;
    result.steps.push_back(path_step(problem, {sigma, sets.at(sigma)},
                                     path.waypoint_wrench[static_cast<std::size_t>(i - 1)],
                                     poses[static_cast<std::size_t>(i)], way));
    if (!result.steps.back().solution.stability->stable) {
      refusal.why = std::string(way.path_name()) + " passes an unstable equilibrium at " +
                    std::to_string(sigma) + " of the way";
      return std::nullopt;
    }
  }
  result.steps.push_back(goal);
  record_path(result, problem, path, way);
  result.end_effector_path = plan_stages::time_waypoints(from, result.steps, options.end_effector);
  if (!plan_stages::follows_timed_path(problem, result)) {
    refusal.why = cannot_follow(way) +
                  "along the timed path's samples it snaps on the way or arrives elsewhere (the "
                  "path passes where the equilibrium's branch divides)";
    return std::nullopt;
  }
  return result;
}

/// The ways tried in turn: the straight path, the wrench line (where the grasp holds every
/// component: elsewhere the line's equilibria are not the grasped rod's), then the twists (on the
/// sweep's helices the wrench line was gentle wherever a twist was, at 1.00 ×, and cheaper than
/// trying the ten twists first).
std::vector<Way> ways(const PlanProblem& problem) {
  std::vector<Way> result;
  for (const double twist : kTwists) result.push_back(Way{twist, false});
  const std::array<bool, 6>& released = problem.grasp.released;
  if (std::none_of(released.begin(), released.end(), [](bool b) { return b; }))
    result.insert(result.begin() + 1, Way{0.0, true});
  return result;
}

}  // namespace

std::optional<PlanResult> plan(const PlanProblem& problem,
                               const PlanOptions& options,
                               const plan_stages::InitialEquilibrium& initial,
                               const PlanResult& reference,
                               const detour::Reoptimise& reoptimise,
                               Refusal& refusal) {
  std::optional<PlanResult> best;
  const double reach = plan_stages::reached_within(reference, problem);
  for (const Way& way : ways(problem)) {
    Refusal why;
    std::optional<PlanResult> tried =
        plan_along(problem, options, initial, reference, reoptimise, way, why);
    if (tried && !(tried->steps.back().solution.cost.max_distance <= reach)) {
      why.why = cannot_follow(way) + "it arrives on another equilibrium, whose optimum is " +
                detail::format_value(tried->steps.back().solution.cost.max_distance * 1e3) +
                " mm from the target";
      tried.reset();
    }
    if (way.straight()) refusal = why;  // the straight path's refusal speaks for all
    if (!tried) continue;
    if (!best || plan_stages::peak_ratio(*tried) < plan_stages::peak_ratio(*best))
      best = std::move(tried);
    if (plan_stages::peak_ratio(*best) <= PlanOptions::kGentleRatio) break;
  }
  return best;
}

}  // namespace rodshape::pose_continuation
