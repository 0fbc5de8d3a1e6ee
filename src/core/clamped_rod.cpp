#include "rodshape/core/clamped_rod.hpp"

#include "rodshape/core/so3.hpp"
#include "validation.hpp"

namespace rodshape {

void ClampedRod::validate() const {
  properties.validate();
  detail::require_finite("distributed_load.force", load.force);
  detail::require_finite("distributed_load.moment", load.moment);
  detail::require_finite("base.position", clamp.position);
  if (!clamp.rotation.allFinite()) throw InputError("base.rotation must be finite");
  if (!is_rotation(clamp.rotation, 1e-6))
    throw InputError("base.rotation is not a rotation (RᵀR = I and det R = 1 within 1e-6)");
  if (intervals < 1)
    throw InputError("rod.nodes = " + std::to_string(intervals + 1) + " must be >= 2");
}

}  // namespace rodshape
