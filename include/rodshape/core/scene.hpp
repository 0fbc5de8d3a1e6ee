// scene.hpp: the cell around the rod: obstacles, the least gap the rod's surface must keep from
// them (the clearance) and the rod's circumscribed radius (its surface is the centreline inflated
// by it: half the rectangle's diagonal, the circle's radius).
//
// The gap of a segment [p_i, p_{i+1}] of the centreline to obstacle j is d_j([p_i, p_{i+1}]) - r.
// The chord stands for the rod between two nodes; the rod bows off it by at most κ Δs² / 8
// (κ its curvature, Δs = L / N): 0.01 mm for the paper's band at 100 intervals and κ = 20 1/m.
//
// The clamp may be mounted on an obstacle (a table under it): an obstacle whose gap at the clamp
// point p(0) is below the clearance is the clamp's mount, and the rod must keep from it only the
// gap the clamp itself has, min(clearance, gap at p(0)): it may lie on the table it is clamped to,
// never sink into it.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <limits>
#include <vector>

#include "rodshape/core/obstacle.hpp"

namespace rodshape {

/// Where a rod comes closest to the scene.
struct SceneGap {
  double gap = std::numeric_limits<double>::infinity();  // d - r, m (< 0: the surfaces overlap)
  /// gap minus the gap required of that obstacle (the clearance, or a mount's own gap): < 0 is a
  /// violation.
  double margin = std::numeric_limits<double>::infinity();
  int obstacle = -1;  // index into Scene::obstacles, -1 for an empty scene
  int segment = -1;   // the segment [p_i, p_{i+1}], i = segment
  double t = 0.0;     // where along it
  /// Clear within the solved rod's accuracy (the shooting residual's, far below the µm).
  static constexpr double kTolerance = 1e-9;  // m
  bool clear() const { return margin >= -kTolerance; }
};

struct Scene {
  /// Upper bounds (docs/limits.md, "Sizes"): every obstacle near the rod adds a row per rod
  /// segment to every step's optimisation.
  static constexpr std::size_t kMaxObstacles = 1000;
  static constexpr double kMaxClearance = 1.0;  // m

  std::vector<Obstacle> obstacles;
  double clearance = 0.005;  // m, least gap between the rod's surface and an obstacle
  double rod_radius = 0.0;   // m, the section's circumscribed radius

  bool empty() const { return obstacles.empty(); }
  /// The gap each obstacle requires of the rod clamped at `clamp`: the clearance, or for the
  /// clamp's mount min(clearance, its gap at the clamp).
  std::vector<double> required_gaps(const Eigen::Vector3d& clamp) const;
  /// The least margin over every segment of the polyline `nodes` and every obstacle, against
  /// `required` (one per obstacle, from required_gaps()).
  SceneGap least_gap(const std::vector<Eigen::Vector3d>& nodes,
                     const std::vector<double>& required) const;
  /// The least margin of the polyline moving from `from` to `to` (the same number of nodes), to
  /// first order (each point on the straight line between its two places): a segment whose points
  /// move at most d (its nodes' larger displacement) with gaps g0 and g1 at the two ends keeps,
  /// since a signed distance changes by at most the distance moved, at least
  /// min over τ of max(g0 - τ d, g1 - (1 - τ) d) = (g0 + g1 - d) / 2, or min(g0, g1) when
  /// |g0 - g1| ≥ d. The SceneGap is that of the end where the segment is nearer, its gap lowered.
  SceneGap swept_gap(const std::vector<Eigen::Vector3d>& from,
                     const std::vector<Eigen::Vector3d>& to,
                     const std::vector<double>& required) const;
  /// The same for obstacle `j` alone, against the gap `required` of it.
  SceneGap obstacle_gap(std::size_t j,
                        const std::vector<Eigen::Vector3d>& nodes,
                        double required) const;
  /// Throws InputError naming the field: "Scene.clearance" (≥ 0, ≤ kMaxClearance),
  /// "Scene.rod_radius" (≥ 0), "Scene.obstacles" (at most kMaxObstacles), each obstacle's fields
  /// ("Scene.obstacles[2].radius").
  void validate() const;
  /// Throws InputError naming "ClampedRod.clamp.position" when the clamp point lies inside an
  /// obstacle (its centreline would start in a solid).
  void check_clamp(const Eigen::Vector3d& clamp) const;
};

}  // namespace rodshape
