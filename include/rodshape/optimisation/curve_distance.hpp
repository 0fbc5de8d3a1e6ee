// curve_distance.hpp: dist(Γ, p), the distance from a point to the rod's curve Γ, continuous in s:
// between nodes the curve is the cubic Hermite interpolant of p and p' = R v at the nodes (fourth
// order, like the integrator), not the polyline and not the nearest node.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "rodshape/core/clamped_rod.hpp"
#include "rodshape/core/rod_configuration.hpp"

namespace rodshape {

struct CurveProjection {
  double s = 0.0;                                     // arc length of the closest point
  int interval = 0;                                   // i with s in [s_i, s_{i+1}]
  double t = 0.0;                                     // (s - s_i) / h in [0, 1]
  Eigen::Vector3d closest = Eigen::Vector3d::Zero();  // Γ(s)
  double distance = 0.0;                              // |Γ(s) - p|
};

/// Γ(s), s clamped to [0, L]: the cubic Hermite interpolant of the nodes (the curve the distances
/// are measured to).
Eigen::Vector3d curve_point(const RodConfiguration& configuration, double s);

/// dΓ(s)/dw at fixed s (s clamped to [0, L]): the Hermite interpolant of dp_i/dw and
/// d(p'_i)/dw = R_i (δv_i - v_i × θ_i). `configuration` must carry Derivatives::AllNodes.
Matrix36d curve_point_jacobian(const ClampedRod& rod,
                               const RodConfiguration& configuration,
                               double s);

/// ∂Γ'(s)/∂w at fixed s, Γ' = dΓ/ds (s clamped to [0, L]): the s-derivative of
/// curve_point_jacobian's interpolant. `configuration` must carry Derivatives::AllNodes.
Matrix36d curve_tangent_jacobian(const ClampedRod& rod,
                                 const RodConfiguration& configuration,
                                 double s);
/// The bounding ball of one interval's Bézier control points: the segment of Γ lies inside it.
struct IntervalBall {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  double radius = 0.0;
};

/// The ball of every interval of `configuration`, into `balls` (resized to the intervals; no
/// allocation when its capacity suffices). Computed once per configuration, they serve every point.
void interval_balls(const RodConfiguration& configuration, std::vector<IntervalBall>& balls);

/// The global minimiser of |Γ(s) - p| over s ∈ [0, L].
CurveProjection project_onto_curve(const RodConfiguration& configuration,
                                   const Eigen::Vector3d& point);
/// The same, with the balls of interval_balls(configuration) given (several points, one curve).
CurveProjection project_onto_curve(const RodConfiguration& configuration,
                                   const Eigen::Vector3d& point,
                                   const std::vector<IntervalBall>& balls);

/// The minimiser of |Γ(s) - p| over the (one or two) intervals next to node `node`: the closest
/// point when `node` is the node nearest to p and Γ bends little within an interval (a cloud's
/// points, a section's radius off the curve; feedback/cloud_estimator.hpp finds `node` with a k-d
/// tree). 0 ≤ node < configuration.nodes().
CurveProjection project_near_node(const RodConfiguration& configuration,
                                  const Eigen::Vector3d& point,
                                  int node);
/// The minimiser of |Γ(s) - p| over the intervals within `reach` of the interval found by a
/// descent along the nodes from `interval` (towards the nearer node while one is nearer), the
/// window widened while its best lies at its first or last end: a warm start from the last closest
/// point of a point that moved. Local: a closer point elsewhere on Γ is only found by
/// project_onto_curve.
CurveProjection project_from_interval(const RodConfiguration& configuration,
                                      const Eigen::Vector3d& point,
                                      int interval,
                                      int reach = 1);
/// d dist(Γ, p) / dw by the envelope argument: the closest point moves with the curve, but at an
/// interior minimum (Γ(s) - p) ⟂ Γ'(s), so d dist/dw = (Γ(s) - p)ᵀ/dist · dΓ(s)/dw at fixed s,
/// with dΓ(s)/dw the Hermite interpolant of dp_i/dw and d(p'_i)/dw = R_i (δv_i - v_i × θ_i).
/// `configuration` must carry Derivatives::AllNodes. Zero when dist = 0.
Eigen::Matrix<double, 1, 6> distance_gradient(const ClampedRod& rod,
                                              const RodConfiguration& configuration,
                                              const CurveProjection& projection,
                                              const Eigen::Vector3d& point);

}  // namespace rodshape
