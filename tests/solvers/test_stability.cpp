// test_stability.cpp: the conjugate-point test (assess_stability) on equilibria whose stability is
// known in closed form.
//
// Straight rod under an end load P (compression), clamped at both ends. Linearising the Cosserat
// equations about the straight state (R = I, n = (0, 0, -P), v_z = 1 - P/EA) in the x–z plane, with
// θ the rotation about y and (δn_x, δm_y) the base-wrench perturbation:
//     δp_x' = v_z θ + δn̄_x/GA,  δn̄_x = δn_x + P θ,  δm_y' = -P δp_x' - v_z δn_x,  θ' = δm_y/EI
//  ⇒  EI θ'' = -α (P θ + δn_x),  α = 1 - P/EA + P/GA,   k² = α P / EI.
// The bending block of J = d(p_x, θ)/d(n_x, m_y) then has, with x = k s,
//     P² det = 2 - 2 cos x - x sin x + (P/(α GA)) x sin x,
// whose first positive root is x = 2π exactly (the shear term vanishes there with sin x): the first
// conjugate point is s* = 2π / k = 2π sqrt(EI / (α P)) = L sqrt(P_E / (α P)), P_E = 4π² EI / L²,
// the clamped–clamped Euler load. The extension and shear enter only through α = 1 + O(P/EA) +
// O(P/GA): with GA = 1e3 EA and P ≈ P_E ≈ 18.8 N, P/EA ≈ 1.5e-2, so P = 0.8 P_E (stable) and 1.2
// P_E (unstable, s* ≈ 0.92 L) are both 20% away from the threshold, far beyond the 1.5% correction.
// The other blocks (y–z bending with EIx, axial L/EA, torsion L/GJ) are the same or never singular.
// Discretisation: the variational equations of the straight rod are linear with constant
// coefficients; RK4 shifts their phase by (kh)⁵/120 per step, so s* moves by s* (kh)⁴/120. We allow
// ten times that plus the root finder's 1e-9 L.
//
// Buckled (elastica) shapes under end shortening: for the clamped–clamped elastica the first,
// symmetric mode is stable and the second, antisymmetric (S-shaped) mode unstable (a classical
// result; Bretl and McCarthy, IJRR 2014, find the same with this test). In 3D that holds for a rod
// that buckles about its weak axis; a round rod's planar shape is neutral (it can turn about the
// line of its clamps) — see FirstBuckledModeOfARoundRodIsNeutral.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>

#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/error.hpp"
#include "rodshape/solvers/shooting_solver.hpp"
#include "rodshape/solvers/stability.hpp"
#include "support/analytic_rods.hpp"
#include "support/eigen_compare.hpp"
#include "support/solver_fixtures.hpp"

