// shape_target.hpp: the wanted shape (paper, "Shape Control Approach"): k objective points the rod
// should pass through, ordered along the rod, and the weights of the cost
//   F = W1/(2L) ∫ (Δvᵀ K_tra Δv + Δuᵀ K_rot Δu) ds + W2 Σᵢ dist(Γ, p_obj,i).
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <string>
#include <vector>

#include "rodshape/core/clamped_rod.hpp"

namespace rodshape {

struct ShapeTarget {
  /// Upper bound on points (docs/limits.md, "Sizes"): each point's distance to the curve is
  /// evaluated over the nodes at every iteration; the 101-node band plans 10 points in 0.12 s,
  /// 100 in 0.6 s, 1000 in 2.7 s.
  static constexpr std::size_t kMaxPoints = 1000;

  std::vector<Eigen::Vector3d> points;  // p_obj,i, world frame, ordered from the clamp to the tip
  double energy_weight = 1.0;           // W1 ≥ 0
  double distance_weight = 1.0;         // W2 ≥ 0 (W1 + W2 > 0)
  bool squared_distances = false;       // Σ dist² instead of Σ dist
  /// δ, m. Σ dist is evaluated as Σ (sqrt(dist² + δ²) - δ): within δ of the paper's sum, and smooth
  /// where a point is reached (dist²/(2δ) there), which IPOPT needs to certify the optimum of a
  /// reachable target — with the exact |·| it ends at the iteration limit on the kink. 0: exact.
  double distance_smoothing = 1e-4;

  /// Throws InputError naming the field: "target.points" empty or non-finite,
  /// "weights.energy" / "weights.distance" negative or both zero, "target.distance_smoothing" < 0.
  void validate() const;
};

/// Whether a rod clamped at `rod.clamp` can pass through the target's points, judged on the
/// chord-length cubic B-spline (Eigen's Splines module) from p(0) through the points.
struct FeasibilityResult {
  bool feasible = true;
  std::string reason;         // empty when feasible
  int offending_point = -1;   // index into ShapeTarget::points, or -1
  double curve_length = 0.0;  // length of the fitted spline from the clamp to the last point
  double reach = 0.0;         // L times the largest stretch the model allows (Kirchhoff: L)
  /// Per target point, the spline's length from the clamp to it, m: the arc length the point has
  /// on the target curve (0 for points at the clamp; computed also when infeasible), scaled by
  /// reach / curve_length when the spline is longer than the reach.
  std::vector<double> arc_lengths;
  /// "feasible (spline 0.27 m of a reach of 0.29 m)" or "infeasible: <reason>".
  std::string brief() const;
};

/// The chord-length cubic B-spline check_feasibility() judges, from `clamp` through the target's
/// points (a point repeating the one before it skipped), at `samples` ≥ 2 parameters evenly
/// spaced from the clamp to the last point: a picture of the target curve (plan.html). Just the
/// clamp when every point is at it.
std::vector<Eigen::Vector3d> sample_target_curve(const ShapeTarget& target,
                                                 const Eigen::Vector3d& clamp,
                                                 int samples);

/// Infeasible when a point lies farther than `reach` from the clamp (offending_point: the first
/// such point), or when the chain clamp → p_1 → … → p_n, the shortest curve through the points in
/// order, is longer than `reach` (offending_point: the first point it reaches beyond it). The
/// spline is one plausible curve through the points, not the rod: where they are sparse on a
/// tightly bent curve it bulges between them and is longer than the rod they lie on (4 points on
/// 1.1 turns of a helix: 1.5 %), so its length is no proof; its arc lengths are scaled to the
/// reach when it is longer. The length is computed by Gauss–Legendre quadrature of |C'| (see
/// shape_target.cpp for its error). `max_axial_strain` bounds the stretch of the Cosserat model
/// (reach = L (1 + max_axial_strain)); the Kirchhoff model cannot stretch.
FeasibilityResult check_feasibility(const ShapeTarget& target,
                                    const ClampedRod& rod,
                                    double max_axial_strain = 0.0);

}  // namespace rodshape
