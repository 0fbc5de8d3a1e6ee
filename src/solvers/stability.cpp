#include "rodshape/solvers/stability.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <algorithm>
#include <array>
#include <boost/math/tools/minima.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <sstream>
#include <utility>
#include <variant>
#include <vector>

#include "rodshape/core/pose_between_nodes.hpp"
#include "rodshape/error.hpp"
#include "rodshape/solvers/tip_stiffness.hpp"

namespace rodshape {

namespace {

// A local minimum of σ_min(J̃) that refinement drives below this fraction of σ_min at the
// neighbouring nodes is a root (a conjugate point). Relative, so that the verdict does not depend
// on the units or on the ratio of axial to bending stiffness (issue 12).
constexpr double kConjugateTolerance = 1e-6;

/// C(s) = d(pose at s)/d(base wrench) of the unloaded straight rod of length s, clamp frame,
/// from the linearised equations m(σ) = m(0) - σ e_z × n(0), θ' = K_rot⁻¹ m, δp' = K_tra⁻¹ n + θ ×
/// e_z:
///   δp_x = (c_x s - b_y s³/6) n_x + b_y s²/2 m_y      θ_x = b_x (s m_x + s²/2 n_y)
///   δp_y = (c_y s - b_x s³/6) n_y - b_x s²/2 m_x      θ_y = b_y (s m_y - s²/2 n_x)
///   δp_z = c_z s n_z                                  θ_z = b_z s m_z
/// with b = K_rot⁻¹, c = K_tra⁻¹. A Kirchhoff rod has c = 0; its axial entry, which would vanish,
/// takes the bending value s³/(3 EI) so that C stays a scale.
Matrix6d straight_rod_compliance(const RodProperties& props, double s) {
  const Eigen::Vector3d b = props.K_rot.cwiseInverse();
  Eigen::Vector3d c = props.K_tra.cwiseInverse();
  if (props.model == ConstitutiveModel::Kirchhoff) c << 0.0, 0.0, s * s * (b.x() + b.y()) / 6.0;
  const double s2 = s * s, s3 = s2 * s;
  Matrix6d C = Matrix6d::Zero();
  C(0, 0) = c.x() * s - b.y() * s3 / 6.0;
  C(0, 4) = b.y() * s2 / 2.0;
  C(1, 1) = c.y() * s - b.x() * s3 / 6.0;
  C(1, 3) = -b.x() * s2 / 2.0;
  C(2, 2) = c.z() * s;
  C(3, 3) = b.x() * s;
  C(3, 1) = b.x() * s2 / 2.0;
  C(4, 4) = b.y() * s;
  C(4, 0) = -b.y() * s2 / 2.0;
  C(5, 5) = b.z() * s;
  return C;
}

/// C(s)⁻¹: C couples only (0, 4) and (1, 3), so it inverts as two 2 × 2 blocks and a diagonal.
Matrix6d straight_rod_stiffness(const RodProperties& props, double s) {
  const Matrix6d C = straight_rod_compliance(props, s);
  Matrix6d K = Matrix6d::Zero();
  for (const auto& [a, b] : {std::pair{0, 4}, std::pair{1, 3}}) {
    const double det = C(a, a) * C(b, b) - C(a, b) * C(b, a);
    K(a, a) = C(b, b) / det;
    K(b, b) = C(a, a) / det;
    K(a, b) = -C(a, b) / det;
    K(b, a) = -C(b, a) / det;
  }
  K(2, 2) = 1.0 / C(2, 2);
  K(5, 5) = 1.0 / C(5, 5);
  return K;
}

/// J̃(s) = J_c(s) C(s)⁻¹, J_c the Jacobian in the clamp frame (positions R0ᵀδp, rotations R0ᵀRθ,
/// wrench components along the clamp axes). J̃ = I for the unloaded straight rod.
class ScaledJacobian {
 public:
  ScaledJacobian(const RodProperties& props, const Eigen::Matrix3d& R0) : props_(props), R0_(R0) {}

