#include "rodshape/solvers/model_validity.hpp"

#include "rodshape/core/strain_extremes.hpp"
#include "rodshape/error.hpp"
#include "validation.hpp"

namespace rodshape {

void ModelValidityLimits::validate(const std::string& owner) const {
  detail::require_positive(owner + ".max_axial_strain", max_axial_strain);
  detail::require_positive(owner + ".max_shear_strain", max_shear_strain);
}

void check_model_validity(const RodProperties& properties,
                          const RodConfiguration& configuration,
                          const ModelValidityLimits& limits,
                          const std::string& pose_field,
                          const std::string& limits_owner) {
  using detail::format_value;
  if (!configuration.finite())
    throw InputError(pose_field, ": the equilibrium there is not finite (NaN or infinite values)");
  const StrainExtremes e = strain_extremes(properties, configuration);
  if (!(e.min_axial_stretch > 0.0))
    throw InputError(pose_field,
                     ": the rod would be compressed to v_z = " + format_value(e.min_axial_stretch) +
                         " <= 0 at s = " + format_value(e.min_axial_stretch_s) +
                         " m (squashed to nothing or inverted), which the rod model "
                         "cannot describe");
  // The largest |v_z - ṽ_z| is a compression when the smallest v_z reaches it.
  const bool compressed = properties.v_rest.z() - e.min_axial_stretch >= e.max_axial;
  if (e.max_axial > limits.max_axial_strain)
    throw InputError(
        pose_field, std::string(": the rod would be ") + (compressed ? "compressed" : "stretched") +
                        " by an axial strain of " + format_value(e.max_axial) +
                        " at s = " + format_value(e.max_axial_s) + " m, beyond " + limits_owner +
                        ".max_axial_strain = " + format_value(limits.max_axial_strain) +
                        " (the linear elastic law's range)");
  if (e.max_shear > limits.max_shear_strain)
    throw InputError(pose_field,
                     ": the rod would be sheared by " + format_value(e.max_shear) +
                         " at s = " + format_value(e.max_shear_s) + " m, beyond " + limits_owner +
                         ".max_shear_strain = " + format_value(limits.max_shear_strain) +
                         " (the linear elastic law's range)");
}

}  // namespace rodshape
