// base_pose_derivatives.hpp: the derivatives of every node's state with respect to the clamp pose
// (world_T_base: p0 = p(0), R0 = R(0)), at a fixed base wrench in the clamp's (body) frame.
//
// The perturbation is ξ = (δt, δφ) ∈ R⁶: p0 → p0 + δt, R0 → exp([δφ]×) R0 (δφ a world-frame
// rotation), with the body-frame base wrench w_b = (n_b, m_b) fixed, so that the world base wrench
// w = (R0 n_b, R0 m_b) turns with the clamp. The distributed load (f, l) stays fixed in the world.
//
// By equivariance (a solution turned about p0 by Q solves the problem with clamp Q R0, base wrench
// Q w and load (Q f, Q l); the Runge–Kutta map is exactly equivariant too, its state transforming
// linearly), the derivative is the rigid motion less the effect of turning the load the other way:
//
//   δp_i = δt + δφ × (p_i - p0) - G_p,i     δθ_i = R_iᵀ δφ - G_θ,i     (body frame: δR_i = R_i θ̂)
//   δn_i = δφ × n_i - G_n,i                  δm_i = δφ × m_i - G_m,i     δE = -G_E
//
// with G_x = dx/df (δφ × f) + dx/dl (δφ × l), the derivatives with respect to the uniform load
// (one more tangent integration through the same Runge–Kutta stages, skipped when f = l = 0).
// In matrix form, with D_x = dx/df [f]× + dx/dl [l]×:
//
//   dp_i/dξ = [I, -[p_i - p0]× + D_p,i]    dθ_i/dξ = [0, R_iᵀ + D_θ,i]
//   dn_i/dξ = [0, -[n_i]× + D_n,i]          dm_i/dξ = [0, -[m_i]× + D_m,i]    dE/dξ = [0, D_E]
//
// These are the exact derivatives of the discrete map integrate() computes (to round-off), like the
// base-wrench derivatives. The translation δt moves p only: the ODE does not depend on p itself.
#pragma once

#include "rodshape/core/clamped_rod.hpp"
#include "rodshape/core/rod_configuration.hpp"

namespace rodshape {

/// `c` is a configuration of `rod` as integrate() left it (typically with Derivatives::AllNodes;
/// only its state is read, and its base wrench c.base_wrench() is the world wrench w). `out`
/// receives c's state (s, p, R, n, m, v, u, energy: a copy) and, in its derivative arrays, the
/// derivatives with respect to the clamp pose ξ = (δt, δφ) instead of w: columns 0–2 are δt,
/// 3–5 are δφ, for every node (dp_dw, dtheta_dw, dn_dw, dm_dw), the tip (tip_*) and the energy
/// (denergy_dw); out.derivatives is AllNodes. `out` is resized once and then reused without
/// allocating; it must not be `c`. Costs about one integrate() with Derivatives::AllNodes when the
/// load is not zero, a copy otherwise.
void base_pose_derivatives(const ClampedRod& rod, const RodConfiguration& c, RodConfiguration& out);

/// Convenience overload that returns a fresh configuration.
RodConfiguration base_pose_derivatives(const ClampedRod& rod, const RodConfiguration& c);

}  // namespace rodshape
