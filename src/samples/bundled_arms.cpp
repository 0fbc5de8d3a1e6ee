#include "rodshape/samples/bundled_arms.hpp"

#include "rodshape/samples/fr3.hpp"
#include "rodshape/samples/franka_limits.hpp"
#include "rodshape/samples/panda.hpp"
#include "samples/franka_arm.hpp"

namespace rodshape::samples {

std::string bundled_arm_names() { return "fr3, panda"; }

bool is_bundled_arm(std::string_view name) { return name == "fr3" || name == "panda"; }

std::optional<ArmModel> bundled_arm(std::string_view name,
                                    const std::string& base_link,
                                    const std::string& tip_link) {
  if (!is_bundled_arm(name)) return std::nullopt;
  const bool fr3_arm = name == "fr3";
  const std::string source = fr3_arm ? "the bundled FR3 URDF" : "the bundled Panda URDF";
  return detail::with_franka_limits(
      ArmModel::from_urdf_string(std::string(fr3_arm ? fr3_urdf() : panda_urdf()), base_link,
                                 tip_link, source),
      fr3_arm ? fr3_joint_limits() : panda_joint_limits(), source);
}

}  // namespace rodshape::samples
