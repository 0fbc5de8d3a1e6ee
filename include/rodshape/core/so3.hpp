// so3.hpp: rotations. hat/vee, the exponential and logarithm of SO(3) and the inverse of the right
// Jacobian, each with a series for small angles.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <string>

namespace rodshape {

/// û: the skew-symmetric matrix with û x = u × x.
inline Eigen::Matrix3d hat(const Eigen::Vector3d& u) {
  Eigen::Matrix3d u_hat;
  u_hat << 0.0, -u.z(), u.y(),  //
      u.z(), 0.0, -u.x(),       //
      -u.y(), u.x(), 0.0;
  return u_hat;
}

/// The inverse of hat on the skew part of a matrix: vee(û) = u.
inline Eigen::Vector3d vee(const Eigen::Matrix3d& u_hat) {
  return {u_hat(2, 1), u_hat(0, 2), u_hat(1, 0)};
}

/// exp(θ̂) by Rodrigues' formula, with Taylor series below |θ| = 1e-4.
inline Eigen::Matrix3d exp_so3(const Eigen::Vector3d& theta) {
  const double angle2 = theta.squaredNorm();
  const double angle = std::sqrt(angle2);
  // a = sin|θ|/|θ|, b = (1 - cos|θ|)/|θ|²
  const double a = angle < 1e-4 ? 1.0 - angle2 / 6.0 : std::sin(angle) / angle;
  const double b = angle < 1e-4 ? 0.5 - angle2 / 24.0 : (1.0 - std::cos(angle)) / angle2;
  const Eigen::Matrix3d theta_hat = hat(theta);
  return Eigen::Matrix3d::Identity() + a * theta_hat + b * theta_hat * theta_hat;
}

/// log(R)^∨: the rotation vector θ with exp(θ̂) = R, |θ| ≤ π.
inline Eigen::Vector3d log_so3(const Eigen::Matrix3d& R) {
  const Eigen::AngleAxisd angle_axis(R);
  return angle_axis.angle() * angle_axis.axis();
}

/// J_r⁻¹(θ): maps a body-frame perturbation δ (R → R exp(δ̂)) to the change of log(R):
/// δθ = J_r⁻¹(θ) δ, with J_r⁻¹ = I + ½θ̂ + (1/|θ|² - (1 + cos|θ|)/(2|θ| sin|θ|)) θ̂².
inline Eigen::Matrix3d right_jacobian_inverse_so3(const Eigen::Vector3d& theta) {
  const double angle2 = theta.squaredNorm();
  const double angle = std::sqrt(angle2);
  const double c = angle < 1e-4
                       ? 1.0 / 12.0 + angle2 / 720.0
                       : 1.0 / angle2 - (1.0 + std::cos(angle)) / (2.0 * angle * std::sin(angle));
  const Eigen::Matrix3d theta_hat = hat(theta);
  return Eigen::Matrix3d::Identity() + 0.5 * theta_hat + c * theta_hat * theta_hat;
}

/// J_l(θ) = I + (1 - cos|θ|)/|θ|² θ̂ + (|θ| - sin|θ|)/|θ|³ θ̂²: the left Jacobian of SO(3), which is
/// also the V of SE(3)'s exponential, exp((ρ, θ)) = (exp(θ̂), J_l(θ) ρ).
inline Eigen::Matrix3d left_jacobian_so3(const Eigen::Vector3d& theta) {
  const double angle2 = theta.squaredNorm();
  const double angle = std::sqrt(angle2);
  const double b = angle < 1e-4 ? 0.5 - angle2 / 24.0 : (1.0 - std::cos(angle)) / angle2;
  const double c =
      angle < 1e-4 ? 1.0 / 6.0 - angle2 / 120.0 : (angle - std::sin(angle)) / (angle2 * angle);
  const Eigen::Matrix3d theta_hat = hat(theta);
  return Eigen::Matrix3d::Identity() + b * theta_hat + c * theta_hat * theta_hat;
}

/// max |RᵀR - I| and det(R) - 1 both within tolerance.
inline bool is_rotation(const Eigen::Matrix3d& R, double tolerance = 1e-6) {
  if (!R.allFinite()) return false;
  const double orthogonality =
      (R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  return orthogonality <= tolerance && std::abs(R.determinant() - 1.0) <= tolerance;
}

/// The tolerance of a rotation given as input, a matrix (is_rotation) or a quaternion (its norm).
inline constexpr double kRotationInputTolerance = 1e-6;

/// The rotation of the unit quaternion [w, x, y, z]. Throws InputError naming `field` when it is
/// not finite or its norm differs from 1 by more than kRotationInputTolerance (a mistyped
/// quaternion); a smaller error is normalised away.
Eigen::Matrix3d rotation_from_wxyz(const Eigen::Vector4d& wxyz, const std::string& field);

}  // namespace rodshape
