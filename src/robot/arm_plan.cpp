// arm_plan.cpp: plan, check by IK, tighten the reach shell and plan again (see arm_plan.hpp).
#include "rodshape/robot/arm_plan.hpp"

#include <algorithm>
#include <sstream>

#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/error.hpp"
#include "rodshape/robot/inverse_kinematics.hpp"
#include "validation.hpp"

namespace rodshape {

void ArmPlanOptions::validate() const {
  detail::require_non_negative("robot.reach.margin", reach_margin);
  detail::require_positive("robot.reach.tightening", replan_tightening);
  if (max_replans < 0)
    throw InputError("robot.reach.max_replans = " + std::to_string(max_replans) + " must be >= 0");
  reach.validate();
  joints.ik.validate();
}

std::string to_string(ArmPlanStatus status) {
  switch (status) {
    case ArmPlanStatus::Reachable:
      return "reachable";
    case ArmPlanStatus::Unreachable:
      return "unreachable";
    case ArmPlanStatus::NotChecked:
      return "not_checked";
  }
  return "unknown";
}

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
                          const IkOptions& options,
                          std::vector<Eigen::VectorXd>& waypoint_q) {
  waypoint_q.resize(1);
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const IkResult ik =
        solve_ik(arm, flange_target(placement, steps[k].end_effector), waypoint_q.back(), options);
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

}  // namespace

ArmPlan plan_with_arm(const PlanRequest& request,
                      const PlanOptions& options,
                      const ArmModel& arm,
                      const ArmPlacement& placement,
                      const ArmPlanOptions& arm_options) {
  arm_options.validate();
  options.validate();
  request.rod.validate();
  if (arm_options.joints.seed.size() > 0)
    arm.check_joint_positions(arm_options.joints.seed, "robot.seed");

  ArmPlan result;
  PlanRequest planned = request;
  const Pose initial_tip =
      request.initial_tip ? *request.initial_tip : integrate(request.rod, BaseWrench{}).tip();
  const Pose initial_ee = compose(initial_tip, request.grasp.tip_to_end_effector);
  // The initial pose does not change from one plan to the next: its IK is solved once, and its
  // solution seeds the steps' checks and the joint trajectory.
  const IkResult initial_ik = solve_ik(arm, flange_target(placement, initial_ee),
                                       arm_options.joints.first_seed(arm), arm_options.joints.ik);
  JointTrajectoryOptions joint_options = arm_options.joints;
  joint_options.seed = initial_ik.q;
  double r_start = 0.0;  // the wrist's distance where the rod starts
  if (arm_options.use_reach) {
    if (request.workspace.reach)
      throw InputError(
          "workspace.reach: given together with the arm's reach (use_reach); give one of them");
    result.reach = compute_arm_reach(arm, arm_options.reach);
    result.shell = reach_shell(*result.reach, placement, request.grasp.tip_to_end_effector,
                               arm_options.reach_margin);
    r_start = wrist_distance(*result.reach, placement, initial_ee);
    if (r_start > result.shell->outer_radius || r_start < result.shell->inner_radius) {
      throw InputError("robot: where the rod starts, the arm's wrist would be " + metres(r_start) +
                       " from its shoulder, outside its reach shell " +
                       describe_shell(*result.shell) + " (robot.reach.margin " +
                       metres(arm_options.reach_margin) +
                       "): move the arm's base or the clamp, or lower robot.reach.margin");
    }
  }

  for (;;) {
    if (result.shell) planned.workspace.reach = result.shell;
    result.plan = plan_shape(planned, options);
    result.joints = {};
    result.joints.joint_names = arm.joint_names();
    if (result.plan.status == PlanStatus::Infeasible || result.plan.end_effector_path.empty()) {
      result.status = ArmPlanStatus::NotChecked;
      result.message = "no end-effector path to check";
      result.joints.message = result.message;
      result.waypoint_q.clear();
      return result;
    }
    if (!initial_ik.converged()) {  // no plan moves the start: nothing to re-plan
      result.status = ArmPlanStatus::Unreachable;
      result.message = "the initial end-effector pose has no inverse kinematics solution: " +
                       initial_ik.message + " (the arm cannot hold the rod where it starts)";
      result.joints.message = "not computed: " + result.message;
      return result;
    }

    // 1. Every step's pose, seeded from the one before.
    result.waypoint_q = {initial_ik.q};
    const WaypointCheck check =
        check_steps(arm, placement, result.plan.steps, arm_options.joints.ik, result.waypoint_q);
    std::string failure;
    Pose failed_pose;
    if (check.failed_step > 0) {
      failure = check.message;
      result.joints.message = "not computed: " + failure;
      failed_pose = result.plan.steps[static_cast<std::size_t>(check.failed_step - 1)].end_effector;
    } else {
      // 2. The joint trajectory along the timed path (every sample by IK), from the initial
      //    pose's joints.
      result.joints =
          joint_trajectory(arm, result.plan.end_effector_path, placement, joint_options);
      if (result.joints.complete()) {
        result.status = ArmPlanStatus::Reachable;
        result.message = result.replans.empty()
                             ? "every planned pose is reachable"
                             : "every planned pose is reachable after " +
                                   std::to_string(result.replans.size()) + " re-plan" +
                                   (result.replans.size() == 1 ? "" : "s") +
                                   " with a tighter reach shell";
        return result;
      }
      failure = "joint trajectory: " + result.joints.message;
      failed_pose =
          result.plan.end_effector_path[static_cast<std::size_t>(result.joints.failed_sample)].pose;
    }

    // 3. Re-plan with a tighter shell, or report.
    result.status = ArmPlanStatus::Unreachable;
    if (!result.shell) {
      result.message = failure;
      return result;
    }
    if (static_cast<int>(result.replans.size()) >= arm_options.max_replans) {
      result.message = failure + " (after " + std::to_string(result.replans.size()) +
                       " re-plans with a tighter reach shell, now " +
                       describe_shell(*result.shell) + ")";
      return result;
    }
    Replan replan;
    replan.reason = failure;
    replan.wrist_distance = wrist_distance(*result.reach, placement, failed_pose);
    replan.shell = *result.shell;
    if (!tighten(replan.shell, replan.wrist_distance, arm_options.replan_tightening)) {
      result.message = failure + " (tightening the reach shell " + describe_shell(*result.shell) +
                       " past its wrist distance " + metres(replan.wrist_distance) +
                       " leaves nothing)";
      return result;
    }
    if (r_start > replan.shell.outer_radius || r_start < replan.shell.inner_radius) {
      result.message = failure + " (a reach shell tightened past its wrist distance " +
                       metres(replan.wrist_distance) + ", " + describe_shell(replan.shell) +
                       ", would exclude where the rod starts, " + metres(r_start) + ")";
      return result;
    }
    result.shell = replan.shell;
    result.replans.push_back(std::move(replan));
  }
}

}  // namespace rodshape
