// obstacle.cpp: every operation on the obstacle shapes (obstacle_shapes.hpp), one section per
// shape, and Obstacle's dispatch of each through one exhaustive visit.
//   sphere     d = |p - c| - r
//   capsule    d = |p - q(p)| - r, q(p) the nearest point of [from, to]
//   half-space d = (offset - nᵀp) / |n|
//   box        q = Rᵀ(p - c), e = |q| - size/2 (per axis): outside d = |max(e, 0)|, inside d = max
//   e
// Over a segment: closed forms for the sphere, the capsule (segment–segment) and the half-space
// (an end); for the box, d(a + t (b - a)) is convex in t: an end is the minimiser when the slope
// there points inwards, else golden-section search on [0, 1].
// Rays o + t d: the roots of |o + t d − c|² = r² (balls), the same across the capsule's axis (its
// cylinder), the slabs of a box, the plane of a half-space.
#include "rodshape/core/obstacle.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

#include "rodshape/core/pose.hpp"
#include "rodshape/core/segment.hpp"
#include "validation.hpp"

namespace rodshape {

namespace {

constexpr double kMiss = std::numeric_limits<double>::infinity();

/// A unit vector along v, or `fallback` when v is (numerically) zero.
Eigen::Vector3d unit_or(const Eigen::Vector3d& v, const Eigen::Vector3d& fallback) {
  const double norm = v.norm();
  return norm > 1e-300 ? Eigen::Vector3d(v / norm) : fallback;
}

/// x_a = p + R x_b.
Eigen::Vector3d moved(const Pose& a_T_b, const Eigen::Vector3d& x) {
  return a_T_b.position + a_T_b.rotation * x;
}

template <class Shape>
SegmentDistance at(const Shape& shape,
                   const Eigen::Vector3d& a,
                   const Eigen::Vector3d& b,
                   double t) {
  const PointDistance d = shape_distance(shape, Eigen::Vector3d(a + t * (b - a)));
  return {d.distance, t, d.gradient};
}

/// min over t of a convex d(a + t (b - a)): an end when the slope there points away from the
/// interior, else golden-section search to |Δt| ≤ 1e-10 (|Δd| ≤ 1e-10 |b - a|, as |∇d| = 1).
template <class Shape>
SegmentDistance convex_segment_distance(const Shape& shape,
                                        const Eigen::Vector3d& a,
                                        const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const SegmentDistance at_a = at(shape, a, b, 0.0);
  if (at_a.gradient.dot(ab) >= 0.0) return at_a;
  const SegmentDistance at_b = at(shape, a, b, 1.0);
  if (at_b.gradient.dot(ab) <= 0.0) return at_b;
  constexpr double kInverseGolden = 0.6180339887498949;
  double lo = 0.0, hi = 1.0;
  double x1 = hi - kInverseGolden * (hi - lo), x2 = lo + kInverseGolden * (hi - lo);
  double f1 = at(shape, a, b, x1).distance, f2 = at(shape, a, b, x2).distance;
  while (hi - lo > 1e-10) {
    if (f1 <= f2) {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - kInverseGolden * (hi - lo);
      f1 = at(shape, a, b, x1).distance;
    } else {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + kInverseGolden * (hi - lo);
      f2 = at(shape, a, b, x2).distance;
    }
  }
  return at(shape, a, b, 0.5 * (lo + hi));
}

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

// ---- sphere -------------------------------------------------------------------------------------

const char* shape_kind(const SphereObstacle&) { return "sphere"; }

PointDistance shape_distance(const SphereObstacle& s, const Eigen::Vector3d& p) {
  const Eigen::Vector3d r = p - s.center;
  return {r.norm() - s.radius, unit_or(r, Eigen::Vector3d::UnitZ())};
}

SegmentDistance shape_distance(const SphereObstacle& s,
                               const Eigen::Vector3d& a,
                               const Eigen::Vector3d& b) {
  return at(s, a, b, nearest_on_segment(s.center, a, b));
}

double shape_ray_hit(const SphereObstacle& s, const Eigen::Vector3d& o, const Eigen::Vector3d& d) {
  return ray_ball(o, d, s.center, s.radius);
}

SphereObstacle transformed(const Pose& a_T_b, const SphereObstacle& s) {
  return {moved(a_T_b, s.center), s.radius};
}

std::optional<AxisAlignedBox> shape_bounds(const SphereObstacle& s) {
  const Eigen::Vector3d r = Eigen::Vector3d::Constant(s.radius);
  return AxisAlignedBox{s.center - r, s.center + r};
}

std::vector<ObstacleField> shape_fields(const SphereObstacle& s) {
  return {{"center", s.center}, {"radius", s.radius}};
}

void validate_shape(const SphereObstacle& s, const std::string& field) {
  validate_point(field + ".center", s.center);
  validate_radius(field + ".radius", s.radius);
}

// ---- box ----------------------------------------------------------------------------------------

const char* shape_kind(const BoxObstacle&) { return "box"; }

PointDistance shape_distance(const BoxObstacle& box, const Eigen::Vector3d& p) {
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

SegmentDistance shape_distance(const BoxObstacle& box,
                               const Eigen::Vector3d& a,
                               const Eigen::Vector3d& b) {
  return convex_segment_distance(box, a, b);
}

/// The slabs |q_k| ≤ size_k / 2 of the box's frame: the ray is inside all of them on [enter,
/// leave].
double shape_ray_hit(const BoxObstacle& box, const Eigen::Vector3d& o, const Eigen::Vector3d& d) {
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

BoxObstacle transformed(const Pose& a_T_b, const BoxObstacle& box) {
  return {moved(a_T_b, box.center), box.size, a_T_b.rotation * box.rotation};
}

/// Half extents |R| size / 2 (the corners' reach along each world axis).
std::optional<AxisAlignedBox> shape_bounds(const BoxObstacle& box) {
  const Eigen::Vector3d half = box.rotation.cwiseAbs() * (0.5 * box.size);
  return AxisAlignedBox{box.center - half, box.center + half};
}

std::vector<ObstacleField> shape_fields(const BoxObstacle& box) {
  return {{"center", box.center}, {"size", box.size}, {"rotation", box.rotation}};
}

void validate_shape(const BoxObstacle& box, const std::string& field) {
  validate_point(field + ".center", box.center);
  for (int i = 0; i < 3; ++i)
    validate_radius(field + ".size[" + std::to_string(i) + "]", box.size(i));
  if (!box.rotation.allFinite() || !is_rotation(box.rotation, 1e-6))
    throw InputError(field + ".rotation", " is not a rotation (RᵀR = I and det R = 1 within 1e-6)");
}

// ---- capsule ------------------------------------------------------------------------------------

const char* shape_kind(const CapsuleObstacle&) { return "capsule"; }

PointDistance shape_distance(const CapsuleObstacle& c, const Eigen::Vector3d& p) {
  const Eigen::Vector3d axis_point = c.from + nearest_on_segment(p, c.from, c.to) * (c.to - c.from);
  const Eigen::Vector3d r = p - axis_point;
  return {r.norm() - c.radius,
          unit_or(r, unit_or((c.to - c.from).unitOrthogonal(), Eigen::Vector3d::UnitZ()))};
}

SegmentDistance shape_distance(const CapsuleObstacle& c,
                               const Eigen::Vector3d& a,
                               const Eigen::Vector3d& b) {
  const auto [t, t_axis] = nearest_between_segments(a, b, c.from, c.to);
  const Eigen::Vector3d p = a + t * (b - a);
  const Eigen::Vector3d r = p - (c.from + t_axis * (c.to - c.from));
  const PointDistance d = shape_distance(c, p);  // its normal where r = 0
  return SegmentDistance{r.norm() - c.radius, t, unit_or(r, d.gradient)};
}

/// The cylinder between the two end balls, then the balls.
double shape_ray_hit(const CapsuleObstacle& c, const Eigen::Vector3d& o, const Eigen::Vector3d& d) {
  const Eigen::Vector3d &a = c.from, &b = c.to;
  const double r = c.radius;
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

CapsuleObstacle transformed(const Pose& a_T_b, const CapsuleObstacle& c) {
  return {moved(a_T_b, c.from), moved(a_T_b, c.to), c.radius};
}

std::optional<AxisAlignedBox> shape_bounds(const CapsuleObstacle& c) {
  const Eigen::Vector3d r = Eigen::Vector3d::Constant(c.radius);
  return AxisAlignedBox{c.from.cwiseMin(c.to) - r, c.from.cwiseMax(c.to) + r};
}

std::vector<ObstacleField> shape_fields(const CapsuleObstacle& c) {
  return {{"from", c.from}, {"to", c.to}, {"radius", c.radius}};
}

void validate_shape(const CapsuleObstacle& c, const std::string& field) {
  validate_point(field + ".from", c.from);
  validate_point(field + ".to", c.to);
  validate_radius(field + ".radius", c.radius);
}

// ---- half-space ---------------------------------------------------------------------------------

const char* shape_kind(const HalfSpaceObstacle&) { return "half_space"; }

PointDistance shape_distance(const HalfSpaceObstacle& h, const Eigen::Vector3d& p) {
  const double norm = h.normal.norm();
  return {(h.offset - h.normal.dot(p)) / norm, -h.normal / norm};
}

/// d is affine along the segment: the end deeper along the normal.
SegmentDistance shape_distance(const HalfSpaceObstacle& h,
                               const Eigen::Vector3d& a,
                               const Eigen::Vector3d& b) {
  return h.normal.dot(a) >= h.normal.dot(b) ? at(h, a, b, 0.0) : at(h, a, b, 1.0);
}

/// nᵀ(o + t d) = offset.
double shape_ray_hit(const HalfSpaceObstacle& h,
                     const Eigen::Vector3d& o,
                     const Eigen::Vector3d& d) {
  const double outside = h.offset - h.normal.dot(o);  // ≥ 0 in free space
  if (outside <= 0.0) return 0.0;
  const double closing = h.normal.dot(d);
  return closing > 0.0 ? outside / closing : kMiss;
}

/// nᵀx_b > offset with x_b = Rᵀ(x_a - p): n' = R n, offset' = offset + n'ᵀp.
HalfSpaceObstacle transformed(const Pose& a_T_b, const HalfSpaceObstacle& h) {
  HalfSpaceObstacle out{a_T_b.rotation * h.normal, h.offset};
  out.offset += out.normal.dot(a_T_b.position);
  return out;
}

std::optional<AxisAlignedBox> shape_bounds(const HalfSpaceObstacle&) { return std::nullopt; }

std::vector<ObstacleField> shape_fields(const HalfSpaceObstacle& h) {
  return {{"normal", h.normal}, {"offset", h.offset}};
}

void validate_shape(const HalfSpaceObstacle& h, const std::string& field) {
  detail::require_finite(field + ".normal", h.normal);
  const double norm = h.normal.stableNorm();  // |[1e300, 0, 0]| is 1e300, not inf
  if (norm == 0.0) throw InputError(field + ".normal", " must not be zero");
  if (norm < Obstacle::kMinNormal || norm > Obstacle::kMaxNormal)
    throw InputError(field + ".normal", " has magnitude " + detail::format_value(norm) +
                                            "; it must be in [" +
                                            detail::format_value(Obstacle::kMinNormal) + ", " +
                                            detail::format_value(Obstacle::kMaxNormal) +
                                            "] (it is normalised; docs/task-file.md)");
  detail::require_finite(field + ".offset", h.offset);
  if (std::abs(h.offset) > Obstacle::kMaxSize * h.normal.norm())
    throw InputError(field + ".offset",
                     " = " + detail::format_value(h.offset) + ": the plane must lie within " +
                         detail::format_value(Obstacle::kMaxSize) + " m of the origin");
}

// ---- the obstacle: each operation on its shape, whichever it is --------------------------------

std::string Obstacle::kind() const {
  return std::visit([](const auto& s) { return std::string(shape_kind(s)); }, shape);
}

std::string Obstacle::label(int index) const {
  return name.empty() ? std::to_string(index) : "'" + name + "'";
}

PointDistance Obstacle::distance(const Eigen::Vector3d& p) const {
  return std::visit([&](const auto& s) { return shape_distance(s, p); }, shape);
}

SegmentDistance Obstacle::distance(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const {
  return std::visit([&](const auto& s) { return shape_distance(s, a, b); }, shape);
}

double Obstacle::ray_hit(const Eigen::Vector3d& o, const Eigen::Vector3d& d) const {
  return std::visit([&](const auto& s) { return shape_ray_hit(s, o, d); }, shape);
}

std::optional<AxisAlignedBox> Obstacle::bounds() const {
  return std::visit([](const auto& s) { return shape_bounds(s); }, shape);
}

ObstacleDescription Obstacle::describe() const {
  return {name, kind(), std::visit([](const auto& s) { return shape_fields(s); }, shape)};
}

void Obstacle::validate(const std::string& field) const {
  std::visit([&](const auto& s) { validate_shape(s, field); }, shape);
  const std::string mu = field + ".friction";
  if (!std::isfinite(friction) || friction < 0.0 || friction > kMaxFriction)
    throw InputError(mu, " = " + detail::format_value(friction) +
                             " must be a Coulomb coefficient in [0, " +
                             detail::format_value(kMaxFriction) + "]");
  if (friction > 0.0 && !touchable())
    throw InputError(mu, " is for an obstacle the rod may touch (contact: touch)");
  if (friction > 0.0)
    throw InputError(mu, " = " + detail::format_value(friction) +
                             ": Coulomb friction is not solved yet; contact is frictionless (0)");
}

Obstacle transformed(const Pose& a_T_b, const Obstacle& in_b) {
  Obstacle out = in_b;
  out.shape =
      std::visit([&](const auto& s) { return ObstacleShape(transformed(a_T_b, s)); }, in_b.shape);
  return out;
}

}  // namespace rodshape
