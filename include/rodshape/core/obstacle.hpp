// obstacle.hpp: one solid of a cell (a post, a fixture, a rail, a table top), world frame, metres,
// as a convex shape with its signed distance d(p) (> 0 outside, < 0 inside) and its gradient ∇d
// (the outward unit normal of the nearest surface point). Optimisation (clearance rows), robot
// (links) and sim (contacts, the depth camera's rays) all measure gaps with these functions; the
// shapes and each operation per shape are in obstacle_shapes.hpp, Obstacle dispatches them.
//
// The rod between two nodes is the chord [a, b]; its distance to a convex obstacle is
//   d([a, b]) = min_{t ∈ [0, 1]} d(a + t (b - a)),
// convex in t, and by the envelope theorem ∂d/∂a = (1 - t*) ∇d(p*), ∂d/∂b = t* ∇d(p*), with p* the
// minimiser (a subgradient where the minimiser is not unique).
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "rodshape/core/obstacle_shapes.hpp"
#include "rodshape/enum_names.hpp"

namespace rodshape {

/// An obstacle as the task file and plan.json give it: its name ("" when unnamed), the shape's
/// kind and fields (shape_fields).
struct ObstacleDescription {
  std::string name;
  std::string kind;
  std::vector<ObstacleField> fields;
};

/// What the rod may do with an obstacle: keep the scene's clearance from it, or rest on it
/// (unilateral contact: the gap ≥ 0, a reaction along the obstacle's normal where it is 0).
enum class ContactMode { Avoid, Touch };
inline constexpr EnumNames<ContactMode, 2> kContactModeNames = {{
    {ContactMode::Avoid, "avoid"},
    {ContactMode::Touch, "touch"},
}};

struct Obstacle {
  std::string name;  // optional; messages say "obstacle 'post'" or "obstacle 3"
  ObstacleShape shape;
  ContactMode contact = ContactMode::Avoid;
  /// Coulomb's μ of a touchable obstacle (0: frictionless, the only kind solved today).
  double friction = 0.0;
  static constexpr double kMaxFriction = 10.0;

  bool touchable() const { return contact == ContactMode::Touch; }

  /// "sphere", "box", "capsule", "half_space".
  std::string kind() const;
  /// The name, or the index when unnamed: "'post'" or "3".
  std::string label(int index) const;
  PointDistance distance(const Eigen::Vector3d& p) const;
  SegmentDistance distance(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const;
  /// Where the ray o + t d (|d| = 1, t ≥ 0) first meets the solid: +inf when it misses, 0 when o
  /// is inside.
  double ray_hit(const Eigen::Vector3d& o, const Eigen::Vector3d& d) const;
  /// An axis-aligned box holding the solid; none for a half-space.
  std::optional<AxisAlignedBox> bounds() const;
  /// The name, the kind and the shape's fields, as io's JSON and the figures write them.
  ObstacleDescription describe() const;
  /// Throws InputError naming `field` (e.g. "Scene.obstacles[2]") and the member: sizes and radii
  /// finite and > 0 (at most kMaxSize), positions finite, a rotation, a normal of magnitude in
  /// [kMinNormal, kMaxNormal].
  void validate(const std::string& field) const;

  /// The largest size or distance an obstacle may have (docs/limits.md): a cell is metres across.
  static constexpr double kMaxSize = 1e3;
  /// A half-space's normal is normalised where it is used; its magnitude stays within these so
  /// that n/|n| and offset/|n| are exact to round-off (|n|² of 1e300 overflowed: every distance
  /// read 0, and 1e-300 underflowed to a "zero" normal).
  static constexpr double kMinNormal = 1e-6;
  static constexpr double kMaxNormal = 1e6;
};

/// The obstacle given in frame b, in frame a (same name): every point x_b maps to p + R x_b.
Obstacle transformed(const Pose& a_T_b, const Obstacle& in_b);

}  // namespace rodshape
