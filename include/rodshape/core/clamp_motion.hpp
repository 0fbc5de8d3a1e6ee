// clamp_motion.hpp: a configuration carried rigidly with its clamp, without integrating.
//
// Without a distributed load (f = l = 0) the equilibrium equations are equivariant under rigid
// motions (base_pose_derivatives.hpp): the configuration for the clamp (p0', R0') with the same
// body-frame base wrench is the one for (p0, R0) moved by Q = R0' R0ᵀ about p0 and shifted to p0',
//   p_i' = p0' + Q (p_i - p0),   R_i' = Q R_i,   n_i' = Q n_i,   m_i' = Q m_i,
// with v, u (body frame), s and E unchanged. Its world base wrench is w' = B w, B = blockdiag(Q,
// Q), so the derivatives with respect to w' are
//   dp'/dw' = Q dp/dw Bᵀ,   dn'/dw' = Q dn/dw Bᵀ,   dm'/dw' = Q dm/dw Bᵀ,
//   dθ'/dw' = dθ/dw Bᵀ (θ is a body-frame angle),   dE/dw' = dE/dw Bᵀ.
// integrate() at the new clamp gives the same to round-off (its Runge–Kutta map is equivariant).
#pragma once

#include "rodshape/core/pose.hpp"
#include "rodshape/core/rod_configuration.hpp"

namespace rodshape {

/// `out` = `c` (a configuration of an unloaded rod clamped at `from`) moved with its clamp to `to`,
/// derivatives included (as many as c has). `out` must not be `c`; it is resized to c's size and
/// derivatives, allocating only when they change.
void move_with_clamp(const RodConfiguration& c,
                     const Pose& from,
                     const Pose& to,
                     RodConfiguration& out);

}  // namespace rodshape
