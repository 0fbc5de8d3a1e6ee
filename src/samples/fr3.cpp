#include "rodshape/samples/fr3.hpp"

#include <numbers>
#include <string>

#include "rodshape/samples/franka_limits.hpp"
#include "samples/franka_arm.hpp"

namespace rodshape::samples {

namespace detail {
extern const char* const kFr3Urdf;  // generated from data/robots/fr3.urdf (CMakeLists.txt)
}

std::string_view fr3_urdf() { return detail::kFr3Urdf; }

ArmModel fr3() {
  return detail::with_franka_limits(ArmModel::from_urdf_string(std::string(fr3_urdf()), "fr3_link0",
                                                               "fr3_link8", "the bundled FR3 URDF"),
                                    fr3_joint_limits(), "the FR3's published limits");
}

Eigen::VectorXd fr3_ready_pose() {
  constexpr double pi = std::numbers::pi;
  Eigen::VectorXd q(7);
  q << 0.0, -pi / 4, 0.0, -3 * pi / 4, 0.0, pi / 2, pi / 4;
  return q;
}

}  // namespace rodshape::samples
