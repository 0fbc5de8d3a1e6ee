// test_shooting_residual.cpp: the shooting residual r(w) of each tip condition and its exact
// Jacobian.
//
//  * Identities: r = 0 at the wrench a forward solve started from (clamped, grasped with any axes
//    released, free with the tip wrench the forward solve ends with).
//  * The Jacobian against central finite differences of shooting_residual(integrate(w)).
//
// Error model of the finite differences (as in tests/core/test_integrator_derivatives.cpp). In the
// scaled unknown ξ_j = w_j / S_j (S = EI/L² for forces, EI/L for moments: ξ ~ 1 bends the rod by
// ~1 rad), a central difference of a residual row r_i whose natural size is F_i errs by
//     |FD_ij - ∂r_i/∂ξ_j| ≤ η² M₃ / 6 + δ / η,
// with M₃ = |∂³r_i/∂ξ_j³| ≤ μ F_i (μ = 10: trigonometric-like in ξ, third derivatives of order F at
// ξ ~ 1, times 10), δ = 16 N ε F_i the round-off of one integration (N RK4 steps on O(F) numbers),
// and η = (3δ/M₃)^(1/3) the step that minimises the sum. With N = 20 the bound is ≈ 3.8e-9 F_i,
// while a wrong row, a missing J_r⁻¹(θ) or a wrong frame (R_d vs R_dᵀ) errs by O(0.1…1) F_i.
// F_i: 1 m for positions (|p| ≤ 1 m here, so round-off is relative to 1 m, not to L), 1 rad for
// angles, EI/L² for forces and EI/L for moments. The log map is evaluated away from |θ| = π.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/core/so3.hpp"
#include "rodshape/solvers/shooting_residual.hpp"
#include "support/analytic_rods.hpp"
#include "support/eigen_compare.hpp"
#include "support/solver_fixtures.hpp"