namespace rodshape {
namespace test_stability {
namespace {

using std::numbers::pi;
using testing::CompareScalars;

/// The rubber band with a shear stiffness 1e3 EA (nearly unshearable) and the given bending
/// stiffnesses.
ClampedRod stiff_shear_band(double EIx, double EIy) {
  ClampedRod rod = testing::rubber_band(ConstitutiveModel::Cosserat, 100);
  rod.properties.K_rot.x() = EIx;
  rod.properties.K_rot.y() = EIy;
  const double EA = rod.properties.K_tra.z();
  rod.properties.K_tra.x() = rod.properties.K_tra.y() = 1e3 * EA;
  rod.validate();
  return rod;
}

double euler_load(double EI, double L) { return 4.0 * pi * pi * EI / (L * L); }

/// The straight rod compressed by P, as the integrator leaves it (with every node's derivatives).
RodConfiguration compressed(const ClampedRod& rod, double P) {
  return integrate(rod, BaseWrench{Eigen::Vector3d(0.0, 0.0, -P), Eigen::Vector3d::Zero()},
                   Derivatives::AllNodes);
}

/// s* = 2π sqrt(EI / (α P)) and its tolerance, from the header's model.
struct ConjugatePoint {
  double s = 0.0, tolerance = 0.0;
};
ConjugatePoint expected_conjugate_point(const ClampedRod& rod, double EI, double P) {
  const double alpha = 1.0 - P / rod.properties.K_tra.z() + P / rod.properties.K_tra.x();
  const double k = std::sqrt(alpha * P / EI);
  const double kh = k * rod.step();
  ConjugatePoint c;
  c.s = 2.0 * pi / k;
  c.tolerance = c.s * std::pow(kh, 4) / 12.0 + 1e-9 * rod.properties.length;
  return c;
}

// ---- straight rods
// --------------------------------------------------------------------------------

class StraightCompressedRod : public ::testing::TestWithParam<double> {};  // param: EIy / EIx

TEST_P(StraightCompressedRod, StableBelowTheClampedClampedEulerLoad) {
  const ClampedRod rod = stiff_shear_band(0.04, 0.04 * GetParam());
  const double P = 0.8 * euler_load(0.04, rod.properties.length);  // EIx = min(EIx, EIy)
  const StabilityResult report = assess_stability(rod, compressed(rod, P));
  EXPECT_TRUE(report.stable);
  EXPECT_FALSE(report.degenerate);
  EXPECT_FALSE(report.conjugate_point_s.has_value());
  EXPECT_GT(report.min_singular_value, 0.0);
  EXPECT_GT(report.tip_singular_value, 0.0);
}

TEST_P(StraightCompressedRod, UnstableBeyondItWithTheConjugatePointWhereSqrtPOverEITimesSIsTwoPi) {
  const ClampedRod rod = stiff_shear_band(0.04, 0.04 * GetParam());
  const double L = rod.properties.length;
  const double P = 1.2 * euler_load(0.04, L);
  const StabilityResult report = assess_stability(rod, compressed(rod, P));
  EXPECT_FALSE(report.stable);
  EXPECT_FALSE(report.degenerate);
  ASSERT_TRUE(report.conjugate_point_s.has_value());
  const ConjugatePoint expected = expected_conjugate_point(rod, 0.04, P);
  EXPECT_TRUE(CompareScalars(*report.conjugate_point_s, expected.s, expected.tolerance));
  // Without the O(P/EA) correction the prediction L sqrt(P_E/P) is off by ~0.7%: the test resolves
  // it.
  std::cout << "[ conjugate point ] EIy/EIx = " << GetParam()
            << ": s* = " << *report.conjugate_point_s << " m, 2π/k = " << expected.s << " m (±"
            << expected.tolerance << "), L sqrt(P_E/P) = " << L * std::sqrt(1.0 / 1.2) << " m\n";
  EXPECT_EQ(report.min_singular_value, 0.0);
}

// A larger load moves the first conjugate point towards the clamp as 1/sqrt(P).
TEST_P(StraightCompressedRod, ConjugatePointMovesAsOneOverSqrtP) {
  const ClampedRod rod = stiff_shear_band(0.04, 0.04 * GetParam());
  for (double factor : {1.5, 2.0, 3.0}) {
    const double P = factor * euler_load(0.04, rod.properties.length);
    const StabilityResult report = assess_stability(rod, compressed(rod, P));
    SCOPED_TRACE("P = " + std::to_string(factor) + " P_E");
    ASSERT_TRUE(report.conjugate_point_s.has_value());
    const ConjugatePoint expected = expected_conjugate_point(rod, 0.04, P);
    EXPECT_TRUE(CompareScalars(*report.conjugate_point_s, expected.s, expected.tolerance));
  }
}

// EIy/EIx = 1: a round-like rod, both bending blocks singular at the same s (a double root: det J
// keeps its sign). 1.5: distinct roots, the first one from the weaker axis (EIx).
INSTANTIATE_TEST_SUITE_P(BendingStiffnessRatio,
                         StraightCompressedRod,
                         ::testing::Values(1.0, 1.5),
                         [](const auto& info) {
                           return info.param == 1.0 ? "EqualEI" : "UnequalEI";
                         });

// The unloaded straight Cosserat rod: J(s) is the compliance C(s) of the straight rod of length s,
// so the normalised J̃ = J C⁻¹ is the identity at every node (RK4 is exact on the unloaded rod,
// whose variational solution is polynomial of degree 3 in s): σ_min = 1 up to round-off, amplified
// by cond(C(h)) ≈ (L/h)² EA h² / EI... ≲ 1e6 at the first node; 1e-6 covers ε·1e6 with margin.
TEST(Stability, UnloadedStraightCosseratRodIsStableWithUnitSingularValues) {
  const ClampedRod rod = testing::rubber_band(ConstitutiveModel::Cosserat, 100);
  const StabilityResult report = assess_stability(rod, integrate(rod, {}, Derivatives::AllNodes));
  EXPECT_TRUE(report.stable);
  EXPECT_FALSE(report.degenerate);
  EXPECT_FALSE(report.conjugate_point_s.has_value());
  EXPECT_TRUE(CompareScalars(report.min_singular_value, 1.0, 1e-6));
  EXPECT_TRUE(CompareScalars(report.tip_singular_value, 1.0, 1e-6));
}

// A straight Kirchhoff rod cannot move its tip along its tangent: dp/dn_z = 0 at every node, the
// test does not apply.
TEST(Stability, StraightKirchhoffRodIsDegenerate) {
  const ClampedRod rod = testing::rubber_band(ConstitutiveModel::Kirchhoff, 100);
  for (double P : {0.0, 0.5 * euler_load(testing::kBandEI, rod.properties.length)}) {
    SCOPED_TRACE("P = " + std::to_string(P));
    const StabilityResult report = assess_stability(rod, compressed(rod, P));
    EXPECT_TRUE(report.degenerate);
    EXPECT_FALSE(report.stable);
  }
}

TEST(Stability, NeedsEveryNodesDerivatives) {
  const ClampedRod rod = testing::rubber_band();
  EXPECT_THROW(assess_stability(rod, integrate(rod, {}, Derivatives::Tip)), InputError);
  EXPECT_THROW(assess_stability(rod, integrate(rod, {}, Derivatives::None)), InputError);
  ClampedRod coarser = rod;
  coarser.intervals = 50;
  EXPECT_THROW(assess_stability(rod, integrate(coarser, {}, Derivatives::AllNodes)), InputError);
}

// ---- buckled shapes
// -------------------------------------------------------------------------------

struct BuckledMode {
  ShootingResult solution;
  double symmetry_tolerance = 0.0;  // m
};

/// Clamped–clamped with the tip at (0, 0, 0.8 L) and the clamp's rotation, solved from `guess`.
/// The symmetry tolerance: each half of the discrete shape is within rk4_error_bound of the exact
/// (symmetric or antisymmetric) elastica, and the solver's residual τ moves the shape by at most
/// max_i ||dp_i/dw||_∞ ||J⁻¹||_∞ τ.
BuckledMode buckle(const ClampedRod& rod, const BaseWrench& guess) {
  const double L = rod.properties.length;
  ClampedTip tip;
  tip.pose.position = Eigen::Vector3d(0.0, 0.0, 0.8 * L);
  BuckledMode mode;
  mode.solution = solve_equilibrium(rod, tip, guess);
  const RodConfiguration& c = mode.solution.configuration;
  double kappa_max = 0.0, dp_dw_max = 0.0;
  for (int i = 0; i < c.nodes(); ++i) {
    kappa_max = std::max(kappa_max, c.u[i].norm());
    dp_dw_max = std::max(dp_dw_max, c.dp_dw[i].cwiseAbs().rowwise().sum().maxCoeff());
  }
  const Matrix6d J = testing::residual_jacobian(rod, tip, mode.solution.base_wrench);
  mode.symmetry_tolerance =
      2.0 * testing::rk4_error_bound(L, kappa_max, rod.intervals) +
      2.0 * dp_dw_max * testing::inverse_inf_norm(J) * ShootingOptions{}.residual_tolerance;
  return mode;
}

/// The rubber band buckled under 20% end shortening. EIy = 1.5 EIx: it buckles about its weak axis
/// (x), in the y–z plane, and the plane cannot turn (with EIx = EIy it could, at no cost: see
/// FirstBuckledModeOfARoundRodIsNeutral).
ClampedRod buckling_band(ConstitutiveModel model, double EIy = 1.5 * testing::kBandEI) {
  ClampedRod rod = testing::rubber_band(model, 100);
  rod.properties.K_rot.y() = EIy;
  rod.validate();
  return rod;
}

/// The first mode: a compression a little above P_E and a base moment about x of one bending unit
/// (the brief's 0.05 EI/L starts too close to the straight rod and converges to a higher mode).
BuckledMode first_mode(const ClampedRod& rod) {
  const double L = rod.properties.length, EI = testing::kBandEI;
  const double P_E = euler_load(EI, L);
  return buckle(rod, {Eigen::Vector3d(0.0, 0.0, -1.05 * P_E), Eigen::Vector3d(EI / L, 0.0, 0.0)});
}

/// The second mode: it has an inflection point at s = L/2, where m_x = 0. With m_x' ≈ n_y along a
/// nearly straight rod, the guess m_x(0) = -n_y L/2 starts from that shape; its compression is near
/// the second critical load, (8.99/2π)² P_E ≈ 2.05 P_E.
BuckledMode second_mode(const ClampedRod& rod) {
  const double L = rod.properties.length;
  const double P_E = euler_load(testing::kBandEI, L);
  const double V = 0.5 * P_E;
  return buckle(rod,
                {Eigen::Vector3d(0.0, V, -2.05 * P_E), Eigen::Vector3d(-V * L / 2.0, 0.0, 0.0)});
}

/// p_y(s) = sign · p_y(L - s), p_z(s) = 0.8 L - p_z(L - s), p_x = 0 at every node.
void expect_mirror_symmetry(const BuckledMode& mode, double sign, double L) {
  const RodConfiguration& c = mode.solution.configuration;
  const int N = c.nodes() - 1;
  for (int i = 0; i <= N; ++i) {
    SCOPED_TRACE("node " + std::to_string(i));
    EXPECT_TRUE(CompareScalars(c.p[i].y(), sign * c.p[N - i].y(), mode.symmetry_tolerance));
    EXPECT_TRUE(CompareScalars(c.p[i].z(), 0.8 * L - c.p[N - i].z(), mode.symmetry_tolerance));
    EXPECT_TRUE(CompareScalars(c.p[i].x(), 0.0, mode.symmetry_tolerance));
  }
}

TEST(Stability, FirstBuckledModeIsSymmetricAndStable) {
  const ClampedRod rod = buckling_band(ConstitutiveModel::Cosserat);
  const double L = rod.properties.length;
  const BuckledMode mode = first_mode(rod);
  const ShootingResult& solution = mode.solution;
  ASSERT_EQ(solution.summary.status, SolveStatus::Converged) << solution.summary.brief();
  std::cout << "[ buckled mode 1 ] " << solution.summary.brief()
            << ", w = " << solution.base_wrench.to_vector().transpose() << "\n";
  const RodConfiguration& c = solution.configuration;
  const int N = c.nodes() - 1;
  // Buckled, not straight: the midpoint is well off the axis; no lateral force (symmetric mode).
  EXPECT_GT(std::abs(c.p[N / 2].y()), 0.05 * L);
  expect_mirror_symmetry(mode, +1.0, L);
  const StabilityResult report = assess_stability(rod, c);
  EXPECT_TRUE(report.stable);
  EXPECT_FALSE(report.degenerate);
  EXPECT_FALSE(report.conjugate_point_s.has_value());
  EXPECT_GT(report.min_singular_value, 0.0);
  EXPECT_GT(report.tip_singular_value, 0.0);
}

TEST(Stability, SecondBuckledModeIsAntisymmetricAndUnstable) {
  const ClampedRod rod = buckling_band(ConstitutiveModel::Cosserat);
  const double L = rod.properties.length;
  const BuckledMode mode = second_mode(rod);
  const ShootingResult& solution = mode.solution;
  ASSERT_EQ(solution.summary.status, SolveStatus::Converged) << solution.summary.brief();
  std::cout << "[ buckled mode 2 ] " << solution.summary.brief()
            << ", w = " << solution.base_wrench.to_vector().transpose() << "\n";
  const RodConfiguration& c = solution.configuration;
  const int N = c.nodes() - 1;
  // S-shaped: off the axis at the quarter points, on it at the middle.
  EXPECT_GT(std::abs(c.p[N / 4].y()), 0.02 * L);
  expect_mirror_symmetry(mode, -1.0, L);
  const StabilityResult report = assess_stability(rod, c);
  EXPECT_FALSE(report.stable);
  EXPECT_FALSE(report.degenerate);
  ASSERT_TRUE(report.conjugate_point_s.has_value());
  // An interior conjugate point: a genuine instability, not the neutral direction at s = L.
  EXPECT_GT(*report.conjugate_point_s, 2.0 * rod.step());
  EXPECT_LT(*report.conjugate_point_s, L - rod.step());
  std::cout << "[ buckled mode 2 ] conjugate point at s = " << *report.conjugate_point_s << " m\n";
}

// With EIx = EIy the planar buckled shape can turn about the line of its clamps at no cost (rotate
// the shape by φ about z and each section by -φ about its tangent: the bending energy is unchanged
// and both clamp frames are kept). J(L) is singular along that direction: a conjugate point exactly
// at s = L, reported as degenerate (neutral), not stable.
TEST(Stability, FirstBuckledModeOfARoundRodIsNeutral) {
  const ClampedRod rod = buckling_band(ConstitutiveModel::Cosserat, testing::kBandEI);
  const BuckledMode mode = first_mode(rod);
  ASSERT_EQ(mode.solution.summary.status, SolveStatus::Converged) << mode.solution.summary.brief();
  expect_mirror_symmetry(mode, +1.0, rod.properties.length);
  const StabilityResult report = assess_stability(rod, mode.solution.configuration);
  EXPECT_FALSE(report.stable);
  EXPECT_TRUE(report.degenerate);
  // `degenerate` alone may also mean "J̃ singular along the whole rod" (no conjugate point).
  ASSERT_TRUE(report.conjugate_point_s.has_value());
  // That the point is at s = L restates the degenerate rule; check the reason instead: J(L) is
  // singular along the turn. The turned equilibria have base wrench Rz(φ) w and, the discrete
  // integration being exactly equivariant for a round section, tip pose Rz(φ) p(L) and
  // Rz(φ) R(L) Rz(-φ) (body twist): d/dφ = (ẑ × p(L), R(L)ᵀẑ - ẑ), of size ≤ √3 τ each since the
  // solver holds the tip on the z axis with R(L) = I to τ. In the scaled unknowns ξ = w / S, with
  // positions in units of L, that bounds |J̃ δξ| by √3 τ (1/L + 1), plus the round-off of the
  // derivatives (16 N ε of |J̃| |δξ|); a wrong Jacobian or a shape that is not the planar mode
  // gives |J̃ δξ| of the order of |J̃| |δξ| ≈ 8.
  const RodConfiguration& c = mode.solution.configuration;
  const double L = rod.properties.length;
  const Vector6d S = testing::wrench_scale(rod);
  Vector6d dw;
  dw << Eigen::Vector3d::UnitZ().cross(c.n[0]), Eigen::Vector3d::UnitZ().cross(c.m[0]);
  const Vector6d dxi = dw.cwiseQuotient(S);
  ASSERT_GT(dxi.norm(), 1.0);  // a genuine direction (the planar mode's m(0) is not along z)
  Matrix6d J;
  J << c.dp_dw.back() / L, c.dtheta_dw.back();
  J = J * S.asDiagonal();
  const double tau = ShootingOptions{}.residual_tolerance;
  EXPECT_LE((J * dxi).norm(), std::sqrt(3.0) * tau * (1.0 / L + 1.0) +
                                  16.0 * rod.intervals * testing::kEps * J.norm() * dxi.norm())
      << "|J̃| |δξ| = " << J.norm() * dxi.norm();
}

// The same modes for the Kirchhoff rod: the first is stable, the second unstable at an interior
// point.
TEST(Stability, BuckledModesOfAKirchhoffRod) {
  const ClampedRod rod = buckling_band(ConstitutiveModel::Kirchhoff);
  const double L = rod.properties.length;
  const BuckledMode first = first_mode(rod);
  ASSERT_EQ(first.solution.summary.status, SolveStatus::Converged)
      << first.solution.summary.brief();
  expect_mirror_symmetry(first, +1.0, L);
  const StabilityResult first_report = assess_stability(rod, first.solution.configuration);
  EXPECT_TRUE(first_report.stable);
  EXPECT_FALSE(first_report.degenerate);
  EXPECT_FALSE(first_report.conjugate_point_s.has_value())
      << "conjugate point at s = " << first_report.conjugate_point_s.value_or(-1.0)
      << " m (h = " << rod.step() << " m)";

  const BuckledMode second = second_mode(rod);
  ASSERT_EQ(second.solution.summary.status, SolveStatus::Converged)
      << second.solution.summary.brief();
  expect_mirror_symmetry(second, -1.0, L);
  const StabilityResult second_report = assess_stability(rod, second.solution.configuration);
  EXPECT_FALSE(second_report.stable);
  ASSERT_TRUE(second_report.conjugate_point_s.has_value());
  EXPECT_GT(*second_report.conjugate_point_s, 2.0 * rod.step())
      << "a conjugate point within the first interval moves with h: not the rod's";
  EXPECT_LT(*second_report.conjugate_point_s, L - rod.step());
}

}  // namespace
}  // namespace test_stability
}  // namespace rodshape
