#include "rodshape/core/clamped_rod.hpp"

#include "validation.hpp"

namespace rodshape {

void ClampedRod::validate() const {
  properties.validate();
  detail::require_finite("distributed_load.force", load.force);
  detail::require_finite("distributed_load.moment", load.moment);
  detail::require_pose("base", clamp);
  if (intervals < 1)
    throw InputError("rod.nodes = " + std::to_string(intervals + 1) + " must be >= 2");
  if (substeps < 1 || substeps > kMaxSubsteps)
    throw InputError("substeps = " + std::to_string(substeps) + " must be in [1, " +
                     std::to_string(kMaxSubsteps) + "]");
}

}  // namespace rodshape
