// shape_problem.cpp: F(w), ∇F(w), g(w) and dg/dw from one integration with all-node derivatives.
//
// Rows of g, in this order (constraint_count() in all):
//  1. workspace, on the tip pose (p(L), R(L)): g_ws, d/dw = dg_ws/dp · tip_dp_dw
//     + dg_ws/dθ · tip_dtheta_dw (only the reach shell depends on R(L));
//  2. grasp, one per true entry of Grasp::released (force x, y, z, then moment x, y, z): the tip
//     wrench in the tip frame, e_kᵀ R(L)ᵀ n(L) or e_kᵀ R(L)ᵀ m(L), bounds [0, 0];
//     δ(Rᵀn) = (Rᵀn) × θ_L + Rᵀ δn (δR = R θ̂);
//  3. curvature, one per node when limits.max_curvature is set: |u_i - ũ|² ≤ κ², with
//     u - ũ = K_rot⁻¹ m̄, m̄ = Rᵀm, so d/dw = 2 (u - ũ)ᵀ K_rot⁻¹ (m̄ × θ + Rᵀ δm);
//  4. axial strain, one per node when limits.max_axial_strain is set and the model is Cosserat:
//     v_z - ṽ_z = (K_tra⁻¹ n̄)_z ∈ [-ε, ε], d/dw = e_zᵀ K_tra⁻¹ (n̄ × θ + Rᵀ δn). The Kirchhoff
//     model cannot stretch (v = ṽ): no rows.
// Cost: F = W1 E / L + W2 Σ ρ(dist_k), ∇F = W1/L dE/dw + W2 Σ ρ'(dist_k) ∇dist_k, with
// ρ(d) = sqrt(d² + δ²) - δ (δ = ShapeTarget::distance_smoothing: the paper's sum of distances made
// smooth where a point is reached, which an interior-point method needs to certify an optimum), or
// ρ(d) = d (δ = 0: the exact form; ∇dist is taken as 0 at dist = 0, a subgradient), or ρ(d) = d²
// (squared_distances).
#include "rodshape/optimisation/shape_problem.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/core/so3.hpp"
#include "validation.hpp"

namespace rodshape {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

void validate_wrench_bounds(const WrenchBounds& bounds) {
  static const char* const kNames[6] = {"force.x",  "force.y",  "force.z",
                                        "moment.x", "moment.y", "moment.z"};
  for (int k = 0; k < 6; ++k) {
    const std::string field = std::string("WrenchBounds.") + kNames[k];
    if (std::isnan(bounds.lower(k)) || std::isnan(bounds.upper(k)))
      throw InputError(field, ": a bound is NaN");
    if (bounds.lower(k) > bounds.upper(k)) {
      throw InputError(field, ": lower = " + detail::format_value(bounds.lower(k)) +
                                  " is above upper = " + detail::format_value(bounds.upper(k)));
    }
  }
}

int count_true(const std::array<bool, 6>& flags) {
  return static_cast<int>(std::count(flags.begin(), flags.end(), true));
}

}  // namespace

