// integration_error.hpp: how far the nodes of an integrated configuration are from the exact
// solution of the rod's differential equations at the same base wrench, by step doubling.
#pragma once

#include "rodshape/core/clamped_rod.hpp"
#include "rodshape/core/rod_configuration.hpp"
#include "rodshape/core/wrench.hpp"

namespace rodshape {

/// Integrates `rod` again at `base_wrench` with steps twice as long (half its sub-steps, or half
/// its intervals, comparing every other node; twice as short when both counts are odd) and compares
/// the nodes with `configuration` (integrated from the same rod and wrench). Classical Runge–Kutta
/// is of order 4, so the error of `configuration` is 1/15 of the difference (16/15 against the
/// finer run). Returned dimensionless, the largest over the compared nodes of: |Δp| / L, the angle
/// between the two rotations (rad), and |Δm| / (EI / L) (the curvature error times L); +inf when
/// either integration is not finite. Cost: one integration without derivatives at half the steps
/// (about a sixth of a solve iteration with derivatives); for the end of a solve, not its loop.
double integration_error_estimate(const ClampedRod& rod,
                                  const BaseWrench& base_wrench,
                                  const RodConfiguration& configuration);

}  // namespace rodshape
