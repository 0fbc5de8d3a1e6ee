// curve_distance.cpp: the distance from a point to the rod's curve Γ, with Γ between nodes s_i and
// s_{i+1} = s_i + h the cubic Hermite interpolant of the node positions p_i and tangents p'_i = R_i
// v_i:
//   H(t) = h00(t) p_i + h10(t) h p'_i + h01(t) p_{i+1} + h11(t) h p'_{i+1},  t = (s - s_i)/h,
//   = a0 + a1 t + a2 t² + a3 t³,  a0 = p_i, a1 = h p'_i, a2 = 3(p_{i+1} - p_i) - h(2p'_i +
//   p'_{i+1}), a3 = 2(p_i - p_{i+1}) + h(p'_i + p'_{i+1}).
// Its error against the exact curve through exact nodes is |Γ(s) - H| ≤ h⁴/384 · max|p''''| (the
// integrator's nodes add their own O(h⁴) error; see tests/support/analytic_rods.hpp).
//
// The global minimum over s ∈ [0, L]: the best node distance is an upper bound; an interval can
// only beat it if the bounding ball of its Bézier control points b0 = a0, b1 = p_i + h p'_i/3, b2 =
// p_{i+1} - h p'_{i+1}/3, b3 = p_{i+1} (the segment lies in their convex hull) comes closer. Each
// such interval is searched: f(t) = |H(t) - p|² sampled at t = k/8, then safeguarded Newton on
// f'(t)/2 = (H - p)·H' in the bracket around the best sample. The endpoints t = 0, 1 are samples,
// so a minimum at a node or at the rod's ends is found too.
#include "rodshape/optimisation/curve_distance.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <limits>

#include "rodshape/core/so3.hpp"

namespace rodshape {

namespace {

/// H(t) = a0 + a1 t + a2 t² + a3 t³ on one interval.
struct HermiteSegment {
  Eigen::Vector3d a0, a1, a2, a3;

  HermiteSegment(const Eigen::Vector3d& p0,
                 const Eigen::Vector3d& p1,
                 const Eigen::Vector3d& hd0,  // h p'_i
                 const Eigen::Vector3d& hd1)  // h p'_{i+1}
      : a0(p0), a1(hd0), a2(3.0 * (p1 - p0) - 2.0 * hd0 - hd1), a3(2.0 * (p0 - p1) + hd0 + hd1) {}

  Eigen::Vector3d value(double t) const { return a0 + t * (a1 + t * (a2 + t * a3)); }
  Eigen::Vector3d first(double t) const { return a1 + t * (2.0 * a2 + 3.0 * t * a3); }
  Eigen::Vector3d second(double t) const { return 2.0 * a2 + 6.0 * t * a3; }
};

HermiteSegment segment_of(const RodConfiguration& c, int i) {
  const double h = c.s[i + 1] - c.s[i];
  return HermiteSegment(c.p[i], c.p[i + 1], h * (c.R[i] * c.v[i]), h * (c.R[i + 1] * c.v[i + 1]));
}

/// The ball around the control points b0 = p_i, b1 = p_i + h p'_i/3, b2 = p_{i+1} - h p'_{i+1}/3,
/// b3 = p_{i+1}: centred at their mean, through the farthest.
IntervalBall ball_of(const RodConfiguration& c, int i) {
  const double h = c.s[i + 1] - c.s[i];
  const std::array<Eigen::Vector3d, 4> b = {c.p[i], c.p[i] + (h / 3.0) * (c.R[i] * c.v[i]),
                                            c.p[i + 1] - (h / 3.0) * (c.R[i + 1] * c.v[i + 1]),
                                            c.p[i + 1]};
  IntervalBall ball;
  ball.center = 0.25 * (b[0] + b[1] + b[2] + b[3]);
  for (const Eigen::Vector3d& corner : b)
    ball.radius = std::max(ball.radius, (corner - ball.center).norm());
  return ball;
}

/// A lower bound on min_t |H(t) - p|: the distance to the interval's ball.
double distance_lower_bound(const IntervalBall& ball, const Eigen::Vector3d& point) {
  return std::max(0.0, (point - ball.center).norm() - ball.radius);
}

struct LocalMinimum {
  double t = 0.0;
  double squared = std::numeric_limits<double>::infinity();
};

/// min over t ∈ [0, 1] of |H(t) - p|², as described at the top of the file.
LocalMinimum minimise_on_segment(const HermiteSegment& H, const Eigen::Vector3d& point) {
  constexpr int kSamples = 8;
  LocalMinimum best;
  int best_k = 0;
  for (int k = 0; k <= kSamples; ++k) {
    const double t = static_cast<double>(k) / kSamples;
    const double f = (H.value(t) - point).squaredNorm();
    if (f < best.squared) {
      best = {t, f};
      best_k = k;
    }
  }
  double lo = std::max(0, best_k - 1) / static_cast<double>(kSamples);
  double hi = std::min(kSamples, best_k + 1) / static_cast<double>(kSamples);
  double t = best.t;
  for (int iteration = 0; iteration < 60; ++iteration) {
    const Eigen::Vector3d r = H.value(t) - point;
    const Eigen::Vector3d d1 = H.first(t);
    const double g = r.dot(d1);                               // f'/2
    const double dg = d1.squaredNorm() + r.dot(H.second(t));  // f''/2
    if (g == 0.0) break;
    (g > 0.0 ? hi : lo) = t;
    double next = dg > 0.0 ? t - g / dg : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);  // Newton left the bracket: bisect
    const bool done = std::abs(next - t) <= 4.0 * std::numeric_limits<double>::epsilon();
    t = next;
    if (done || hi - lo <= 4.0 * std::numeric_limits<double>::epsilon()) break;
  }
  const double f = (H.value(t) - point).squaredNorm();
  if (f < best.squared) best = {t, f};
  return best;
}

}  // namespace

