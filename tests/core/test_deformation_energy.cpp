// test_deformation_energy.cpp: the deformation energy E = ∫ ½ΔvᵀK_traΔv + ½ΔuᵀK_rotΔu ds that the
// integrator accumulates, against closed forms for linear cases (end moment, torsion, axial force),
// against the principle of virtual work (dE/dw = work of the end and distributed loads on the
// variation), and against the work of a tip load along a loading path (through the solver).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <vector>

#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/core/so3.hpp"
#include "rodshape/solvers/shooting_solver.hpp"
#include "support/analytic_rods.hpp"
#include "support/eigen_compare.hpp"

namespace rodshape {
namespace test_deformation_energy {
namespace {

using testing::CompareScalars;
using testing::kEps;

ClampedRod make_rod(ConstitutiveModel model, int intervals) {
  ClampedRod rod;
  rod.properties.length = 0.75;
  rod.properties.model = model;
  rod.properties.K_rot = Eigen::Vector3d(2.0, 5.0, 1.3);      // EIx, EIy, GJ
  rod.properties.K_tra = Eigen::Vector3d(60.0, 90.0, 400.0);  // GA (x, y), EA
  rod.intervals = intervals;
  rod.clamp.rotation = exp_so3(Eigen::Vector3d(0.4, 0.1, -0.7));
  rod.validate();
  return rod;
}

// The energy density is constant along the rod in these three cases, so the integrator's quadrature
// is exact and only round-off remains: 16 N ε E.
TEST(DeformationEnergy, PureEndMomentStoresMSquaredLOverTwoEI) {
  for (ConstitutiveModel model : {ConstitutiveModel::Cosserat, ConstitutiveModel::Kirchhoff}) {
    const ClampedRod rod = make_rod(model, 40);
    const double L = rod.properties.length;
    for (int axis : {0, 1}) {  // about the section's x (EIx) and y (EIy) axes
      const double EI = rod.properties.K_rot(axis), M = 3.0;  // κL = 1.1 or 0.45 rad
      const Eigen::Vector3d moment = M * rod.clamp.rotation.col(axis);
      const RodConfiguration c = integrate(rod, {Eigen::Vector3d::Zero(), moment});
      const double expected = M * M * L / (2.0 * EI);
      EXPECT_TRUE(CompareScalars(c.energy, expected, 16.0 * 40 * kEps * expected))
          << to_string(model) << ", axis " << axis;
    }
  }
}

TEST(DeformationEnergy, PureTorsionStoresTSquaredLOverTwoGJ) {
  for (ConstitutiveModel model : {ConstitutiveModel::Cosserat, ConstitutiveModel::Kirchhoff}) {
    const ClampedRod rod = make_rod(model, 40);
    const double L = rod.properties.length, GJ = rod.properties.K_rot.z(), T = 2.5;
    const RodConfiguration c =
        integrate(rod, {Eigen::Vector3d::Zero(), T * rod.clamp.rotation.col(2)});
    const double expected = T * T * L / (2.0 * GJ);
    EXPECT_TRUE(CompareScalars(c.energy, expected, 16.0 * 40 * kEps * expected))
        << to_string(model);
  }
}

TEST(DeformationEnergy, AxialForceStoresFSquaredLOverTwoEAOnlyInTheCosseratModel) {
  for (double F : {40.0, -25.0}) {
    const ClampedRod cosserat = make_rod(ConstitutiveModel::Cosserat, 40);
    const double L = cosserat.properties.length, EA = cosserat.properties.K_tra.z();
    const BaseWrench w{F * cosserat.clamp.rotation.col(2), Eigen::Vector3d::Zero()};
    const double expected = F * F * L / (2.0 * EA);
    EXPECT_TRUE(
        CompareScalars(integrate(cosserat, w).energy, expected, 16.0 * 40 * kEps * expected));
    // Inextensible: the axial force is a reaction and does no work. Only round-off bends the rod:
    // m = -(p - p0) × n with p ∥ n up to 16 N ε, so E ≤ (16 N ε F L)² L / (2 EI_min).
    const double bent = 16.0 * 40 * kEps * std::abs(F) * L;
    EXPECT_LE(integrate(make_rod(ConstitutiveModel::Kirchhoff, 40), w).energy,
              bent * bent * L / (2.0 * 1.3));
  }
}

TEST(DeformationEnergy, IsZeroForARodAtRestAndPositiveOtherwise) {
  ClampedRod rod = make_rod(ConstitutiveModel::Cosserat, 20);
  rod.properties.u_rest = Eigen::Vector3d(1.0, -2.0, 0.5);  // precurved: at rest, not straight
  EXPECT_EQ(integrate(rod, BaseWrench{}).energy, 0.0);
  EXPECT_GT(integrate(rod, {{0.0, 1e-3, 0.0}, Eigen::Vector3d::Zero()}).energy, 0.0);
}

// Principle of virtual work: at an equilibrium clamped at s = 0 (every integrated configuration is
// one, for the tip wrench it ends with), the first variation of the strain energy equals the
// virtual work of the external loads,
//     dE/dw = n(L)ᵀ dp(L)/dw + m(L)ᵀ R(L) dθ(L)/dw + ∫ fᵀ dp/dw ds,
// (θ is body-frame, so the world-frame rotation is R θ). Continuous model: exact. Discrete map:
// each side is a derivative of RK4 outputs, so they agree to the derivative of the O(h⁴) global
// error; with the error model of rk4_error_bound, per unit ξ_j = w_j/S_j (see the derivative
// tests), the defect is ≤ F_E (1 + κL)(κh)⁴/100, F_E the energy scale. The integral over f uses
// composite Simpson on the nodes (error L h⁴ max|g''''|/180, of the same order, covered by the same
// bound).
TEST(DeformationEnergy, GradientEqualsVirtualWorkOfTheLoads) {
  for (ConstitutiveModel model : {ConstitutiveModel::Cosserat, ConstitutiveModel::Kirchhoff}) {
    for (bool gravity : {false, true}) {
      ClampedRod rod = make_rod(model, 100);
      if (gravity) rod.load = DistributedLoad::gravity(1.2, Eigen::Vector3d(0.0, 0.0, -9.81));
      const double L = rod.properties.length, EI = 2.0;
      Vector6d S;
      S << Eigen::Vector3d::Constant(EI / (L * L)), Eigen::Vector3d::Constant(EI / L);
      Vector6d xi;
      xi << 0.8, -0.5, 0.4, 1.0, 0.6, -0.7;
      const BaseWrench w = Wrench::from_vector(xi.cwiseProduct(S));
      const RodConfiguration c = integrate(rod, w, Derivatives::AllNodes);

      Eigen::Matrix<double, 1, 6> work = c.n.back().transpose() * c.tip_dp_dw +
                                         c.m.back().transpose() * c.R.back() * c.tip_dtheta_dw;
      const int N = rod.intervals;  // even: composite Simpson
      const double h = L / N;
      for (int i = 0; i <= N; ++i) {
        const double weight = (i == 0 || i == N) ? 1.0 : (i % 2 ? 4.0 : 2.0);
        work += weight * h / 3.0 * rod.load.force.transpose() * c.dp_dw[i];
      }
      double kappa_max = 0.0;
      for (const auto& u : c.u) kappa_max = std::max(kappa_max, u.norm());
      const double kh = kappa_max * h;
      const double F_E = std::max(EI / L, c.energy);
      const double relative = (1.0 + kappa_max * L) * std::pow(kh, 4) / 100.0 + 16.0 * N * kEps;
      for (int j = 0; j < 6; ++j)
        EXPECT_TRUE(CompareScalars(c.denergy_dw(j), work(j), relative * F_E / S(j)))
            << to_string(model) << (gravity ? " with gravity" : "") << ", column " << j
            << " (κ_max h = " << kh << ")";
    }
  }
}

// Energy = work along a loading path. A tip force λF (fixed direction, 3D: bending in both planes,
// shear and stretch) is ramped from 0 to F, on both models; at each λ the free-tip solve gives
// the equilibrium, and the work done is W = ∫₀¹ λF · dp(L)/dλ dλ with dp(L)/dλ = dp(L)/dw · dw/dλ,
// dw/dλ = J⁻¹ (F, 0), J = d(n(L), m(L))/dw the free tip's Jacobian. Composite Simpson on K = 32
// panels; its error is estimated by Richardson, |S₃₂ - S₁₆|/15, which we allow twice. Added to
// that: the virtual-work defect of the discrete map (previous test: ≤ F_E (1 + κL)(κh)⁴/100 per
// unit load, with κ the largest curvature met on the path, at λ = 1; N = 60), and
// the solver's residual (≤ 1e-10 N at the tip times |p(L) - p(0)| ≤ L). A conservative
// linear-elastic rod stores exactly the work done, so E(F) = W.
TEST(DeformationEnergy, EqualsWorkOfTipLoadAlongALoadingPath) {
  for (ConstitutiveModel model : {ConstitutiveModel::Cosserat, ConstitutiveModel::Kirchhoff}) {
    ClampedRod rod = make_rod(model, 60);
    const double L = rod.properties.length, EI = 2.0;
    // α = |F| L²/EI ≈ 3: large deflection.
    const Eigen::Vector3d F = (EI / (L * L)) * Eigen::Vector3d(2.0, -2.0, 0.8);
    ShootingOptions options;
    options.output_derivatives = Derivatives::Tip;
    const int K = 32;
    std::vector<double> g(K + 1);
    double energy_at_F = 0.0, kappa_max = 0.0;
    BaseWrench guess;
    for (int k = 0; k <= K; ++k) {
      const double lambda = static_cast<double>(k) / K;
      const ShootingResult s =
          solve_equilibrium(rod, FreeTip{{lambda * F, Eigen::Vector3d::Zero()}}, guess, options);
      ASSERT_TRUE(s.summary.converged()) << "λ = " << lambda << ": " << s.summary.brief();
      guess = s.base_wrench;
      const RodConfiguration& c = s.configuration;
      Matrix6d J;
      J << c.tip_dn_dw, c.tip_dm_dw;
      Vector6d rhs;
      rhs << F, Eigen::Vector3d::Zero();
      const Vector6d dw_dlambda = J.partialPivLu().solve(rhs);
      g[k] = lambda * F.dot(c.tip_dp_dw * dw_dlambda);
      if (k == K) {
        energy_at_F = c.energy;
        for (const auto& u : c.u) kappa_max = std::max(kappa_max, u.norm());
      }
    }
    auto simpson = [&](int stride) {  // panels of width stride/K
      double sum = 0.0;
      for (int k = 0; k <= K; k += stride) {
        const bool end = k == 0 || k == K;
        sum += (end ? 1.0 : ((k / stride) % 2 ? 4.0 : 2.0)) * g[k];
      }
      return sum * stride / (3.0 * K);
    };
    const double W32 = simpson(1), W16 = simpson(2);
    const double quadrature = 2.0 * std::abs(W32 - W16) / 15.0;
    const double kh = kappa_max * L / rod.intervals;
    const double defect =
        (1.0 + kappa_max * L) * std::pow(kh, 4) / 100.0 * std::max(EI / L, energy_at_F);
    const double tolerance = quadrature + defect + 1e-10 * L;
    std::printf(
        "  %s: E(F) = %.12f J, W = %.12f J, |E - W| = %.2e, tolerance %.2e (Simpson %.2e)\n",
        to_string(model).c_str(), energy_at_F, W32, std::abs(energy_at_F - W32), tolerance,
        quadrature);
    EXPECT_TRUE(CompareScalars(energy_at_F, W32, tolerance)) << to_string(model);
    EXPECT_GT(energy_at_F, 0.1 * EI / L);  // a genuinely large deformation
  }
}

}  // namespace
}  // namespace test_deformation_energy
}  // namespace rodshape
