#include "rodshape/samples/panda.hpp"

#include <numbers>
#include <string>

#include "rodshape/samples/franka_limits.hpp"
#include "samples/franka_arm.hpp"

namespace rodshape::samples {

namespace detail {
extern const char* const kPandaUrdf;  // generated from data/robots/panda.urdf (CMakeLists.txt)
}

std::string_view panda_urdf() { return detail::kPandaUrdf; }

ArmModel panda() {
  return detail::with_franka_limits(
      ArmModel::from_urdf_string(std::string(panda_urdf()), "panda_link0", "panda_link8",
                                 "the bundled Panda URDF"),
      panda_joint_limits(), "the Panda's published limits");
}

Eigen::VectorXd panda_ready_pose() {
  constexpr double pi = std::numbers::pi;
  Eigen::VectorXd q(7);
  q << 0.0, -pi / 4, 0.0, -3 * pi / 4, 0.0, pi / 2, pi / 4;
  return q;
}

}  // namespace rodshape::samples
