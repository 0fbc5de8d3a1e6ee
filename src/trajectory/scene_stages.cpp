// scene_stages.cpp: the scene's stages of plan() (see scene_stages.hpp).
#include "scene_stages.hpp"

#include <algorithm>
#include <sstream>

#include "validation.hpp"

namespace rodshape::scene_stages {

namespace {

bool is_mount(const Scene& scene, const std::vector<double>& required, std::size_t j) {
  return required[j] < scene.clearance;
}

}  // namespace

std::optional<BlockedPoint> target_clear(const Scene& scene,
                                         const std::vector<double>& required,
                                         const PointSet& points) {
  for (std::size_t k = 0; k < points.size(); ++k) {
    for (std::size_t j = 0; j < scene.obstacles.size(); ++j) {
      const double gap = scene.obstacles[j].distance(points[k]).distance - scene.rod_radius;
      if (gap < required[j]) {
        std::ostringstream out;
        out.precision(4);
        out << "objective point " << k << " at " << detail::format_point(points[k])
            << " is within the rod's radius plus the clearance of obstacle "
            << scene.obstacles[j].label(static_cast<int>(j)) << " (gap " << gap * 1e3
            << " mm, required " << required[j] * 1e3 << " mm)";
        return BlockedPoint{static_cast<int>(k), out.str()};
      }
    }
  }
  return std::nullopt;
}

PointSet clear_of_scene(const Scene& scene,
                        const std::vector<double>& required,
                        const PointSet& points) {
  PointSet cleared = points;
  for (Eigen::Vector3d& p : cleared) {
    for (int pass = 0; pass < 4; ++pass) {
      bool moved = false;
      for (std::size_t j = 0; j < scene.obstacles.size(); ++j) {
        const PointDistance d = scene.obstacles[j].distance(p);
        const double wanted = scene.rod_radius + std::max(required[j], 0.0);
        if (d.distance < wanted) {
          p += (wanted - d.distance) * d.gradient;  // along ∇d: exact for a sphere and a plane
          moved = true;
        }
      }
      if (!moved) break;
    }
  }
  return cleared;
}

Clearance step_clearance(const Scene& scene,
                         const std::vector<double>& required,
                         const RodConfiguration& start,
                         const PointSet& points,
                         double radius,
                         double margin,
                         const std::vector<int>& forced) {
  Clearance clearance;
  clearance.scene.clearance = scene.clearance;
  clearance.scene.rod_radius = scene.rod_radius;
  for (std::size_t j = 0; j < scene.obstacles.size(); ++j) {
    const Obstacle& obstacle = scene.obstacles[j];
    const double reach = radius + scene.rod_radius + required[j];
    const auto near = [&](const Eigen::Vector3d& p) {
      return obstacle.distance(p).distance < reach;
    };
    const bool chosen =
        std::find(forced.begin(), forced.end(), static_cast<int>(j)) != forced.end() ||
        std::any_of(start.p.begin(), start.p.end(), near) ||
        std::any_of(points.begin(), points.end(), near);
    if (!chosen) continue;
    clearance.scene.obstacles.push_back(obstacle);
    clearance.required.push_back(required[j] + (is_mount(scene, required, j) ? 0.0 : margin));
    clearance.indices.push_back(static_cast<int>(j));
  }
  return clearance;
}

std::vector<int> violated_obstacles(const Scene& scene,
                                    const std::vector<double>& required,
                                    const RodConfiguration& c,
                                    const Clearance& selected) {
  std::vector<int> violated;
  for (std::size_t j = 0; j < scene.obstacles.size(); ++j) {
    const int index = static_cast<int>(j);
    if (std::find(selected.indices.begin(), selected.indices.end(), index) !=
        selected.indices.end())
      continue;
    if (scene.obstacle_gap(j, c.p, required[j]).margin < 0.0) violated.push_back(index);
  }
  return violated;
}

SweptGap::SweptGap(const Scene& scene,
                   const std::vector<double>& required,
                   const std::vector<Eigen::Vector3d>& start)
    : scene_(scene), required_(required), previous_(start) {}

SceneGap SweptGap::add(const std::vector<Eigen::Vector3d>& p) {
  const SceneGap swept = scene_.swept_gap(previous_, p, required_);
  previous_ = p;
  return swept;
}

}  // namespace rodshape::scene_stages
