// eigen_compare.hpp: a gtest comparator for Eigen matrices that prints both operands, their
// difference and the worst entry when it fails (after Drake's CompareMatrices), and the angle
// between two rotations.
//
//   EXPECT_TRUE(CompareMatrices(actual, expected, 1e-12));  // max |a - b| ≤ tol
//   EXPECT_TRUE(CompareMatrices(actual, expected, 1e-9, MatrixCompareType::relative));
//
// `relative` means max |a - b| ≤ tol · max(max |a|, max |b|): relative to the larger operand's
// size, not entry by entry (an entry that should be 0 would otherwise need an exact 0). A
// non-finite entry in either operand always fails.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>

namespace rodshape::testing {

enum class MatrixCompareType { absolute, relative };

template <typename DerivedA, typename DerivedB>
::testing::AssertionResult CompareMatrices(const Eigen::MatrixBase<DerivedA>& a,
                                           const Eigen::MatrixBase<DerivedB>& b,
                                           double tolerance,
                                           MatrixCompareType type = MatrixCompareType::absolute) {
  if (a.rows() != b.rows() || a.cols() != b.cols()) {
    return ::testing::AssertionFailure() << "size mismatch: " << a.rows() << "x" << a.cols()
                                         << " vs " << b.rows() << "x" << b.cols();
  }
  const Eigen::MatrixXd A = a.template cast<double>();
  const Eigen::MatrixXd B = b.template cast<double>();
  const Eigen::IOFormat format(Eigen::FullPrecision, 0, ", ", "\n", "  [", "]");
  auto describe = [&](std::ostream& out) {
    out << "\nactual:\n"
        << A.format(format) << "\nexpected:\n"
        << B.format(format) << "\ndifference (actual - expected):\n"
        << (A - B).format(format) << "\n";
  };
  if (!A.allFinite() || !B.allFinite()) {
    std::ostringstream out;
    out << "non-finite entry";
    describe(out);
    return ::testing::AssertionFailure() << out.str();
  }
  if (A.size() == 0) return ::testing::AssertionSuccess();

  Eigen::Index worst_row = 0, worst_col = 0;
  const double max_error = (A - B).cwiseAbs().maxCoeff(&worst_row, &worst_col);
  const double scale = type == MatrixCompareType::relative
                           ? std::max(A.cwiseAbs().maxCoeff(), B.cwiseAbs().maxCoeff())
                           : 1.0;
  const double allowed = tolerance * scale;
  if (max_error <= allowed) return ::testing::AssertionSuccess();

  std::ostringstream out;
  out << std::setprecision(6) << "max |actual - expected| = " << max_error << " at (" << worst_row
      << ", " << worst_col << ") exceeds "
      << (type == MatrixCompareType::relative ? "relative " : "absolute ") << "tolerance "
      << tolerance;
  if (type == MatrixCompareType::relative) out << " x scale " << scale << " = " << allowed;
  out << " (error / allowed = " << max_error / allowed << ")";
  describe(out);
  return ::testing::AssertionFailure() << out.str();
}

/// A scalar version with the same message style: |actual - expected| ≤ tolerance.
inline ::testing::AssertionResult CompareScalars(double actual, double expected, double tolerance) {
  if (std::isfinite(actual) && std::isfinite(expected) &&
      std::abs(actual - expected) <= tolerance) {
    return ::testing::AssertionSuccess();
  }
  std::ostringstream out;
  out << std::setprecision(17) << "actual = " << actual << ", expected = " << expected
      << ", |difference| = " << std::abs(actual - expected) << " exceeds tolerance "
      << std::setprecision(6) << tolerance;
  if (tolerance > 0.0)
    out << " (error / tolerance = " << std::abs(actual - expected) / tolerance << ")";
  return ::testing::AssertionFailure() << out.str();
}

/// The angle (rad, in [0, π]) of the rotation a bᵀ that takes rotation b to rotation a.
inline double rotation_angle(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  return Eigen::AngleAxisd(a * b.transpose()).angle();
}

}  // namespace rodshape::testing
