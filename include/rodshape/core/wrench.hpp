// wrench.hpp: a force and a moment in the world frame.
#pragma once

#include <Eigen/Core>

namespace rodshape {

using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;
/// Derivatives of a 3-vector with respect to the 6 base-wrench components (n(0), m(0)).
using Matrix36d = Eigen::Matrix<double, 3, 6>;

struct Wrench {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();   // N
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();  // N·m

  Vector6d to_vector() const {
    Vector6d w;
    w << force, moment;
    return w;
  }
  static Wrench from_vector(const Vector6d& w) { return {w.head<3>(), w.tail<3>()}; }
};

/// The shooting unknown: the internal force n(0) and moment m(0) at the clamp, world frame.
/// (The clamp applies -n(0), -m(0) to the rod.)
using BaseWrench = Wrench;

}  // namespace rodshape
