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

/// a_T_c = a_T_b · b_T_c.
inline Pose compose(const Pose& a_T_b, const Pose& b_T_c) {
  return {a_T_b.position + a_T_b.rotation * b_T_c.position, a_T_b.rotation * b_T_c.rotation};
}

/// b_T_a = (a_T_b)⁻¹.
inline Pose inverse(const Pose& a_T_b) {
  const Eigen::Matrix3d R = a_T_b.rotation.transpose();
  return {-(R * a_T_b.position), R};
}

/// The pose between a (σ = 0) and b (σ = 1): p = (1 - σ) p_a + σ p_b, R = slerp(R_a, R_b, σ).
inline Pose interpolate(const Pose& a, const Pose& b, double sigma) {
  const Eigen::Quaterniond qa(a.rotation), qb(b.rotation);
  return {(1.0 - sigma) * a.position + sigma * b.position, qa.slerp(sigma, qb).toRotationMatrix()};
}

}  // namespace rodshape
