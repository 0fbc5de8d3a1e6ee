// pose.hpp: a rigid pose world_T_frame = (p, R).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace rodshape {

struct Pose {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();

  /// The rotation as a unit quaternion [w, x, y, z] with w ≥ 0.
  Eigen::Vector4d quaternion_wxyz() const {
    Eigen::Quaterniond q(rotation);
    q.normalize();
    if (q.w() < 0.0) q.coeffs() *= -1.0;
    return {q.w(), q.x(), q.y(), q.z()};
  }
};

}  // namespace rodshape
