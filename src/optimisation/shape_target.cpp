// shape_target.cpp: validation of the target, and the feasibility check on the chord-length cubic
// B-spline through the clamp and the objective points (paper: "We then approximate the target shape
// with B-splines to ensure its feasibility").
//
// Length of the spline, ℓ = ∫ |C'(u)| du over the parameter u ∈ [0, 1]. On each knot span C is a
// polynomial of degree ≤ 3, so |C'| = √q(u) with q a polynomial of degree ≤ 4, smooth wherever
// C' ≠ 0. Each span (also split at the data parameters, for the length up to each point) is cut
// into kPanels panels, each integrated with 8-point Gauss–Legendre, exact for degree 15. Error: for
// an integrand analytic inside the Bernstein ellipse E_ρ of the panel, |error| ≤ (64/15) M ρ^(-16)
// / (ρ² - 1) · (panel width / 2) (Trefethen, "Is Gauss quadrature better than Clenshaw–Curtis?",
// 2008, Thm 4.5). The singularities of √q are the zeros of q, at a distance ≥ |C'|/|C''| from
// the real axis; with 4 panels per span and a spline that does not almost stop (|C'|/|C''| ≥ a
// tenth of the span), ρ ≥ 1 + 0.4·2 ≈ 1.8 and ρ^(-16) ≈ 1e-4 — in practice the relative error is
// far smaller (straight and circular data: round-off, see test_shape_target.cpp). Near a cusp
// (C' → 0) |C'| has a kink and the error degrades to O(panel²·|C''|), still far below the
// spline's own interpolation error (which is why the spline's length decides nothing).
#include "rodshape/optimisation/shape_target.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <optional>
#include <sstream>
#include <unsupported/Eigen/Splines>

#include "rodshape/core/physical_bounds.hpp"
#include "validation.hpp"

