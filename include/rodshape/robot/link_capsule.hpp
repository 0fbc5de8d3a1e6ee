// link_capsule.hpp: the collision geometry of an arm's links, each piece a capsule (the points
// within `radius` of the segment [from, to]) fixed in its link's frame. URDF <collision> primitives
// become capsules that cover them:
//   sphere (r)          the zero-length capsule [c, c], radius r (exact)
//   cylinder (r, l)     the segment ±l/2 along the cylinder's axis, radius r (covers the cylinder
//                       and adds two half-balls of radius r at its ends)
//   box (a ≥ b ≥ c)     the segment ±a/2 along its longest edge, radius ½√(b² + c²) (covers the
//                       box; a flat box is covered loosely)
// A sphere within another capsule of the same link is dropped (Franka's self-collision model writes
// each capsule as a cylinder and the two balls at its ends). Meshes are not read: each is ignored
// with a note (ArmModel::collision_notes()).
//
// The gap of a capsule to an obstacle is the obstacle's signed distance over the segment minus
// the radius (core/obstacle.hpp), so every obstacle shape is measured exactly against it.
#pragma once

#include <Eigen/Core>
#include <string>

namespace rodshape {

struct LinkCapsule {
  std::string link;  // the URDF link that carries it
  std::string name;  // the <collision name="..."> when given, else empty
  /// The frame it is fixed in: 0 is the chain's base link, i + 1 the child link of the chain's
  /// segment i (ArmModel::link_frames()).
  int frame = 0;
  Eigen::Vector3d from = Eigen::Vector3d::Zero();  // m, in the link's frame
  Eigen::Vector3d to = Eigen::Vector3d::Zero();
  double radius = 0.0;  // m
  /// "panda_link4", or "panda_link8 (hand)" when named.
  std::string label() const { return name.empty() ? link : link + " (" + name + ")"; }
};

}  // namespace rodshape
