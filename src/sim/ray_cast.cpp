// ray_cast.cpp: ray–solid intersections by the roots of |o + t d − c|² = r² (balls), the same
// across the capsule's axis (its cylinder) and the slabs of a box.
#include "ray_cast.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <variant>

#include "overloaded.hpp"

namespace rodshape::sim_detail {

namespace {

constexpr double kMiss = std::numeric_limits<double>::infinity();

/// The smaller root t ≥ 0 of t² + 2 b t + c = 0 (0 when the origin is inside: c ≤ 0).
double first_root(double b, double c) {
  if (c <= 0.0) return 0.0;
  const double h = b * b - c;
  if (h < 0.0 || b > 0.0) return kMiss;  // no root, or both behind the origin
  return -b - std::sqrt(h);
}

double ray_ball(const Eigen::Vector3d& o,
                const Eigen::Vector3d& d,
                const Eigen::Vector3d& c,
                double r) {
  const Eigen::Vector3d oc = o - c;
  return first_root(oc.dot(d), oc.squaredNorm() - r * r);
}

double ray_box(const Eigen::Vector3d& o, const Eigen::Vector3d& d, const BoxObstacle& box) {
  const Eigen::Vector3d lo = box.rotation.transpose() * (o - box.center);  // box frame
  const Eigen::Vector3d ld = box.rotation.transpose() * d;
  double enter = 0.0, leave = kMiss;
  for (int k = 0; k < 3; ++k) {
    const double half = 0.5 * box.size(k);
    if (std::abs(ld(k)) < 1e-300) {
      if (std::abs(lo(k)) > half) return kMiss;  // parallel to the slab, outside it
      continue;
    }
    double t0 = (-half - lo(k)) / ld(k), t1 = (half - lo(k)) / ld(k);
    if (t0 > t1) std::swap(t0, t1);
    enter = std::max(enter, t0);
    leave = std::min(leave, t1);
    if (enter > leave) return kMiss;
  }
  return enter;
}

double ray_half_space(const Eigen::Vector3d& o,
                      const Eigen::Vector3d& d,
                      const HalfSpaceObstacle& half) {
  const double outside = half.offset - half.normal.dot(o);  // ≥ 0 in free space
  if (outside <= 0.0) return 0.0;
  const double closing = half.normal.dot(d);
  return closing > 0.0 ? outside / closing : kMiss;
}

}  // namespace

double ray_capsule(const Eigen::Vector3d& o,
                   const Eigen::Vector3d& d,
                   const Eigen::Vector3d& a,
                   const Eigen::Vector3d& b,
                   double r) {
  const Eigen::Vector3d ba = b - a, oa = o - a;
  const double baba = ba.squaredNorm();
  if (baba <= 0.0) return ray_ball(o, d, a, r);
  // The infinite cylinder: |w × ba|² = r² |ba|² with w = oa + t d, a quadratic in t.
  const double bard = ba.dot(d), baoa = ba.dot(oa);
  const double qa = baba - bard * bard;
  const double qb = baba * oa.dot(d) - baoa * bard;
  const double qc = baba * oa.squaredNorm() - baoa * baoa - r * r * baba;
  if (qa > 1e-12 * baba) {
    const double h = qb * qb - qa * qc;
    if (h >= 0.0) {
      const double t = (-qb - std::sqrt(h)) / qa;
      const double along = baoa + t * bard;  // the hit's position along ba, × |ba|
      if (t >= 0.0 && along > 0.0 && along < baba) return t;
    }
  }
  return std::min(ray_ball(o, d, a, r), ray_ball(o, d, b, r));
}

double ray_obstacle(const Eigen::Vector3d& o, const Eigen::Vector3d& d, const Obstacle& obstacle) {
  return std::visit(
      detail::Overloaded{
          [&](const SphereObstacle& s) { return ray_ball(o, d, s.center, s.radius); },
          [&](const BoxObstacle& box) { return ray_box(o, d, box); },
          [&](const CapsuleObstacle& c) { return ray_capsule(o, d, c.from, c.to, c.radius); },
          [&](const HalfSpaceObstacle& h) { return ray_half_space(o, d, h); },
      },
      obstacle.shape);
}

}  // namespace rodshape::sim_detail
