#include "rodshape/core/strain_extremes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rodshape {

StrainExtremes strain_extremes(const RodProperties& properties, const RodConfiguration& c) {
  StrainExtremes e;
  if (!c.finite()) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return {nan, nan, nan, nan, nan, nan, nan};
  }
  for (int i = 0; i < c.nodes(); ++i) {
    const Eigen::Vector3d dv = c.v[i] - properties.v_rest;
    const double axial = std::abs(dv.z());
    const double shear = std::max(std::abs(dv.x()), std::abs(dv.y()));
    if (axial > e.max_axial) e.max_axial = axial, e.max_axial_s = c.s[i];
    if (shear > e.max_shear) e.max_shear = shear, e.max_shear_s = c.s[i];
    if (i == 0 || c.v[i].z() < e.min_axial_stretch)
      e.min_axial_stretch = c.v[i].z(), e.min_axial_stretch_s = c.s[i];
    e.max_curvature = std::max(e.max_curvature, c.u[i].head<2>().norm());
  }
  return e;
}

}  // namespace rodshape
