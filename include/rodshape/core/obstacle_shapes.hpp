// obstacle_shapes.hpp: the obstacle shapes (world frame, metres) and every operation on one, as
// free functions overloaded per shape (defined in src/core/obstacle.cpp, one section per shape).
// Obstacle (obstacle.hpp) dispatches each through std::visit with no fallback: a shape added to
// ObstacleShape without its overloads does not compile.
//   shape_kind       the task file's name of the shape ("sphere", ...)
//   shape_distance   d(p) and ∇d(p); min over [a, b] of d and its minimiser (obstacle.hpp)
//   shape_ray_hit    the least t ≥ 0 with d(o + t d̂) ≤ 0: +inf on a miss, 0 from inside
//   transformed      the shape in frame a from its pose in frame b: x_a = p + R x_b
//   shape_bounds     an axis-aligned box holding the shape; none for an unbounded one
//   shape_fields     the task file's fields of the shape, in its order (docs/task-file.md)
//   validate_shape   InputError naming the field of a bad size, position, rotation or normal
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace rodshape {

struct Pose;

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

/// lower ≤ p ≤ upper.
struct AxisAlignedBox {
  Eigen::Vector3d lower = Eigen::Vector3d::Zero();
  Eigen::Vector3d upper = Eigen::Vector3d::Zero();
  bool contains(const Eigen::Vector3d& p, double tolerance = 0.0) const {
    return (p.array() >= lower.array() - tolerance).all() &&
           (p.array() <= upper.array() + tolerance).all();
  }
};

/// One field of a shape as the task file names it: a length, a point or vector, or a rotation.
struct ObstacleField {
  const char* key = "";
  std::variant<double, Eigen::Vector3d, Eigen::Matrix3d> value;
};

const char* shape_kind(const SphereObstacle&);
const char* shape_kind(const BoxObstacle&);
const char* shape_kind(const CapsuleObstacle&);
const char* shape_kind(const HalfSpaceObstacle&);

PointDistance shape_distance(const SphereObstacle& s, const Eigen::Vector3d& p);
PointDistance shape_distance(const BoxObstacle& s, const Eigen::Vector3d& p);
PointDistance shape_distance(const CapsuleObstacle& s, const Eigen::Vector3d& p);
PointDistance shape_distance(const HalfSpaceObstacle& s, const Eigen::Vector3d& p);

SegmentDistance shape_distance(const SphereObstacle& s,
                               const Eigen::Vector3d& a,
                               const Eigen::Vector3d& b);
SegmentDistance shape_distance(const BoxObstacle& s,
                               const Eigen::Vector3d& a,
                               const Eigen::Vector3d& b);
SegmentDistance shape_distance(const CapsuleObstacle& s,
                               const Eigen::Vector3d& a,
                               const Eigen::Vector3d& b);
SegmentDistance shape_distance(const HalfSpaceObstacle& s,
                               const Eigen::Vector3d& a,
                               const Eigen::Vector3d& b);

/// o + t d with |d| = 1.
double shape_ray_hit(const SphereObstacle& s, const Eigen::Vector3d& o, const Eigen::Vector3d& d);
double shape_ray_hit(const BoxObstacle& s, const Eigen::Vector3d& o, const Eigen::Vector3d& d);
double shape_ray_hit(const CapsuleObstacle& s, const Eigen::Vector3d& o, const Eigen::Vector3d& d);
double shape_ray_hit(const HalfSpaceObstacle& s,
                     const Eigen::Vector3d& o,
                     const Eigen::Vector3d& d);

SphereObstacle transformed(const Pose& a_T_b, const SphereObstacle& s);
BoxObstacle transformed(const Pose& a_T_b, const BoxObstacle& s);
CapsuleObstacle transformed(const Pose& a_T_b, const CapsuleObstacle& s);
HalfSpaceObstacle transformed(const Pose& a_T_b, const HalfSpaceObstacle& s);

std::optional<AxisAlignedBox> shape_bounds(const SphereObstacle& s);
std::optional<AxisAlignedBox> shape_bounds(const BoxObstacle& s);
std::optional<AxisAlignedBox> shape_bounds(const CapsuleObstacle& s);
std::optional<AxisAlignedBox> shape_bounds(const HalfSpaceObstacle& s);

std::vector<ObstacleField> shape_fields(const SphereObstacle& s);
std::vector<ObstacleField> shape_fields(const BoxObstacle& s);
std::vector<ObstacleField> shape_fields(const CapsuleObstacle& s);
std::vector<ObstacleField> shape_fields(const HalfSpaceObstacle& s);

/// `field` is the obstacle's ("Scene.obstacles[2]"); the member is appended (".radius").
void validate_shape(const SphereObstacle& s, const std::string& field);
void validate_shape(const BoxObstacle& s, const std::string& field);
void validate_shape(const CapsuleObstacle& s, const std::string& field);
void validate_shape(const HalfSpaceObstacle& s, const std::string& field);

}  // namespace rodshape
