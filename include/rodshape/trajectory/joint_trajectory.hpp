// joint_trajectory.hpp: the joint trajectory that makes an arm follow a timed end-effector path.
//
// Frames: the path gives world_T_ee; the arm's base link sits at world_T_base and its tip link (the
// flange) carries the end effector at flange_T_ee, so the IK target of a sample is
//   base_T_flange = world_T_base⁻¹ · world_T_ee · flange_T_ee⁻¹.
// Positions: solve_ik at every sample, seeded from the previous sample's solution (the first from
// `seed`), so that the arm stays on one branch.
// Velocities: finite differences between samples, central inside
//   q̇_i = (q_{i+1} - q_{i-1}) / (t_{i+1} - t_{i-1}),
// one-sided at the ends (q̇_0 = (q_1 - q_0) / (t_1 - t_0), likewise backward at the last sample).
// Velocity limits: a segment between samples i and i+1 needs Δt_i ≥ max_j |Δq_j| / v_lim,j; a
// segment that is faster is stretched to exactly that duration (the samples after it are shifted
// later; the poses are not changed, nothing is clipped). Since a central difference is a weighted
// mean of its two segments' rates, every sample's velocity then respects the limits too.
//
// Clearance (`clearance` set): every sample's IK keeps the links clear through the redundancy
// (IkClearance), and every sample's least link gap is measured, against the scene and against the
// rod: the rod at a sample between waypoints k and k+1 is taken as both planned shapes, `rods[k]`
// and `rods[k + 1]` (the tracked rod between them is not stored). The least gap over the samples
// is reported; the caller decides what a violation means (the planner: re-plan, then collision).
// With two arms (`others`), each sample's IK keeps the links off the other arm's capsules at that
// sample too; link_gap stays the gap to the scene and the rod (the arms' mutual gap is measured by
// the planner from both trajectories, robot/arm_clearance.hpp's arm_arm_gap).
#pragma once

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "rodshape/core/pose.hpp"
#include "rodshape/enum_names.hpp"
#include "rodshape/robot/arm_model.hpp"
#include "rodshape/robot/arm_placement.hpp"
#include "rodshape/robot/inverse_kinematics.hpp"
#include "rodshape/trajectory/end_effector_path.hpp"

namespace rodshape {

struct JointTrajectoryOptions {
  /// The joint positions the first sample's IK starts from; empty: default_seed(arm).
  Eigen::VectorXd seed;
  /// `seed`, or default_seed(arm) when it is empty.
  Eigen::VectorXd first_seed(const ArmModel& arm) const;
  IkOptions ik;
  /// With a scene: the links kept clear and measured at every sample; null: neither.
  std::shared_ptr<const ArmClearance> clearance;
  /// The rod's planned centreline at each waypoint (world frame); empty: the links are not
  /// checked against the rod.
  std::vector<RodNodes> rods;
  /// Per sample, the waypoint k + 1 it moves towards (rods[k] and rods[k + 1] are checked;
  /// clamped to the rods given). Empty with `rods` empty.
  std::vector<int> sample_waypoint;
  double clearance_influence = 0.03;  // m, IkClearance::influence
  /// With `clearance`: per sample, the other arm's link capsules at that sample (world_capsules();
  /// empty: no other arm), which IK keeps the links off as it does the obstacles.
  std::vector<std::vector<Obstacle>> others;
};

enum class JointTrajectoryStatus {
  Complete,     // every sample has joint positions; velocities within the limits
  Unreachable,  // a sample's pose has no IK solution (message: its time and pose)
  NotRun,       // nothing was asked (an empty path)
};
/// The names of JointTrajectoryStatus, in its order (to_string).
inline constexpr EnumNames<JointTrajectoryStatus, 3> kJointTrajectoryStatusNames = {{
    {JointTrajectoryStatus::Complete, "complete"},
    {JointTrajectoryStatus::Unreachable, "unreachable"},
    {JointTrajectoryStatus::NotRun, "not_run"},
}};
std::string to_string(JointTrajectoryStatus status);

struct JointTrajectoryResult {
  JointTrajectoryStatus status = JointTrajectoryStatus::NotRun;
  std::string message;  // empty when complete
  std::vector<std::string> joint_names;
  /// Sample times, s (re-timed when slowed). Unreachable: the samples solved before the failure,
  /// at the path's times, and qdot is empty.
  std::vector<double> t;
  std::vector<Eigen::VectorXd> q;     // joint positions per sample (rad or m)
  std::vector<Eigen::VectorXd> qdot;  // joint velocities per sample (rad/s or m/s)
  bool slowed = false;                // a segment was stretched to respect the velocity limits
  double slowdown = 1.0;              // duration after / duration of the path (1 if not slowed)
  double path_duration = 0.0;         // the end-effector path's own duration, s
  int failed_sample = -1;             // the unreachable sample's index, else -1
  int ik_restarts = 0;                // samples whose IK needed a restart (a possible branch jump)
  double max_position_error = 0.0;    // over the samples, |p* - p(q)| of the flange, m
  double max_rotation_error = 0.0;    // over the samples, rad
  /// With a clearance: the least link gap over the samples (capsule -1 when none was measured) and
  /// the sample where it is.
  LinkGap link_gap;
  int link_gap_sample = -1;
  int clearance_steps = 0;  // null-space clearance steps over the samples' IK
  bool complete() const { return status == JointTrajectoryStatus::Complete; }
  double duration() const { return t.empty() ? 0.0 : t.back() - t.front(); }
  /// "complete: 812 samples over 8.1 s (slowed ×1.3)" or "<status>: <message>".
  std::string brief() const;
};

/// The joint trajectory that follows `path` (world_T_ee over time, e.g. PlanResult's
/// end_effector_path). Throws InputError for a seed of the wrong size or outside the limits,
/// invalid IK options or a non-finite pose; an unreachable pose is a status.
JointTrajectoryResult joint_trajectory(const ArmModel& arm,
                                       const std::vector<TimedPose>& path,
                                       const ArmPlacement& placement = {},
                                       const JointTrajectoryOptions& options = {});

/// Two arms moving on one clock (their paths have the same sample times `path_t`, e.g. the
/// tip's and the base's end-effector paths of a plan with a moving base): both complete
/// trajectories re-timed together from `path_t`, each segment stretched to the longest either
/// arm's velocity limits need, so both keep the same times (and their velocities are taken
/// anew). Throws InputError when either is not complete or its sample count differs from
/// path_t's.
void retime_together(const ArmModel& arm_a,
                     JointTrajectoryResult& a,
                     const ArmModel& arm_b,
                     JointTrajectoryResult& b,
                     const std::vector<double>& path_t);

}  // namespace rodshape
