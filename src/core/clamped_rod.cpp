#include "rodshape/core/clamped_rod.hpp"

#include "validation.hpp"

namespace rodshape {

void ClampedRod::validate() const {
  properties.validate();
  detail::require_finite("ClampedRod.load.force", load.force);
  detail::require_finite("ClampedRod.load.moment", load.moment);
  detail::require_pose("ClampedRod.clamp", clamp);
  detail::require_count("ClampedRod.intervals", intervals, 1, kMaxIntervals);
  if (substeps < 1 || substeps > kMaxSubsteps)
    throw InputError("ClampedRod.substeps", " = " + std::to_string(substeps) + " must be in [1, " +
                                                std::to_string(kMaxSubsteps) + "]");
}

}  // namespace rodshape
