#include "rodshape/solvers/shooting_residual.hpp"

#include "overloaded.hpp"
#include "rodshape/core/so3.hpp"

namespace rodshape {

namespace {

using detail::Overloaded;

/// Residual and (optionally) Jacobian of a held tip; `released` axes use the tip wrench instead.
void held_tip_residual(const Pose& target,
                       const std::array<bool, 6>& released,
                       const RodConfiguration& c,
                       Vector6d& r,
                       Matrix6d* J) {
  const Eigen::Matrix3d& R_d = target.rotation;
  const Eigen::Matrix3d R_dT = R_d.transpose();
  // position error in the grasp frame: R_dᵀ (p(L) - p_d)
  r.head<3>() = R_dT * (c.p.back() - target.position);
  // rotation error: θ = log(R_dᵀ R(L)); δR = R δ̂ gives δθ = J_r⁻¹(θ) δ
  const Eigen::Vector3d theta = log_so3(R_dT * c.R.back());
  r.tail<3>() = theta;
  if (J) {
    J->topRows<3>() = R_dT * c.tip_dp_dw;
    J->bottomRows<3>() = right_jacobian_inverse_so3(theta) * c.tip_dtheta_dw;
  }
  const Eigen::Vector3d force_grasp = R_dT * c.n.back();
  const Eigen::Vector3d moment_grasp = R_dT * c.m.back();
  for (int i = 0; i < 3; ++i) {
    if (released[i]) {
      r[i] = force_grasp[i];
      if (J) J->row(i) = R_dT.row(i) * c.tip_dn_dw;
    }
    if (released[3 + i]) {
      r[3 + i] = moment_grasp[i];
      if (J) J->row(3 + i) = R_dT.row(i) * c.tip_dm_dw;
    }
  }
}

void residual_of(const TipCondition& condition,
                 const RodConfiguration& c,
                 Vector6d& r,
                 Matrix6d* J) {
  std::visit(Overloaded{
                 [&](const FreeTip& tip) {
                   // n(L) = F, m(L) = M
                   r.head<3>() = c.n.back() - tip.wrench.force;
                   r.tail<3>() = c.m.back() - tip.wrench.moment;
                   if (J) *J << c.tip_dn_dw, c.tip_dm_dw;
                 },
                 [&](const ClampedTip& tip) { held_tip_residual(tip.pose, {}, c, r, J); },
                 [&](const GraspedTip& tip) { held_tip_residual(tip.pose, tip.released, c, r, J); },
             },
             condition);
}

}  // namespace

Vector6d shooting_residual(const TipCondition& condition, const RodConfiguration& configuration) {
  Vector6d r;
  residual_of(condition, configuration, r, nullptr);
  return r;
}

void shooting_residual(const TipCondition& condition,
                       const RodConfiguration& configuration,
                       Vector6d& residual,
                       Matrix6d& jacobian) {
  residual_of(condition, configuration, residual, &jacobian);
}

}  // namespace rodshape
