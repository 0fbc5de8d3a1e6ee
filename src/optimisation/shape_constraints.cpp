// shape_constraints.cpp: validation of the strain limits (the grasp offset and the wrench bounds
// are checked where the ShapeProblem is built).
#include "rodshape/optimisation/shape_constraints.hpp"

#include "validation.hpp"

#include <cmath>
#include <numbers>

namespace rodshape {

WrenchBounds WrenchBounds::from_scale(const ClampedRod& rod) {
  const RodProperties& k = rod.properties;
  const double L = k.length;
  const double load = rod.load.force.norm();  // N/m
  const double M = 4.0 * std::numbers::pi * k.K_rot.maxCoeff() / L + 0.5 * load * L * L +
                   rod.load.moment.norm() * L;
  const double F = 0.5 * k.K_tra.maxCoeff() + load * L;
  WrenchBounds bounds;
  bounds.upper << Eigen::Vector3d::Constant(F), Eigen::Vector3d::Constant(M);
  bounds.lower = -bounds.upper;
  return bounds;
}

WrenchBounds WrenchBounds::or_else(const WrenchBounds& fallback) const {
  WrenchBounds bounds = *this;
  // A side given beyond the fallback's other side leaves that other side as it was (unbounded).
  for (int j = 0; j < 6; ++j) {
    if (!std::isfinite(bounds.lower(j)) && !(bounds.upper(j) < fallback.lower(j)))
      bounds.lower(j) = fallback.lower(j);
    if (!std::isfinite(bounds.upper(j)) && !(bounds.lower(j) > fallback.upper(j)))
      bounds.upper(j) = fallback.upper(j);
  }
  return bounds;
}

void StrainLimits::validate() const {
  if (max_curvature) detail::require_positive("StrainLimits.max_curvature", *max_curvature);
  if (max_axial_strain)
    detail::require_positive("StrainLimits.max_axial_strain", *max_axial_strain);
}

}  // namespace rodshape
