// obstacle.cpp: signed distances of the obstacle shapes at a point and over a segment.
//   sphere     d = |p - c| - r
//   capsule    d = |p - q(p)| - r, q(p) the nearest point of [from, to]
//   half-space d = (offset - nᵀp) / |n|
//   box        q = Rᵀ(p - c), e = |q| - size/2 (per axis): outside d = |max(e, 0)|, inside d = max
//   e
// Over a segment: closed forms for the sphere, the capsule (segment–segment) and the half-space
// (an end); for the box, d(a + t (b - a)) is convex in t: an end is the minimiser when the slope
// there points inwards, else golden-section search on [0, 1].
#include "rodshape/core/obstacle.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "overloaded.hpp"
#include "validation.hpp"

namespace rodshape {

namespace {

/// A unit vector along v, or `fallback` when v is (numerically) zero.
Eigen::Vector3d unit_or(const Eigen::Vector3d& v, const Eigen::Vector3d& fallback) {
  const double norm = v.norm();
  return norm > 1e-300 ? Eigen::Vector3d(v / norm) : fallback;
}

/// The parameter in [0, 1] of the point of [a, b] nearest to p.
double nearest_on_segment(const Eigen::Vector3d& a,
                          const Eigen::Vector3d& b,
                          const Eigen::Vector3d& p) {
  const Eigen::Vector3d ab = b - a;
  const double length2 = ab.squaredNorm();
  if (!(length2 > 0.0)) return 0.0;
  return std::clamp((p - a).dot(ab) / length2, 0.0, 1.0);
}

/// Parameters (s on [a, b], t on [c, d]) of the nearest points of two segments: minimise
/// |a + s u - c - t v|² over [0, 1]², u = b - a, v = d - c, by the clamped normal equations.
std::pair<double, double> nearest_between_segments(const Eigen::Vector3d& a,
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

PointDistance sphere_distance(const SphereObstacle& s, const Eigen::Vector3d& p) {
  const Eigen::Vector3d r = p - s.center;
  return {r.norm() - s.radius, unit_or(r, Eigen::Vector3d::UnitZ())};
}

PointDistance capsule_distance(const CapsuleObstacle& c, const Eigen::Vector3d& p) {
  const Eigen::Vector3d axis_point = c.from + nearest_on_segment(c.from, c.to, p) * (c.to - c.from);
  const Eigen::Vector3d r = p - axis_point;
  return {r.norm() - c.radius,
          unit_or(r, unit_or((c.to - c.from).unitOrthogonal(), Eigen::Vector3d::UnitZ()))};
}

PointDistance half_space_distance(const HalfSpaceObstacle& h, const Eigen::Vector3d& p) {
  const double norm = h.normal.norm();
  return {(h.offset - h.normal.dot(p)) / norm, -h.normal / norm};
}

PointDistance box_distance(const BoxObstacle& box, const Eigen::Vector3d& p) {
  const Eigen::Vector3d q = box.rotation.transpose() * (p - box.center);
  const Eigen::Vector3d sign = q.unaryExpr([](double x) { return x < 0.0 ? -1.0 : 1.0; });
  const Eigen::Vector3d e = q.cwiseAbs() - 0.5 * box.size;
  Eigen::Index k = 0;
  const double largest = e.maxCoeff(&k);
  if (largest > 0.0) {  // outside: the distance to the nearest point of the box
    const Eigen::Vector3d outside = e.cwiseMax(0.0).cwiseProduct(sign);
    const double d = outside.norm();
    return {d, box.rotation * (outside / d)};
  }
  // inside (or on the surface): the nearest face's distance, negative
  return {largest, box.rotation.col(k) * sign(k)};
}

SegmentDistance at(const Obstacle& obstacle,
                   const Eigen::Vector3d& a,
                   const Eigen::Vector3d& b,
                   double t) {
  const PointDistance d = obstacle.distance(Eigen::Vector3d(a + t * (b - a)));
  return {d.distance, t, d.gradient};
}

/// min over t of a convex d(a + t (b - a)): an end when the slope there points away from the
/// interior, else golden-section search to |Δt| ≤ 1e-10 (|Δd| ≤ 1e-10 |b - a|, as |∇d| = 1).
SegmentDistance convex_segment_distance(const Obstacle& obstacle,
                                        const Eigen::Vector3d& a,
                                        const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const SegmentDistance at_a = at(obstacle, a, b, 0.0);
  if (at_a.gradient.dot(ab) >= 0.0) return at_a;
  const SegmentDistance at_b = at(obstacle, a, b, 1.0);
  if (at_b.gradient.dot(ab) <= 0.0) return at_b;
  constexpr double kInverseGolden = 0.6180339887498949;
  double lo = 0.0, hi = 1.0;
  double x1 = hi - kInverseGolden * (hi - lo), x2 = lo + kInverseGolden * (hi - lo);
  double f1 = at(obstacle, a, b, x1).distance, f2 = at(obstacle, a, b, x2).distance;
  while (hi - lo > 1e-10) {
    if (f1 <= f2) {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - kInverseGolden * (hi - lo);
      f1 = at(obstacle, a, b, x1).distance;
    } else {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + kInverseGolden * (hi - lo);
      f2 = at(obstacle, a, b, x2).distance;
    }
  }
  return at(obstacle, a, b, 0.5 * (lo + hi));
}

void validate_radius(const std::string& field, double radius) {
  detail::require_positive(field, radius);
  if (radius > Obstacle::kMaxSize)
    throw InputError(field, " = " + detail::format_value(radius) +
                                " must be <= " + detail::format_value(Obstacle::kMaxSize) + " m");
}

void validate_point(const std::string& field, const Eigen::Vector3d& p) {
  detail::require_finite(field, p);
  for (int i = 0; i < 3; ++i) {
    if (std::abs(p(i)) > Obstacle::kMaxSize)
      throw InputError(field, "[" + std::to_string(i) + "] = " + detail::format_value(p(i)) +
                                  " must be within ±" + detail::format_value(Obstacle::kMaxSize) +
                                  " m");
  }
}

}  // namespace

std::string Obstacle::kind() const {
  return std::visit(detail::Overloaded{[](const SphereObstacle&) { return "sphere"; },
                                       [](const BoxObstacle&) { return "box"; },
                                       [](const CapsuleObstacle&) { return "capsule"; },
                                       [](const HalfSpaceObstacle&) { return "half_space"; }},
                    shape);
}

std::string Obstacle::label(int index) const {
  return name.empty() ? std::to_string(index) : "'" + name + "'";
}

PointDistance Obstacle::distance(const Eigen::Vector3d& p) const {
  return std::visit(
      detail::Overloaded{[&](const SphereObstacle& s) { return sphere_distance(s, p); },
                         [&](const BoxObstacle& b) { return box_distance(b, p); },
                         [&](const CapsuleObstacle& c) { return capsule_distance(c, p); },
                         [&](const HalfSpaceObstacle& h) { return half_space_distance(h, p); }},
      shape);
}

SegmentDistance Obstacle::distance(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const {
  return std::visit(detail::Overloaded{
                        [&](const SphereObstacle& s) {
                          return at(*this, a, b, nearest_on_segment(a, b, s.center));
                        },
                        [&](const CapsuleObstacle& c) {
                          const auto [t, t_axis] = nearest_between_segments(a, b, c.from, c.to);
                          const Eigen::Vector3d p = a + t * (b - a);
                          const Eigen::Vector3d r = p - (c.from + t_axis * (c.to - c.from));
                          const PointDistance d = capsule_distance(c, p);  // its normal where r = 0
                          return SegmentDistance{r.norm() - c.radius, t, unit_or(r, d.gradient)};
                        },
                        [&](const HalfSpaceObstacle& h) {
                          return h.normal.dot(a) >= h.normal.dot(b) ? at(*this, a, b, 0.0)
                                                                    : at(*this, a, b, 1.0);
                        },
                        [&](const BoxObstacle&) { return convex_segment_distance(*this, a, b); }},
                    shape);
}

void Obstacle::validate(const std::string& field) const {
  std::visit(detail::Overloaded{
                 [&](const SphereObstacle& s) {
                   validate_point(field + ".center", s.center);
                   validate_radius(field + ".radius", s.radius);
                 },
                 [&](const BoxObstacle& b) {
                   validate_point(field + ".center", b.center);
                   for (int i = 0; i < 3; ++i)
                     validate_radius(field + ".size[" + std::to_string(i) + "]", b.size(i));
                   if (!b.rotation.allFinite() || !is_rotation(b.rotation, 1e-6))
                     throw InputError(field + ".rotation",
                                      " is not a rotation (RᵀR = I and det R = 1 within 1e-6)");
                 },
                 [&](const CapsuleObstacle& c) {
                   validate_point(field + ".from", c.from);
                   validate_point(field + ".to", c.to);
                   validate_radius(field + ".radius", c.radius);
                 },
                 [&](const HalfSpaceObstacle& h) {
                   detail::require_finite(field + ".normal", h.normal);
                   if (!(h.normal.norm() > 1e-12))
                     throw InputError(field + ".normal", " must not be zero");
                   detail::require_finite(field + ".offset", h.offset);
                   if (std::abs(h.offset) > kMaxSize * h.normal.norm())
                     throw InputError(field + ".offset", " = " + detail::format_value(h.offset) +
                                                             ": the plane must lie within " +
                                                             detail::format_value(kMaxSize) +
                                                             " m of the origin");
                 }},
             shape);
}

}  // namespace rodshape
