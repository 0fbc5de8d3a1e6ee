#include "rodshape/core/clamped_rod.hpp"

#include "validation.hpp"

namespace rodshape {

void ClampedRod::validate() const {
  properties.validate();
  detail::require_finite("ClampedRod.load.force", load.force);
  detail::require_finite("ClampedRod.load.moment", load.moment);
  detail::require_pose("ClampedRod.clamp", clamp);
  if (intervals < 1)
    throw InputError("ClampedRod.intervals", " = " + std::to_string(intervals) + " must be >= 1");
}

}  // namespace rodshape
