// shape_constraints.cpp: validation of the strain limits (the grasp offset and the wrench bounds
// are checked where the ShapeProblem is built).
#include "rodshape/optimisation/shape_constraints.hpp"

#include "validation.hpp"

namespace rodshape {

void StrainLimits::validate() const {
  if (max_curvature) detail::require_positive("StrainLimits.max_curvature", *max_curvature);
  if (max_axial_strain)
    detail::require_positive("StrainLimits.max_axial_strain", *max_axial_strain);
}

}  // namespace rodshape
