// model_validity.hpp: the range of strains where the linear constitutive law (paper, "Constitutive
// Equations") describes a rod, and the check that a held pose asks for nothing beyond it.
#pragma once

#include <string>

#include "rodshape/core/rod_configuration.hpp"
#include "rodshape/core/rod_properties.hpp"

namespace rodshape {

/// Past a few tens of percent of axial strain or shear the linear law n = R K_tra (v - ṽ) means
/// little, and v_z ≤ 0 (a rod squashed to nothing or turned inside out) means nothing at all.
struct ModelValidityLimits {
  double max_axial_strain = 0.5;  // max |v_z - ṽ_z|
  double max_shear_strain = 0.5;  // max |v_x - ṽ_x|, |v_y - ṽ_y|

  /// Throws InputError naming `owner`.max_axial_strain etc. when a limit is not finite and > 0;
  /// `owner` is where the limits live, e.g. "ShootingOptions.strain_limits".
  void validate(const std::string& owner = "ModelValidityLimits") const;
};

/// Throws InputError(pose_field, ": the rod would be …") when `configuration` (an equilibrium of a
/// rod with `properties`) has v_z ≤ 0 at a node or a strain beyond `limits` (named in the message
/// as `limits_owner`.max_axial_strain etc.): the pose named by `pose_field` asks the model for
/// more than it can say. Meant for poses a user asks the rod to be held at (an equilibrium task's
/// tip, a plan's initial tip), not for intermediate solves.
void check_model_validity(const RodProperties& properties,
                          const RodConfiguration& configuration,
                          const ModelValidityLimits& limits,
                          const std::string& pose_field,
                          const std::string& limits_owner);

}  // namespace rodshape
