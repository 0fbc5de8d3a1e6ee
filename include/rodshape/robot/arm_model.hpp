// arm_model.hpp: a serial arm, read from a URDF file: the chain of joints between a base link and a
// tip link, its joint limits (position and velocity from the URDF; acceleration and jerk, which a
// URDF cannot hold, set by with_motion_limits()), forward kinematics and the tip's Jacobian.
// The chain is held by Orocos KDL and the URDF is read by urdfdom; neither appears here (pimpl).
//
// The links' collision geometry (<collision> boxes, spheres, cylinders) is read as capsules
// (link_capsule.hpp), with every link frame and point Jacobians for the clearance terms.
//
// Frames: world_T_tip is the tip link's pose in the base link's frame. The Jacobian maps joint
// velocities to the tip's twist [v; ω], both in the base frame, v being the tip origin's velocity.
#pragma once

#include <Eigen/Core>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "rodshape/core/pose.hpp"
#include "rodshape/robot/link_capsule.hpp"

namespace rodshape {

/// One moving joint of the chain. Continuous joints have infinite position limits; a joint whose
/// URDF gives no velocity limit (continuous joints may omit it) has an infinite one. A URDF has no
/// acceleration or jerk limits: they are infinite unless set (ArmModel::with_motion_limits; the
/// bundled arms carry Franka's, samples/franka.hpp).
struct JointInfo {
  std::string name;
  bool prismatic = false;     // false: revolute or continuous (rad); true: prismatic (m)
  double lower = 0.0;         // rad or m
  double upper = 0.0;         // rad or m
  double max_velocity = 0.0;  // rad/s or m/s
  double max_acceleration = std::numeric_limits<double>::infinity();  // rad/s² or m/s²
  double max_jerk = std::numeric_limits<double>::infinity();          // rad/s³ or m/s³
};

/// A moving joint's axis at some joint positions, in the base frame: the line through `origin`
/// along the unit vector `direction` (the rotation axis, or the direction of travel).
struct JointAxis {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();
};

/// Every link frame of the chain at some joint positions, in the base frame: frames[0] is the base
/// link, frames[i + 1] the child link of the chain's segment i; and every moving joint's axis.
struct LinkFrames {
  std::vector<Pose> frames;
  std::vector<JointAxis> axes;
};

class ArmModel {
 public:
  /// Upper bound (docs/limits.md, "Sizes"): every capsule is measured against every obstacle at
  /// every IK iteration of a joint trajectory's samples.
  static constexpr int kMaxLinkCapsules = 1000;

  /// Reads the URDF file at `path` and takes the chain from `base_link` to `tip_link`. An empty
  /// `base_link` is the URDF's root link; an empty `tip_link` is the last link below the base (the
  /// deepest leaf; when two leaves are equally deep the tip must be named). Throws InputError when
  /// the file cannot be read or does not parse, a link is unknown, the tip is not below the base,
  /// the chain holds a floating, planar or mimic joint, or a limit is malformed.
  static ArmModel from_urdf_file(const std::string& path,
                                 const std::string& base_link = "",
                                 const std::string& tip_link = "");
  /// As from_urdf_file, from the URDF text; `source` names it in messages.
  static ArmModel from_urdf_string(const std::string& urdf,
                                   const std::string& base_link = "",
                                   const std::string& tip_link = "",
                                   const std::string& source = "URDF");

  ArmModel(const ArmModel&);
  ArmModel(ArmModel&&) noexcept;
  ArmModel& operator=(const ArmModel&);
  ArmModel& operator=(ArmModel&&) noexcept;
  ~ArmModel();

  const std::string& robot_name() const;
  const std::string& base_link() const;
  const std::string& tip_link() const;

  /// Number of moving joints n (fixed joints are folded into the chain's geometry).
  int joints() const;
  const std::vector<JointInfo>& joint_info() const;
  std::vector<std::string> joint_names() const;
  Eigen::VectorXd lower_limits() const;
  Eigen::VectorXd upper_limits() const;
  Eigen::VectorXd velocity_limits() const;
  Eigen::VectorXd acceleration_limits() const;
  Eigen::VectorXd jerk_limits() const;

  /// This arm with each joint's acceleration and jerk limits set (n entries each, every one > 0;
  /// infinity: none), else InputError naming `source`. The other limits and the geometry are kept.
  ArmModel with_motion_limits(const Eigen::VectorXd& max_acceleration,
                              const Eigen::VectorXd& max_jerk,
                              const std::string& source = "motion limits") const;

  /// Throws InputError unless `q` has n finite entries within the position limits (a margin of
  /// `tolerance` is allowed). `what` names the vector in the message, e.g. "q" or "--seed".
  void check_joint_positions(const Eigen::VectorXd& q,
                             const std::string& what = "q",
                             double tolerance = 1e-12) const;
  /// q with every entry clamped to its joint's position limits.
  Eigen::VectorXd clamp_to_limits(const Eigen::VectorXd& q) const;

  /// base_T_tip at joint positions `q` (n finite entries, else InputError; limits are not checked,
  /// see check_joint_positions).
  Pose forward_kinematics(const Eigen::VectorXd& q) const;
  /// base_T_tip and the 6×n Jacobian J_twist_q (rows: v then ω, base frame) at `q`.
  void forward_kinematics(const Eigen::VectorXd& q,
                          Pose& base_T_tip,
                          Eigen::Matrix<double, 6, Eigen::Dynamic>& J_twist_q) const;

  /// Every moving joint's axis at joint positions `q` (n finite entries, else InputError), in the
  /// chain's order.
  std::vector<JointAxis> joint_axes(const Eigen::VectorXd& q) const;

  /// The collision geometry of the chain's links (base link included), read from the URDF's
  /// <collision> elements (link_capsule.hpp says how each primitive becomes a capsule).
  const std::vector<LinkCapsule>& link_capsules() const;
  /// What was not read of the collision geometry, one line each ("link 'x': a <mesh> collision
  /// is ignored (meshes are not read)"); empty when everything was.
  const std::vector<std::string>& collision_notes() const;
  /// The link of each frame of link_frames(): the base link, then each segment's child link.
  const std::vector<std::string>& frame_links() const;
  /// The number of moving joints that move frame `f` (joints 0 … k-1 of the chain move it): 0 for
  /// the base link and the links fixed to it.
  int joints_moving_frame(int f) const;
  /// Every link frame and joint axis at `q` (n finite entries, else InputError), into `out`
  /// (reused: no allocation once it has the chain's size, besides the chain's own copy).
  void link_frames(const Eigen::VectorXd& q, LinkFrames& out) const;
  /// The 3×n Jacobian of the base-frame point `p` fixed in frame `f`, from `frames` (the
  /// link_frames() at the q of interest): column j is axis_j × (p − origin_j) for a revolute
  /// joint that moves the frame, axis_j for a prismatic one, zero for the others.
  void point_jacobian(const LinkFrames& frames,
                      int f,
                      const Eigen::Vector3d& p,
                      Eigen::Matrix<double, 3, Eigen::Dynamic>& J) const;

  /// An upper bound of the distance from the base frame's origin to the tip's origin over all
  /// joint positions (the sum of the chain's offsets and prismatic strokes).
  double reach() const;

 private:
  struct Impl;
  explicit ArmModel(std::shared_ptr<const Impl> impl);
  void check_size(const Eigen::VectorXd& q, const std::string& what) const;
  std::shared_ptr<const Impl> impl_;  // immutable, so copies share it
};

}  // namespace rodshape
