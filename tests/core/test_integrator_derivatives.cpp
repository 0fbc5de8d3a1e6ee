// test_integrator_derivatives.cpp: the integrator's derivatives with respect to the base wrench
// (every node with Derivatives::AllNodes, the tip_* fields with Derivatives::Tip, denergy_dw)
// against central finite differences of integrate(), for both constitutive models.
//
// Error model. The integrator differentiates its own discrete map (RK4 on the variational
// equations with the same stages), so its derivatives are exact up to round-off and the only error
// is the finite difference's. In the scaled variable ξ_j = w_j / S_j (S = EI/L² for forces, EI/L
// for moments, so that ξ ~ 1 bends the rod by ~1 rad) a central difference of an output f of size F
// errs by
//     |FD - ∂f/∂ξ_j| ≤ η² M₃ / 6 + δ / η,
// with M₃ = |∂³f/∂ξ³| ≤ μ F (μ = 10: the outputs are trigonometric-like in ξ, with third
// derivatives of order F at ξ ~ 1; μ = 10 is a margin over the ~1 of the arc's p(L) = L (1 - cos
// ξ)/ξ) and δ the round-off of one evaluation, δ = 16 N ε F (N steps, as in rk4_error_bound). η =
// (3δ/M₃)^(1/3) minimises the sum. For N = 20: η ≈ 2.8e-5 and the bound is ≈ 3.8e-9 F — five orders
// of magnitude below the O(1e-4…1) errors of a dropped or mis-signed term in the variational
// equations.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <string>

#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/core/so3.hpp"
#include "support/analytic_rods.hpp"
#include "support/eigen_compare.hpp"

