// step_doubling.hpp (private): the two halves of integration_error_estimate(), so that a solver
// whose last iterates were integrated at both step lengths can estimate without integrating again.
#pragma once

#include "rodshape/core/clamped_rod.hpp"
#include "rodshape/core/rod_configuration.hpp"

namespace rodshape::detail {

/// The rod of the comparison run: steps twice as long where possible (`coarse`: half the
/// sub-steps, or half the intervals with node j there node `stride` j of the rod's), else twice as
/// short (both counts odd).
struct ComparisonRod {
  ClampedRod rod;
  int stride = 1;
  bool coarse = true;
};
ComparisonRod comparison_rod(const ClampedRod& rod);

/// integration_error_estimate() from `c` (integrated from `rod`) and `other` (from `compared.rod`
/// at the same wrench, Output::Full).
double step_doubling_error(const ClampedRod& rod,
                           const RodConfiguration& c,
                           const ComparisonRod& compared,
                           const RodConfiguration& other);

}  // namespace rodshape::detail