ShapeProblem::ShapeProblem(ClampedRod rod,
                           ShapeTarget target,
                           Workspace workspace,
                           Grasp grasp,
                           StrainLimits limits,
                           WrenchBounds wrench_bounds)
    : rod_(std::move(rod)),
      target_(std::move(target)),
      workspace_(std::move(workspace)),
      grasp_(std::move(grasp)),
      limits_(std::move(limits)),
      wrench_bounds_(std::move(wrench_bounds)) {
  rod_.validate();
  target_.validate();
  workspace_.validate();
  limits_.validate();
  validate_wrench_bounds(wrench_bounds_);
  detail::require_pose("Grasp.tip_to_end_effector", grasp_.tip_to_end_effector);

  const int nodes = rod_.nodes();
  rows_.workspace = workspace_.constraint_count();
  rows_.grasp = count_true(grasp_.released);
  rows_.curvature = limits_.max_curvature ? nodes : 0;
  rows_.axial =
      limits_.max_axial_strain && rod_.properties.model == ConstitutiveModel::Cosserat ? nodes : 0;
  constraint_count_ = rows_.workspace + rows_.grasp + rows_.curvature + rows_.axial;

  g_lower_.resize(constraint_count_);
  g_upper_.resize(constraint_count_);
  workspace_.bounds(g_lower_.head(rows_.workspace), g_upper_.head(rows_.workspace));
  int row = rows_.workspace;
  g_lower_.segment(row, rows_.grasp).setZero();
  g_upper_.segment(row, rows_.grasp).setZero();
  row += rows_.grasp;
  if (rows_.curvature > 0) {
    const double kappa = *limits_.max_curvature;
    g_lower_.segment(row, rows_.curvature).setConstant(-kInf);
    g_upper_.segment(row, rows_.curvature).setConstant(kappa * kappa);
    row += rows_.curvature;
  }
  if (rows_.axial > 0) {
    g_lower_.segment(row, rows_.axial).setConstant(-*limits_.max_axial_strain);
    g_upper_.segment(row, rows_.axial).setConstant(*limits_.max_axial_strain);
  }

  // Every buffer evaluate() writes, sized once.
  configuration_.resize(nodes, Derivatives::AllNodes);
  const std::size_t points = target_.points.size();
  projections_.resize(points);
  balls_.resize(static_cast<std::size_t>(rod_.intervals));
  breakdown_.distances.assign(points, 0.0);
  g_ = Eigen::VectorXd::Zero(constraint_count_);
  dg_dw_ = Eigen::MatrixXd::Zero(constraint_count_, 6);
  workspace_dg_dp_ = Eigen::MatrixXd::Zero(rows_.workspace, 3);
  workspace_dg_dtheta_ = Eigen::MatrixXd::Zero(rows_.workspace, 3);
}

void ShapeProblem::evaluate(const Vector6d& w) {
  if (evaluated_ && w == w_) return;
  integrate(rod_, BaseWrench::from_vector(w), configuration_, Derivatives::AllNodes);
  evaluate_cost();
  evaluate_constraints();
  w_ = w;
  evaluated_ = true;
}

double ShapeProblem::constraint_violation() const {
  double violation = 0.0;
  for (Eigen::Index i = 0; i < g_.size(); ++i) {
    if (!std::isfinite(g_(i))) return std::numeric_limits<double>::infinity();
    violation = std::max({violation, g_(i) - g_upper_(i), g_lower_(i) - g_(i)});
  }
  for (int j = 0; j < 6; ++j)
    violation =
        std::max({violation, w_(j) - wrench_bounds_.upper(j), wrench_bounds_.lower(j) - w_(j)});
  return violation;
}

void ShapeProblem::evaluate_cost() {
  const RodConfiguration& c = configuration_;
  const double L = rod_.properties.length;
  const double W1 = target_.energy_weight, W2 = target_.distance_weight;
  breakdown_.energy = c.energy;
  breakdown_.energy_term = W1 * c.energy / L;
  cost_gradient_ = (W1 / L) * c.denergy_dw.transpose();
  double distance_term = 0.0;
  breakdown_.max_distance = 0.0;
  interval_balls(c, balls_);  // once for all the points
  for (std::size_t k = 0; k < target_.points.size(); ++k) {
    const Eigen::Vector3d& point = target_.points[k];
    projections_[k] = project_onto_curve(c, point, balls_);
    const double d = projections_[k].distance;
    breakdown_.distances[k] = d;
    breakdown_.max_distance = std::max(breakdown_.max_distance, d);
    if (W2 == 0.0) continue;
    const Eigen::Matrix<double, 1, 6> gradient = distance_gradient(rod_, c, projections_[k], point);
    if (target_.squared_distances) {
      distance_term += d * d;
      cost_gradient_ += (2.0 * W2 * d) * gradient.transpose();
    } else if (target_.distance_smoothing > 0.0) {
      // pseudo-Huber: ρ(d) = sqrt(d² + δ²) - δ, ρ'(d) = d / sqrt(d² + δ²)
      const double delta = target_.distance_smoothing;
      const double root = std::sqrt(d * d + delta * delta);
      distance_term += root - delta;
      cost_gradient_ += (W2 * d / root) * gradient.transpose();
    } else {
      distance_term += d;
      cost_gradient_ += W2 * gradient.transpose();
    }
  }
  breakdown_.distance_term = W2 * distance_term;
  breakdown_.cost = breakdown_.energy_term + breakdown_.distance_term;
}

