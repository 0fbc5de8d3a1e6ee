// scene.cpp: the scene's checks, the clamp's mount and the least gap of a polyline.
#include "rodshape/core/scene.hpp"

#include <algorithm>
#include <cmath>
#include <queue>
#include <string>

#include "validation.hpp"

namespace rodshape {

namespace {

/// The segment [a0, a1] moving to [b0, b1], each point on the straight line between its two places:
/// x(t, τ) = (1 - τ) ((1 - t) a0 + t a1) + τ ((1 - t) b0 + t b1), a bilinear patch over [0, 1]².
struct SweptSegment {
  Eigen::Vector3d a0, a1, b0, b1;
  Eigen::Vector3d at(double t, double tau) const {
    return (1.0 - tau) * ((1.0 - t) * a0 + t * a1) + tau * ((1.0 - t) * b0 + t * b1);
  }
};

/// A cell [t0, t1] × [τ0, τ1] of the patch and the lower bound of its gap.
struct SweptCell {
  double t0, t1, tau0, tau1;
  double gap = 0.0;       // lower bound over the cell, m
  double attained = 0.0;  // the least gap of its two sub-segments (at τ0, at τ1): a real gap
  double t = 0.0;         // where along the segment the nearer sub-segment is nearest
  double move0 = 0.0, move1 = 0.0;  // how far the sub-segment's ends move over [τ0, τ1]
  bool operator<(const SweptCell& other) const { return gap > other.gap; }  // least gap on top
};

/// The Lipschitz bound of scene.hpp on one cell: the sub-segment at τ0 and at τ1 have gaps g0, g1;
/// for fixed t the point moves by (1 - λ) Δ_start + λ Δ_end (λ along the sub-segment), whose norm
/// is at most d = max(|Δ_start|, |Δ_end|); the gap over the cell is at least
/// min over τ of max(g0 - τ d, g1 - (1 - τ) d).
SweptCell bound_cell(const SweptSegment& s,
                     const Obstacle& obstacle,
                     double rod_radius,
                     SweptCell cell) {
  const Eigen::Vector3d p00 = s.at(cell.t0, cell.tau0), p10 = s.at(cell.t1, cell.tau0);
  const Eigen::Vector3d p01 = s.at(cell.t0, cell.tau1), p11 = s.at(cell.t1, cell.tau1);
  const SegmentDistance a = obstacle.distance(p00, p10), b = obstacle.distance(p01, p11);
  const double g0 = a.distance - rod_radius, g1 = b.distance - rod_radius;
  cell.move0 = (p01 - p00).norm();
  cell.move1 = (p11 - p10).norm();
  const double d = std::max(cell.move0, cell.move1);
  cell.gap = std::abs(g0 - g1) >= d ? std::min(g0, g1) : 0.5 * (g0 + g1 - d);
  cell.attained = std::min(g0, g1);
  cell.t = cell.t0 + (g0 < g1 ? a.t : b.t) * (cell.t1 - cell.t0);
  return cell;
}

/// Where the whole patch's bound falls below `required` while no sub-segment does, the bound may be
/// the argument's slack rather than the motion: near a fixed node (the clamp, on its mount, whose
/// gap cannot change) it lies d / 2 below a gap that stays put. The cells are bisected, the worst
/// first (along t where one end moves more than twice the other, so the still end's cell shrinks;
/// else along τ), until the worst bound meets `required` within SceneGap::kTolerance, a sub-segment
/// is found within it (a violation the motion does make), or kMaxCells cells were bounded. Returns
/// the worst cell then: its bound is below the gap of every point of the patch.
SweptCell refine_cell(const SweptSegment& s,
                      const Obstacle& obstacle,
                      double rod_radius,
                      double required,
                      const SweptCell& whole) {
  constexpr int kMaxCells = 256;
  std::priority_queue<SweptCell> cells;
  cells.push(whole);
  for (int bounded = 1; bounded < kMaxCells;) {
    const SweptCell worst = cells.top();
    if (worst.gap - required >= -0.5 * SceneGap::kTolerance ||  // half: room for rounding
        worst.attained - required < -SceneGap::kTolerance)
      break;
    cells.pop();
    SweptCell first = worst, second = worst;
    if (std::max(worst.move0, worst.move1) > 2.0 * std::min(worst.move0, worst.move1))
      first.t1 = second.t0 = 0.5 * (worst.t0 + worst.t1);
    else
      first.tau1 = second.tau0 = 0.5 * (worst.tau0 + worst.tau1);
    cells.push(bound_cell(s, obstacle, rod_radius, first));
    cells.push(bound_cell(s, obstacle, rod_radius, second));
    bounded += 2;
  }
  return cells.top();
}

}  // namespace

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
    const SweptSegment segment{from[i], from[i + 1], to[i], to[i + 1]};
    for (std::size_t j = 0; j < obstacles.size(); ++j) {
      SweptCell cell = bound_cell(segment, obstacles[j], rod_radius, {0.0, 1.0, 0.0, 1.0});
      if (cell.gap - required[j] < -SceneGap::kTolerance)
        cell = refine_cell(segment, obstacles[j], rod_radius, required[j], cell);
      if (cell.gap - required[j] < least.margin)
        least = {cell.gap, cell.gap - required[j], static_cast<int>(j), static_cast<int>(i),
                 cell.t};
    }
  }
  return least;
}

}  // namespace rodshape
