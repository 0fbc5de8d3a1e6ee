// arm_plan.hpp: the paper's plan carried out by an arm. The arm's reach joins the workspace Ws (a
// shell for its wrist point, see arm_reach.hpp); every planned end-effector pose (the initial one,
// then one per step) is checked by exact inverse kinematics, seeded from the pose before it; when
// a pose has no IK solution the plan is made again with the shell tightened past that pose's
// wrist distance (its outer radius pulled in when the pose was far out, its inner radius pushed
// out when it was close in), up to max_replans times; then the joint trajectory follows the path,
// and a sample without IK solution there tightens the shell the same way.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "rodshape/optimisation/workspace.hpp"
#include "rodshape/robot/arm_model.hpp"
#include "rodshape/robot/arm_reach.hpp"
#include "rodshape/robot/joint_trajectory.hpp"
#include "rodshape/trajectory/shape_plan.hpp"

namespace rodshape {

struct ArmPlanOptions {
  bool use_reach = true;            // add the arm's reach shell to the workspace
  double reach_margin = 0.02;       // m: the shell is [r_min + margin, r_max - margin]
  double replan_tightening = 0.02;  // m: how far past an unreachable pose's wrist distance the
                                    // tightened shell ends
  int max_replans = 3;
  ArmReachOptions reach;
  JointTrajectoryOptions joints;  // the first seed and the IK options, for the checks too
  /// Throws InputError naming "robot.reach.margin", "robot.reach.tightening",
  /// "robot.reach.max_replans" etc.
  void validate() const;
};

enum class ArmPlanStatus {
  Reachable,    // every planned pose and every path sample has an IK solution
  Unreachable,  // a pose or a sample has none, after the re-plans allowed (message: which)
  NotChecked,   // the plan has no end-effector path (infeasible target)
};
std::string to_string(ArmPlanStatus status);  // "reachable", "unreachable", "not_checked"

/// One re-plan: which pose had no IK solution and the shell it led to.
struct Replan {
  std::string reason;           // the pose (step or path sample) and the IK's message
  double wrist_distance = 0.0;  // |w - c| of that pose, m
  Workspace::ReachShell shell;  // the shell of the next plan
};

struct ArmPlan {
  ArmPlanStatus status = ArmPlanStatus::NotChecked;
  std::string message;
  ShapePlan plan;                              // the last plan made
  std::optional<ArmReach> reach;               // the arm's reach (use_reach)
  std::optional<Workspace::ReachShell> shell;  // the shell the last plan was made with
  std::vector<Replan> replans;
  /// Joint positions of the initial end-effector pose and then of each step's, as far as the
  /// check got (IK seeded from the one before).
  std::vector<Eigen::VectorXd> waypoint_q;
  JointTrajectory joints;  // along plan.end_effector_path
  bool reachable() const { return status == ArmPlanStatus::Reachable; }
};

/// Plans `request` (see plan_shape) for the arm at `placement` holding the rod's tip at
/// request.grasp.tip_to_end_effector. Throws InputError for bad input, including a workspace that
/// already has a reach shell while use_reach is set, and an initial tip pose outside the arm's
/// reach shell (the message gives the wrist's distance and the shell); an unreachable pose after
/// the re-plans is the status Unreachable.
ArmPlan plan_with_arm(const PlanRequest& request,
                      const PlanOptions& options,
                      const ArmModel& arm,
                      const ArmPlacement& placement,
                      const ArmPlanOptions& arm_options = {});

}  // namespace rodshape
