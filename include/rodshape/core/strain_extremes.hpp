// strain_extremes.hpp: the largest strains of a configuration, to judge it against the range where
// the linear constitutive law n = R K_tra (v - ṽ), m = R K_rot (u - ũ) means something.
#pragma once

#include "rodshape/core/rod_configuration.hpp"
#include "rodshape/core/rod_properties.hpp"

namespace rodshape {

struct StrainExtremes {
  double max_axial = 0.0;      // max over nodes of |v_z - ṽ_z| (1: stretched to twice its length)
  double max_shear = 0.0;      // max over nodes of max(|v_x - ṽ_x|, |v_y - ṽ_y|)
  double max_curvature = 0.0;  // max over nodes of |(u_x, u_y)|, the bending curvature, 1/m
  double min_axial_stretch = 1.0;  // min over nodes of v_z (≤ 0: squashed to nothing or inverted)
  double min_axial_stretch_s = 0.0;  // where min_axial_stretch is reached, m
  double max_axial_s = 0.0;          // where max_axial is reached, m
  double max_shear_s = 0.0;          // where max_shear is reached, m
};

/// The extremes over the nodes; NaN strains make every field NaN (a non-finite configuration).
StrainExtremes strain_extremes(const RodProperties& properties,
                               const RodConfiguration& configuration);

}  // namespace rodshape