namespace rodshape {

namespace {

std::string point_field(std::size_t i) { return "ShapeTarget.points[" + std::to_string(i) + "]"; }

std::string metres(double value) {
  std::ostringstream out;
  out << std::setprecision(3) << value << " m";
  return out.str();
}

// 8-point Gauss–Legendre on [-1, 1]: nodes ±x_k, weights w_k.
constexpr std::array<double, 4> kGaussNodes = {0.1834346424956498, 0.5255324099163290,
                                               0.7966664774136267, 0.9602898564975363};
constexpr std::array<double, 4> kGaussWeights = {0.3626837833783620, 0.3137066458778873,
                                                 0.2223810344533745, 0.1012285362903763};
constexpr int kPanels = 4;

/// ∫_a^b |C'(u)| du, composite 8-point Gauss–Legendre on kPanels panels.
double spline_length(const Eigen::Spline3d& spline, double a, double b) {
  if (!(b > a)) return 0.0;
  const double width = (b - a) / kPanels;
  double length = 0.0;
  for (int panel = 0; panel < kPanels; ++panel) {
    const double mid = a + (panel + 0.5) * width;
    const double half = 0.5 * width;
    for (std::size_t k = 0; k < kGaussNodes.size(); ++k) {
      for (double sign : {-1.0, 1.0}) {
        const double u = std::clamp(mid + sign * half * kGaussNodes[k], 0.0, 1.0);
        length += kGaussWeights[k] * half * spline.derivatives(u, 1).col(1).matrix().norm();
      }
    }
  }
  return length;
}

/// The chord-length cubic B-spline from the clamp through the target's points. Points that repeat
/// the previous one are dropped (a zero chord would make the interpolation singular); `owner`
/// maps the spline's data points back to target.points (-1 for the clamp). No spline (nullopt)
/// when fewer than two data points remain.
struct TargetSpline {
  std::optional<Eigen::Spline3d> spline;
  Eigen::Spline3d::KnotVectorType parameters;
  std::vector<int> owner;
};

TargetSpline fit_target_spline(const ShapeTarget& target,
                               const Eigen::Vector3d& clamp,
                               double length_scale) {
  TargetSpline fitted;
  std::vector<Eigen::Vector3d> data{clamp};
  fitted.owner = {-1};
  const double repeat = 1e-12 * std::max(length_scale, 1.0);
  for (std::size_t i = 0; i < target.points.size(); ++i) {
    if ((target.points[i] - data.back()).norm() > repeat) {
      data.push_back(target.points[i]);
      fitted.owner.push_back(static_cast<int>(i));
    }
  }
  const int n = static_cast<int>(data.size());
  if (n < 2) return fitted;
  Eigen::Matrix3Xd points(3, n);
  for (int j = 0; j < n; ++j) points.col(j) = data[j];
  Eigen::ChordLengths(points, fitted.parameters);
  const int degree = std::min(3, n - 1);
  fitted.spline =
      Eigen::SplineFitting<Eigen::Spline3d>::Interpolate(points, degree, fitted.parameters);
  return fitted;
}

/// Infeasible (into `result`) when the chain clamp → p_1 → … → p_n is longer than result.reach;
/// offending_point: the first point the chain reaches beyond it.
void check_chain_length(const ShapeTarget& target,
                        const Eigen::Vector3d& clamp,
                        FeasibilityResult& result) {
  double chain = 0.0;
  int beyond = -1;
  Eigen::Vector3d joint = clamp;
  for (std::size_t i = 0; i < target.points.size(); ++i) {
    chain += (target.points[i] - joint).norm();
    joint = target.points[i];
    if (beyond < 0 && chain > result.reach) beyond = static_cast<int>(i);
  }
  if (beyond < 0) return;
  result.feasible = false;
  result.offending_point = beyond;
  result.reason =
      "the chain from the clamp through the points in order (the shortest curve "
      "through them) is " +
      metres(chain) + " long, longer than the rod (" + metres(result.reach) + "); it passes " +
      point_field(static_cast<std::size_t>(beyond)) + " beyond that length";
}

}  // namespace

void ShapeTarget::validate() const {
  if (points.empty())
    throw InputError("ShapeTarget.points", " is empty: give at least one objective point");
  if (points.size() > kMaxPoints)
    throw InputError("ShapeTarget.points", " has " + std::to_string(points.size()) +
                                               " points; at most " + std::to_string(kMaxPoints));
  for (std::size_t i = 0; i < points.size(); ++i)
    require_magnitude_at_most("ShapeTarget.points[" + std::to_string(i) + "]", points[i],
                              bounds::kMaxPosition, "m");
  detail::require_non_negative("ShapeTarget.energy_weight", energy_weight);
  detail::require_non_negative("ShapeTarget.distance_weight", distance_weight);
  if (energy_weight == 0.0 && distance_weight == 0.0)
    throw InputError("ShapeTarget.energy_weight",
                     " and ShapeTarget.distance_weight are both 0: at least one must be > 0");
  detail::require_non_negative("ShapeTarget.distance_smoothing", distance_smoothing);
}

FeasibilityResult check_feasibility(const ShapeTarget& target,
                                    const ClampedRod& rod,
                                    double max_axial_strain) {
  target.validate();
  detail::require_non_negative("StrainLimits.max_axial_strain", max_axial_strain);
  const double L = rod.properties.length;
  const bool extensible = rod.properties.model == ConstitutiveModel::Cosserat;
  FeasibilityResult result;
  result.reach = extensible ? L * (1.0 + max_axial_strain) : L;
  const Eigen::Vector3d& clamp = rod.clamp.position;

  // 1. Every point within reach of the clamp (a straight rod, fully stretched).
  for (std::size_t i = 0; i < target.points.size(); ++i) {
    const double distance = (target.points[i] - clamp).norm();
    if (distance > result.reach) {
      result.feasible = false;
      result.offending_point = static_cast<int>(i);
      result.reason = point_field(i) + " is " + metres(distance) +
                      " from the clamp, farther than the rod reaches (" + metres(result.reach) +
                      ")";
      break;
    }
  }

  // 2. The chain clamp → p_1 → … → p_n: no curve through the points, in order, is shorter.
  if (result.feasible) check_chain_length(target, clamp, result);

  // 3. The spline from the clamp through the points: the arc lengths.
  const TargetSpline fitted = fit_target_spline(target, clamp, L);
  const double repeat = 1e-12 * std::max(L, 1.0);  // as fit_target_spline skips a repeated point
  const std::vector<int>& owner = fitted.owner;
  const int n = static_cast<int>(owner.size());
  result.arc_lengths.assign(target.points.size(), 0.0);
  if (n < 2) return result;  // every point is at the clamp: length 0
  const Eigen::Spline3d& spline = *fitted.spline;
  const Eigen::Spline3d::KnotVectorType& parameters = fitted.parameters;

  // Integrate between consecutive breakpoints: the knots (where C' changes polynomial) and the
  // data parameters (to know the length up to each point).
  std::vector<double> breaks(spline.knots().data(), spline.knots().data() + spline.knots().size());
  breaks.insert(breaks.end(), parameters.data(), parameters.data() + parameters.size());
  std::sort(breaks.begin(), breaks.end());
  breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
  double length = 0.0;
  int next_data = 1;  // the data point whose parameter we reach next
  for (std::size_t b = 0; b + 1 < breaks.size(); ++b) {
    const double a = std::max(breaks[b], 0.0), c = std::min(breaks[b + 1], 1.0);
    if (c <= a) continue;
    length += spline_length(spline, a, c);
    while (next_data < n && parameters(next_data) <= c) {
      result.arc_lengths[static_cast<std::size_t>(owner[next_data])] = length;
      ++next_data;
    }
  }
  result.curve_length = length;
  // A point that repeats the one before it (dropped from the spline) is where that one is.
  for (std::size_t i = 1; i < target.points.size(); ++i)
    if ((target.points[i] - target.points[i - 1]).norm() <= repeat)
      result.arc_lengths[i] = result.arc_lengths[i - 1];
  // Where the points are sparse on a tightly bent curve the spline bulges between them (4 points
  // on 1.1 turns of a helix: 1.5 % longer than the rod they lie on): its arc lengths, scaled to
  // the reach, are the points' places along the rod.
  if (result.feasible && length > result.reach)
    for (double& s : result.arc_lengths) s *= result.reach / length;
  return result;
}

std::vector<Eigen::Vector3d> sample_target_curve(const ShapeTarget& target,
                                                 const Eigen::Vector3d& clamp,
                                                 int samples) {
  const TargetSpline fitted = fit_target_spline(target, clamp, 1.0);
  if (!fitted.spline) return {clamp};
  std::vector<Eigen::Vector3d> curve;
  const int count = std::max(samples, 2);
  for (int k = 0; k < count; ++k)
    curve.push_back(fitted.spline->operator()(static_cast<double>(k) / (count - 1)));
  return curve;
}

std::string FeasibilityResult::brief() const {
  if (!feasible) return "infeasible: " + reason;
  std::ostringstream out;
  out.precision(3);
  out << "feasible (spline " << curve_length << " m of a reach of " << reach << " m)";
  return out.str();
}

}  // namespace rodshape