  Matrix6d operator()(const Matrix36d& dp_dw,
                      const Matrix36d& dtheta_dw,
                      const Eigen::Matrix3d& R,
                      double s) const {
    Matrix6d J;
    J << R0_.transpose() * dp_dw, R0_.transpose() * R * dtheta_dw;
    J.leftCols<3>() = J.leftCols<3>() * R0_;  // dw_world = R0 dw_clamp
    J.rightCols<3>() = J.rightCols<3>() * R0_;
    return J * straight_rod_stiffness(props_, s);
  }

 private:
  const RodProperties& props_;
  Eigen::Matrix3d R0_;
};

/// σ_min(J) from the eigenvalues of JᵀJ, a third of the cost of a 6 × 6 SVD. Their absolute error
/// is about ε λ_max, so σ_min = √λ_min is within ε κ²/2 of itself relative (κ = σ_max/σ_min):
/// within 1e-4 where λ_min ≥ 1e-12 λ_max (κ ≤ 1e6; the bent band's J̃ has κ ≈ 1e5 at most nodes).
/// Nearer to singular, where the conjugate-point test compares σ_min with 1e-6 of its neighbours,
/// the SVD gives σ_min to ε σ_max.
double smallest_singular_value(const Matrix6d& J) {
  const Eigen::SelfAdjointEigenSolver<Matrix6d> gram(J.transpose() * J, Eigen::EigenvaluesOnly);
  const double lambda_min = gram.eigenvalues()(0), lambda_max = gram.eigenvalues()(5);
  if (lambda_min >= 1e-12 * lambda_max) return std::sqrt(lambda_min);
  return Eigen::JacobiSVD<Matrix6d>(J).singularValues()(5);
}

/// Evaluates J̃ between nodes by re-entering the integration at node i.
class JacobianBetweenNodes {
 public:
  JacobianBetweenNodes(const ClampedRod& rod,
                       const RodConfiguration& c,
                       const ScaledJacobian& scaled)
      : rod_(rod), c_(c), scaled_(scaled) {}

  Matrix6d at(int i, double s) const {
    const PoseDerivatives d = pose_between_nodes(rod_, c_, i, s);
    return scaled_(d.dp_dw, d.dtheta_dw, d.pose.rotation, s);
  }

