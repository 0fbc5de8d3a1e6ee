// arm_reach.hpp: the arm's reach as the planner's workspace Ws (paper: p(s = L) ⊂ Ws, "the robot's
// workspace"), seen from the rod's tip.
//
// Two points of the chain carry it:
//  - the shoulder c: the point of the first joint's axis nearest to the second joint's axis (fixed
//    in the base frame: joint 1 turns about a line through it);
//  - the wrist w: the point of the last joint's axis nearest to the axis before it (fixed in the
//    tip link's frame, the flange: the last joint turns about a line through it).
// So |w - c| does not depend on the first and last joints, and a flange pose whose wrist point lies
// outside the range [r_min, r_max] of |w(q) - c| over the joint limits is out of reach, whatever
// the joints. (For the Panda, c is the shoulder 0.333 m above the base and w lies on the flange
// axis 0.107 m behind the flange, where the 0.088 m offset of joint 7 meets it.) Since the hand
// holds the rod's tip rigidly, w is a point fixed in the rod's tip frame too, and the reach is a
// smooth constraint on the tip pose: Workspace::ReachShell. The range is estimated by sampling the
// joint space and refining the extreme samples by projected gradient steps, so it lies inside
// the true range; a margin shrinks it further. The shell is necessary for reach but not sufficient
// (joint limits of the wrist, orientation); an exact IK check of every planned pose settles it
// (plan_with_arm).
#pragma once

#include <Eigen/Core>

#include "rodshape/core/pose.hpp"
#include "rodshape/optimisation/workspace.hpp"
#include "rodshape/robot/arm_model.hpp"
#include "rodshape/robot/arm_placement.hpp"

namespace rodshape {

struct ArmReachOptions {
  /// Upper bounds (docs/limits.md, "Sizes"): a sample is one forward kinematics (about 0.5 µs for
  /// the Panda), a refinement step one with its Jacobian.
  static constexpr int kMaxSamples = 1'000'000;
  static constexpr int kMaxRefinementSteps = 100'000;

  int samples = 4096;          // joint positions drawn uniformly within the limits, 1 … kMax…
  int refinement_steps = 200;  // projected gradient steps from the extreme samples, 0 … kMax…
  unsigned random_seed = 1;
  /// Throws InputError naming "robot.reach.samples" etc.
  void validate() const;
};

struct ArmReach {
  Eigen::Vector3d shoulder = Eigen::Vector3d::Zero();           // c, in the arm's base frame
  Eigen::Vector3d wrist_in_tip_link = Eigen::Vector3d::Zero();  // w, in the tip link's frame
  double min_distance = 0.0;  // r_min: the smallest |w - c| found within the joint limits, m
  double max_distance = 0.0;  // r_max: the largest, m
  Eigen::VectorXd q_min_distance, q_max_distance;  // the joint positions where they were found

  /// |w - c| for a flange pose in the base frame.
  double wrist_distance(const Pose& base_T_flange) const;
};

/// The reach of `arm`'s chain (deterministic for given options).
ArmReach compute_arm_reach(const ArmModel& arm, const ArmReachOptions& options = {});

/// The reach as a constraint on the rod's tip pose, in the world: the shell [r_min + margin,
/// r_max - margin] around the shoulder, for the wrist point expressed in the tip frame. The hand
/// holds the tip at tip_T_ee (Grasp::tip_to_end_effector) and the flange at flange_T_ee
/// (ArmPlacement), so tip_T_flange = tip_T_ee · flange_T_ee⁻¹. Throws InputError when the margin is
/// negative or leaves no shell ("robot.reach.margin").
Workspace::ReachShell reach_shell(const ArmReach& reach,
                                  const ArmPlacement& placement,
                                  const Pose& tip_T_ee,
                                  double margin);

}  // namespace rodshape
