// arm_plan.cpp: plan, check by IK, tighten the reach shell and plan again (see arm_replanning.hpp).
#include <algorithm>
#include <sstream>

#include "arm_replanning.hpp"
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
  switch (status) {
    case ArmPlanStatus::Reachable:
      return "reachable";
    case ArmPlanStatus::Unreachable:
      return "unreachable";
    case ArmPlanStatus::Collision:
      return "collision";
    case ArmPlanStatus::NotChecked:
      return "not_checked";
  }
  return "unknown";
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

/// The first step whose end-effector pose has no IK solution (1 …), or 0; waypoint_q (which holds
/// the initial pose's joints) gets each step's, each IK seeded from the one before.
struct WaypointCheck {
  int failed_step = 0;
  std::string message;
};

WaypointCheck check_steps(const ArmModel& arm,
                          const ArmPlacement& placement,
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
    const IkResult ik = solve_ik(arm, flange_target(placement, steps[k].end_effector),
                                 waypoint_q.back(), options.ik, clearance);
    if (!ik.converged()) {
      return {static_cast<int>(k) + 1, "step " + std::to_string(k + 1) +
                                           "'s end-effector pose has no inverse kinematics "
                                           "solution: " +
                                           ik.message};
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
/// InputError when the rod starts outside the shell.
ArmStart prepare_arm(const PlanProblem& problem,
                     const ArmPlanOptions& options,
                     const Pose& initial_tip,
                     ArmPlanResult& arm) {
  const ArmModel& model = problem.arm->model;
  const ArmPlacement& placement = problem.arm->placement;
  ArmStart start;
  start.end_effector = compose(initial_tip, problem.grasp.tip_to_end_effector);
  start.joint_options = options.joints;
  IkClearance clearance;
  if (options.link_clearance && !problem.scene.empty() && !model.link_capsules().empty()) {
    start.joint_options.clearance = std::make_shared<const ArmClearance>(
        model, placement.world_T_base, problem.scene, options.joints.first_seed(model));
    start.joint_options.clearance_influence = options.link_influence;
    clearance.clearance = start.joint_options.clearance.get();
    clearance.influence = options.link_influence;
  }
  start.ik = solve_ik(model, flange_target(placement, start.end_effector),
                      options.joints.first_seed(model), options.joints.ik, clearance);
  start.joint_options.seed = start.ik.q;
  if (!options.use_reach) return start;
  if (problem.workspace.reach)
    throw InputError(
        "PlanProblem.workspace.reach",
        ": given together with the arm's reach (ArmPlanOptions.use_reach); give one of them");
  arm.reach = compute_arm_reach(model, options.reach);
  try {
    arm.shell =
        reach_shell(*arm.reach, placement, problem.grasp.tip_to_end_effector, options.reach_margin);
  } catch (const InputError& error) {  // reach_shell's only field is the margin
    throw InputError("ArmPlanOptions.reach_margin", error.problem());
  }
  start.r_start = wrist_distance(*arm.reach, placement, start.end_effector);
  if (start.r_start > arm.shell->outer_radius || start.r_start < arm.shell->inner_radius) {
    throw InputError("PlanArm", ": where the rod starts, the arm's wrist would be " +
                                    metres(start.r_start) +
                                    " from its shoulder, outside its reach "
                                    "shell " +
                                    describe_shell(*arm.shell) + " (reach margin " +
                                    metres(options.reach_margin) +
                                    "): move the arm's base or the clamp, or lower the margin");
  }
  return start;
}

/// A pose of the plan that the arm cannot reach.
struct Unreachable {
  std::string failure;
  Pose pose;
  bool collision = false;  // reachable, but a link too near the scene or the rod
};

/// The rod's planned centreline at every waypoint (the initial shape, then each step's) and, per
/// path sample, the waypoint it moves towards (a sample at waypoint k's pose belongs to it).
void set_rods(const PlanResult& plan, JointTrajectoryOptions& options) {
  options.rods.clear();
  options.rods.push_back(plan.initial_configuration.p);
  for (const PlanStep& step : plan.steps) options.rods.push_back(step.solution.configuration.p);
  options.sample_waypoint.assign(plan.end_effector_path.size(), 0);
  std::size_t reached = 0;  // the last waypoint reached
  for (std::size_t i = 0; i < plan.end_effector_path.size(); ++i) {
    const Pose& pose = plan.end_effector_path[i].pose;
    bool at_waypoint = i == 0;
    while (reached < plan.steps.size() &&
           (pose.position - plan.steps[reached].end_effector.position).norm() <= 1e-12 &&
           (pose.rotation - plan.steps[reached].end_effector.rotation).norm() <= 1e-12) {
      ++reached;
      at_waypoint = true;
    }
    options.sample_waypoint[i] =
        static_cast<int>(at_waypoint ? reached : std::min(reached + 1, plan.steps.size()));
  }
}

/// 1. Every step's pose, seeded from the one before; 2. the joint trajectory along the timed path
/// (every sample by IK) from the initial pose's joints. Sets `arm`'s status and message when
/// every pose is reachable and returns nothing; else the first pose that is not.
std::optional<Unreachable> check_reach(const PlanProblem& problem,
                                       const PlanResult& plan,
                                       const ArmStart& start,
                                       ArmPlanResult& arm) {
  const ArmModel& model = problem.arm->model;
  const ArmPlacement& placement = problem.arm->placement;
  arm.waypoint_q = {start.ik.q};
  JointTrajectoryOptions joint_options = start.joint_options;
  if (joint_options.clearance) set_rods(plan, joint_options);
  const WaypointCheck check =
      check_steps(model, placement, plan.steps, joint_options, arm.waypoint_q);
  if (check.failed_step > 0) {
    arm.joints.message = "not computed: " + check.message;
    return Unreachable{check.message,
                       plan.steps[static_cast<std::size_t>(check.failed_step - 1)].end_effector};
  }
  arm.joints = joint_trajectory(model, plan.end_effector_path, placement, joint_options);
  if (!arm.joints.complete()) {
    return Unreachable{
        "joint trajectory: " + arm.joints.message,
        plan.end_effector_path[static_cast<std::size_t>(arm.joints.failed_sample)].pose};
  }
  if (joint_options.clearance && !arm.joints.link_gap.clear()) {
    const int i = arm.joints.link_gap_sample;
    const int step = joint_options.sample_waypoint[static_cast<std::size_t>(i)];
    std::ostringstream failure;
    failure.precision(4);
    failure << "the arm's links come too near at step " << step << " (sample " << i
            << ", t = " << arm.joints.t[static_cast<std::size_t>(i)]
            << " s): " << joint_options.clearance->describe(arm.joints.link_gap);
    return Unreachable{failure.str(), plan.end_effector_path[static_cast<std::size_t>(i)].pose,
                       true};
  }
  arm.status = ArmPlanStatus::Reachable;
  arm.message = arm.replans.empty()
                    ? "every planned pose is reachable"
                    : "every planned pose is reachable after " +
                          std::to_string(arm.replans.size()) + " re-plan" +
                          (arm.replans.size() == 1 ? "" : "s") + " with a tighter reach shell";
  return std::nullopt;
}

/// 3. The shell tightened past the unreachable pose, for the next plan; false (with `arm`'s
/// message saying why) when there is no next plan.
bool tighten_for_replan(const PlanProblem& problem,
                        const ArmPlanOptions& options,
                        const ArmStart& start,
                        const Unreachable& unreachable,
                        ArmPlanResult& arm) {
  arm.status = unreachable.collision ? ArmPlanStatus::Collision : ArmPlanStatus::Unreachable;
  const std::string& failure = unreachable.failure;
  if (!arm.shell) {
    arm.message = failure;
    return false;
  }
  if (static_cast<int>(arm.replans.size()) >= options.max_replans) {
    arm.message = failure + " (after " + std::to_string(arm.replans.size()) +
                  " re-plans with a tighter reach shell, now " + describe_shell(*arm.shell) + ")";
    return false;
  }
  Replan replan;
  replan.reason = failure;
  replan.wrist_distance = wrist_distance(*arm.reach, problem.arm->placement, unreachable.pose);
  replan.shell = *arm.shell;
  if (!tighten(replan.shell, replan.wrist_distance, options.replan_tightening)) {
    arm.message = failure + " (tightening the reach shell " + describe_shell(*arm.shell) +
                  " past its wrist distance " + metres(replan.wrist_distance) + " leaves nothing)";
    return false;
  }
  if (start.r_start > replan.shell.outer_radius || start.r_start < replan.shell.inner_radius) {
    arm.message = failure + " (a reach shell tightened past its wrist distance " +
                  metres(replan.wrist_distance) + ", " + describe_shell(replan.shell) +
                  ", would exclude where the rod starts, " + metres(start.r_start) + ")";
    return false;
  }
  arm.shell = replan.shell;
  arm.replans.push_back(std::move(replan));
  return true;
}

/// The plan's arm part when there is nothing to check (no path), or the start is unreachable.
bool nothing_to_check(const PlanResult& plan, const ArmStart& start, ArmPlanResult& arm) {
  if (plan.status == PlanStatus::Infeasible || plan.end_effector_path.empty()) {
    arm.status = ArmPlanStatus::NotChecked;
    arm.message = "no end-effector path to check";
    arm.joints.message = arm.message;
    arm.waypoint_q.clear();
    return true;
  }
  if (!start.ik.converged()) {  // no plan moves the start: nothing to re-plan
    arm.status = ArmPlanStatus::Unreachable;
    arm.message =
        "the initial end-effector pose has no inverse kinematics solution: " + start.ik.message +
        " (the arm cannot hold the rod where it starts)";
    arm.joints.message = "not computed: " + arm.message;
    return true;
  }
  return false;
}

/// With link clearance: the least link gap of the joint trajectory in the plan's scene result, and
/// a plan whose links stay too near has the status collision.
void report_link_gap(const ArmStart& start, const ArmPlanResult& arm, PlanResult& result) {
  const std::shared_ptr<const ArmClearance>& clearance = start.joint_options.clearance;
  if (!clearance) return;
  const LinkGap& gap = arm.joints.link_gap;
  if (arm.joints.complete() && gap.capsule >= 0) {
    if (!result.scene) result.scene = SceneResult{};
    RobotGapResult robot;
    robot.min_gap = gap.gap;
    robot.margin = gap.margin;
    robot.sample = arm.joints.link_gap_sample;
    robot.t = arm.joints.t[static_cast<std::size_t>(robot.sample)];
    JointTrajectoryOptions rods;
    set_rods(result, rods);
    robot.step = rods.sample_waypoint[static_cast<std::size_t>(robot.sample)];
    robot.link = clearance->arm().link_capsules()[static_cast<std::size_t>(gap.capsule)].label();
    robot.obstacle = gap.obstacle;
    if (gap.obstacle >= 0)
      robot.obstacle_name =
          clearance->scene().obstacles[static_cast<std::size_t>(gap.obstacle)].name;
    robot.note = clearance->describe(gap);
    result.scene->robot = std::move(robot);
  }
  if (arm.status == ArmPlanStatus::Collision && result.status == PlanStatus::Complete) {
    result.status = PlanStatus::Collision;
    result.message = "the arm: " + arm.message;
  }
}

}  // namespace

PlanResult plan_with_arm(const PlanProblem& problem, const PlanOptions& options) {
  const ArmPlanOptions& arm_options = options.arm;
  const ArmModel& model = problem.arm->model;
  if (arm_options.joints.seed.size() > 0)
    model.check_joint_positions(arm_options.joints.seed, "ArmPlanOptions.joints.seed");
  const plan_stages::InitialEquilibrium initial = plan_stages::initial_equilibrium(problem);
  // The pose the arm holds at the start: the one asked for (the solved tip is within the
  // solver's tolerance of it), or the tip of the given equilibrium.
  const Pose initial_tip = problem.initial.kind == InitialState::Kind::HeldTip
                               ? problem.initial.tip
                               : initial.configuration.tip();
  ArmPlanResult arm;
  const ArmStart start = prepare_arm(problem, arm_options, initial_tip, arm);
  PlanProblem planned = problem;
  // A complete rod plan whose links came too near, kept in case the re-plan with a tighter shell
  // does not complete (the shell can squeeze the rod's optimisation): then it is the answer.
  std::optional<PlanResult> collided;
  for (;;) {
    if (arm.shell) planned.workspace.reach = arm.shell;
    PlanResult result = plan_rod(planned, options, initial);
    if (collided && result.status != PlanStatus::Complete) {
      collided->message += " (a re-plan with the reach shell " + describe_shell(*arm.shell) +
                           " did not complete: " + to_string(result.status) + ")";
      collided->arm->message = collided->message.substr(std::string("the arm: ").size());
      return std::move(*collided);
    }
    arm.joints = {};
    arm.joints.joint_names = model.joint_names();
    if (!nothing_to_check(result, start, arm)) {
      const std::optional<Unreachable> unreachable = check_reach(problem, result, start, arm);
      if (unreachable) {
        ArmPlanResult before = arm;  // as it would be reported without a re-plan
        if (tighten_for_replan(problem, arm_options, start, *unreachable, arm)) {
          if (unreachable->collision && result.status == PlanStatus::Complete) {
            before.status = ArmPlanStatus::Collision;
            before.message = unreachable->failure;
            report_link_gap(start, before, result);
            result.arm = std::move(before);
            collided = std::move(result);
          }
          continue;
        }
      }
    }
    report_link_gap(start, arm, result);
    result.arm = std::move(arm);
    return result;
  }
}

}  // namespace detail

}  // namespace rodshape
