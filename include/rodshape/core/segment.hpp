// segment.hpp: the nearest points of a segment [a, b], in any dimension.
//   to a point p:           t* = clamp((p - a)ᵀ(b - a) / |b - a|², 0, 1)   (0 when a = b)
//   to a segment [c, d]:    (s*, t*) minimising |a + s u - c - t v|² over [0, 1]², u = b - a,
//                           v = d - c, by the clamped normal equations
// Obstacles (capsules), the arm's links, the depth camera's normals and the shape errors all use
// these.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <utility>

namespace rodshape {

/// The parameter t* ∈ [0, 1] of the point a + t* (b - a) of [a, b] nearest to p.
template <int D>
double nearest_on_segment(const Eigen::Matrix<double, D, 1>& p,
                          const Eigen::Matrix<double, D, 1>& a,
                          const Eigen::Matrix<double, D, 1>& b) {
  const Eigen::Matrix<double, D, 1> ab = b - a;
  const double length2 = ab.squaredNorm();
  return length2 > 0.0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
}

/// The distance from p to [a, b]: |a + t* (b - a) - p|.
template <int D>
double distance_to_segment(const Eigen::Matrix<double, D, 1>& p,
                           const Eigen::Matrix<double, D, 1>& a,
                           const Eigen::Matrix<double, D, 1>& b) {
  const Eigen::Matrix<double, D, 1> ab = b - a;
  return (a + nearest_on_segment(p, a, b) * ab - p).norm();
}

/// Parameters (s on [a, b], t on [c, d]) of the nearest points of two segments. Parallel segments
/// (uu vv - (uv)² ≤ 1e-14 uu vv) take s = 0 before t is clamped.
inline std::pair<double, double> nearest_between_segments(const Eigen::Vector3d& a,
                                                          const Eigen::Vector3d& b,
                                                          const Eigen::Vector3d& c,
                                                          const Eigen::Vector3d& d) {
  const Eigen::Vector3d u = b - a, v = d - c, r = a - c;
  const double uu = u.squaredNorm(), vv = v.squaredNorm(), uv = u.dot(v);
  const double ur = u.dot(r), vr = v.dot(r);
  if (!(uu > 0.0) && !(vv > 0.0)) return {0.0, 0.0};
  if (!(uu > 0.0)) return {0.0, std::clamp(vr / vv, 0.0, 1.0)};
  if (!(vv > 0.0)) return {std::clamp(-ur / uu, 0.0, 1.0), 0.0};
  const double denominator = uu * vv - uv * uv;  // ≥ 0; 0 when parallel
  double s =
      denominator > 1e-14 * uu * vv ? std::clamp((uv * vr - vv * ur) / denominator, 0.0, 1.0) : 0.0;
  double t = (uv * s + vr) / vv;  // the best t for this s
  if (t < 0.0) {
    t = 0.0;
    s = std::clamp(-ur / uu, 0.0, 1.0);
  } else if (t > 1.0) {
    t = 1.0;
    s = std::clamp((uv - ur) / uu, 0.0, 1.0);
  }
  return {s, t};
}

}  // namespace rodshape
