// moving_base_problem.cpp: ShapeProblem with a moving base (base_motion.hpp). One integration with
// the wrench's derivatives and the base pose's (base_pose_derivatives), then, with B =
// blockdiag(R(0), R(0)) (w = B w_b) and J = blockdiag(I, J_l(δφ)) (exp([δφ + ε]×) ≈
// exp([J_l(δφ) ε]×) exp([δφ]×): the world-frame turn of a change ε of δφ),
//   ∇_x F = (Bᵀ ∇_w F, Jᵀ ∇_ξ F + ∇ motion term),   dg/dx = (dg/dw B, dg/dξ J).
// Every block is linear in the configuration's derivative arrays (the chain rule), so evaluated on
// the configuration of base_pose_derivatives it gives dg/dξ.
#include <Eigen/Cholesky>
#include <cmath>

#include "optimisation/blocks/constraint_blocks.hpp"
#include "rodshape/core/base_pose_derivatives.hpp"
#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/core/so3.hpp"
#include "rodshape/optimisation/shape_problem.hpp"
#include "validation.hpp"

namespace rodshape {

void BaseMotion::validate() const {
  detail::require_pose("BaseMotion.reference", reference);
  workspace.validate();
  detail::require_non_negative("BaseMotion.motion_weight", motion_weight);
  for (int k = 0; k < 6; ++k)
    if (std::isnan(wrench_bounds.lower(k)) || std::isnan(wrench_bounds.upper(k)) ||
        wrench_bounds.lower(k) > wrench_bounds.upper(k))
      throw InputError("BaseMotion.wrench_bounds",
                       ": component " + std::to_string(k) + " has lower above upper, or NaN");
}

void ShapeProblem::move_base(BaseMotion motion) {
  motion.validate();
  base_motion_ = std::move(motion);
  rod_.clamp = base_motion_->reference;
  blocks_.push_back(blocks::base_workspace(base_motion_->workspace));
  rows_.base = blocks_.back()->rows();
  const int old_count = constraint_count_;
  constraint_count_ += rows_.base;
  g_lower_.conservativeResize(constraint_count_);
  g_upper_.conservativeResize(constraint_count_);
  blocks_.back()->bounds(g_lower_.segment(old_count, rows_.base),
                         g_upper_.segment(old_count, rows_.base));
  g_ = Eigen::VectorXd::Zero(constraint_count_);
  dg_dw_ = Eigen::MatrixXd::Zero(constraint_count_, 6);
  dg_dxi_ = Eigen::MatrixXd::Zero(constraint_count_, 6);
  dg_dx_ = Eigen::MatrixXd::Zero(constraint_count_, 12);
  gradient_x_ = Eigen::VectorXd::Zero(12);
  pose_tangent_.resize(rod_.nodes(), Derivatives::AllNodes);
  evaluated_ = false;
}

void ShapeProblem::set_base_reference(const Pose& reference) {
  detail::require_pose("BaseMotion.reference", reference);
  base_motion_->reference = reference;
  rod_.clamp = reference;
  evaluated_ = false;
}

Pose ShapeProblem::base_pose(const Vector12d& x) const {
  const Pose& reference = base_motion_->reference;
  return {reference.position + x.segment<3>(6), exp_so3(x.segment<3>(9)) * reference.rotation};
}

BaseWrench ShapeProblem::world_wrench(const Vector12d& x) const {
  const Eigen::Matrix3d R0 = base_pose(x).rotation;
  return {R0 * x.segment<3>(0), R0 * x.segment<3>(3)};
}

Vector12d ShapeProblem::variables_at_reference(const BaseWrench& w) const {
  const Eigen::Matrix3d& R0 = base_motion_->reference.rotation;
  Vector12d x = Vector12d::Zero();
  x << R0.transpose() * w.force, R0.transpose() * w.moment, Eigen::Vector3d::Zero(),
      Eigen::Vector3d::Zero();
  return x;
}

Vector12d ShapeProblem::variable_lower() const {
  Vector12d lower;
  const BaseMotion& motion = *base_motion_;
  for (int k = 0; k < 6; ++k) lower[k] = motion.released[k] ? 0.0 : motion.wrench_bounds.lower(k);
  lower.segment<3>(6).setConstant(-std::numeric_limits<double>::infinity());
  lower.segment<3>(9).setConstant(-BaseMotion::kMaxTurn);
  return lower;
}

Vector12d ShapeProblem::variable_upper() const {
  Vector12d upper;
  const BaseMotion& motion = *base_motion_;
  for (int k = 0; k < 6; ++k) upper[k] = motion.released[k] ? 0.0 : motion.wrench_bounds.upper(k);
  upper.segment<3>(6).setConstant(std::numeric_limits<double>::infinity());
  upper.segment<3>(9).setConstant(BaseMotion::kMaxTurn);
  return upper;
}

void ShapeProblem::set_clamp(const Vector12d& x) { rod_.clamp = base_pose(x); }

Vector6d ShapeProblem::distance_gradient_sum(const RodConfiguration& derivatives) const {
  Vector6d sum = Vector6d::Zero();
  if (target_.distance_weight == 0.0) return sum;
  for (std::size_t k = 0; k < target_.points.size(); ++k) {
    const double d = breakdown_.distances[k];
    sum += distance_term_slope(d) *
           distance_gradient(rod_, derivatives, projections_[k], target_.points[k]).transpose();
  }
  return sum;
}

void ShapeProblem::evaluate_with_base(const Vector12d& x) {
  if (evaluated_ && x == x_) return;
  x_ = x;
  set_clamp(x);
  const Eigen::Matrix3d& R0 = rod_.clamp.rotation;
  const BaseWrench w{R0 * x.segment<3>(0), R0 * x.segment<3>(3)};  // world_wrench(x), R0 once
  integrate(rod_, w, configuration_, Derivatives::AllNodes);
  base_pose_derivatives(rod_, configuration_, pose_tangent_);
  evaluate_cost();  // F, ∇_w F (world wrench), the projections
  evaluate_moving_constraints();
  const double L = rod_.properties.length;
  const double W1 = target_.energy_weight;
  gradient_xi_ =
      (W1 / L) * pose_tangent_.denergy_dw.transpose() + distance_gradient_sum(pose_tangent_);
  // The motion term W_b W2 (|δt|² + L² |δφ|²) / L.
  const double Wb = base_motion_->motion_weight * target_.distance_weight;
  const Eigen::Vector3d dt = x.segment<3>(6), dphi = x.segment<3>(9);
  const double motion = Wb * (dt.squaredNorm() + L * L * dphi.squaredNorm()) / L;
  breakdown_.cost += motion;
  const Eigen::Matrix3d J = left_jacobian_so3(dphi);
  gradient_x_.segment<3>(0) = R0.transpose() * cost_gradient_.head<3>();
  gradient_x_.segment<3>(3) = R0.transpose() * cost_gradient_.tail<3>();
  gradient_x_.segment<3>(6) = gradient_xi_.head<3>() + (2.0 * Wb / L) * dt;
  gradient_x_.segment<3>(9) = J.transpose() * gradient_xi_.tail<3>() + (2.0 * Wb * L) * dphi;
  w_ = w.to_vector();
  evaluated_ = true;
}

void ShapeProblem::evaluate_moving_constraints() {
  const Eigen::Matrix3d& R0 = rod_.clamp.rotation;
  const Eigen::Matrix3d J = left_jacobian_so3(x_.segment<3>(9));
  int row = 0;
  for (const auto& block : blocks_) {
    const int rows = block->rows();
    if (rows > 0) {
      block->evaluate(configuration_, g_.segment(row, rows), dg_dw_.middleRows(row, rows));
      block->evaluate(pose_tangent_, g_.segment(row, rows), dg_dxi_.middleRows(row, rows));
    }
    row += rows;
  }
  dg_dx_.leftCols<3>().noalias() = dg_dw_.leftCols<3>() * R0;
  dg_dx_.middleCols<3>(3).noalias() = dg_dw_.middleCols<3>(3) * R0;
  dg_dx_.middleCols<3>(6) = dg_dxi_.leftCols<3>();
  dg_dx_.rightCols<3>().noalias() = dg_dxi_.rightCols<3>() * J;
}

bool ShapeProblem::rigid_alignment_applies() const {
  return base_motion_ && rod_.load.force.isZero(0.0) && rod_.load.moment.isZero(0.0) &&
         target_.distance_weight > 0.0 &&
         (target_.squared_distances || target_.distance_smoothing > 0.0);
}

namespace {
/// align_base() stops at |∂F/∂ξ̃|∞ below this (ξ̃ = (δt / L, δφ)).
constexpr double kAlignedGradient = 1e-12;
}  // namespace

double ShapeProblem::aligned_cost(const Vector6d& xi_scaled,
                                  Vector6d* gradient,
                                  Eigen::Matrix<double, 6, 6>* hessian) {
  const double L = rod_.properties.length;
  const Pose& reference = base_motion_->reference;
  const Eigen::Vector3d dt = L * xi_scaled.head<3>(), dphi = xi_scaled.tail<3>();
  const Eigen::Matrix3d R0 = exp_so3(dphi) * reference.rotation;
  const Eigen::Matrix3d Jl = left_jacobian_so3(dphi);
  const Eigen::Vector3d p0 = reference.position + dt;
  const double Wb = base_motion_->motion_weight * target_.distance_weight;
  const double W2 = target_.distance_weight, delta = target_.distance_smoothing;
  double cost = Wb * (dt.squaredNorm() + L * L * dphi.squaredNorm()) / L;
  Vector6d g = Vector6d::Zero();
  g << 2.0 * Wb * dt, (2.0 * Wb * L) * dphi;  // in ξ̃ = (δt / L, δφ)
  Eigen::Matrix<double, 6, 6> H = (2.0 * Wb * L) * Eigen::Matrix<double, 6, 6>::Identity();
  for (const Eigen::Vector3d& point : target_.points) {
    // The point in the base's frame, q = R0ᵀ (p - p0), and its distance to the body-frame curve.
    const Eigen::Vector3d q = R0.transpose() * (point - p0);
    const CurveProjection projection = project_onto_curve(body_, q, body_balls_);
    const double d = projection.distance;
    cost += W2 * distance_penalty(d);
    if (gradient == nullptr) continue;
    // The closest point c moves with the base by J ξ̃, J = [L I, -[c - p0]× J_l] (world); d(dist)
    // = -n̂ · dc with n̂ the unit normal from c to the point (c's own motion along the curve is
    // normal to it).
    Eigen::Matrix<double, 3, 6> J;
    J << L * Eigen::Matrix3d::Identity(), -hat(R0 * projection.closest) * Jl;
    const double slope = distance_term_slope(d);  // W2 ρ'(d)
    Eigen::Vector3d normal = Eigen::Vector3d::Zero();
    if (d > 0.0) {
      normal = R0 * (q - projection.closest) / d;
      g -= slope * (J.transpose() * normal);
    }
    if (hessian == nullptr) continue;
    // Gauss–Newton in the normal plane of the curve: W2 ρ'' along n̂, W2 ρ'/d across it.
    const int node =
        std::min(projection.interval + (projection.t > 0.5 ? 1 : 0), body_.nodes() - 1);
    const Eigen::Vector3d tangent = (R0 * (body_.R[node] * body_.v[node])).normalized();
    double along = 0.0, across = 0.0;
    if (target_.squared_distances) {
      along = across = 2.0 * W2;
    } else if (delta > 0.0) {
      const double root = std::sqrt(d * d + delta * delta);
      along = W2 * delta * delta / (root * root * root);
      across = W2 / root;
    } else if (d > 0.0) {
      across = W2 / d;
    }
    const Eigen::Matrix3d across_plane =
        Eigen::Matrix3d::Identity() - tangent * tangent.transpose() - normal * normal.transpose();
    const Eigen::Matrix3d M = along * normal * normal.transpose() + across * across_plane;
    H.noalias() += J.transpose() * M * J;
  }
  if (gradient != nullptr) *gradient = g;
  if (hessian != nullptr) *hessian = 0.5 * (H + H.transpose());
  return cost;
}

bool ShapeProblem::align_base(const Vector6d& w_b, Vector6d& xi) {
  ClampedRod body = rod_;
  body.clamp = Pose{};
  integrate(body, BaseWrench::from_vector(w_b), body_, Derivatives::None);
  interval_balls(body_, body_balls_);
  const double L = rod_.properties.length;
  using Matrix6 = Eigen::Matrix<double, 6, 6>;
  Vector6d at;
  at << xi.head<3>() / L, xi.tail<3>();
  Vector6d gradient;
  Matrix6 hessian;
  double cost = aligned_cost(at, &gradient, &hessian);
  if (!std::isfinite(cost) || !gradient.allFinite() || !hessian.allFinite()) return false;
  // Gauss–Newton steps from the last ξ*, to a gradient at the rounding level of F's: ξ* enters
  // the reduced gradient through H_wξ δξ. Shifted towards a gradient step until it descends.
  for (int iteration = 0; iteration < 100; ++iteration) {
    if (gradient.lpNorm<Eigen::Infinity>() <= kAlignedGradient) break;
    double shift = 0.0;
    bool moved = false;
    for (int trial = 0; trial < 12 && !moved; ++trial) {
      const Eigen::LDLT<Matrix6> ldlt(hessian + shift * Matrix6::Identity());
      const Vector6d step = -ldlt.solve(gradient);
      if (ldlt.isPositive() && step.allFinite()) {
        Vector6d next_gradient;
        Matrix6 next_hessian;
        const double next_cost = aligned_cost(at + step, &next_gradient, &next_hessian);
        // Armijo, or, where F's differences are at its rounding, a gradient that falls.
        const bool descends =
            next_cost <= cost + 1e-4 * gradient.dot(step) ||
            (next_cost <= cost + 1e-14 * std::abs(cost) &&
             next_gradient.lpNorm<Eigen::Infinity>() < 0.5 * gradient.lpNorm<Eigen::Infinity>());
        if (std::isfinite(next_cost) && next_gradient.allFinite() && next_hessian.allFinite() &&
            descends) {
          at += step;
          cost = next_cost;
          gradient = next_gradient;
          hessian = next_hessian;
          moved = true;
        }
      }
      const double top = std::max(1.0, hessian.diagonal().cwiseAbs().maxCoeff());
      shift = shift == 0.0 ? 1e-8 * top : 10.0 * shift;
    }
    if (!moved) break;  // no descent left: at the minimiser to rounding
  }
  xi << L * at.head<3>(), at.tail<3>();
  return gradient.lpNorm<Eigen::Infinity>() <= 1e-6;
}

}  // namespace rodshape
