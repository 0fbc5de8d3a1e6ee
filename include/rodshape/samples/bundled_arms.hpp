// bundled_arms.hpp: the arms compiled into the library by name, as a task's `robot.urdf` may name
// them instead of a file: "panda" (samples::panda()) and "fr3" (samples::fr3()).
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "rodshape/robot/arm_model.hpp"

namespace rodshape::samples {

/// The names, sorted, comma-separated: "fr3, panda".
std::string bundled_arm_names();

/// Whether `name` is a bundled arm's.
bool is_bundled_arm(std::string_view name);

/// The bundled arm called `name`, from `base_link` to `tip_link` (empty: its base link0 and its
/// flange link8; ArmModel::from_urdf_string's errors), with Franka's limits; nullopt for another
/// name.
std::optional<ArmModel> bundled_arm(std::string_view name,
                                    const std::string& base_link = "",
                                    const std::string& tip_link = "");

}  // namespace rodshape::samples