Eigen::Vector3d curve_point(const RodConfiguration& configuration, double s) {
  const RodConfiguration& c = configuration;
  if (c.nodes() < 2) return c.p.empty() ? Eigen::Vector3d::Zero() : c.p.front();
  s = std::clamp(s, c.s.front(), c.s.back());
  // The interval [s_i, s_{i+1}] holding s.
  const auto upper = std::upper_bound(c.s.begin(), c.s.end(), s);
  const int i = std::clamp(static_cast<int>(upper - c.s.begin()) - 1, 0, c.nodes() - 2);
  const double t = (s - c.s[i]) / (c.s[i + 1] - c.s[i]);
  return segment_of(c, i).value(t);
}

void interval_balls(const RodConfiguration& configuration, std::vector<IntervalBall>& balls) {
  const int intervals = std::max(configuration.nodes() - 1, 0);
  balls.resize(static_cast<std::size_t>(intervals));
  for (int i = 0; i < intervals; ++i)
    balls[static_cast<std::size_t>(i)] = ball_of(configuration, i);
}

namespace {

/// Upper bound: the nearest node, as a projection with t = 0 (or 1 at the tip).
CurveProjection nearest_node(const RodConfiguration& c, const Eigen::Vector3d& point) {
  const int intervals = c.nodes() - 1;
  CurveProjection result;
  result.distance = std::numeric_limits<double>::infinity();
  for (int i = 0; i < c.nodes(); ++i) {
    const double d = (c.p[i] - point).norm();
    if (d < result.distance) {
      result.distance = d;
      result.interval = std::min(i, std::max(intervals - 1, 0));
      result.t = i > result.interval ? 1.0 : 0.0;
      result.closest = c.p[i];
    }
  }
  return result;
}

/// `result` replaced by the nearest point of interval i when that is nearer.
void closer_on_segment(const RodConfiguration& c,
                       int i,
                       const Eigen::Vector3d& point,
                       CurveProjection& result) {
  const HermiteSegment H = segment_of(c, i);
  const LocalMinimum local = minimise_on_segment(H, point);
  const double d = std::sqrt(local.squared);
  if (d < result.distance) {
    result.distance = d;
    result.interval = i;
    result.t = local.t;
    result.closest = H.value(local.t);
  }
}

/// s of the projection from its interval and t.
void set_arc_length(const RodConfiguration& c, CurveProjection& result) {
  const int i = result.interval;
  result.s = c.s[i] + result.t * (c.s[i + 1] - c.s[i]);
}

/// Every interval whose ball (from `ball_at`) comes closer than the best distance so far is
/// searched.
template <typename BallAt>
CurveProjection project(const RodConfiguration& c, const Eigen::Vector3d& point, BallAt ball_at) {
  const int intervals = c.nodes() - 1;
  CurveProjection result = nearest_node(c, point);
  if (intervals < 1) return result;
  for (int i = 0; i < intervals; ++i) {
    if (distance_lower_bound(ball_at(i), point) >= result.distance) continue;
    closer_on_segment(c, i, point, result);
  }
  set_arc_length(c, result);
  return result;
}

}  // namespace

