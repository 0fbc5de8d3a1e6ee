// test_so3.cpp: hat/vee, exp/log of SO(3) and the inverse right Jacobian (core/so3.hpp), against
// Eigen's AngleAxis (an independent implementation) and a linearisation test (after manif).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>
#include <vector>

#include "rodshape/core/so3.hpp"
#include "support/analytic_rods.hpp"
#include "support/eigen_compare.hpp"

namespace rodshape {
namespace test_so3 {
namespace {

using testing::CompareMatrices;
using testing::kEps;

// Fixed seed: the sweep is reproducible; 200 draws per test.
constexpr unsigned kSeed = 20240611;
constexpr int kDraws = 200;

Eigen::Vector3d random_unit(std::mt19937& rng) {
  std::normal_distribution<double> normal;
  Eigen::Vector3d d(normal(rng), normal(rng), normal(rng));
  return d.normalized();
}

// Angles on both sides of the series switch at 1e-4, down to 0 and up to near π.
const std::vector<double> kAngles = {0.0, 1e-12, 1e-8, 5e-5, 0.999e-4, 1.001e-4, 2e-4, 1e-3,
                                     0.1, 0.5,   1.0,  2.0,  2.5,      3.0,      3.1};

TEST(So3, HatIsTheCrossProductMatrix) {
  std::mt19937 rng(kSeed);
  std::uniform_real_distribution<double> scale(0.1, 10.0);
  for (int i = 0; i < kDraws; ++i) {
    const Eigen::Vector3d u = scale(rng) * random_unit(rng);
    const Eigen::Vector3d x = scale(rng) * random_unit(rng);
    // Each entry of û x and u × x is a difference of two products: rounding ≤ 2ε |u||x| each.
    EXPECT_TRUE(CompareMatrices(hat(u) * x, u.cross(x), 4.0 * kEps * u.norm() * x.norm()));
    EXPECT_TRUE(CompareMatrices(hat(u).transpose(), -hat(u), 0.0));  // exactly skew
  }
}

TEST(So3, VeeInvertsHat) {
  std::mt19937 rng(kSeed);
  for (int i = 0; i < kDraws; ++i) {
    const Eigen::Vector3d u = 3.0 * random_unit(rng);
    EXPECT_TRUE(CompareMatrices(vee(hat(u)), u, 0.0));  // hat and vee only move entries
  }
}

// exp_so3 against AngleAxisd(angle, axis): both O(1) entries built from a few roundings of sin and
// cos, so they agree to ~8ε. Below 1e-4 exp_so3 uses a = 1 - θ²/6, b = ½ - θ²/24, whose truncation
// errors θ⁴/120 and θ⁴/720 are < 1e-18 there; just above, 1 - cos θ loses ~1e-8 relative accuracy
// but multiplies θ̂² = O(1e-8): still ~1e-16.
TEST(So3, ExpMatchesAngleAxisOnBothSidesOfTheSeriesBranch) {
  std::mt19937 rng(kSeed);
  for (double angle : kAngles) {
    for (int i = 0; i < 20; ++i) {
      const Eigen::Vector3d axis = random_unit(rng);
      const Eigen::Matrix3d expected = Eigen::AngleAxisd(angle, axis).toRotationMatrix();
      EXPECT_TRUE(CompareMatrices(exp_so3(angle * axis), expected, 8.0 * kEps))
          << "angle " << angle;
    }
  }
}

TEST(So3, ExpIsAnExactRotation) {
  std::mt19937 rng(kSeed);
  std::uniform_real_distribution<double> angle(0.0, 20.0);  // also several turns
  for (int i = 0; i < kDraws; ++i) {
    const Eigen::Matrix3d R = exp_so3(angle(rng) * random_unit(rng));
    // RᵀR: sums of three products of O(1) entries that carry ~4ε each: ≤ 24ε.
    EXPECT_TRUE(CompareMatrices(R.transpose() * R, Eigen::Matrix3d::Identity(), 24.0 * kEps));
    EXPECT_NEAR(R.determinant(), 1.0, 24.0 * kEps);
  }
}

// log(exp(θ)) = θ for |θ| < π. Eigen's AngleAxis(R) goes through a quaternion: angle and axis to a
// few ε relative; we allow 16ε (1 + |θ|).
TEST(So3, LogInvertsExp) {
  std::mt19937 rng(kSeed);
  for (double angle : kAngles) {
    for (int i = 0; i < 20; ++i) {
      const Eigen::Vector3d theta = angle * random_unit(rng);
      EXPECT_TRUE(CompareMatrices(log_so3(exp_so3(theta)), theta, 16.0 * kEps * (1.0 + angle)))
          << "angle " << angle;
    }
  }
}

TEST(So3, ExpOfSumAboutOneAxisComposes) {
  // exp((a + b) ω̂) = exp(a ω̂) exp(b ω̂): a group property that a wrong coefficient in exp breaks.
  std::mt19937 rng(kSeed);
  for (int i = 0; i < kDraws; ++i) {
    const Eigen::Vector3d axis = random_unit(rng);
    const double a = 0.7, b = -1.9;
    EXPECT_TRUE(CompareMatrices(exp_so3((a + b) * axis), exp_so3(a * axis) * exp_so3(b * axis),
                                16.0 * kEps));
  }
}

// Linearisation (after manif's tests): log(exp(θ̂) exp(hδ̂))^∨ = θ + h J_r⁻¹(θ) δ + O(h²).
// Central difference g(h) = [log(R exp(hδ̂)) - log(R exp(-hδ̂))] / 2h, error model
//   |g - J_r⁻¹δ| ≤ h² M₃ / 6 + e_log / h,
// M₃ = max |d³ log(R exp(tδ̂))/dt³| for unit δ: the coefficients of J_r⁻¹ and its derivatives stay
// below ~1/(1 - cos|θ|) ≈ 2 for |θ| ≤ 2.5, so M₃ ≤ 10 with margin; e_log ≈ 16ε(1 + |θ|) (see
// LogInvertsExp). h = (3 e_log / M₃)^(1/3) ≈ 1e-5 balances the two terms, giving a tolerance of
// ≈ 5e-10 (evaluated per angle from the formula). A left instead of right Jacobian, or a wrong θ̂²
// coefficient, errs by O(|θ|) or O(|θ|²).
TEST(So3, RightJacobianInverseLinearisesTheLogarithm) {
  std::mt19937 rng(kSeed);
  const double M3 = 10.0;
  for (double angle : {0.0, 5e-5, 0.999e-4, 1.001e-4, 1e-3, 0.3, 1.0, 2.0, 2.5}) {
    for (int i = 0; i < 20; ++i) {
      const Eigen::Vector3d theta = angle * random_unit(rng);
      const Eigen::Vector3d delta = random_unit(rng);
      const double e_log = 16.0 * kEps * (1.0 + angle);
      const double h = std::cbrt(3.0 * e_log / M3);
      const Eigen::Matrix3d R = exp_so3(theta);
      const Eigen::Vector3d g =
          (log_so3(R * exp_so3(h * delta)) - log_so3(R * exp_so3(-h * delta))) / (2.0 * h);
      const double tolerance = h * h * M3 / 6.0 + e_log / h;
      EXPECT_TRUE(CompareMatrices(g, right_jacobian_inverse_so3(theta) * delta, tolerance))
          << "angle " << angle;
    }
  }
}

TEST(So3, RightJacobianInverseIsTheIdentityAtZeroAndInvertsTheRightJacobian) {
  EXPECT_TRUE(CompareMatrices(right_jacobian_inverse_so3(Eigen::Vector3d::Zero()),
                              Eigen::Matrix3d::Identity(), 0.0));
  // J_r(θ) = J_l(-θ) (closed form in analytic_rods.hpp, independent of so3.hpp).
  std::mt19937 rng(kSeed);
  for (double angle : {1e-6, 0.999e-4, 1.001e-4, 0.5, 2.0, 3.0}) {
    const Eigen::Vector3d theta = angle * random_unit(rng);
    const Eigen::Matrix3d J_r = testing::left_jacobian(-theta);
    // Both sides O(1)-conditioned for |θ| ≤ 3 (||J_r⁻¹|| ≤ |θ|/(2 sin(|θ|/2)) ≈ 1.5 at 3): ~32ε.
    EXPECT_TRUE(CompareMatrices(right_jacobian_inverse_so3(theta) * J_r,
                                Eigen::Matrix3d::Identity(), 64.0 * kEps))
        << "angle " << angle;
  }
}

TEST(So3, IsRotationAcceptsRotationsAndRejectsEverythingElse) {
  const Eigen::Matrix3d R = exp_so3(Eigen::Vector3d(0.3, -1.2, 0.8));
  EXPECT_TRUE(is_rotation(R));
  EXPECT_TRUE(is_rotation(R + 1e-8 * Eigen::Matrix3d::Ones()));  // within the default 1e-6
  EXPECT_FALSE(is_rotation(R * (1.0 + 1e-5)));                   // scaled: RᵀR = (1 + 2e-5) I
  EXPECT_FALSE(
      is_rotation(Eigen::Vector3d(1.0, 1.0, -1.0).asDiagonal().toDenseMatrix()));  // det -1
  EXPECT_FALSE(is_rotation(Eigen::Matrix3d::Zero()));
  Eigen::Matrix3d with_nan = R;
  with_nan(1, 2) = std::nan("");
  EXPECT_FALSE(is_rotation(with_nan));
  EXPECT_TRUE(is_rotation(R * (1.0 + 1e-5), 1e-4));  // the tolerance is honoured
}

}  // namespace
}  // namespace test_so3
}  // namespace rodshape
