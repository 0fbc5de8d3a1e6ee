// test_base_pose_derivatives.cpp: the derivatives of every node's state with respect to the clamp
// pose at a fixed body-frame base wrench (base_pose_derivatives), and the private load tangent
// they are built from (detail::integrate_load_tangent), against central finite differences of
// integrate().
//
// Finite differences. The clamp is moved by ξ = (δt, δφ): p0 + δt, exp([δφ]×) R0, and the world
// base wrench recomputed as (R0' n_b, R0' m_b). Steps are η = 1e-5 in the scaled variable ξ_j / S_j
// (S = L for a translation, 1 rad for a rotation; for the load, S = EI/L³ for f and EI/L² for l, a
// load that bends the rod by ~1 rad). Both sides are derivatives of the same discrete map, so the
// only error is the difference's: truncation η² M₃ / 6 ≈ 1.7e-10 μ F (M₃ ≤ μ F, the outputs being
// trigonometric-like in ξ, μ ~ 1) plus round-off δ / η, δ the round-off of one integration (a few ε
// F over these 20–60 steps: ~1e-15 F, so ~1e-10 F). Errors are measured per unit F and ξ, F the
// output's size (L + max |p| for p, 1 rad for θ, max(EI/L², max |n|) for n, max(EI/L, max |m|) for
// m, max(EI/L, E) for E); the worst seen is 2e-10 (the load tangent's n with 3 sub-steps), most are
// 1e-11…6e-11 (recorded as test properties fd_error_*). The tolerance is 1e-8: a dropped or
// mis-signed load term errs by 0.06…2 (checked by flipping the sign of the load part).
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/load_tangent.hpp"
#include "rodshape/core/base_pose_derivatives.hpp"
#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/core/so3.hpp"
#include "support/eigen_compare.hpp"

