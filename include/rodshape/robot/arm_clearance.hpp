// arm_clearance.hpp: the gaps between an arm's link capsules (link_capsule.hpp) and a scene's
// obstacles, and between them and a rod, with their exact derivatives in the joint positions.
//
// The gap of capsule c (segment [a(q), b(q)] in the world, radius r_c) to obstacle j is
//   g = d_j([a, b]) - r_c,
// d_j the obstacle's signed distance over the segment (core/obstacle.hpp). By the envelope argument
// ∂g/∂q = ∇d_j(p*)ᵀ J_p*(q), p* the nearest point of the segment, held fixed in the link's frame
// and J_p* its point Jacobian (ArmModel::point_jacobian). The rod is a chain of capsules of radius
// Scene::rod_radius around its centreline's segments [p_i, p_{i+1}].
//
// Required gaps: the scene's clearance, except
// - the arm's mount: a capsule that no joint but the first moves (the base link, the links fixed to
//   it and the first joint's link) may stand on what it is mounted on: against an obstacle it is
//   nearer to than the clearance at the mount joint positions, it keeps min(clearance, that gap),
//   as the rod's clamp does (core/scene.hpp);
// - the hand: capsules on links that no joint moves relative to the tip link (the flange, the hand,
//   its fingers, and the last joint's link) hold the rod and are not checked against it.
// Self-collision (link against link) is not measured here (docs/robot.md says why).
//
// Two arms (one holding each end of the rod, issue 21): the gap between a capsule of one arm and
// a capsule of the other is the distance between their segments minus both radii, and every pair
// must keep the scene's clearance (arm_arm_gap). Against the other arm a link is pushed off, in
// IK's null space, as off an obstacle: the other arm's capsules at that instant are passed as
// capsule obstacles (`others`, world_capsules()), their gaps reported with obstacle = kOtherArm.
#pragma once

#include <Eigen/Core>
#include <limits>
#include <string>
#include <vector>

#include "rodshape/core/pose.hpp"
#include "rodshape/core/scene.hpp"
#include "rodshape/robot/arm_model.hpp"

namespace rodshape {

/// LinkGap::obstacle of a pair with the other arm's link (LinkGap::other_capsule names it).
inline constexpr int kOtherArm = -2;

/// Where an arm's links come closest to the scene, the rod or the other arm.
struct LinkGap {
  double gap = std::numeric_limits<double>::infinity();     // m, surface to surface (< 0: overlap)
  double margin = std::numeric_limits<double>::infinity();  // gap - the gap required of the pair
  int capsule = -1;        // index into ArmModel::link_capsules(); -1: nothing measured
  int obstacle = -1;       // index into Scene::obstacles; -1 for the rod; kOtherArm: the other arm
  int rod_segment = -1;    // the rod's segment [p_i, p_{i+1}] when obstacle = -1
  int other_capsule = -1;  // the other arm's capsule (its ArmModel::link_capsules()) for kOtherArm
  bool clear() const { return margin >= -SceneGap::kTolerance; }
};

/// One pair within the influence distance: its shortfall and the gradient of its gap.
struct LinkGapRow {
  double shortfall = 0.0;    // required + influence - gap, > 0
  Eigen::VectorXd gradient;  // ∂gap/∂q (n)
};

/// A rod's centreline, world frame (the nodes' positions), for the link–rod gaps.
using RodNodes = std::vector<Eigen::Vector3d>;

class ArmClearance {
 public:
  /// The arm standing at `world_T_base` in `scene` (validated), its mount gaps measured at the
  /// joint positions `q_mount` (e.g. the plan's first IK seed).
  ArmClearance(const ArmModel& arm,
               const Pose& world_T_base,
               const Scene& scene,
               const Eigen::VectorXd& q_mount);

  const ArmModel& arm() const { return arm_; }
  const Scene& scene() const { return scene_; }
  /// Whether capsule c is checked against the rod (not part of the hand holding it).
  bool checks_rod(int c) const { return checks_rod_[static_cast<std::size_t>(c)]; }
  /// Whether capsule c is fixed to the tip link (every joint moves it: the last joint's link, the
  /// flange, the hand): where the hand is on its pose, no joint positions move it.
  bool fixed_to_hand(int c) const { return !checks_rod(c); }
  /// The gap capsule c must keep from obstacle j.
  double required_gap(int c, int j) const;

  /// Whether the pair of `gap` is a mount pair (a capsule of the mount on what it stands on).
  bool is_mount(const LinkGap& gap) const;
  /// The pair with the least margin at `q`, over the obstacles, every rod in `rods` (each may be
  /// null) and the other arm's capsules `others` (each required to keep the clearance); mount
  /// pairs count only where they sink deeper than at the mount positions.
  LinkGap least_gap(const Eigen::VectorXd& q,
                    const std::vector<const RodNodes*>& rods = {},
                    const std::vector<Obstacle>* others = nullptr) const;
  /// Every pair (capsule, obstacle), (capsule, rod: its nearest segment) and (capsule, other
  /// arm's capsule) whose gap is below its required gap plus `influence`, with its gradient in q,
  /// into `rows` (mount pairs left out).
  void near_pairs(const Eigen::VectorXd& q,
                  const std::vector<const RodNodes*>& rods,
                  double influence,
                  std::vector<LinkGapRow>& rows,
                  const std::vector<Obstacle>* others = nullptr) const;
  /// "link panda_link4, obstacle 'shelf', gap 3.2 mm (required 5 mm)"; for the rod "the rod";
  /// for the other arm "the other arm's link panda_link7" (its label when `other` is given).
  std::string describe(const LinkGap& gap, const ArmModel* other = nullptr) const;

 private:
  struct Measured {
    LinkGap gap;
    Eigen::Vector3d point;     // p*, base frame
    Eigen::Vector3d gradient;  // ∇d(p*), base frame
  };
  template <typename Visit>
  void for_each_pair(const Eigen::VectorXd& q,
                     const std::vector<const RodNodes*>& rods,
                     const std::vector<Obstacle>* others,
                     const double& prefilter,
                     LinkFrames& frames,
                     Visit&& visit) const;

  ArmModel arm_;
  Pose world_T_base_;
  Scene scene_;
  std::vector<double> required_;  // per capsule × obstacle
  std::vector<bool> mount_;       // per capsule × obstacle
  std::vector<bool> checks_rod_;
};

/// The arm's link capsules at `q`, standing at `world_T_base`, as capsule obstacles in the world
/// (one per ArmModel::link_capsules(), in order; named by their labels).
std::vector<Obstacle> world_capsules(const ArmModel& arm,
                                     const Pose& world_T_base,
                                     const Eigen::VectorXd& q);

/// The pair of capsules of two arms (a at q_a, b at q_b, each standing at its world_T_base) with
/// the least gap, its margin over `required` (m, the scene's clearance): capsule indexes a's
/// capsules, other_capsule b's, obstacle = kOtherArm; capsule = -1 when either has none.
LinkGap arm_arm_gap(const ArmModel& a,
                    const Pose& world_T_a,
                    const Eigen::VectorXd& q_a,
                    const ArmModel& b,
                    const Pose& world_T_b,
                    const Eigen::VectorXd& q_b,
                    double required);

}  // namespace rodshape
