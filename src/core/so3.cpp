// so3.cpp: a rotation from a quaternion given as input (the one parser for task files and the CLI).
#include "rodshape/core/so3.hpp"

#include "rodshape/error.hpp"
#include "validation.hpp"

namespace rodshape {

Eigen::Matrix3d rotation_from_wxyz(const Eigen::Vector4d& wxyz, const std::string& field) {
  detail::require_finite(field, wxyz);
  const double norm = wxyz.norm();
  if (!(std::abs(norm - 1.0) <= kRotationInputTolerance)) {
    throw InputError(field, ": quaternion [w, x, y, z] has norm " + detail::format_value(norm) +
                                "; it must be 1 within 1e-6 (give more digits)");
  }
  return Eigen::Quaterniond(wxyz[0], wxyz[1], wxyz[2], wxyz[3]).normalized().toRotationMatrix();
}

}  // namespace rodshape