 private:
  const ClampedRod& rod_;
  const RodConfiguration& c_;
  const ScaledJacobian& scaled_;
};

void check_configuration(const ClampedRod& rod, const RodConfiguration& c) {
  if (c.derivatives != Derivatives::AllNodes || static_cast<int>(c.dp_dw.size()) != c.nodes())
    throw InputError(
        "assess_stability needs a configuration integrated with Derivatives::AllNodes");
  if (c.nodes() != rod.nodes())
    throw InputError("assess_stability: the configuration has " + std::to_string(c.nodes()) +
                     " nodes, the rod " + std::to_string(rod.nodes()));
}

/// σ_min and det of the scaled Jacobian J̃(s_i) at every node (index 0 unused: J̃(0) = 0).
struct NodeJacobians {
  std::vector<double> sigma, det;
};

NodeJacobians node_jacobians(const RodConfiguration& c, const ScaledJacobian& scaled_jacobian) {
  const int N = c.nodes() - 1;
  NodeJacobians nodes{std::vector<double>(N + 1, 0.0), std::vector<double>(N + 1, 0.0)};
  for (int i = 1; i <= N; ++i) {
    const Matrix6d J = scaled_jacobian(c.dp_dw[i], c.dtheta_dw[i], c.R[i], c.s[i]);
    nodes.sigma[i] = smallest_singular_value(J);
    nodes.det[i] = J.determinant();
  }
  return nodes;
}

/// 1. det J̃ > 0 near s = 0 (J̃ → I for a Cosserat rod); a change from positive to non-positive
///    between nodes i-1 and i is a conjugate point: bisect on the sign. Near s = 0 the det of a
///    curved Kirchhoff rod is of high order in s (its axial compliance vanishes) and one step may
///    not resolve its sign, so the test is armed only once det J̃ has been positive at a node.
///    Returns the first node with det J̃ > 0 (0: never, the test cannot decide).
int sign_change_test(const ClampedRod& rod,
                     const RodConfiguration& c,
                     const NodeJacobians& nodes,
                     const JacobianBetweenNodes& between,
                     std::optional<double>& conjugate) {
  const int N = c.nodes() - 1;
  int armed_at = 0;
  for (int i = 1; i <= N && !conjugate; ++i) {
    if (armed_at == 0) {
      if (nodes.det[i] > 0.0) armed_at = i;
      continue;
    }
    if (nodes.det[i] > 0.0) continue;
    double a = c.s[i - 1], b = c.s[i];
    for (int k = 0; k < 60 && b - a > 1e-12 * rod.properties.length; ++k) {
      const double mid = 0.5 * (a + b);
      (between.at(i - 1, mid).determinant() > 0.0 ? a : b) = mid;
    }
    conjugate = 0.5 * (a + b);
  }
  return armed_at;
}

/// Golden-section search for the least σ_min of J̃ on (a, b), interpolated from node `from`, to
/// 1e-12 L. Returns (s, σ) at the least value found.
std::pair<double, double> golden_least_sigma(
    const ClampedRod& rod, const JacobianBetweenNodes& between, int from, double a, double b) {
  const auto sigma_at = [&](double s) { return smallest_singular_value(between.at(from, s)); };
  const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
  double x1 = b - golden * (b - a), x2 = a + golden * (b - a);
  double f1 = sigma_at(x1), f2 = sigma_at(x2);
  for (int k = 0; k < 60 && b - a > 1e-12 * rod.properties.length; ++k) {
    if (f1 < f2) {
      b = x2, x2 = x1, f2 = f1;
      x1 = b - golden * (b - a);
      f1 = sigma_at(x1);
    } else {
      a = x1, x1 = x2, f1 = f2;
      x2 = a + golden * (b - a);
      f2 = sigma_at(x2);
    }
  }
  return f1 < f2 ? std::pair{x1, f1} : std::pair{x2, f2};
}

/// The least σ_min of J̃ on (a, b). A smooth minimum well above the conjugate tolerance is found by
/// Brent's parabolic search (Boost.Math) with s to half the digits: σ there is within
/// σ'' δs² ≈ 1e-12 of its neighbours' scale of the least value, in about 10 evaluations where the
/// golden section takes about 50. Near a root σ_min is V-shaped (|s - s*|), and s to half the
/// digits leaves σ only within about 1e-6 of the scale, the conjugate tolerance itself: a least
/// value below kRefineBelow of the scale, or a search that did not converge, is searched again by
/// the golden section to 1e-12 L.
std::pair<double, double> least_sigma(const ClampedRod& rod,
                                      const JacobianBetweenNodes& between,
                                      int from,
                                      double a,
                                      double b,
                                      double scale) {
  constexpr double kRefineBelow = 1e-3;
  constexpr std::uintmax_t kMaxIterations = 60;
  const auto sigma_at = [&](double s) { return smallest_singular_value(between.at(from, s)); };
  std::uintmax_t iterations = kMaxIterations;
  const auto [s, f] = boost::math::tools::brent_find_minima(
      sigma_at, a, b, std::numeric_limits<double>::digits / 2, iterations);
  if (iterations < kMaxIterations && f > kRefineBelow * scale) return {s, f};
  return golden_least_sigma(rod, between, from, a, b);
}

/// 2. A local minimum of σ_min at a node: golden-section search on (s_{i-1}, s_{i+1}) for a root
///    that keeps the sign of det (a double root, as when EIx = EIy), or two roots within one
///    interval. Only after the test is armed: before, J̃ is not resolved (and σ_min may grow
///    from 0).
void minimum_test(const ClampedRod& rod,
                  const RodConfiguration& c,
                  const NodeJacobians& nodes,
                  const JacobianBetweenNodes& between,
                  int armed_at,
                  StabilityResult& report,
                  std::optional<double>& conjugate) {
  const int N = c.nodes() - 1;
  const std::vector<double>& sigma = nodes.sigma;
  for (int i = armed_at + 1; i <= N && !conjugate; ++i) {
    const bool left_ok = sigma[i] <= sigma[i - 1];
    const bool right_ok = i == N || sigma[i] <= sigma[i + 1];
    if (!left_ok || !right_ok) continue;
    // Relative to its neighbours: a root drives σ_min to round-off, while a rod that is nearly
    // inextensible (EA, GA ≫ EI/L²) has a small but smooth σ_min near the clamp, whose size
    // depends on EA L²/EI (about 1e-5 for the band at E ≥ 1e11) and not on a conjugate point.
    const double scale = std::max(sigma[i - 1], i == N ? sigma[i] : sigma[i + 1]);
    if (sigma[i] <= kConjugateTolerance * scale) {
      conjugate = c.s[i];
      break;
    }
    const auto [s_min, f_min] =
        least_sigma(rod, between, i - 1, c.s[i - 1], i == N ? c.s[N] : c.s[i + 1], scale);
    report.min_singular_value = std::min(report.min_singular_value, f_min);
    if (f_min <= kConjugateTolerance * scale) conjugate = s_min;
  }
}

}  // namespace

StabilityResult assess_stability(const ClampedRod& rod, const RodConfiguration& c) {
  check_configuration(rod, c);
  const ScaledJacobian scaled_jacobian(rod.properties, c.R[0]);
  const NodeJacobians nodes = node_jacobians(c, scaled_jacobian);
  const int N = c.nodes() - 1;

  StabilityResult report;
  report.tip_singular_value = nodes.sigma[N];
  report.min_singular_value = *std::min_element(nodes.sigma.begin() + 1, nodes.sigma.end());
  int singular_nodes = 0;
  for (int i = 1; i <= N; ++i) singular_nodes += nodes.sigma[i] <= kConjugateTolerance;
  if (2 * singular_nodes > N) {
    report.degenerate = true;  // (stable stays false)
    return report;
  }

  const JacobianBetweenNodes between(rod, c, scaled_jacobian);
  std::optional<double> conjugate;
  const int armed_at = sign_change_test(rod, c, nodes, between, conjugate);
  if (armed_at == 0) {         // det J̃ never positive: the test cannot decide
    report.degenerate = true;  // (stable stays false)
    return report;
  }
  minimum_test(rod, c, nodes, between, armed_at, report, conjugate);

  report.conjugate_point_s = conjugate;
  report.stable = !conjugate.has_value();
  if (conjugate) report.min_singular_value = 0.0;
  // Singular only at s = L: the equilibrium is degenerate (e.g. the planar buckled shape of a rod
  // with EIx = EIy, which can turn about the line of its clamps at no cost): neutral, not shown
  // stable, and not unstable either.
  if (conjugate && *conjugate >= rod.properties.length * (1.0 - 1e-9)) report.degenerate = true;
  return report;
}

StabilityResult assess_stability(const ClampedRod& rod,
                                 const RodConfiguration& c,
                                 const TipCondition& tip) {
  StabilityResult report = assess_stability(rod, c);
  std::array<bool, 6> free{};
  Eigen::Matrix3d grasp = Eigen::Matrix3d::Identity();
  if (std::holds_alternative<FreeTip>(tip)) free.fill(true);
  if (const auto* grasped = std::get_if<GraspedTip>(&tip)) {
    free = grasped->released;
    grasp = grasped->pose.rotation;
  }
  const bool any_free = std::find(free.begin(), free.end(), true) != free.end();
  if (!any_free || !report.stable) return report;
  constexpr double kNeutral = 1e-9;  // |λ| below this: a direction of (nearly) zero stiffness
  const double lambda = tip_stiffness_eigenvalue(rod, c, grasp, free);
  report.tip_stiffness_eigenvalue = lambda;
  report.stable = lambda > kNeutral;
  report.degenerate = !(std::abs(lambda) > kNeutral);  // NaN included
  return report;
}

std::string StabilityResult::brief() const {
  std::ostringstream out;
  out.precision(3);
  if (stable) {
    out << "stable (min σ̃ = " << min_singular_value << ", at the tip " << tip_singular_value << ")";
  } else if (conjugate_point_s) {
    out << "unstable: conjugate point at s = " << *conjugate_point_s << " m";
  } else if (tip_stiffness_eigenvalue && !degenerate) {
    out << "unstable: the free tip's stiffness has eigenvalue " << *tip_stiffness_eigenvalue
        << " <= 0 (it can move with no restoring wrench)";
  } else if (degenerate) {
    out << "not shown stable: degenerate (J singular along the rod or only at the tip)";
  } else {
    out << "not shown stable (min σ̃ = " << min_singular_value << ")";
  }
  return out.str();
}

}  // namespace rodshape
