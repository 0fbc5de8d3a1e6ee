// moving_base_problem.cpp: ShapeProblem with a moving base (base_motion.hpp). One integration with
// the wrench's derivatives and the base pose's (base_pose_derivatives), then, with B =
// blockdiag(R(0), R(0)) (w = B w_b) and J = blockdiag(I, J_l(δφ)) (exp([δφ + ε]×) ≈
// exp([J_l(δφ) ε]×) exp([δφ]×): the world-frame turn of a change ε of δφ),
//   ∇_x F = (Bᵀ ∇_w F, Jᵀ ∇_ξ F + ∇ motion term),   dg/dx = (dg/dw B, dg/dξ J).
// Every block is linear in the configuration's derivative arrays (the chain rule), so evaluated on
// the configuration of base_pose_derivatives it gives dg/dξ.
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

}  // namespace rodshape
