// arm_plan.cpp: plan, check by IK, tighten the reach shell and plan again (see arm_replanning.hpp).
#include <algorithm>
#include <sstream>

#include "arm_replanning.hpp"
#include "robot/arm_reach_cache.hpp"
#include "rodshape/error.hpp"
#include "rodshape/robot/inverse_kinematics.hpp"
#include "validation.hpp"

namespace rodshape {

void ArmPlanOptions::validate() const {
  detail::require_non_negative("ArmPlanOptions.reach_margin", reach_margin);
  detail::require_positive("ArmPlanOptions.replan_tightening", replan_tightening);
  detail::require_count("ArmPlanOptions.max_replans", max_replans, 0, kMaxReplans);
  detail::require_non_negative("ArmPlanOptions.link_influence", link_influence);
  if (link_influence > Scene::kMaxClearance)
    throw InputError("ArmPlanOptions.link_influence",
                     " = " + detail::format_value(link_influence) +
                         " must be <= " + detail::format_value(Scene::kMaxClearance) + " m");
  reach.validate();
  joints.ik.validate();
}

std::string to_string(ArmPlanStatus status) {
  return std::string(name_of(kArmPlanStatusNames, status));
}

namespace detail {

namespace {

std::string metres(double value) {
  std::ostringstream out;
  out.precision(4);
  out << value << " m";
  return out.str();
}

std::string describe_shell(const Workspace::ReachShell& shell) {
  std::ostringstream out;  // (not "[" + ...: GCC 12 warns about it, -Wrestrict, a false positive)
  out.precision(4);
  out << "[" << shell.inner_radius << " m, " << shell.outer_radius << " m]";
  return out.str();
}

/// The wrist's distance from the shoulder when the hand is at world_T_ee.
double wrist_distance(const ArmReach& reach,
                      const ArmPlacement& placement,
                      const Pose& world_T_ee) {
  return reach.wrist_distance(flange_target(placement, world_T_ee));
}

/// The shell tightened past a pose with wrist distance r: the outer radius pulled in below r when
/// r lies in the outer half of the shell, else the inner radius pushed out beyond r. False when
/// nothing is left.
bool tighten(Workspace::ReachShell& shell, double r, double tightening) {
  if (r >= 0.5 * (shell.inner_radius + shell.outer_radius))
    shell.outer_radius = std::min(shell.outer_radius, r) - tightening;
  else
    shell.inner_radius = std::max(shell.inner_radius, r) + tightening;
  return shell.outer_radius > shell.inner_radius;  // (inner ≥ 0, so outer > 0 too)
}

/// Which end of the rod an arm holds; what differs between the two arms: the arm, the grasp of
/// its end, the plan's poses of that end and the names its messages and errors use.
struct ArmSide {
  bool base = false;  // the base end (s = 0, PlanProblem::base_arm), else the tip (s = L)
  const PlanArm* arm = nullptr;
  Pose grasp;             // rod end → end effector (tip_T_ee, or base_T_ee of the moving base)
  std::string name;       // "the arm", "the base arm"
  std::string pose_name;  // "end-effector", "base end-effector"