void ShapeProblem::evaluate_constraints() {
  const RodConfiguration& c = configuration_;
  const int N = c.nodes() - 1;
  int row = 0;
  // 1. workspace
  if (rows_.workspace > 0) {
    workspace_.evaluate(Pose{c.p[N], c.R[N]}, g_.head(rows_.workspace), workspace_dg_dp_,
                        workspace_dg_dtheta_);
    dg_dw_.topRows(rows_.workspace) = workspace_dg_dp_.lazyProduct(c.tip_dp_dw);  // no GEMM buffers
    if (workspace_.reach)
      dg_dw_.topRows(rows_.workspace) += workspace_dg_dtheta_.lazyProduct(c.tip_dtheta_dw);
    row += rows_.workspace;
  }
  // 2. grasp: the tip wrench in the tip frame
  if (rows_.grasp > 0) {
    const Eigen::Matrix3d& R = c.R[N];
    const Matrix36d& theta = c.tip_dtheta_dw;
    const Eigen::Vector3d n_body = R.transpose() * c.n[N];
    const Eigen::Vector3d m_body = R.transpose() * c.m[N];
    const Matrix36d dn_body = hat(n_body) * theta + R.transpose() * c.tip_dn_dw;
    const Matrix36d dm_body = hat(m_body) * theta + R.transpose() * c.tip_dm_dw;
    for (int k = 0; k < 6; ++k) {
      if (!grasp_.released[k]) continue;
      g_(row) = k < 3 ? n_body(k) : m_body(k - 3);
      dg_dw_.row(row) = k < 3 ? dn_body.row(k) : dm_body.row(k - 3);
      ++row;
    }
  }
  // 3. curvature at every node
  if (rows_.curvature > 0) {
    const Eigen::Vector3d C_rot = rod_.properties.K_rot.cwiseInverse();
    for (int i = 0; i <= N; ++i, ++row) {
      const Eigen::Matrix3d& R = c.R[i];
      const Eigen::Vector3d m_body = R.transpose() * c.m[i];
      // u - ũ = K_rot⁻¹ m̄, computed from m̄ rather than as c.u[i] - ũ: no cancellation against ũ
      const Eigen::Vector3d du = C_rot.cwiseProduct(m_body);
      const Matrix36d dm_body = hat(m_body) * c.dtheta_dw[i] + R.transpose() * c.dm_dw[i];
      g_(row) = du.squaredNorm();
      dg_dw_.row(row) = 2.0 * du.cwiseProduct(C_rot).transpose() * dm_body;
    }
  }
  // 4. axial strain at every node (Cosserat)
  if (rows_.axial > 0) {
    const double c_axial = 1.0 / rod_.properties.K_tra.z();
    for (int i = 0; i <= N; ++i, ++row) {
      const Eigen::Matrix3d& R = c.R[i];
      const Eigen::Vector3d n_body = R.transpose() * c.n[i];
      const Matrix36d dn_body = hat(n_body) * c.dtheta_dw[i] + R.transpose() * c.dn_dw[i];
      g_(row) = c_axial * n_body.z();  // v_z - ṽ_z, without the cancellation against ṽ_z ≈ 1
      dg_dw_.row(row) = c_axial * dn_body.row(2);
    }
  }
}

}  // namespace rodshape