namespace rodshape {
namespace test_integrator_derivatives {
namespace {

using testing::CompareMatrices;
using testing::kEps;

constexpr double kMu = 10.0;  // M₃ ≤ μ F, see above

struct FdProblem {
  ClampedRod rod;
  BaseWrench w;
  Vector6d S;  // scale of each wrench component
};

/// The rubber band of the paper (EIx ≠ EIy here), precurved, tilted, under gravity, with a base
/// wrench that bends it by O(1) rad in 3D and twists it.
FdProblem make_problem(ConstitutiveModel model) {
  FdProblem problem;
  ClampedRod& rod = problem.rod;
  rod.properties.length = 0.29;
  rod.properties.model = model;
  rod.properties.K_rot = Eigen::Vector3d(0.04, 0.03, 0.028);
  rod.properties.K_tra = Eigen::Vector3d(30.0, 40.0, 1280.0);  // soft shear: shear strain ~1%
  rod.properties.u_rest = Eigen::Vector3d(0.5, -0.3, 1.0);
  rod.properties.mass_per_length = 0.5568;
  rod.load = DistributedLoad::gravity(0.5568, Eigen::Vector3d(0.0, -9.81, 0.0));
  rod.clamp.position = Eigen::Vector3d(0.1, 0.2, 0.3);
  rod.clamp.rotation = exp_so3(Eigen::Vector3d(0.2, -0.5, 0.3));
  rod.intervals = 20;
  rod.validate();
  const double L = rod.properties.length, EI = 0.035;
  problem.S << Eigen::Vector3d::Constant(EI / (L * L)), Eigen::Vector3d::Constant(EI / L);
  Vector6d xi;
  xi << 0.6, -0.4, 0.3, 0.7, -0.5, 0.4;  // O(1): genuinely nonlinear
  problem.w = Wrench::from_vector(xi.cwiseProduct(problem.S));
  return problem;
}

struct FiniteDifferences {
  double eta = 0.0;    // step in ξ
  double bound = 0.0;  // error bound per unit F, in ξ
  RodConfiguration plus[6], minus[6];
};

FiniteDifferences finite_differences(const FdProblem& problem) {
  FiniteDifferences fd;
  const double delta = 16.0 * problem.rod.intervals * kEps;  // per unit F
  fd.eta = std::cbrt(3.0 * delta / kMu);
  fd.bound = fd.eta * fd.eta * kMu / 6.0 + delta / fd.eta;
  for (int j = 0; j < 6; ++j) {
    Vector6d step = Vector6d::Zero();
    step(j) = fd.eta * problem.S(j);
    fd.plus[j] = integrate(problem.rod, Wrench::from_vector(problem.w.to_vector() + step));
    fd.minus[j] = integrate(problem.rod, Wrench::from_vector(problem.w.to_vector() - step));
  }
  return fd;
}

double max_norm(const std::vector<Eigen::Vector3d>& values) {
  double out = 0.0;
  for (const auto& v : values) out = std::max(out, v.norm());
  return out;
}

/// Body-frame rotation between two nearby orientations around R0: vee of the skew part of
/// R0ᵀ (R₊ - R₋). (The symmetric part is O(η²) and carries no first-order information.)
Eigen::Vector3d body_difference(const Eigen::Matrix3d& R0,
                                const Eigen::Matrix3d& R_plus,
                                const Eigen::Matrix3d& R_minus) {
  const Eigen::Matrix3d A = R0.transpose() * (R_plus - R_minus);
  return vee(0.5 * (A - A.transpose()));
}

/// Compares a 3×6 derivative with its finite differences, column by column, with tolerance
/// bound · F / S_j (the bound is in ξ; ∂f/∂w_j = (∂f/∂ξ_j) / S_j).
void expect_columns_match(const Matrix36d& analytic,
                          const Matrix36d& numeric,
                          const Vector6d& S,
                          double bound,
                          double F,
                          const std::string& what) {
  for (int j = 0; j < 6; ++j)
    EXPECT_TRUE(CompareMatrices(analytic.col(j), numeric.col(j), bound * F / S(j)))
        << what << ", column " << j;
}

class IntegratorDerivatives : public ::testing::TestWithParam<ConstitutiveModel> {};

TEST_P(IntegratorDerivatives, EveryNodeMatchesCentralFiniteDifferences) {
  const FdProblem problem = make_problem(GetParam());
  const RodConfiguration c = integrate(problem.rod, problem.w, Derivatives::AllNodes);
  ASSERT_EQ(c.derivatives, Derivatives::AllNodes);
  ASSERT_EQ(static_cast<int>(c.dp_dw.size()), c.nodes());
  ASSERT_EQ(static_cast<int>(c.dtheta_dw.size()), c.nodes());
  ASSERT_EQ(static_cast<int>(c.dn_dw.size()), c.nodes());
  ASSERT_EQ(static_cast<int>(c.dm_dw.size()), c.nodes());
  const FiniteDifferences fd = finite_differences(problem);
  const double L = problem.rod.properties.length;
  // Output sizes F: positions ~ L (plus the clamp offset), angles ~ 1, forces and moments at least
  // their characteristic scale.
  const double F_p = L + max_norm(c.p);
  const double F_n = std::max(problem.S(0), max_norm(c.n));
  const double F_m = std::max(problem.S(3), max_norm(c.m));
  for (int i = 0; i < c.nodes(); ++i) {
    Matrix36d dp, dtheta, dn, dm;
    for (int j = 0; j < 6; ++j) {
      const double h2 = 2.0 * fd.eta * problem.S(j);
      dp.col(j) = (fd.plus[j].p[i] - fd.minus[j].p[i]) / h2;
      dtheta.col(j) = body_difference(c.R[i], fd.plus[j].R[i], fd.minus[j].R[i]) / h2;
      dn.col(j) = (fd.plus[j].n[i] - fd.minus[j].n[i]) / h2;
      dm.col(j) = (fd.plus[j].m[i] - fd.minus[j].m[i]) / h2;
    }
    const std::string where = to_string(GetParam()) + ", node " + std::to_string(i);
    expect_columns_match(c.dp_dw[i], dp, problem.S, fd.bound, F_p, "dp_dw, " + where);
    expect_columns_match(c.dtheta_dw[i], dtheta, problem.S, fd.bound, 1.0, "dtheta_dw, " + where);
    expect_columns_match(c.dn_dw[i], dn, problem.S, fd.bound, F_n, "dn_dw, " + where);
    expect_columns_match(c.dm_dw[i], dm, problem.S, fd.bound, F_m, "dm_dw, " + where);
  }
  // At the clamp nothing depends on w but the wrench itself: exact zeros and identities.
  EXPECT_TRUE(CompareMatrices(c.dp_dw[0], Matrix36d::Zero(), 0.0));
  EXPECT_TRUE(CompareMatrices(c.dtheta_dw[0], Matrix36d::Zero(), 0.0));
  EXPECT_TRUE(CompareMatrices(
      c.dn_dw[0], (Matrix36d() << Eigen::Matrix3d::Identity(), Eigen::Matrix3d::Zero()).finished(),
      0.0));
  EXPECT_TRUE(CompareMatrices(
      c.dm_dw[0], (Matrix36d() << Eigen::Matrix3d::Zero(), Eigen::Matrix3d::Identity()).finished(),
      0.0));
}

TEST_P(IntegratorDerivatives, TipDerivativesAndEnergyGradientMatchCentralFiniteDifferences) {
  const FdProblem problem = make_problem(GetParam());
  const RodConfiguration c = integrate(problem.rod, problem.w, Derivatives::Tip);
  ASSERT_EQ(c.derivatives, Derivatives::Tip);
  EXPECT_TRUE(c.dp_dw.empty());  // per-node derivatives only with AllNodes
  EXPECT_TRUE(c.dtheta_dw.empty());
  const FiniteDifferences fd = finite_differences(problem);
  const double L = problem.rod.properties.length;
  Matrix36d dp, dtheta, dn, dm;
  Eigen::Matrix<double, 1, 6> dE;
  for (int j = 0; j < 6; ++j) {
    const double h2 = 2.0 * fd.eta * problem.S(j);
    dp.col(j) = (fd.plus[j].p.back() - fd.minus[j].p.back()) / h2;
    dtheta.col(j) = body_difference(c.R.back(), fd.plus[j].R.back(), fd.minus[j].R.back()) / h2;
    dn.col(j) = (fd.plus[j].n.back() - fd.minus[j].n.back()) / h2;
    dm.col(j) = (fd.plus[j].m.back() - fd.minus[j].m.back()) / h2;
    dE(j) = (fd.plus[j].energy - fd.minus[j].energy) / h2;
  }
  const std::string model = to_string(GetParam());
  expect_columns_match(c.tip_dp_dw, dp, problem.S, fd.bound, L + c.p.back().norm(),
                       "tip_dp_dw, " + model);
  expect_columns_match(c.tip_dtheta_dw, dtheta, problem.S, fd.bound, 1.0,
                       "tip_dtheta_dw, " + model);
  expect_columns_match(c.tip_dn_dw, dn, problem.S, fd.bound,
                       std::max(problem.S(0), c.n.back().norm()), "tip_dn_dw, " + model);
  expect_columns_match(c.tip_dm_dw, dm, problem.S, fd.bound,
                       std::max(problem.S(3), c.m.back().norm()), "tip_dm_dw, " + model);
  // Energy size: EI/L (one radian of bending), or the energy itself if larger.
  const double F_E = std::max(problem.S(3), c.energy);
  for (int j = 0; j < 6; ++j)
    EXPECT_TRUE(testing::CompareScalars(c.denergy_dw(j), dE(j), fd.bound * F_E / problem.S(j)))
        << "denergy_dw, " << model << ", column " << j;
}

// The three derivative levels run the same primal computation, and Tip and AllNodes the same
// tangent: the shape must not depend on what was asked for, and the tip fields must equal the last
// node's.
TEST_P(IntegratorDerivatives, DerivativeLevelsAgreeWithEachOther) {
  const FdProblem problem = make_problem(GetParam());
  const RodConfiguration none = integrate(problem.rod, problem.w, Derivatives::None);
  const RodConfiguration tip = integrate(problem.rod, problem.w, Derivatives::Tip);
  const RodConfiguration all = integrate(problem.rod, problem.w, Derivatives::AllNodes);
  EXPECT_TRUE(none.dp_dw.empty());
  const double tol = 16.0 * problem.rod.intervals * kEps;  // round-off only, should be 0
  for (int i = 0; i < none.nodes(); ++i) {
    EXPECT_TRUE(CompareMatrices(tip.p[i], none.p[i], tol));
    EXPECT_TRUE(CompareMatrices(all.p[i], none.p[i], tol));
    EXPECT_TRUE(CompareMatrices(all.R[i], none.R[i], tol));
    EXPECT_TRUE(CompareMatrices(all.m[i], none.m[i], tol));
  }
  EXPECT_TRUE(testing::CompareScalars(all.energy, none.energy, tol * none.energy));
  EXPECT_TRUE(CompareMatrices(all.tip_dp_dw, all.dp_dw.back(), 0.0));
  EXPECT_TRUE(CompareMatrices(all.tip_dtheta_dw, all.dtheta_dw.back(), 0.0));
  EXPECT_TRUE(CompareMatrices(all.tip_dn_dw, all.dn_dw.back(), 0.0));
  EXPECT_TRUE(CompareMatrices(all.tip_dm_dw, all.dm_dw.back(), 0.0));
  EXPECT_TRUE(
      CompareMatrices(tip.tip_dp_dw, all.tip_dp_dw, tol, testing::MatrixCompareType::relative));
  EXPECT_TRUE(CompareMatrices(tip.tip_dtheta_dw, all.tip_dtheta_dw, tol,
                              testing::MatrixCompareType::relative));
  EXPECT_TRUE(
      CompareMatrices(tip.denergy_dw, all.denergy_dw, tol, testing::MatrixCompareType::relative));
}

// Reusing a configuration across levels must not leave stale derivatives behind.
TEST_P(IntegratorDerivatives, ReusedConfigurationTakesTheNewLevel) {
  const FdProblem problem = make_problem(GetParam());
  RodConfiguration c;
  integrate(problem.rod, problem.w, c, Derivatives::AllNodes);
  ASSERT_EQ(static_cast<int>(c.dp_dw.size()), c.nodes());
  integrate(problem.rod, problem.w, c, Derivatives::None);
  EXPECT_EQ(c.derivatives, Derivatives::None);
  EXPECT_TRUE(c.dp_dw.empty());
  EXPECT_TRUE(c.dm_dw.empty());
  integrate(problem.rod, problem.w, c, Derivatives::Tip);
  EXPECT_EQ(c.derivatives, Derivatives::Tip);
  EXPECT_TRUE(c.dtheta_dw.empty());
}

INSTANTIATE_TEST_SUITE_P(BothModels,
                         IntegratorDerivatives,
                         ::testing::Values(ConstitutiveModel::Cosserat,
                                           ConstitutiveModel::Kirchhoff),
                         [](const ::testing::TestParamInfo<ConstitutiveModel>& info) {
                           return to_string(info.param);
                         });

}  // namespace
}  // namespace test_integrator_derivatives
}  // namespace rodshape