CurveProjection project_onto_curve(const RodConfiguration& configuration,
                                   const Eigen::Vector3d& point) {
  return project(configuration, point, [&](int i) { return ball_of(configuration, i); });
}

CurveProjection project_onto_curve(const RodConfiguration& configuration,
                                   const Eigen::Vector3d& point,
                                   const std::vector<IntervalBall>& balls) {
  assert(balls.size() + 1 == static_cast<std::size_t>(std::max(configuration.nodes(), 1)));
  return project(configuration, point,
                 [&](int i) -> const IntervalBall& { return balls[static_cast<std::size_t>(i)]; });
}

CurveProjection project_near_node(const RodConfiguration& configuration,
                                  const Eigen::Vector3d& point,
                                  int node) {
  const RodConfiguration& c = configuration;
  assert(node >= 0 && node < c.nodes());
  CurveProjection result;
  result.closest = c.p[static_cast<std::size_t>(node)];
  result.distance = (result.closest - point).norm();
  const int intervals = c.nodes() - 1;
  if (intervals < 1) return result;
  result.interval = std::min(node, intervals - 1);
  result.t = node > result.interval ? 1.0 : 0.0;
  for (int i = std::max(node - 1, 0); i <= std::min(node, intervals - 1); ++i)
    closer_on_segment(c, i, point, result);
  set_arc_length(c, result);
  return result;
}

namespace {

/// The interval holding the minimum of |Γ(s) - p| near `interval`: from its first node, along the
/// nodes while the next is closer to p (a descent, one distance per node), then the side of the
/// nearest node on which the distance falls, the sign of (p_i - p) · p'_i.
int interval_of_descent(const RodConfiguration& c, const Eigen::Vector3d& point, int interval) {
  const auto squared = [&](int i) { return (c.p[i] - point).squaredNorm(); };
  int node = interval;
  // Backwards while nearer, else forwards: after a move the node left behind is farther.
  while (node > 0 && squared(node - 1) < squared(node)) --node;
  while (node + 1 < c.nodes() && squared(node + 1) < squared(node)) ++node;
  const int intervals = c.nodes() - 1;
  const bool falls_before = (c.p[node] - point).dot(c.R[node] * c.v[node]) > 0.0;
  return std::clamp(falls_before ? node - 1 : node, 0, intervals - 1);
}

}  // namespace

CurveProjection project_from_interval(const RodConfiguration& configuration,
                                      const Eigen::Vector3d& point,
                                      int interval,
                                      int reach) {
  const RodConfiguration& c = configuration;
  const int intervals = c.nodes() - 1;
  if (intervals < 1) return nearest_node(c, point);
  interval = interval_of_descent(c, point, std::clamp(interval, 0, intervals - 1));
  int lo = std::max(interval - reach, 0), hi = std::min(interval + reach, intervals - 1);
  CurveProjection result;
  result.distance = std::numeric_limits<double>::infinity();
  for (int i = lo; i <= hi; ++i) closer_on_segment(c, i, point, result);
  // A descent along the curve: the window grows while its best lies at its first or last end
  // (an interior minimum on the window is a local minimum of the distance along the curve).
  constexpr double kAtEnd = 1e-12;
  while (result.interval == lo && result.t <= kAtEnd && lo > 0)
    closer_on_segment(c, --lo, point, result);
  while (result.interval == hi && result.t >= 1.0 - kAtEnd && hi < intervals - 1)
    closer_on_segment(c, ++hi, point, result);
  set_arc_length(c, result);
  return result;
}

