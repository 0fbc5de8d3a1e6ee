// shooting_residual.hpp: the six boundary-condition residuals at s = L as functions of the base
// wrench, and their exact Jacobian from the integrator's derivatives.
//   free:     r = (n(L) - F, m(L) - M)                               [N, N·m]
//   clamped:  r = (R_dᵀ (p(L) - p_d), log(R_dᵀ R(L))^∨)              [m, rad]
//   grasped:  as clamped, with the component of each released axis replaced by the tip wrench's
//             component along it in the grasp frame, R_dᵀ n(L) or R_dᵀ m(L).
#pragma once

#include "rodshape/core/rod_configuration.hpp"
#include "rodshape/solvers/tip_condition.hpp"

namespace rodshape {

/// Residual of `condition` for an integrated configuration (any Derivatives level).
Vector6d shooting_residual(const TipCondition& condition, const RodConfiguration& configuration);

/// Residual and its Jacobian dr/dw; `configuration` must carry Tip or AllNodes derivatives.
void shooting_residual(const TipCondition& condition,
                       const RodConfiguration& configuration,
                       Vector6d& residual,
                       Matrix6d& jacobian);

}  // namespace rodshape
