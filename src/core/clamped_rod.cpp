#include "rodshape/core/clamped_rod.hpp"

#include "rodshape/core/physical_bounds.hpp"
#include "validation.hpp"

namespace rodshape {

void ClampedRod::validate() const {
  properties.validate();
  require_magnitude_at_most("ClampedRod.load.force", load.force, bounds::kMaxForce, "N/m");
  require_magnitude_at_most("ClampedRod.load.moment", load.moment, bounds::kMaxForce, "N*m/m");
  detail::require_pose("ClampedRod.clamp", clamp);
  require_magnitude_at_most("ClampedRod.clamp.position", clamp.position, bounds::kMaxPosition, "m");
  detail::require_count("ClampedRod.intervals", intervals, 1, kMaxIntervals);
  if (substeps < 1 || substeps > kMaxSubsteps)
    throw InputError("ClampedRod.substeps", " = " + std::to_string(substeps) + " must be in [1, " +
                                                std::to_string(kMaxSubsteps) + "]");
}

}  // namespace rodshape