namespace rodshape {
namespace test_base_pose_derivatives {
namespace {

using testing::CompareMatrices;

constexpr double kEta = 1e-5;        // finite-difference step in ξ
constexpr double kTolerance = 1e-8;  // per unit F and ξ, see above

enum class Load { None, Gravity, Moment, GravityAndMoment };

struct Case {
  ConstitutiveModel model;
  Load load;
  int substeps;
};

std::string load_name(Load load) {
  switch (load) {
    case Load::None:
      return "NoLoad";
    case Load::Gravity:
      return "Gravity";
    case Load::Moment:
      return "MomentLoad";
    case Load::GravityAndMoment:
      return "GravityAndMomentLoad";
  }
  return "";
}

std::string case_name(const Case& c) {
  return to_string(c.model) + "_" + load_name(c.load) + "_Substeps" + std::to_string(c.substeps);
}

constexpr double kEI = 0.035;  // a representative bending stiffness, N·m²

/// The paper's rubber band (EIx ≠ EIy here), precurved, with a soft shear, the clamp away from the
/// origin and tilted, and a body-frame base wrench that bends it by O(1) rad in 3D and twists it.
struct Problem {
  ClampedRod rod;
  Wrench body_wrench;  // (n_b, m_b) = R0ᵀ (n(0), m(0))
};

Problem make_problem(const Case& c) {
  Problem problem;
  ClampedRod& rod = problem.rod;
  rod.properties.length = 0.29;
  rod.properties.model = c.model;
  rod.properties.K_rot = Eigen::Vector3d(0.04, 0.03, 0.028);
  rod.properties.K_tra = Eigen::Vector3d(30.0, 40.0, 1280.0);
  rod.properties.u_rest = Eigen::Vector3d(0.5, -0.3, 1.0);
  rod.properties.mass_per_length = 0.5568;
  if (c.load == Load::Gravity || c.load == Load::GravityAndMoment)
    rod.load = DistributedLoad::gravity(0.5568, Eigen::Vector3d(0.0, -9.81, 0.0));
  if (c.load == Load::Moment || c.load == Load::GravityAndMoment)
    rod.load.moment = Eigen::Vector3d(0.3, -0.2, 0.25);  // N·m/m, ~EI/L²
  rod.clamp.position = Eigen::Vector3d(0.1, 0.2, 0.3);
  rod.clamp.rotation = exp_so3(Eigen::Vector3d(0.2, -0.5, 0.3));
  rod.intervals = 20;
  rod.substeps = c.substeps;
  rod.validate();
  const double L = rod.properties.length;
  problem.body_wrench = {Eigen::Vector3d(0.6, -0.4, 0.3) * (kEI / (L * L)),
                         Eigen::Vector3d(0.7, -0.5, 0.4) * (kEI / L)};
  return problem;
}

BaseWrench world_wrench(const ClampedRod& rod, const Wrench& body) {
  return {rod.clamp.rotation * body.force, rod.clamp.rotation * body.moment};
}

/// Derivatives of every node's p, θ (body frame), n, m and of the energy, 6 columns.
struct Jacobians {
  std::vector<Matrix36d> dp, dtheta, dn, dm;
  Eigen::Matrix<double, 1, 6> dE;
};

/// Central differences: `perturbed(j, t)` integrates the problem moved by t along direction j;
/// steps(j) is that direction's step (η S_j). The rotation is compared as log(R_iᵀ R_i±).
template <class Perturbed>
Jacobians central_differences(const RodConfiguration& c,
                              const Eigen::Matrix<double, 6, 1>& steps,
                              Perturbed perturbed) {
  const int nodes = c.nodes();
  Jacobians fd{std::vector<Matrix36d>(nodes), std::vector<Matrix36d>(nodes),
               std::vector<Matrix36d>(nodes), std::vector<Matrix36d>(nodes),
               Eigen::Matrix<double, 1, 6>::Zero()};
  for (int j = 0; j < 6; ++j) {
    const RodConfiguration plus = perturbed(j, steps(j));
    const RodConfiguration minus = perturbed(j, -steps(j));
    const double h2 = 2.0 * steps(j);
    for (int i = 0; i < nodes; ++i) {
      fd.dp[i].col(j) = (plus.p[i] - minus.p[i]) / h2;
      fd.dtheta[i].col(j) =
          (log_so3(c.R[i].transpose() * plus.R[i]) - log_so3(c.R[i].transpose() * minus.R[i])) / h2;
      fd.dn[i].col(j) = (plus.n[i] - minus.n[i]) / h2;
      fd.dm[i].col(j) = (plus.m[i] - minus.m[i]) / h2;
    }
    fd.dE(j) = (plus.energy - minus.energy) / h2;
  }
  return fd;
}

std::string scientific(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2e", x);
  return text;
}

double max_norm(const std::vector<Eigen::Vector3d>& values) {
  double out = 0.0;
  for (const auto& v : values) out = std::max(out, v.norm());
  return out;
}

/// The worst error per unit F and ξ over every node and column: |exact - FD|∞ S_j / F.
double worst_error(const std::vector<Matrix36d>& exact,
                   const std::vector<Matrix36d>& fd,
                   const Eigen::Matrix<double, 6, 1>& S,
                   double F) {
  double worst = 0.0;
  for (std::size_t i = 0; i < exact.size(); ++i)
    for (int j = 0; j < 6; ++j)
      worst = std::max(worst, (exact[i].col(j) - fd[i].col(j)).cwiseAbs().maxCoeff() * S(j) / F);
  return worst;
}

/// Compares every node's derivatives (and the tip fields, and the energy gradient) with `fd`.
void expect_match(const RodConfiguration& exact,
                  const Jacobians& fd,
                  const Eigen::Matrix<double, 6, 1>& S,
                  double F_force,
                  double F_moment) {
  const double L = exact.length();
  const double F_p = L + max_norm(exact.p);
  const double F_n = std::max(F_force, max_norm(exact.n));
  const double F_m = std::max(F_moment, max_norm(exact.m));
  const double F_E = std::max(kEI / L, exact.energy);
  const double e_p = worst_error(exact.dp_dw, fd.dp, S, F_p);
  const double e_theta = worst_error(exact.dtheta_dw, fd.dtheta, S, 1.0);
  const double e_n = worst_error(exact.dn_dw, fd.dn, S, F_n);
  const double e_m = worst_error(exact.dm_dw, fd.dm, S, F_m);
  double e_E = 0.0;
  for (int j = 0; j < 6; ++j)
    e_E = std::max(e_E, std::abs(exact.denergy_dw(j) - fd.dE(j)) * S(j) / F_E);
  EXPECT_LE(e_p, kTolerance) << "dp";
  EXPECT_LE(e_theta, kTolerance) << "dtheta";
  EXPECT_LE(e_n, kTolerance) << "dn";
  EXPECT_LE(e_m, kTolerance) << "dm";
  EXPECT_LE(e_E, kTolerance) << "dE";
  ::testing::Test::RecordProperty("fd_error_p", scientific(e_p));
  ::testing::Test::RecordProperty("fd_error_theta", scientific(e_theta));
  ::testing::Test::RecordProperty("fd_error_n", scientific(e_n));
  ::testing::Test::RecordProperty("fd_error_m", scientific(e_m));
  ::testing::Test::RecordProperty("fd_error_E", scientific(e_E));
  // The tip fields are the last node's.
  EXPECT_TRUE(CompareMatrices(exact.tip_dp_dw, exact.dp_dw.back(), 0.0));
  EXPECT_TRUE(CompareMatrices(exact.tip_dtheta_dw, exact.dtheta_dw.back(), 0.0));
  EXPECT_TRUE(CompareMatrices(exact.tip_dn_dw, exact.dn_dw.back(), 0.0));
  EXPECT_TRUE(CompareMatrices(exact.tip_dm_dw, exact.dm_dw.back(), 0.0));
}

class BasePoseDerivatives : public ::testing::TestWithParam<Case> {};

TEST_P(BasePoseDerivatives, EveryNodeMatchesCentralFiniteDifferencesOfTheMovedClamp) {
  const Problem problem = make_problem(GetParam());
  const ClampedRod& rod = problem.rod;
  const RodConfiguration c =
      integrate(rod, world_wrench(rod, problem.body_wrench), Derivatives::AllNodes);
  const RodConfiguration d = base_pose_derivatives(rod, c);
  ASSERT_EQ(d.derivatives, Derivatives::AllNodes);
  ASSERT_EQ(d.nodes(), c.nodes());
  ASSERT_EQ(static_cast<int>(d.dp_dw.size()), c.nodes());

  const double L = rod.properties.length;
  Eigen::Matrix<double, 6, 1> S;
  S << L, L, L, 1.0, 1.0, 1.0;
  const Jacobians fd = central_differences(c, kEta * S, [&](int j, double t) {
    ClampedRod moved = rod;
    if (j < 3) {
      moved.clamp.position[j] += t;
    } else {
      moved.clamp.rotation = exp_so3(t * Eigen::Vector3d::Unit(j - 3)) * rod.clamp.rotation;
    }
    return integrate(moved, world_wrench(moved, problem.body_wrench), Derivatives::None);
  });
  expect_match(d, fd, S, kEI / (L * L), kEI / L);

  // c's state, copied.
  for (int i = 0; i < c.nodes(); ++i) {
    EXPECT_EQ(d.s[i], c.s[i]);
    EXPECT_EQ(d.p[i], c.p[i]);
    EXPECT_EQ(d.R[i], c.R[i]);
    EXPECT_EQ(d.n[i], c.n[i]);
    EXPECT_EQ(d.m[i], c.m[i]);
    EXPECT_EQ(d.v[i], c.v[i]);
    EXPECT_EQ(d.u[i], c.u[i]);
  }
  EXPECT_EQ(d.energy, c.energy);

  // Exact structure: a translation moves p and nothing else; at the clamp the rotation is rigid.
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity(), Z = Eigen::Matrix3d::Zero();
  for (int i = 0; i < d.nodes(); ++i) {
    EXPECT_TRUE(CompareMatrices(d.dp_dw[i].leftCols<3>(), I, 0.0));
    EXPECT_TRUE(CompareMatrices(d.dtheta_dw[i].leftCols<3>(), Z, 0.0));
    EXPECT_TRUE(CompareMatrices(d.dn_dw[i].leftCols<3>(), Z, 0.0));
    EXPECT_TRUE(CompareMatrices(d.dm_dw[i].leftCols<3>(), Z, 0.0));
  }
  EXPECT_TRUE(CompareMatrices(d.denergy_dw.leftCols<3>(), Eigen::RowVector3d::Zero(), 0.0));
  EXPECT_TRUE(CompareMatrices(d.dp_dw[0].rightCols<3>(), Z, 0.0));
  EXPECT_TRUE(CompareMatrices(d.dtheta_dw[0].rightCols<3>(), c.R[0].transpose(), 0.0));
  EXPECT_TRUE(CompareMatrices(d.dn_dw[0].rightCols<3>(), -hat(c.n[0]), 0.0));
  EXPECT_TRUE(CompareMatrices(d.dm_dw[0].rightCols<3>(), -hat(c.m[0]), 0.0));
}

// The six load directions (f, then l) against central differences of integrate() in the load, at
// the same clamp and world base wrench; the state is integrate()'s, bitwise.
TEST_P(BasePoseDerivatives, LoadTangentMatchesCentralFiniteDifferencesOfTheLoad) {
  const Problem problem = make_problem(GetParam());
  const ClampedRod& rod = problem.rod;
  const BaseWrench w = world_wrench(rod, problem.body_wrench);
  const RodConfiguration c = integrate(rod, w, Derivatives::AllNodes);
  RodConfiguration load_tangent;
  detail::integrate_load_tangent(rod, w, load_tangent);
  ASSERT_EQ(load_tangent.derivatives, Derivatives::AllNodes);
  ASSERT_EQ(load_tangent.nodes(), c.nodes());
  for (int i = 0; i < c.nodes(); ++i) {
    EXPECT_EQ(load_tangent.p[i], c.p[i]) << "node " << i;
    EXPECT_EQ(load_tangent.R[i], c.R[i]) << "node " << i;
    EXPECT_EQ(load_tangent.n[i], c.n[i]) << "node " << i;
    EXPECT_EQ(load_tangent.m[i], c.m[i]) << "node " << i;
  }
  EXPECT_EQ(load_tangent.energy, c.energy);

  const double L = rod.properties.length;
  Eigen::Matrix<double, 6, 1> S;
  S << Eigen::Vector3d::Constant(kEI / (L * L * L)), Eigen::Vector3d::Constant(kEI / (L * L));
  const Jacobians fd = central_differences(c, kEta * S, [&](int j, double t) {
    ClampedRod moved = rod;
    if (j < 3) {
      moved.load.force[j] += t;
    } else {
      moved.load.moment[j - 3] += t;
    }
    return integrate(moved, w, Derivatives::None);
  });
  expect_match(load_tangent, fd, S, kEI / (L * L), kEI / L);
  // Nothing at the clamp depends on the load.
  EXPECT_TRUE(CompareMatrices(load_tangent.dp_dw[0], Matrix36d::Zero(), 0.0));
  EXPECT_TRUE(CompareMatrices(load_tangent.dtheta_dw[0], Matrix36d::Zero(), 0.0));
  EXPECT_TRUE(CompareMatrices(load_tangent.dn_dw[0], Matrix36d::Zero(), 0.0));
  EXPECT_TRUE(CompareMatrices(load_tangent.dm_dw[0], Matrix36d::Zero(), 0.0));
}

std::vector<Case> all_cases() {
  std::vector<Case> cases;
  for (ConstitutiveModel model : {ConstitutiveModel::Cosserat, ConstitutiveModel::Kirchhoff})
    for (Load load : {Load::None, Load::Gravity, Load::Moment, Load::GravityAndMoment})
      for (int substeps : {1, 3}) cases.push_back({model, load, substeps});
  return cases;
}

INSTANTIATE_TEST_SUITE_P(ModelsLoadsSubsteps,
                         BasePoseDerivatives,
                         ::testing::ValuesIn(all_cases()),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           return case_name(info.param);
                         });

// A configuration reused across rods (loaded, then not) takes the new rod's derivatives: nothing
// stale from the load pass survives.
TEST(BasePoseDerivativesReuse, ReusedOutputTakesTheNewRod) {
  const Problem loaded = make_problem({ConstitutiveModel::Cosserat, Load::GravityAndMoment, 1});
  const Problem bare = make_problem({ConstitutiveModel::Cosserat, Load::None, 1});
  RodConfiguration out;
  const RodConfiguration c_loaded =
      integrate(loaded.rod, world_wrench(loaded.rod, loaded.body_wrench), Derivatives::AllNodes);
  const RodConfiguration c_bare =
      integrate(bare.rod, world_wrench(bare.rod, bare.body_wrench), Derivatives::AllNodes);
  base_pose_derivatives(loaded.rod, c_loaded, out);
  base_pose_derivatives(bare.rod, c_bare, out);
  const RodConfiguration fresh = base_pose_derivatives(bare.rod, c_bare);
  for (int i = 0; i < out.nodes(); ++i) {
    EXPECT_TRUE(CompareMatrices(out.dp_dw[i], fresh.dp_dw[i], 0.0));
    EXPECT_TRUE(CompareMatrices(out.dtheta_dw[i], fresh.dtheta_dw[i], 0.0));
    EXPECT_TRUE(CompareMatrices(out.dn_dw[i], fresh.dn_dw[i], 0.0));
    EXPECT_TRUE(CompareMatrices(out.dm_dw[i], fresh.dm_dw[i], 0.0));
  }
  EXPECT_TRUE(CompareMatrices(out.tip_dp_dw, fresh.tip_dp_dw, 0.0));
  EXPECT_TRUE(CompareMatrices(out.denergy_dw, fresh.denergy_dw, 0.0));
  EXPECT_EQ(out.energy, c_bare.energy);
}

// Only c's state is read: a configuration integrated without derivatives gives the same result.
TEST(BasePoseDerivativesReuse, ConfigurationWithoutDerivativesGivesTheSame) {
  const Problem problem = make_problem({ConstitutiveModel::Kirchhoff, Load::GravityAndMoment, 1});
  const BaseWrench w = world_wrench(problem.rod, problem.body_wrench);
  const RodConfiguration from_all =
      base_pose_derivatives(problem.rod, integrate(problem.rod, w, Derivatives::AllNodes));
  const RodConfiguration from_none =
      base_pose_derivatives(problem.rod, integrate(problem.rod, w, Derivatives::None));
  ASSERT_EQ(from_none.derivatives, Derivatives::AllNodes);
  for (int i = 0; i < from_all.nodes(); ++i) {
    EXPECT_TRUE(CompareMatrices(from_none.dp_dw[i], from_all.dp_dw[i], 0.0));
    EXPECT_TRUE(CompareMatrices(from_none.dtheta_dw[i], from_all.dtheta_dw[i], 0.0));
    EXPECT_TRUE(CompareMatrices(from_none.dn_dw[i], from_all.dn_dw[i], 0.0));
    EXPECT_TRUE(CompareMatrices(from_none.dm_dw[i], from_all.dm_dw[i], 0.0));
  }
  EXPECT_TRUE(CompareMatrices(from_none.denergy_dw, from_all.denergy_dw, 0.0));
}

}  // namespace
}  // namespace test_base_pose_derivatives
}  // namespace rodshape