namespace rodshape {
namespace test_shooting_residual {
namespace {

using testing::CompareMatrices;
using testing::kEps;

constexpr double kMu = 10.0;  // M₃ ≤ μ F, see the error model above

/// The rubber band, tilted and offset at the clamp, precurved, under gravity: no symmetry left that
/// could hide a frame error.
ClampedRod general_band(ConstitutiveModel model) {
  ClampedRod rod = testing::rubber_band(model, 20);
  rod.properties.K_rot = Eigen::Vector3d(0.04, 0.03, 0.028);  // EIx ≠ EIy
  rod.properties.u_rest = Eigen::Vector3d(0.5, -0.3, 1.0);
  rod.load =
      DistributedLoad::gravity(testing::kBandMassPerLength, Eigen::Vector3d(0.0, -9.81, 0.0));
  rod.clamp.position = Eigen::Vector3d(0.1, 0.2, 0.3);
  rod.clamp.rotation = exp_so3(Eigen::Vector3d(0.2, -0.5, 0.3));
  rod.validate();
  return rod;
}

/// An O(1) scaled wrench: the rod is bent by ~1 rad in 3D and twisted.
BaseWrench general_wrench(const ClampedRod& rod) {
  Vector6d xi;
  xi << 0.6, -0.4, 0.3, 0.7, -0.5, 0.4;
  return Wrench::from_vector(xi.cwiseProduct(testing::wrench_scale(rod)));
}

/// F_i of each residual row, as in the error model.
Vector6d row_sizes(const ClampedRod& rod, const TipCondition& tip) {
  const Vector6d S = testing::wrench_scale(rod);
  Vector6d F;
  if (std::holds_alternative<FreeTip>(tip)) return S;
  F << 1.0, 1.0, 1.0, 1.0, 1.0, 1.0;  // m, rad
  if (const auto* grasp = std::get_if<GraspedTip>(&tip)) {
    for (int i = 0; i < 6; ++i)
      if (grasp->released[i]) F[i] = S[i];
  }
  return F;
}

/// Compares the exact Jacobian with central differences, both in the scaled unknown ξ and with each
/// row divided by F_i, so that one bound applies to every entry.
::testing::AssertionResult jacobian_matches_finite_differences(const ClampedRod& rod,
                                                               const TipCondition& tip,
                                                               const BaseWrench& w) {
  const Vector6d S = testing::wrench_scale(rod);
  const Vector6d F = row_sizes(rod, tip);
  const double delta = 16.0 * rod.intervals * kEps;  // per unit F
  const double eta = std::cbrt(3.0 * delta / kMu);
  const double bound = eta * eta * kMu / 6.0 + delta / eta;

  Vector6d r0;
  const Matrix6d J = testing::residual_jacobian(rod, tip, w, &r0);
  Matrix6d fd;
  for (int j = 0; j < 6; ++j) {
    Vector6d step = Vector6d::Zero();
    step(j) = eta * S(j);
    const Vector6d r_plus =
        shooting_residual(tip, integrate(rod, Wrench::from_vector(w.to_vector() + step)));
    const Vector6d r_minus =
        shooting_residual(tip, integrate(rod, Wrench::from_vector(w.to_vector() - step)));
    fd.col(j) = (r_plus - r_minus) / (2.0 * eta);
  }
  const Matrix6d exact_scaled = F.cwiseInverse().asDiagonal() * J * S.asDiagonal();
  const Matrix6d fd_scaled = F.cwiseInverse().asDiagonal() * fd;
  // The residual must be far from zero, or the Jacobian of the rotation rows would only be tested
  // where J_r⁻¹(θ) ≈ I.
  if (r0.cwiseQuotient(F).lpNorm<Eigen::Infinity>() < 0.1)
    return ::testing::AssertionFailure()
           << "test set-up: residual too small, r = " << r0.transpose();
  return CompareMatrices(exact_scaled, fd_scaled, bound);
}

Pose rotated_target() {
  Pose target;
  target.position = Eigen::Vector3d(0.25, 0.1, 0.35);
  target.rotation = exp_so3(Eigen::Vector3d(0.9, 0.4, -1.1));  // |θ| ≈ 1.5 rad, away from π
  return target;
}

class ShootingResidualJacobian : public ::testing::TestWithParam<ConstitutiveModel> {};

TEST_P(ShootingResidualJacobian, FreeTipMatchesFiniteDifferences) {
  const ClampedRod rod = general_band(GetParam());
  const FreeTip tip{{Eigen::Vector3d(0.1, -0.2, 0.05), Eigen::Vector3d(0.01, 0.02, -0.03)}};
  EXPECT_TRUE(jacobian_matches_finite_differences(rod, tip, general_wrench(rod)));
}

TEST_P(ShootingResidualJacobian, ClampedTipWithRotatedTargetMatchesFiniteDifferences) {
  const ClampedRod rod = general_band(GetParam());
  EXPECT_TRUE(
      jacobian_matches_finite_differences(rod, ClampedTip{rotated_target()}, general_wrench(rod)));
}

TEST_P(ShootingResidualJacobian, GraspedTipWithReleasedMomentXMatchesFiniteDifferences) {
  const ClampedRod rod = general_band(GetParam());
  GraspedTip tip{rotated_target(), {}};
  tip.released[3] = true;  // mx
  EXPECT_TRUE(jacobian_matches_finite_differences(rod, tip, general_wrench(rod)));
}

TEST_P(ShootingResidualJacobian, GraspedTipWithReleasedForceYAndMomentZMatchesFiniteDifferences) {
  const ClampedRod rod = general_band(GetParam());
  GraspedTip tip{rotated_target(), {}};
  tip.released[1] = true;  // fy
  tip.released[5] = true;  // mz
  EXPECT_TRUE(jacobian_matches_finite_differences(rod, tip, general_wrench(rod)));
}

TEST_P(ShootingResidualJacobian, GraspedTipWithEveryAxisReleasedMatchesFiniteDifferences) {
  const ClampedRod rod = general_band(GetParam());
  GraspedTip tip{rotated_target(), {}};
  tip.released.fill(true);
  EXPECT_TRUE(jacobian_matches_finite_differences(rod, tip, general_wrench(rod)));
}

INSTANTIATE_TEST_SUITE_P(BothModels,
                         ShootingResidualJacobian,
                         ::testing::Values(ConstitutiveModel::Cosserat,
                                           ConstitutiveModel::Kirchhoff),
                         [](const auto& info) { return to_string(info.param); });

// ---- identities
// -----------------------------------------------------------------------------------

// The residual of a held tip at the pose a forward solve ends at is zero up to the round-off of
// R_dᵀR(L) - I (a few ε) — the same integration, so no discretisation error enters.
TEST(ShootingResidual, HeldTipIsZeroAtTheForwardSolvedPose) {
  const ClampedRod rod = general_band(ConstitutiveModel::Cosserat);
  const RodConfiguration c = integrate(rod, general_wrench(rod));
  const Pose tip = c.tip();
  const double round_off = 16.0 * kEps;
  EXPECT_TRUE(CompareMatrices(shooting_residual(ClampedTip{tip}, c), Vector6d::Zero(), round_off));
  // A released axis uses the tip wrench along it instead: what that row reads is R_dᵀ n(L), R_dᵀ
  // m(L).
  GraspedTip grasp{tip, {}};
  grasp.released[0] = grasp.released[4] = true;
  const Vector6d r = shooting_residual(grasp, c);
  Vector6d expected = Vector6d::Zero();
  expected[0] = (tip.rotation.transpose() * c.n.back()).x();
  expected[4] = (tip.rotation.transpose() * c.m.back()).y();
  EXPECT_TRUE(CompareMatrices(r, expected, round_off));
  EXPECT_GT(std::abs(expected[0]), 1e-3);  // the rows really are wrench rows, not pose rows
  EXPECT_GT(std::abs(expected[4]), 1e-3);
}

// Free tip: r = (n(L) - F, m(L) - M) exactly, sign and order included.
TEST(ShootingResidual, FreeTipIsTheTipWrenchMinusTheLoad) {
  const ClampedRod rod = general_band(ConstitutiveModel::Cosserat);
  const RodConfiguration c = integrate(rod, general_wrench(rod));
  const Wrench load{Eigen::Vector3d(1.0, 2.0, 3.0), Eigen::Vector3d(-0.1, -0.2, -0.3)};
  Vector6d expected;
  expected << c.n.back() - load.force, c.m.back() - load.moment;
  EXPECT_TRUE(CompareMatrices(shooting_residual(FreeTip{load}, c), expected, 0.0));
}

// The rotation rows are log(R_dᵀ R(L)) in the grasp frame: a target rotated by a known angle about
// a known grasp axis from the reached pose reads minus that rotation vector.
TEST(ShootingResidual, HeldTipRotationRowsAreTheLogInTheGraspFrame) {
  const ClampedRod rod = general_band(ConstitutiveModel::Cosserat);
  const RodConfiguration c = integrate(rod, general_wrench(rod));
  const Eigen::Vector3d phi(0.3, -0.2, 0.1);
  const Eigen::Vector3d offset(0.01, 0.02, -0.03);  // grasp frame
  Pose target;
  target.rotation = c.R.back() * exp_so3(phi);              // R_dᵀ R(L) = exp(-φ)
  target.position = c.p.back() - target.rotation * offset;  // R_dᵀ (p(L) - p_d) = offset
  Vector6d expected;
  expected << offset, -phi;
  EXPECT_TRUE(CompareMatrices(shooting_residual(ClampedTip{target}, c), expected, 16.0 * kEps));
}

}  // namespace
}  // namespace test_shooting_residual
}  // namespace rodshape
