// obstacle.hpp: one solid of a cell (a post, a fixture, a rail, a table top), world frame, metres,
// as a convex shape with its signed distance d(p) (> 0 outside, < 0 inside) and its gradient ∇d
// (the outward unit normal of the nearest surface point). Optimisation (clearance rows), robot
// (links) and sim (contacts) all measure gaps with these functions.
//
// The rod between two nodes is the chord [a, b]; its distance to a convex obstacle is
//   d([a, b]) = min_{t ∈ [0, 1]} d(a + t (b - a)),
// convex in t, and by the envelope theorem ∂d/∂a = (1 - t*) ∇d(p*), ∂d/∂b = t* ∇d(p*), with p* the
// minimiser (a subgradient where the minimiser is not unique).
#pragma once

#include <Eigen/Core>
#include <string>
#include <variant>

namespace rodshape {

/// A ball: d(p) = |p - c| - r.
struct SphereObstacle {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  double radius = 0.0;
};

/// A box of full edges `size` along its own axes, centred at `center`, turned by `rotation`
/// (world_R_box).
struct BoxObstacle {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  Eigen::Vector3d size = Eigen::Vector3d::Zero();
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
};

/// The points within `radius` of the segment [from, to] (a pole, a cable, a rail).
struct CapsuleObstacle {
  Eigen::Vector3d from = Eigen::Vector3d::Zero();
  Eigen::Vector3d to = Eigen::Vector3d::Zero();
  double radius = 0.0;
};

/// The half-space normalᵀp > offset (free space is normalᵀp ≤ offset, as workspace.half_spaces):
/// d(p) = (offset - normalᵀp) / |normal|.
struct HalfSpaceObstacle {
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  double offset = 0.0;
};

using ObstacleShape = std::variant<SphereObstacle, BoxObstacle, CapsuleObstacle, HalfSpaceObstacle>;

/// The signed distance at a point and its gradient there.
struct PointDistance {
  double distance = 0.0;
  Eigen::Vector3d gradient = Eigen::Vector3d::UnitZ();  // ∇d, a unit vector
};

/// The least signed distance over a segment [a, b], where it is reached and its derivatives.
struct SegmentDistance {
  double distance = 0.0;
  double t = 0.0;                                       // p* = a + t (b - a)
  Eigen::Vector3d gradient = Eigen::Vector3d::UnitZ();  // ∇d(p*)
  Eigen::Vector3d dd_da() const { return (1.0 - t) * gradient; }
  Eigen::Vector3d dd_db() const { return t * gradient; }
};

struct Obstacle {
  std::string name;  // optional; messages say "obstacle 'post'" or "obstacle 3"
  ObstacleShape shape;

  /// "sphere", "box", "capsule", "half_space".
  std::string kind() const;
  /// The name, or the index when unnamed: "'post'" or "3".
  std::string label(int index) const;
  PointDistance distance(const Eigen::Vector3d& p) const;
  SegmentDistance distance(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const;
  /// Throws InputError naming `field` (e.g. "Scene.obstacles[2]") and the member: sizes and radii
  /// finite and > 0 (at most kMaxSize), positions finite, a rotation, a non-zero normal.
  void validate(const std::string& field) const;

  /// The largest size or distance an obstacle may have (docs/limits.md): a cell is metres across.
  static constexpr double kMaxSize = 1e3;
};

}  // namespace rodshape