  static ArmSide tip(const PlanProblem& problem) {
    return {false, &*problem.arm, problem.grasp.tip_to_end_effector, "the arm", "end-effector"};
  }
  static ArmSide base_end(const PlanProblem& problem) {
    return {true, &*problem.base_arm, problem.moving_base->grasp.tip_to_end_effector,
            "the base arm", "base end-effector"};
  }
  const ArmModel& model() const { return arm->model; }
  const ArmPlacement& placement() const { return arm->placement; }
  const Pose& end_effector(const PlanStep& step) const {
    return base ? step.base_end_effector : step.end_effector;
  }
  const std::vector<TimedPose>& path(const PlanResult& plan) const {
    return base ? plan.base_end_effector_path : plan.end_effector_path;
  }
};

/// The first step whose end-effector pose has no IK solution (1 …), or 0; waypoint_q (which holds
/// the initial pose's joints) gets each step's, each IK seeded from the one before.
struct WaypointCheck {
  int failed_step = 0;
  std::string message;
};

WaypointCheck check_steps(const ArmSide& side,
                          const std::vector<PlanStep>& steps,
                          const JointTrajectoryOptions& options,
                          std::vector<Eigen::VectorXd>& waypoint_q) {
  waypoint_q.resize(1);
  for (std::size_t k = 0; k < steps.size(); ++k) {
    IkClearance clearance;
    if (options.clearance) {
      clearance.clearance = options.clearance.get();
      clearance.influence = options.clearance_influence;
      if (k + 1 < options.rods.size()) clearance.rods = {&options.rods[k], &options.rods[k + 1]};
    }
    const IkResult ik =
        solve_ik(side.model(), flange_target(side.placement(), side.end_effector(steps[k])),
                 waypoint_q.back(), options.ik, clearance);
    if (!ik.converged()) {
      return {static_cast<int>(k) + 1,
              "step " + std::to_string(k + 1) + "'s " + side.pose_name +
                  " pose has no inverse kinematics solution: " + ik.message};
    }
    waypoint_q.push_back(ik.q);
  }
  return {};
}

/// What does not change from one plan to the next: the initial pose's IK (solved once; its
/// solution seeds the steps' checks and the joint trajectory) and the wrist's distance there.
struct ArmStart {
  Pose end_effector;
  IkResult ik;
  JointTrajectoryOptions joint_options;
  double r_start = 0.0;  // the wrist's distance where the rod starts
};

/// The initial pose's IK and, with use_reach, the arm's reach and shell (into `arm`); throws
/// InputError when the rod starts outside the shell. `with_clearance`: the links are kept clear
/// (of the scene, the rod and, with two arms, of each other).
ArmStart prepare_arm(const PlanProblem& problem,
                     const ArmPlanOptions& options,
                     const ArmSide& side,
                     const Pose& initial_end,
                     bool with_clearance,
                     ArmPlanResult& arm) {
  const ArmModel& model = side.model();
  const ArmPlacement& placement = side.placement();
  ArmStart start;
  start.end_effector = compose(initial_end, side.grasp);
  start.joint_options = options.joints;
  if (side.base) start.joint_options.seed = options.base_seed;
  IkClearance clearance;
  if (with_clearance) {
    start.joint_options.clearance = std::make_shared<const ArmClearance>(
        model, placement.world_T_base, problem.scene, start.joint_options.first_seed(model));
    start.joint_options.clearance_influence = options.link_influence;
    clearance.clearance = start.joint_options.clearance.get();
    clearance.influence = options.link_influence;
  }
  start.ik = solve_ik(model, flange_target(placement, start.end_effector),
                      start.joint_options.first_seed(model), options.joints.ik, clearance);
  start.joint_options.seed = start.ik.q;
  if (!options.use_reach) return start;
  const Workspace& workspace = side.base ? problem.moving_base->workspace : problem.workspace;
  if (workspace.reach)
    throw InputError(
        side.base ? "PlanProblem.moving_base.workspace.reach" : "PlanProblem.workspace.reach",
        ": given together with " + side.name +
            "'s reach (ArmPlanOptions.use_reach); give one of them");
  arm.reach = cached_arm_reach(model, options.reach);  // both arms the same robot: once
  try {
    arm.shell = reach_shell(*arm.reach, placement, side.grasp, options.reach_margin);
  } catch (const InputError& error) {  // reach_shell's only field is the margin
    throw InputError("ArmPlanOptions.reach_margin", error.problem());
  }
  start.r_start = wrist_distance(*arm.reach, placement, start.end_effector);
  if (start.r_start > arm.shell->outer_radius || start.r_start < arm.shell->inner_radius) {
    const std::string where = side.base ? "where the rod's base starts" : "where the rod starts";
    throw InputError(side.base ? "PlanProblem.rod.clamp" : "PlanArm",
                     ": " + where + ", " + side.name + "'s wrist would be " +
                         metres(start.r_start) + " from its shoulder, outside its reach shell " +
                         describe_shell(*arm.shell) + " (reach margin " +
                         metres(options.reach_margin) + "): move " + side.name +
                         "'s base or the clamp, or lower the margin");
  }
  return start;
}

/// A pose of the plan that an arm cannot reach.
struct Unreachable {
  std::string failure;
  Pose pose;
  bool collision = false;  // reachable, but a link too near the scene or the rod
  bool base = false;       // the base arm's pose (else the tip arm's)
};

/// The rod's planned centreline at every waypoint (the initial shape, then each step's) and, per
/// path sample, the waypoint it moves towards (a sample at waypoint k's pose belongs to it: its
/// tip pose and, with a moving base, its base pose are step k's).
void set_rods(const PlanResult& plan, JointTrajectoryOptions& options) {
  options.rods.clear();
  options.rods.push_back(plan.initial_configuration.p);
  for (const PlanStep& step : plan.steps) options.rods.push_back(step.solution.configuration.p);
  options.sample_waypoint.assign(plan.end_effector_path.size(), 0);
  const bool base_path = plan.base_end_effector_path.size() == plan.end_effector_path.size();
  const auto same = [](const Pose& a, const Pose& b) {
    return (a.position - b.position).norm() <= 1e-12 && (a.rotation - b.rotation).norm() <= 1e-12;
  };
  std::size_t reached = 0;  // the last waypoint reached
  for (std::size_t i = 0; i < plan.end_effector_path.size(); ++i) {
    const Pose& pose = plan.end_effector_path[i].pose;
    bool at_waypoint = i == 0;
    while (reached < plan.steps.size() && same(pose, plan.steps[reached].end_effector) &&
           (!base_path ||
            same(plan.base_end_effector_path[i].pose, plan.steps[reached].base_end_effector))) {
      ++reached;
      at_waypoint = true;
    }
    options.sample_waypoint[i] =
        static_cast<int>(at_waypoint ? reached : std::min(reached + 1, plan.steps.size()));
  }
}

/// One arm of the plan: its side, its fixed start and its part of the result.
struct ArmState {
  ArmSide side;
  ArmStart start;
  ArmPlanResult result;
};

/// The plan's arm part when there is nothing to check (no path), or the start is unreachable.
bool nothing_to_check(const PlanResult& plan, ArmState& state) {
  ArmPlanResult& arm = state.result;
  const std::vector<TimedPose>& path = state.side.path(plan);
  if (plan.status == PlanStatus::Infeasible || plan.end_effector_path.empty() ||
      path.size() != plan.end_effector_path.size()) {
    arm.status = ArmPlanStatus::NotChecked;
    arm.message = path.empty() && !plan.end_effector_path.empty()
                      ? "no " + state.side.pose_name + " path to check"
                      : "no end-effector path to check";
    arm.joints.message = arm.message;
    arm.waypoint_q.clear();
    return true;
  }
  if (!state.start.ik.converged()) {  // no plan moves the start: nothing to re-plan
    arm.status = ArmPlanStatus::Unreachable;
    arm.message = "the initial " + state.side.pose_name +
                  " pose has no inverse kinematics solution: " + state.start.ik.message + " (" +
                  state.side.name + " cannot hold the rod where it starts" +
                  (state.side.base ? ", PlanProblem.rod.clamp)" : ")");
    arm.joints.message = "not computed: " + arm.message;
    return true;
  }
  return false;
}

/// 1. Every step's pose, seeded from the one before; 2. the joint trajectory along the timed path
/// (every sample by IK) from the initial pose's joints, with `others` (per sample, the other
/// arm's capsules; may be empty) kept off. Sets the arm's status and message when every pose is
/// reachable and returns nothing; else the first pose that is not.
std::optional<Unreachable> check_reach(const PlanResult& plan,
                                       const JointTrajectoryOptions& rods,
                                       std::vector<std::vector<Obstacle>> others,
                                       ArmState& state) {
  const ArmSide& side = state.side;
  ArmPlanResult& arm = state.result;
  arm.waypoint_q = {state.start.ik.q};
  JointTrajectoryOptions joint_options = state.start.joint_options;
  if (joint_options.clearance) {
    joint_options.rods = rods.rods;
    joint_options.sample_waypoint = rods.sample_waypoint;
    joint_options.others = std::move(others);
  }
  const WaypointCheck check = check_steps(side, plan.steps, joint_options, arm.waypoint_q);
  const std::vector<TimedPose>& path = side.path(plan);
  if (check.failed_step > 0) {
    arm.joints.message = "not computed: " + check.message;
    return Unreachable{
        check.message,
        side.end_effector(plan.steps[static_cast<std::size_t>(check.failed_step - 1)]), false,
        side.base};
  }
  arm.joints = joint_trajectory(side.model(), path, side.placement(), joint_options);
  if (!arm.joints.complete()) {
    return Unreachable{
        (side.base ? "base joint trajectory: " : "joint trajectory: ") + arm.joints.message,
        path[static_cast<std::size_t>(arm.joints.failed_sample)].pose, false, side.base};
  }
  if (joint_options.clearance && !arm.joints.link_gap.clear()) {
    const int i = arm.joints.link_gap_sample;
    const int step = joint_options.sample_waypoint[static_cast<std::size_t>(i)];
    std::ostringstream failure;
    failure.precision(4);
    failure << side.name << "'s links come too near at step " << step << " (sample " << i
            << ", t = " << arm.joints.t[static_cast<std::size_t>(i)]
            << " s): " << joint_options.clearance->describe(arm.joints.link_gap);
    return Unreachable{failure.str(), path[static_cast<std::size_t>(i)].pose, true, side.base};
  }
  arm.status = ArmPlanStatus::Reachable;
  arm.message = arm.replans.empty()
                    ? "every planned pose is reachable"
                    : "every planned pose is reachable after " +
                          std::to_string(arm.replans.size()) + " re-plan" +
                          (arm.replans.size() == 1 ? "" : "s") + " with a tighter reach shell";
  return std::nullopt;
}

/// 3. The shell of the arm that cannot reach tightened past the unreachable pose, for the next
/// plan; false (with that arm's message saying why) when there is no next plan. `replans`: both
/// arms' re-plans so far (they share ArmPlanOptions::max_replans).
bool tighten_for_replan(const ArmPlanOptions& options,
                        const Unreachable& unreachable,
                        std::size_t replans,
                        ArmState& state) {
  ArmPlanResult& arm = state.result;
  arm.status = unreachable.collision ? ArmPlanStatus::Collision : ArmPlanStatus::Unreachable;
  const std::string& failure = unreachable.failure;
  if (!arm.shell) {
    arm.message = failure;
    return false;
  }
  if (static_cast<int>(replans) >= options.max_replans) {
    arm.message = failure + " (after " + std::to_string(replans) +
                  " re-plans with a tighter reach shell, now " + describe_shell(*arm.shell) + ")";
    return false;
  }
  Replan replan;
  replan.reason = failure;
  replan.wrist_distance = wrist_distance(*arm.reach, state.side.placement(), unreachable.pose);
  replan.shell = *arm.shell;
  if (!tighten(replan.shell, replan.wrist_distance, options.replan_tightening)) {
    arm.message = failure + " (tightening the reach shell " + describe_shell(*arm.shell) +
                  " past its wrist distance " + metres(replan.wrist_distance) + " leaves nothing)";
    return false;
  }
  const double r_start = state.start.r_start;
  if (r_start > replan.shell.outer_radius || r_start < replan.shell.inner_radius) {
    arm.message = failure + " (a reach shell tightened past its wrist distance " +
                  metres(replan.wrist_distance) + ", " + describe_shell(replan.shell) +
                  ", would exclude where the rod starts, " + metres(r_start) + ")";
    return false;
  }
  arm.shell = replan.shell;
  arm.replans.push_back(std::move(replan));
  return true;
}

/// The two arms' least gap over the joint samples (both trajectories complete, on one clock).
struct ArmArmGap {
  LinkGap gap;  // capsule: the tip arm's, other_capsule: the base arm's
  int sample = -1;
};

ArmArmGap arm_arm_gap(const ArmState& tip, const ArmState& base, double required) {
  ArmArmGap least;
  const std::vector<Eigen::VectorXd>& q_tip = tip.result.joints.q;
  const std::vector<Eigen::VectorXd>& q_base = base.result.joints.q;
  for (std::size_t i = 0; i < q_tip.size() && i < q_base.size(); ++i) {
    const LinkGap gap = rodshape::arm_arm_gap(
        tip.side.model(), tip.side.placement().world_T_base, q_tip[i], base.side.model(),
        base.side.placement().world_T_base, q_base[i], required);
    if (gap.capsule >= 0 && gap.margin < least.gap.margin) {
      least.gap = gap;
      least.sample = static_cast<int>(i);
    }
  }
  return least;
}

/// "link panda_link7 of the arm and link panda_hand of the base arm, gap -3 mm (required 5 mm)".
std::string describe_arm_arm(const ArmState& tip, const ArmState& base, const LinkGap& gap) {
  std::ostringstream out;
  out.precision(3);
  out << "link " << tip.side.model().link_capsules()[static_cast<std::size_t>(gap.capsule)].label()
      << " of the arm and link "
      << base.side.model().link_capsules()[static_cast<std::size_t>(gap.other_capsule)].label()
      << " of the base arm, gap " << gap.gap * 1e3 << " mm (required "
      << (gap.gap - gap.margin) * 1e3 << " mm)";
  return out.str();
}

/// A gap into the plan's scene result when its margin is the least so far: a link of `state`'s
/// arm against the scene or the rod, or (obstacle = kOtherArm, `state` the tip's arm) against a
/// link of `other`, the base arm.
void record_robot_gap(const LinkGap& gap,
                      int sample,
                      const ArmState& state,
                      const ArmState* other,
                      const JointTrajectoryOptions& rods,
                      double clearance,
                      PlanResult& result) {
  if (gap.capsule < 0 || sample < 0) return;
  if (!result.scene) {  // two arms without a scene: their mutual gap
    result.scene = SceneResult{};
    result.scene->clearance = clearance;
  }
  if (result.scene->robot && !(gap.margin < result.scene->robot->margin)) return;
  const ArmClearance& arm_clearance = *state.start.joint_options.clearance;
  RobotGapResult robot;
  robot.min_gap = gap.gap;
  robot.margin = gap.margin;
  robot.sample = sample;
  robot.t = state.result.joints.t[static_cast<std::size_t>(sample)];
  robot.step = rods.sample_waypoint[static_cast<std::size_t>(sample)];
  robot.arm = state.side.base ? "base" : "tip";
  robot.link = state.side.model().link_capsules()[static_cast<std::size_t>(gap.capsule)].label();
  robot.obstacle = gap.obstacle;
  if (gap.obstacle >= 0)
    robot.obstacle_name =
        arm_clearance.scene().obstacles[static_cast<std::size_t>(gap.obstacle)].name;
  if (gap.obstacle == kOtherArm) {
    robot.other_link =
        other->side.model().link_capsules()[static_cast<std::size_t>(gap.other_capsule)].label();
    robot.note = describe_arm_arm(state, *other, gap);
  } else {
    robot.note = (state.side.base ? "base arm: " : "") + arm_clearance.describe(gap);
  }
  result.scene->robot = std::move(robot);
}

/// The arms the problem has, each prepared (its initial pose's IK, its reach shell).
struct Arms {
  std::optional<ArmState> tip, base;
  /// Both arms' re-plans so far (they share ArmPlanOptions::max_replans).
  std::size_t replans() const {
    return (tip ? tip->result.replans.size() : 0) + (base ? base->result.replans.size() : 0);
  }
  ArmState& of(const Unreachable& u) { return u.base ? *base : *tip; }
};

/// Throws InputError for a seed of the wrong size or outside its arm's limits.
void check_seeds(const PlanProblem& problem, const ArmPlanOptions& options) {
  if (problem.arm && options.joints.seed.size() > 0)
    problem.arm->model.check_joint_positions(options.joints.seed, "ArmPlanOptions.joints.seed");
  if (problem.base_arm && options.base_seed.size() > 0)
    problem.base_arm->model.check_joint_positions(options.base_seed, "ArmPlanOptions.base_seed");
}

/// mm, three digits: "12.3 mm".
std::string overlap_millimetres(double metres) {
  std::ostringstream out;
  out.precision(3);
  out << metres * 1e3 << " mm";
  return out.str();
}

/// The capsules of `arm` at `q` (standing at world_T_base) whose frame `keep(frame)` says, as
/// world capsule obstacles (world_capsules()), with their index into link_capsules().
template <typename Keep>
std::vector<std::pair<int, CapsuleObstacle>> capsules_where(const ArmModel& arm,
                                                            const Pose& world_T_base,
                                                            const Eigen::VectorXd& q,
                                                            Keep&& keep) {
  std::vector<std::pair<int, CapsuleObstacle>> kept;
  const std::vector<Obstacle> all = world_capsules(arm, world_T_base, q);
  for (std::size_t c = 0; c < all.size(); ++c)
    if (keep(arm.link_capsules()[c].frame))
      kept.emplace_back(static_cast<int>(c), std::get<CapsuleObstacle>(all[c].shape));
  return kept;
}

/// Throws InputError when the two arms' base links (the capsules no joint moves) overlap: the
/// bases stand in each other whatever the joints do, so no plan can be carried out (issue 43,
/// item 7; found before only after planning, as a collision).
void check_bases_apart(const PlanProblem& problem, const ArmPlanOptions& options) {
  const ArmModel& tip = problem.arm->model;
  const ArmModel& base = problem.base_arm->model;
  const Pose& world_T_tip = problem.arm->placement.world_T_base;
  const Pose& world_T_base = problem.base_arm->placement.world_T_base;
  const auto fixed = [](const ArmModel& arm) {
    return [&arm](int frame) { return arm.joints_moving_frame(frame) == 0; };
  };
  const auto ours = capsules_where(tip, world_T_tip, options.joints.first_seed(tip), fixed(tip));
  const auto theirs = capsules_where(
      base, world_T_base, options.base_seed.size() > 0 ? options.base_seed : default_seed(base),
      fixed(base));
  for (const auto& [c, a] : ours) {
    for (const auto& [d, b] : theirs) {
      const double gap = Obstacle{"", b}.distance(a.from, a.to).distance - a.radius;
      if (gap >= -SceneGap::kTolerance) continue;
      throw InputError(
          "PlanArm.placement.world_T_base",
          ": the arm's base link " + tip.link_capsules()[static_cast<std::size_t>(c)].label() +
              " overlaps the base arm's base link " +
              base.link_capsules()[static_cast<std::size_t>(d)].label() +
              " (placed by PlanProblem.base_arm.placement.world_T_base) by " +
              overlap_millimetres(-gap) + ": the two bases stand in each other; move one of them");
    }
  }
}

/// Throws InputError when a link fixed to the arm's hand (every joint moves it: the last joint's
/// link, the flange, the hand) overlaps an obstacle at the start: the rod's pose there fixes the
/// hand, no joint can take it out, so the plan would end in a collision.
void check_hand_clear(const PlanProblem& problem, const ArmSide& side, const ArmStart& start) {
  const ArmModel& model = side.model();
  if (problem.scene.empty() || model.joints() <= 1 || !start.ik.converged()) return;
  const auto hand =
      capsules_where(model, side.placement().world_T_base, start.ik.q,
                     [&](int frame) { return model.joints_moving_frame(frame) == model.joints(); });
  for (const auto& [c, capsule] : hand) {
    for (std::size_t j = 0; j < problem.scene.obstacles.size(); ++j) {
      const Obstacle& obstacle = problem.scene.obstacles[j];
      const double gap = obstacle.distance(capsule.from, capsule.to).distance - capsule.radius;
      if (gap >= -SceneGap::kTolerance) continue;
      const std::string label = obstacle.name.empty() ? "" : " (" + obstacle.label(0) + ")";
      throw InputError(
          "Scene.obstacles[" + std::to_string(j) + "]",
          label + ": " + side.name + "'s link " +
              model.link_capsules()[static_cast<std::size_t>(c)].label() +
              ", fixed to its hand, starts inside it (" + overlap_millimetres(-gap) +
              " deep) where " + (side.base ? "the rod's base starts" : "the rod starts") +
              ": the hand holds the rod there and no joint can move it out; move the obstacle "
              "or the rod's start");
    }
  }
}

Arms prepare_arms(const PlanProblem& problem,
                  const ArmPlanOptions& options,
                  const Pose& initial_tip) {
  if (problem.arm && problem.base_arm) check_bases_apart(problem, options);
  const bool two = problem.arm && problem.base_arm;
  // Link clearance with a scene, or with two arms (their gap from each other and from the rod).
  const auto with_clearance = [&](const PlanArm& arm) {
    return options.link_clearance && !arm.model.link_capsules().empty() &&
           (!problem.scene.empty() || two);
  };
  Arms arms;
  if (problem.arm) {
    ArmState tip{ArmSide::tip(problem), {}, {}};
    tip.start = prepare_arm(problem, options, tip.side, initial_tip, with_clearance(*problem.arm),
                            tip.result);
    arms.tip = std::move(tip);
  }
  if (problem.base_arm) {
    ArmState base{ArmSide::base_end(problem), {}, {}};
    base.start = prepare_arm(problem, options, base.side, problem.rod.clamp,
                             with_clearance(*problem.base_arm), base.result);
    arms.base = std::move(base);
  }
  for (const std::optional<ArmState>* state : {&arms.tip, &arms.base})
    if (*state) check_hand_clear(problem, (*state)->side, (*state)->start);
  return arms;
}

/// Per sample, the arm's link capsules in the world along its joint trajectory.
std::vector<std::vector<Obstacle>> capsules_along(const ArmState& state) {
  std::vector<std::vector<Obstacle>> capsules;
  capsules.reserve(state.result.joints.q.size());
  for (const Eigen::VectorXd& q : state.result.joints.q)
    capsules.push_back(world_capsules(state.side.model(), state.side.placement().world_T_base, q));
  return capsules;
}

/// Rounds of keep_arms_apart: the tip's arm, then the base's, then the tip's again.
constexpr int kArmArmRounds = 3;

/// The two arms kept apart through their redundancy (issue 21 item 4). The base arm's IK already
/// kept off the tip arm's links; when their least gap (arm_arm_gap) is still below the clearance,
/// the arms take turns: one arm's joint trajectory is solved again with the other's capsules at
/// each sample as obstacles (IkClearance::others, the null-space push), the tip's first (the
/// links pinned by the base gripper's pose, its link 7 and hand, can only be avoided by the
/// tip's arm). A turn is kept when the arm stays reachable (every pose, the scene and the rod
/// clear) and the least margin grew; the turns stop when the gap is clear. What is left short is
/// reported by report_arms (status collision).
void keep_arms_apart(const PlanResult& plan, const JointTrajectoryOptions& rods, Arms& arms) {
  const double clearance = arms.tip->start.joint_options.clearance->scene().clearance;
  ArmArmGap least = arm_arm_gap(*arms.tip, *arms.base, clearance);
  for (int round = 0; round < kArmArmRounds && least.sample >= 0 && !least.gap.clear(); ++round) {
    const bool tip_turn = round % 2 == 0;
    ArmState& moved = tip_turn ? *arms.tip : *arms.base;
    const ArmState& still = tip_turn ? *arms.base : *arms.tip;
    ArmState trial = moved;
    if (check_reach(plan, rods, capsules_along(still), trial)) continue;
    const ArmArmGap gap = tip_turn ? arm_arm_gap(trial, *arms.base, clearance)
                                   : arm_arm_gap(*arms.tip, trial, clearance);
    if (!(gap.gap.margin > least.gap.margin)) continue;
    moved = std::move(trial);
    least = gap;
  }
}

/// Checks the arms along `plan`: the tip's arm first, then the base's (whose IK keeps its links
/// off the tip arm's at each sample), the two kept apart (keep_arms_apart), and with both
/// reachable their joint trajectories re-timed on one clock. The first pose an arm cannot reach
/// (its status set), or nothing.
std::optional<Unreachable> check_plan(const PlanResult& plan, Arms& arms) {
  JointTrajectoryOptions rods;
  set_rods(plan, rods);
  for (std::optional<ArmState>* state : {&arms.tip, &arms.base}) {
    if (!*state) continue;
    (*state)->result.joints = {};
    (*state)->result.joints.joint_names = (*state)->side.model().joint_names();
  }
  if (arms.tip && !nothing_to_check(plan, *arms.tip)) {
    if (std::optional<Unreachable> u = check_reach(plan, rods, {}, *arms.tip)) {
      if (arms.base) {
        arms.base->result.status = ArmPlanStatus::NotChecked;
        arms.base->result.message = "not checked: the arm cannot follow the plan";
        arms.base->result.joints.message = arms.base->result.message;
        arms.base->result.waypoint_q.clear();
      }
      return u;
    }
  }
  if (arms.base && !nothing_to_check(plan, *arms.base)) {
    std::vector<std::vector<Obstacle>> others;
    if (arms.tip && arms.tip->result.reachable() && arms.base->start.joint_options.clearance) {
      const ArmState& tip = *arms.tip;
      for (const Eigen::VectorXd& q : tip.result.joints.q)
        others.push_back(world_capsules(tip.side.model(), tip.side.placement().world_T_base, q));
    }
    if (std::optional<Unreachable> u = check_reach(plan, rods, std::move(others), *arms.base))
      return u;
  }
  if (arms.tip && arms.base && arms.tip->result.reachable() && arms.base->result.reachable()) {
    if (arms.tip->start.joint_options.clearance && arms.base->start.joint_options.clearance)
      keep_arms_apart(plan, rods, arms);
    std::vector<double> t;
    for (const TimedPose& sample : plan.end_effector_path) t.push_back(sample.t);
    retime_together(arms.tip->side.model(), arms.tip->result.joints, arms.base->side.model(),
                    arms.base->result.joints, t);
  }
  return std::nullopt;
}

/// The arms' results into the plan: the least link gap (each arm against the scene and the rod,
/// and the two arms against each other) in its scene result, and a plan whose links stay too near
/// has the status collision (two arms too near each other: both arms' status collision).
void report_arms(const PlanProblem& problem, Arms& arms, PlanResult& result) {
  JointTrajectoryOptions rods;
  set_rods(result, rods);
  for (std::optional<ArmState>* state : {&arms.tip, &arms.base}) {
    if (!*state || !(*state)->start.joint_options.clearance) continue;
    const JointTrajectoryResult& joints = (*state)->result.joints;
    if (joints.complete())
      record_robot_gap(joints.link_gap, joints.link_gap_sample, **state, nullptr, rods,
                       problem.scene.clearance, result);
  }
  if (arms.tip && arms.base && arms.tip->start.joint_options.clearance &&
      arms.base->start.joint_options.clearance && arms.tip->result.reachable() &&
      arms.base->result.reachable()) {
    const ArmArmGap least = arm_arm_gap(*arms.tip, *arms.base, problem.scene.clearance);
    record_robot_gap(least.gap, least.sample, *arms.tip, &*arms.base, rods, problem.scene.clearance,
                     result);
    if (least.sample >= 0 && !least.gap.clear()) {
      const std::size_t i = static_cast<std::size_t>(least.sample);
      std::ostringstream failure;
      failure.precision(4);
      failure << "the two arms come too near each other at step " << rods.sample_waypoint[i]
              << " (sample " << i << ", t = " << arms.tip->result.joints.t[i]
              << " s): " << describe_arm_arm(*arms.tip, *arms.base, least.gap);
      if (arms.tip->start.joint_options.clearance->fixed_to_hand(least.gap.capsule) &&
          arms.base->start.joint_options.clearance->fixed_to_hand(least.gap.other_capsule))
        failure << "; both links are fixed to their hands, whose poses the rod's plan sets: no "
                   "joint positions keep them apart";
      for (ArmState* state : {&*arms.tip, &*arms.base}) {
        state->result.status = ArmPlanStatus::Collision;
        state->result.message = failure.str();
      }
      if (result.status == PlanStatus::Complete) {
        result.status = PlanStatus::Collision;
        result.message = failure.str();
      }
    }
  }
  for (std::optional<ArmState>* state : {&arms.tip, &arms.base}) {
    if (*state && (*state)->result.status == ArmPlanStatus::Collision &&
        result.status == PlanStatus::Complete) {
      result.status = PlanStatus::Collision;
      result.message = (*state)->side.name + ": " + (*state)->result.message;
    }
  }
  if (arms.tip) result.arm = arms.tip->result;
  if (arms.base) result.base_arm = arms.base->result;
}

/// The pose the tip's arm holds at the start: the one asked for (the solved tip is within the
/// solver's tolerance of it), or the tip of the given equilibrium.
Pose initial_tip(const PlanProblem& problem, const RodConfiguration& initial) {
  return problem.initial.kind == InitialState::Kind::HeldTip ? problem.initial.tip : initial.tip();
}

}  // namespace

PlanResult plan_with_arm(const PlanProblem& problem, const PlanOptions& options) {
  check_seeds(problem, options.arm);
  const plan_stages::InitialEquilibrium initial = plan_stages::initial_equilibrium(problem);
  return plan_with_arms(
      problem, options, initial_tip(problem, initial.configuration),
      [&](const PlanProblem& planned) { return plan_rod(planned, options, initial); });
}

PlanResult plan_with_arms(const PlanProblem& problem,
                          const PlanOptions& options,
                          const Pose& initial_tip,
                          const RodPlanner& planner) {
  Arms arms = prepare_arms(problem, options.arm, initial_tip);
  PlanProblem planned = problem;
  // A complete rod plan whose links came too near, kept in case the re-plan with a tighter shell
  // does not complete (the shell can squeeze the rod's optimisation): then it is the answer.
  std::optional<PlanResult> collided;
  bool collided_base = false;  // whose links (and shell)
  for (;;) {
    if (arms.tip && arms.tip->result.shell) planned.workspace.reach = arms.tip->result.shell;
    if (arms.base && arms.base->result.shell)
      planned.moving_base->workspace.reach = arms.base->result.shell;
    PlanResult result = planner(planned);
    if (collided && result.status != PlanStatus::Complete) {
      const ArmState& side = collided_base ? *arms.base : *arms.tip;
      collided->message += " (a re-plan with the reach shell " +
                           describe_shell(*side.result.shell) +
                           " did not complete: " + to_string(result.status) + ")";
      ArmPlanResult& reported = collided_base ? *collided->base_arm : *collided->arm;
      reported.message = collided->message.substr(side.side.name.size() + 2);
      return std::move(*collided);
    }
    if (const std::optional<Unreachable> unreachable = check_plan(result, arms)) {
      Arms before = arms;  // as it would be reported without a re-plan
      if (tighten_for_replan(options.arm, *unreachable, arms.replans(), arms.of(*unreachable))) {
        if (unreachable->collision && result.status == PlanStatus::Complete) {
          ArmPlanResult& reported = before.of(*unreachable).result;
          reported.status = ArmPlanStatus::Collision;
          reported.message = unreachable->failure;
          report_arms(problem, before, result);
          collided = std::move(result);
          collided_base = unreachable->base;
        }
        continue;
      }
    }
    report_arms(problem, arms, result);
    return result;
  }
}

void check_arms(const PlanProblem& problem, const PlanOptions& options, PlanResult& result) {
  problem.validate();
  options.validate();
  check_seeds(problem, options.arm);
  Arms arms =
      prepare_arms(problem, options.arm, initial_tip(problem, result.initial_configuration));
  if (const std::optional<Unreachable> unreachable = check_plan(result, arms)) {
    ArmPlanResult& arm = arms.of(*unreachable).result;
    arm.status = unreachable->collision ? ArmPlanStatus::Collision : ArmPlanStatus::Unreachable;
    arm.message = unreachable->failure;
  }
  report_arms(problem, arms, result);
}

}  // namespace detail

}  // namespace rodshape