namespace {

/// d(p'_i)/dw = R_i (δv_i - v_i × θ_i), one column per base-wrench direction, with
/// δv_i = K_tra⁻¹ δn̄_i (Cosserat; 0 for Kirchhoff), δn̄_i = n̄_i × θ_i + R_iᵀ δn_i, n̄_i = R_iᵀ n_i.
Matrix36d tangent_derivative(const ClampedRod& rod, const RodConfiguration& c, int i) {
  const Eigen::Matrix3d& R = c.R[i];
  const Matrix36d& theta = c.dtheta_dw[i];
  Matrix36d a = -hat(c.v[i]) * theta;  // -v × θ
  if (rod.properties.model == ConstitutiveModel::Cosserat) {
    const Eigen::Vector3d n_body = R.transpose() * c.n[i];
    const Matrix36d dn_body = hat(n_body) * theta + R.transpose() * c.dn_dw[i];
    a += rod.properties.K_tra.cwiseInverse().asDiagonal() * dn_body;
  }
  return R * a;
}

}  // namespace

namespace {

/// dΓ/dw at (interval i, t): the Hermite interpolant of dp_i/dw and h d(p'_i)/dw.
Matrix36d hermite_jacobian(const ClampedRod& rod, const RodConfiguration& c, int i, double t) {
  const double h = c.s[i + 1] - c.s[i];
  // Hermite basis at t.
  const double t2 = t * t, t3 = t2 * t;
  const double h00 = 2.0 * t3 - 3.0 * t2 + 1.0, h10 = t3 - 2.0 * t2 + t;
  const double h01 = -2.0 * t3 + 3.0 * t2, h11 = t3 - t2;
  Matrix36d dgamma = h00 * c.dp_dw[i] + h01 * c.dp_dw[i + 1];
  if (h10 != 0.0) dgamma += (h10 * h) * tangent_derivative(rod, c, i);
  if (h11 != 0.0) dgamma += (h11 * h) * tangent_derivative(rod, c, i + 1);
  return dgamma;
}

}  // namespace

namespace {

/// The interval i holding s (clamped to [0, L]) and t = (s - s_i) / h there; c has 2 nodes or more.
struct IntervalPoint {
  int i;
  double t;
};
IntervalPoint interval_point(const RodConfiguration& c, double s) {
  s = std::clamp(s, c.s.front(), c.s.back());
  const auto upper = std::upper_bound(c.s.begin(), c.s.end(), s);
  const int i = std::clamp(static_cast<int>(upper - c.s.begin()) - 1, 0, c.nodes() - 2);
  return {i, (s - c.s[i]) / (c.s[i + 1] - c.s[i])};
}

}  // namespace

Matrix36d curve_point_jacobian(const ClampedRod& rod,
                               const RodConfiguration& configuration,
                               double s) {
  if (configuration.nodes() < 2) return Matrix36d::Zero();
  const auto [i, t] = interval_point(configuration, s);
  return hermite_jacobian(rod, configuration, i, t);
}

Matrix36d curve_tangent_jacobian(const ClampedRod& rod,
                                 const RodConfiguration& configuration,
                                 double s) {
  const RodConfiguration& c = configuration;
  if (c.nodes() < 2) return Matrix36d::Zero();
  const auto [i, t] = interval_point(c, s);
  // d/ds of the Hermite basis: h00' = (6t² - 6t)/h = -h01', h10' = 3t² - 4t + 1, h11' = 3t² - 2t.
  const double h00 = (6.0 * t * t - 6.0 * t) / (c.s[i + 1] - c.s[i]);
  return h00 * (c.dp_dw[i] - c.dp_dw[i + 1]) +
         (3.0 * t * t - 4.0 * t + 1.0) * tangent_derivative(rod, c, i) +
         (3.0 * t * t - 2.0 * t) * tangent_derivative(rod, c, i + 1);
}

Eigen::Matrix<double, 1, 6> distance_gradient(const ClampedRod& rod,
                                              const RodConfiguration& configuration,
                                              const CurveProjection& projection,
                                              const Eigen::Vector3d& point) {
  const RodConfiguration& c = configuration;
  if (projection.distance == 0.0 || c.nodes() < 2) return Eigen::Matrix<double, 1, 6>::Zero();
  // dΓ(s)/dw at fixed s: the Hermite interpolant of the nodes' derivatives.
  const Matrix36d dgamma = hermite_jacobian(rod, c, projection.interval, projection.t);
  const Eigen::RowVector3d direction =
      (projection.closest - point).transpose() / projection.distance;
  return direction * dgamma;
}

}  // namespace rodshape
