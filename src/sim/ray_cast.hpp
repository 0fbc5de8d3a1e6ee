// ray_cast.hpp (private to the sim area): where a ray o + t d (|d| = 1, t ≥ 0) first meets a
// convex solid: a capsule (the rod's pieces, the arm's links; a sphere is [c, c]), a box (slabs)
// or a half-space, for the depth camera's occlusion test (depth_camera.hpp). +inf when it misses;
// 0 when o is inside.
#pragma once

#include <Eigen/Core>

#include "rodshape/core/obstacle.hpp"

namespace rodshape::sim_detail {

/// The points within r of [a, b]: the cylinder between the two end balls, then the balls.
double ray_capsule(const Eigen::Vector3d& o,
                   const Eigen::Vector3d& d,
                   const Eigen::Vector3d& a,
                   const Eigen::Vector3d& b,
                   double r);

/// Any obstacle shape of the scene (core/obstacle.hpp).
double ray_obstacle(const Eigen::Vector3d& o, const Eigen::Vector3d& d, const Obstacle& obstacle);

}  // namespace rodshape::sim_detail
