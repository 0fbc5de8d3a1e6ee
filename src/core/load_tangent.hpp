// load_tangent.hpp (private): the derivatives of the rod's shape with respect to its uniform
// distributed load (f, l) (ClampedRod::load), at a fixed clamp pose and base wrench.
#pragma once

#include "rodshape/core/clamped_rod.hpp"
#include "rodshape/core/rod_configuration.hpp"
#include "rodshape/core/wrench.hpp"

namespace rodshape::detail {

/// Integrates like integrate(rod, base_wrench, out, Derivatives::AllNodes), the same state, but
/// the derivative arrays (dp_dw, dtheta_dw, dn_dw, dm_dw, tip_*, denergy_dw) are with respect to
/// the load instead of the base wrench: columns 0–2 are f (world frame, N/m), 3–5 are l (N·m/m).
/// The tangent starts from zero at s = 0 and is forced by δn' = -δf, δm' = ... - δl: the exact
/// derivative of the discrete Runge–Kutta map, as the base-wrench tangent is. Same cost as the
/// base-wrench tangent; `out` is resized once and then reused without allocating.
void integrate_load_tangent(const ClampedRod& rod,
                            const BaseWrench& base_wrench,
                            RodConfiguration& out);

}  // namespace rodshape::detail
