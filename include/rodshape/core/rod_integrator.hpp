// rod_integrator.hpp: the forward problem. From the clamp pose and the base wrench, integrate the
// static Cosserat rod (paper, eq. "system of differential equations"):
//   p' = R v,  R' = R û,  n' = -f,  m' = -p' × n - l,
//   v = K_tra⁻¹ Rᵀ n + ṽ (Kirchhoff: v = ṽ),  u = K_rot⁻¹ Rᵀ m + ũ,
// with the classical fourth-order Runge–Kutta method, one step per interval. The orientation is
// carried as a quaternion q (q' = ½ q ⊗ (0, u)) and read as R = R(q/|q|), exactly orthonormal.
// Derivatives are the exact derivatives of that discrete map (Runge–Kutta applied to the
// variational equations with the same stages), so they match finite differences of integrate() to
// round-off.
#pragma once

#include "rodshape/core/clamped_rod.hpp"
#include "rodshape/core/rod_configuration.hpp"
#include "rodshape/core/wrench.hpp"

namespace rodshape {

/// Integrates into `out`, which is resized once and then reused without allocating.
/// The rod is not validated here (hot path): validate it once with ClampedRod::validate().
/// `stored` = Output::Tip keeps only the base and the tip and skips the energy
/// (rod_configuration.hpp): e.g. integrate(rod, w, out, Derivatives::Tip, Output::Tip) for a
/// solver's Jacobian.
void integrate(const ClampedRod& rod,
               const BaseWrench& base_wrench,
               RodConfiguration& out,
               Derivatives derivatives = Derivatives::None,
               Output stored = Output::Full);

/// Convenience overload that returns a fresh configuration.
RodConfiguration integrate(const ClampedRod& rod,
                           const BaseWrench& base_wrench,
                           Derivatives derivatives = Derivatives::None,
                           Output stored = Output::Full);

}  // namespace rodshape
