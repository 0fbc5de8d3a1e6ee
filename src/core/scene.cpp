// scene.cpp: the scene's checks, the clamp's mount and the least gap of a polyline.
#include "rodshape/core/scene.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "validation.hpp"

namespace rodshape {

void Scene::validate() const {
  detail::require_non_negative("Scene.clearance", clearance);
  if (clearance > kMaxClearance)
    throw InputError("Scene.clearance", " = " + detail::format_value(clearance) + " must be <= " +
                                            detail::format_value(kMaxClearance) + " m");
  detail::require_non_negative("Scene.rod_radius", rod_radius);
  if (obstacles.size() > kMaxObstacles)
    throw InputError("Scene.obstacles", " has " + std::to_string(obstacles.size()) +
                                            " entries; at most " + std::to_string(kMaxObstacles));
  for (std::size_t j = 0; j < obstacles.size(); ++j)
    obstacles[j].validate("Scene.obstacles[" + std::to_string(j) + "]");
}

void Scene::check_clamp(const Eigen::Vector3d& clamp) const {
  for (std::size_t j = 0; j < obstacles.size(); ++j) {
    const double d = obstacles[j].distance(clamp).distance;
    if (d < 0.0)
      throw InputError("ClampedRod.clamp.position",
                       " lies inside obstacle " + obstacles[j].label(static_cast<int>(j)) + " (" +
                           detail::format_value(-d) + " m deep)");
  }
}

std::vector<double> Scene::required_gaps(const Eigen::Vector3d& clamp) const {
  std::vector<double> required(obstacles.size(), clearance);
  for (std::size_t j = 0; j < obstacles.size(); ++j)
    required[j] = std::min(clearance, obstacles[j].distance(clamp).distance - rod_radius);
  return required;
}

SceneGap Scene::obstacle_gap(std::size_t j,
                             const std::vector<Eigen::Vector3d>& nodes,
                             double required) const {
  SceneGap least;
  for (std::size_t i = 0; i + 1 < nodes.size(); ++i) {
    const SegmentDistance d = obstacles[j].distance(nodes[i], nodes[i + 1]);
    const double gap = d.distance - rod_radius;
    if (gap < least.gap)
      least = {gap, gap - required, static_cast<int>(j), static_cast<int>(i), d.t};
  }
  return least;
}

SceneGap Scene::least_gap(const std::vector<Eigen::Vector3d>& nodes,
                          const std::vector<double>& required) const {
  SceneGap least;
  for (std::size_t j = 0; j < obstacles.size(); ++j) {
    const SceneGap gap = obstacle_gap(j, nodes, required[j]);
    if (gap.margin < least.margin || (gap.margin == least.margin && gap.gap < least.gap))
      least = gap;
  }
  return least;
}

SceneGap Scene::swept_gap(const std::vector<Eigen::Vector3d>& from,
                          const std::vector<Eigen::Vector3d>& to,
                          const std::vector<double>& required) const {
  SceneGap least;
  for (std::size_t i = 0; i + 1 < to.size(); ++i) {
    // Every point of the segment moves at most d (its nodes' larger displacement).
    const double d = std::max((to[i] - from[i]).norm(), (to[i + 1] - from[i + 1]).norm());
    for (std::size_t j = 0; j < obstacles.size(); ++j) {
      const SegmentDistance a = obstacles[j].distance(from[i], from[i + 1]);
      const SegmentDistance b = obstacles[j].distance(to[i], to[i + 1]);
      const double g0 = a.distance - rod_radius, g1 = b.distance - rod_radius;
      // Lipschitz: gap(τ) ≥ max(g0 - τ d, g1 - (1 - τ) d); its least over τ ∈ [0, 1].
      const double gap = std::abs(g0 - g1) >= d ? std::min(g0, g1) : 0.5 * (g0 + g1 - d);
      if (gap - required[j] < least.margin) {
        const SegmentDistance& nearer = g0 < g1 ? a : b;
        least = {gap, gap - required[j], static_cast<int>(j), static_cast<int>(i), nearer.t};
      }
    }
  }
  return least;
}

}  // namespace rodshape
