// validation.hpp (private): checks that throw InputError with a message naming the field and value,
// e.g. "rod.length = -0.3 must be > 0".
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <sstream>
#include <string>

#include "rodshape/core/pose.hpp"
#include "rodshape/core/so3.hpp"
#include "rodshape/error.hpp"

namespace rodshape::detail {

inline std::string format_value(double value) {
  std::ostringstream out;
  out.precision(6);
  out << value;
  return out.str();
}

/// "[x, y, z]" with 4 significant digits, for messages.
inline std::string format_point(const Eigen::Vector3d& p) {
  std::ostringstream out;
  out.precision(4);
  out << "[" << p.x() << ", " << p.y() << ", " << p.z() << "]";
  return out.str();
}

inline void require_finite(const std::string& field, double value) {
  if (!std::isfinite(value))
    throw InputError(field, " = " + format_value(value) + " must be finite");
}

inline void require_positive(const std::string& field, double value) {
  require_finite(field, value);
  if (!(value > 0.0)) throw InputError(field, " = " + format_value(value) + " must be > 0");
}

inline void require_non_negative(const std::string& field, double value) {
  require_finite(field, value);
  if (value < 0.0) throw InputError(field, " = " + format_value(value) + " must be >= 0");
}

/// A count or size a user sets: `min` ≤ value ≤ `max` ("PlanOptions.steps = 0 must be >= 1",
/// "PlanOptions.steps = 1000000 must be <= 1000"). Every such bound is in docs/limits.md.
inline void require_count(const std::string& field, long long value, long long min, long long max) {
  if (value < min)
    throw InputError(field, " = " + std::to_string(value) + " must be >= " + std::to_string(min));
  if (value > max)
    throw InputError(field, " = " + std::to_string(value) + " must be <= " + std::to_string(max));
}

template <typename Derived>
void require_finite(const std::string& field, const Eigen::MatrixBase<Derived>& value) {
  for (Eigen::Index i = 0; i < value.size(); ++i)
    if (!std::isfinite(value(i)))
      throw InputError(
          field, "[" + std::to_string(i) + "] = " + format_value(value(i)) + " must be finite");
}

/// A finite position and a rotation (RᵀR = I, det R = 1, within 1e-6); `field` names the pose,
/// e.g. "base" or "tip".
inline void require_pose(const std::string& field, const Pose& pose) {
  require_finite(field + ".position", pose.position);
  if (!pose.rotation.allFinite()) throw InputError(field, ".rotation must be finite");
  if (!is_rotation(pose.rotation, 1e-6))
    throw InputError(field, ".rotation is not a rotation (RᵀR = I and det R = 1 within 1e-6)");
}

}  // namespace rodshape::detail
