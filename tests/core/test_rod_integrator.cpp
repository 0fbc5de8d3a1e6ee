// test_rod_integrator.cpp: the forward problem (core/rod_integrator.hpp) against closed forms (arc
// under an end moment in both bending planes, torsion, stretch, a precurved helix), exact
// identities of the discrete map (wrench balance, rigid-motion equivariance, orthonormal R), the
// RK4 order, and — through solve_equilibrium with a free tip — the cantilever elastica of Bisshopp
// and Drucker and the small-load cantilever under its own weight.
//
// Error model for every tolerance: see rk4_error_bound() in support/analytic_rods.hpp
// (global error L (1 + κL)(κh)⁴ / 1000 with a factor-10 margin, h = L/N, plus 16 N ε round-off).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/core/so3.hpp"
#include "rodshape/solvers/shooting_solver.hpp"
#include "support/analytic_rods.hpp"
#include "support/eigen_compare.hpp"

namespace rodshape {
namespace test_rod_integrator {
namespace {

using testing::CompareMatrices;
using testing::CompareScalars;
using testing::kEps;
using testing::rk4_angle_error_bound;
using testing::rk4_error_bound;

/// A rod with the given stiffness, clamped at the origin with R = I unless changed.
ClampedRod make_rod(double length,
                    const Eigen::Vector3d& K_rot,
                    const Eigen::Vector3d& K_tra,
                    ConstitutiveModel model,
                    int intervals) {
  ClampedRod rod;
  rod.properties.length = length;
  rod.properties.model = model;
  rod.properties.K_rot = K_rot;
  rod.properties.K_tra = K_tra;
  rod.intervals = intervals;
  rod.validate();
  return rod;
}

/// Angle of R_aᵀ R_b (rad), through Eigen's AngleAxis: accurate to ~2ε for small angles.
double angle_between(const Eigen::Matrix3d& R_a, const Eigen::Matrix3d& R_b) {
  return Eigen::AngleAxisd(R_a.transpose() * R_b).angle();
}

const Eigen::Vector3d kAnisotropicBending(2.0, 5.0, 1.3);  // EIx ≠ EIy ≠ GJ, N·m²
const Eigen::Vector3d kShearAxial(400.0, 400.0, 1000.0);   // GA, GA, EA, N

// ---- sampling and constitutive law --------------------------------------------------------------

TEST(RodIntegrator, NodesSampleTheArcLengthUniformlyAndStartAtTheClampAndBaseWrench) {
  ClampedRod rod = make_rod(1.7, kAnisotropicBending, kShearAxial, ConstitutiveModel::Cosserat, 37);
  rod.clamp.position = Eigen::Vector3d(0.1, -0.2, 0.3);
  rod.clamp.rotation = exp_so3(Eigen::Vector3d(0.4, -0.7, 1.1));
  const BaseWrench w{{0.3, -0.5, 0.8}, {0.2, 0.1, -0.4}};
  const RodConfiguration c = integrate(rod, w);
  ASSERT_EQ(c.nodes(), 38);
  for (int i = 0; i <= 37; ++i) EXPECT_NEAR(c.s[i], i * 1.7 / 37, 2.0 * kEps * 1.7) << "node " << i;
  EXPECT_EQ(c.s.back(), 1.7);
  EXPECT_EQ(c.length(), 1.7);
  EXPECT_TRUE(CompareMatrices(c.p[0], rod.clamp.position, 0.0));
  // R(0) goes through a quaternion and back: a few ε per entry.
  EXPECT_TRUE(CompareMatrices(c.R[0], rod.clamp.rotation, 8.0 * kEps));
  EXPECT_TRUE(CompareMatrices(c.base_wrench().to_vector(), w.to_vector(), 0.0));
  EXPECT_EQ(c.derivatives, Derivatives::None);
}

TEST(RodIntegrator, ConstitutiveLawHoldsAtEveryNode) {
  for (ConstitutiveModel model : {ConstitutiveModel::Cosserat, ConstitutiveModel::Kirchhoff}) {
    ClampedRod rod = make_rod(0.9, kAnisotropicBending, kShearAxial, model, 20);
    rod.properties.u_rest = Eigen::Vector3d(0.3, -0.1, 0.2);
    rod.load = DistributedLoad::gravity(0.4, Eigen::Vector3d(0, 0, -9.81));
    const RodConfiguration c = integrate(rod, {{1.0, -2.0, 0.5}, {0.7, 0.4, -0.3}});
    for (int i = 0; i < c.nodes(); ++i) {
      // v = K_tra⁻¹ Rᵀ n + ṽ (Kirchhoff: v = ṽ), u = K_rot⁻¹ Rᵀ m + ũ: a few roundings of O(|n|/K)
      // and O(|m|/K) numbers.
      const Eigen::Vector3d v =
          model == ConstitutiveModel::Kirchhoff
              ? rod.properties.v_rest
              : Eigen::Vector3d(
                    rod.properties.K_tra.cwiseInverse().cwiseProduct(c.R[i].transpose() * c.n[i]) +
                    rod.properties.v_rest);
      const Eigen::Vector3d u =
          rod.properties.K_rot.cwiseInverse().cwiseProduct(c.R[i].transpose() * c.m[i]) +
          rod.properties.u_rest;
      EXPECT_TRUE(CompareMatrices(c.v[i], v, 16.0 * kEps)) << "node " << i;
      EXPECT_TRUE(CompareMatrices(c.u[i], u, 16.0 * kEps * (1.0 + u.norm()))) << "node " << i;
    }
  }
}

// ---- closed forms -------------------------------------------------------------------------------

// A pure end moment M about a principal axis of the section keeps Rᵀm = M e_axis constant, so the
// curvature u = M/EI e_axis is constant and the rod is a circular arc of radius EI/M: about x it
// uses EIx, about y EIy (EIx = 2 ≠ EIy = 5 here, so a swapped stiffness fails by a factor 2.5).
// Free tip, no distributed load: m(0) = m(L) = M, n ≡ 0. Checked at every node, bending well past
// 90°.
TEST(RodIntegrator, ArcUnderEndMomentMatchesClosedFormInBothBendingPlanes) {
  const double L = 1.3;
  const int N = 50;
  for (ConstitutiveModel model : {ConstitutiveModel::Cosserat, ConstitutiveModel::Kirchhoff}) {
    for (int axis : {0, 1}) {
      const ClampedRod rod = make_rod(L, kAnisotropicBending, kShearAxial, model, N);
      const double EI = kAnisotropicBending(axis);
      const double kappa = 2.5 / L;  // 2.5 rad of bending over the rod
      const Eigen::Vector3d M = kappa * EI * Eigen::Vector3d::Unit(axis);
      const RodConfiguration c = integrate(rod, {Eigen::Vector3d::Zero(), M});
      const double tol_p = rk4_error_bound(L, kappa, N);
      const double tol_angle = rk4_angle_error_bound(L, kappa, N);
      for (int i = 0; i < c.nodes(); ++i) {
        const auto expected =
            testing::constant_strain_pose(c.s[i], kappa * Eigen::Vector3d::Unit(axis));
        EXPECT_TRUE(CompareMatrices(c.p[i], expected.position, tol_p))
            << to_string(model) << ", moment about axis " << axis << ", node " << i;
        EXPECT_LE(angle_between(expected.rotation, c.R[i]), tol_angle) << "node " << i;
        // The curvature itself is exact: Rᵀm stays along the axis up to the orientation error.
        EXPECT_TRUE(CompareMatrices(c.u[i], Eigen::Vector3d::Unit(axis) * kappa,
                                    kappa * (tol_angle + 16.0 * kEps)));
      }
      // Tip in closed form, e.g. about x: p(L) = (0, (cos κL - 1)/κ, sin κL/κ).
      const double kL = kappa * L;
      const Eigen::Vector3d tip =
          axis == 0 ? Eigen::Vector3d(0.0, (std::cos(kL) - 1.0) / kappa, std::sin(kL) / kappa)
                    : Eigen::Vector3d((1.0 - std::cos(kL)) / kappa, 0.0, std::sin(kL) / kappa);
      EXPECT_TRUE(CompareMatrices(c.tip().position, tip, tol_p));
    }
  }
}

// Pure torsion T about the tangent: u = T/GJ e_z, the rod stays straight and twists by TL/GJ. With
// a tilted clamp the torque is T R0 e_z in the world frame.
TEST(RodIntegrator, PureTorsionTwistsByTorqueTimesLengthOverGJ) {
  const double L = 0.8;
  const int N = 40;
  for (ConstitutiveModel model : {ConstitutiveModel::Cosserat, ConstitutiveModel::Kirchhoff}) {
    ClampedRod rod = make_rod(L, kAnisotropicBending, kShearAxial, model, N);
    rod.clamp.position = Eigen::Vector3d(1.0, 2.0, -0.5);
    rod.clamp.rotation = exp_so3(Eigen::Vector3d(0.9, 0.3, -0.6));
    const double GJ = kAnisotropicBending.z();
    const double T = 2.0 * GJ / L;  // 2 rad of twist
    const Eigen::Vector3d tangent = rod.clamp.rotation.col(2);
    const RodConfiguration c = integrate(rod, {Eigen::Vector3d::Zero(), T * tangent});
    const double kappa = T / GJ;
    for (int i = 0; i < c.nodes(); ++i) {
      const auto expected = testing::constant_strain_pose(c.s[i], kappa * Eigen::Vector3d::UnitZ(),
                                                          Eigen::Vector3d::UnitZ(),
                                                          rod.clamp.position, rod.clamp.rotation);
      // Straight: the positions are exact up to round-off (p' = R e_z = R0 e_z at every stage).
      EXPECT_TRUE(CompareMatrices(c.p[i], expected.position, 16.0 * N * kEps * (1.0 + L)));
      EXPECT_LE(angle_between(expected.rotation, c.R[i]), rk4_angle_error_bound(L, kappa, N));
    }
    const Eigen::AngleAxisd twist(rod.clamp.rotation.transpose() * c.R.back());
    EXPECT_TRUE(CompareScalars(twist.angle(), T * L / GJ, rk4_angle_error_bound(L, kappa, N)));
    EXPECT_TRUE(CompareMatrices(twist.axis(), Eigen::Vector3d::UnitZ(), 1e-12));
  }
}

// An axial force F along the tangent: n ≡ F R0 e_z, v = (0, 0, 1 + F/EA) (Cosserat) or (0, 0, 1)
// (Kirchhoff): p(L) = p0 + L (1 + F/EA) R0 e_z. p' is constant, so RK4 is exact up to round-off.
TEST(RodIntegrator, AxialForceStretchesCosseratByFOverEAAndNotKirchhoff) {
  const double L = 0.6, EA = kShearAxial.z();
  const int N = 30;
  for (double F : {150.0, -80.0}) {  // 15% stretch, 8% compression
    for (ConstitutiveModel model : {ConstitutiveModel::Cosserat, ConstitutiveModel::Kirchhoff}) {
      ClampedRod rod = make_rod(L, kAnisotropicBending, kShearAxial, model, N);
      rod.clamp.rotation = exp_so3(Eigen::Vector3d(-0.2, 0.5, 0.1));
      const Eigen::Vector3d tangent = rod.clamp.rotation.col(2);
      const RodConfiguration c = integrate(rod, {F * tangent, Eigen::Vector3d::Zero()});
      const double stretch = model == ConstitutiveModel::Cosserat ? 1.0 + F / EA : 1.0;
      for (int i = 0; i < c.nodes(); ++i) {
        EXPECT_TRUE(CompareMatrices(c.p[i], c.s[i] * stretch * tangent, 16.0 * N * kEps * L))
            << to_string(model) << " F = " << F << " node " << i;
        EXPECT_TRUE(CompareMatrices(c.R[i], rod.clamp.rotation, 16.0 * N * kEps));
      }
    }
  }
}

// A precurved rod (constant ũ with bending and twist) under no load rests in a helix, u ≡ ũ.
TEST(RodIntegrator, PrecurvedRodWithoutLoadRestsInItsHelix) {
  const double L = 2.0;
  const int N = 80;
  ClampedRod rod = make_rod(L, kAnisotropicBending, kShearAxial, ConstitutiveModel::Cosserat, N);
  rod.properties.u_rest = Eigen::Vector3d(1.5, -0.8, 2.0);
  const double kappa = rod.properties.u_rest.norm();
  const RodConfiguration c = integrate(rod, BaseWrench{});
  for (int i = 0; i < c.nodes(); ++i) {
    const auto expected = testing::constant_strain_pose(c.s[i], rod.properties.u_rest);
    EXPECT_TRUE(CompareMatrices(c.p[i], expected.position, rk4_error_bound(L, kappa, N)))
        << "node " << i;
    EXPECT_LE(angle_between(expected.rotation, c.R[i]), rk4_angle_error_bound(L, kappa, N));
    EXPECT_TRUE(CompareMatrices(c.u[i], rod.properties.u_rest, 0.0));  // m ≡ 0: exactly ũ
  }
  EXPECT_EQ(c.energy, 0.0);
}

// ---- exact identities of the discrete map -------------------------------------------------------

// With no distributed force n is constant, and since each RK4 increment of m is
// (h/6)Σ bᵢ (-p'ᵢ × n - l) = -(Δp) × n - hl (Δp = (h/6)Σ bᵢ p'ᵢ, bᵢ = 1, 2, 2, 1), the balance m(s)
// = m(0) - (p(s) - p(0)) × n(0) - l s holds at every node to round-off — not just to O(h⁴). So a
// free tip with tip wrench (F, M) has base wrench n(0) = F, m(0) = M + (p(L) - p(0)) × F.
TEST(RodIntegrator, WrenchBalanceHoldsAtEveryNodeWithoutDistributedForce) {
  for (ConstitutiveModel model : {ConstitutiveModel::Cosserat, ConstitutiveModel::Kirchhoff}) {
    ClampedRod rod = make_rod(1.1, kAnisotropicBending, kShearAxial, model, 64);
    rod.clamp.position = Eigen::Vector3d(0.3, 0.0, -0.2);
    rod.clamp.rotation = exp_so3(Eigen::Vector3d(0.1, 0.8, -0.3));
    rod.load.moment = Eigen::Vector3d(0.2, -0.5, 0.1);  // l: distributed moment, N·m/m
    const BaseWrench w{{2.0, -1.0, 3.0}, {0.5, 1.5, -1.0}};
    const RodConfiguration c = integrate(rod, w);
    const double scale = w.moment.norm() + 1.1 * w.force.norm() + 1.1 * rod.load.moment.norm();
    for (int i = 0; i < c.nodes(); ++i) {
      EXPECT_TRUE(CompareMatrices(c.n[i], w.force, 0.0));  // n' = 0: never touched
      const Eigen::Vector3d m =
          w.moment - (c.p[i] - c.p[0]).cross(w.force) - c.s[i] * rod.load.moment;
      EXPECT_TRUE(CompareMatrices(c.m[i], m, 16.0 * c.nodes() * kEps * scale)) << "node " << i;
    }
  }
}

TEST(RodIntegrator, InternalForceFallsLinearlyUnderDistributedForce) {
  ClampedRod rod = make_rod(0.7, kAnisotropicBending, kShearAxial, ConstitutiveModel::Cosserat, 25);
  rod.load = DistributedLoad::gravity(1.3, Eigen::Vector3d(0.0, -9.81, 0.0));
  const BaseWrench w{rod.load.force * 0.7, {-3.0, 0.0, 0.2}};  // n(0) = f L: a free tip's n(L) = 0
  const RodConfiguration c = integrate(rod, w);
  for (int i = 0; i < c.nodes(); ++i)  // n(s) = n(0) - f s: linear, so RK4 is exact
    EXPECT_TRUE(CompareMatrices(c.n[i], w.force - c.s[i] * rod.load.force, 16.0 * 25 * kEps * 9.0));
  EXPECT_TRUE(CompareMatrices(c.n.back(), Eigen::Vector3d::Zero(), 16.0 * 25 * kEps * 9.0));
}

// Moving the clamp by a rigid motion (Q, t) and rotating the base wrench and the loads with it
// moves the whole configuration: p → Qp + t, R → QR, n → Qn, m → Qm, while u, v, energy stay. The
// ODE is written in world coordinates, so this holds for the discrete map too, to round-off.
TEST(RodIntegrator, ConfigurationMovesRigidlyWithTheClampAndLoads) {
  for (ConstitutiveModel model : {ConstitutiveModel::Cosserat, ConstitutiveModel::Kirchhoff}) {
    ClampedRod rod =
        make_rod(0.9, kAnisotropicBending, Eigen::Vector3d(30.0, 45.0, 200.0), model, 40);
    rod.properties.u_rest = Eigen::Vector3d(0.2, 0.0, -0.4);
    rod.load = {Eigen::Vector3d(0.5, -4.0, 1.0), Eigen::Vector3d(0.1, 0.2, -0.1)};
    const BaseWrench w{{1.0, 3.0, -2.0}, {1.5, -0.5, 0.8}};
    const RodConfiguration a = integrate(rod, w);

    const Eigen::Matrix3d Q = exp_so3(Eigen::Vector3d(-1.2, 0.4, 2.2));
    const Eigen::Vector3d t(0.5, -1.0, 2.0);
    ClampedRod moved = rod;
    moved.clamp = {Q * rod.clamp.position + t, Q * rod.clamp.rotation};
    moved.load = {Q * rod.load.force, Q * rod.load.moment};
    const RodConfiguration b = integrate(moved, {Q * w.force, Q * w.moment});
    // Round-off in both runs (16 N ε each, see rk4_error_bound) plus rotating by Q (a few ε),
    // relative to each quantity's size: 64 N ε.
    const double tol = 64.0 * 40 * kEps;
    for (int i = 0; i < a.nodes(); ++i) {
      EXPECT_TRUE(CompareMatrices(b.p[i], Q * a.p[i] + t, tol * (t.norm() + a.p[i].norm())))
          << "node " << i;
      EXPECT_TRUE(CompareMatrices(b.R[i], Q * a.R[i], tol));
      EXPECT_TRUE(CompareMatrices(b.n[i], Q * a.n[i], tol * a.n[i].norm()));
      EXPECT_TRUE(CompareMatrices(b.m[i], Q * a.m[i], tol * a.m[i].norm()));
      EXPECT_TRUE(CompareMatrices(b.u[i], a.u[i], tol * a.u[i].norm()));
      EXPECT_TRUE(CompareMatrices(b.v[i], a.v[i], tol * a.v[i].norm()));
    }
    EXPECT_TRUE(CompareScalars(b.energy, a.energy, tol * a.energy));
  }
}

// R(q/|q|) is orthonormal whatever the drift of |q|: each entry carries ≤ ~5 roundings (≤ 5ε) and
// an entry of RᵀR sums three products of O(1) entries, so |RᵀR - I| ≤ 30ε ≈ 6.7e-15 < 1e-14, for
// any length. A rod 10 m long twisted by 1000 rad (GJ small) and bent, in 2000 steps of 0.5 rad.
TEST(RodIntegrator, RotationsStayOrthonormalOnALongStronglyTwistedRod) {
  const ClampedRod rod = make_rod(10.0, Eigen::Vector3d(1.0, 2.0, 0.01), kShearAxial,
                                  ConstitutiveModel::Cosserat, 2000);
  const RodConfiguration c = integrate(rod, {{0.01, -0.02, 0.0}, {0.3, -0.2, 1.0}});
  double worst_orthogonality = 0.0, worst_det = 0.0;
  for (const Eigen::Matrix3d& R : c.R) {
    worst_orthogonality =
        std::max(worst_orthogonality,
                 (R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff());
    worst_det = std::max(worst_det, std::abs(R.determinant() - 1.0));
  }
  EXPECT_LE(worst_orthogonality, 1e-14);
  EXPECT_LE(worst_det, 1e-14);
  // And the twist really is large: the tip turned ~1000 rad about its tangent (not a trivial rod).
  EXPECT_GT(c.u.back().z(), 90.0);
}

// ---- order of convergence -----------------------------------------------------------------------

/// A 3D rod with bending in both planes (EIx ≠ EIy), torsion, shear (GA soft: up to ~5% shear
/// strain) and gravity, strongly bent: the largest curvature is κ_max ≈ 16.8 /m, κ_max L ≈ 4.9.
struct ConvergenceProblem {
  ClampedRod rod;
  BaseWrench w{{0.8, -0.5, 0.3}, {0.25, -0.15, 0.08}};
  ConvergenceProblem() {
    rod = make_rod(0.29, Eigen::Vector3d(0.04, 0.025, 0.028), Eigen::Vector3d(20.0, 25.0, 1280.0),
                   ConstitutiveModel::Cosserat, 1);
    rod.load = DistributedLoad::gravity(0.5568, Eigen::Vector3d(0.0, 0.0, -9.81));
    rod.clamp.rotation = exp_so3(Eigen::Vector3d(0.3, -0.2, 0.5));
  }
  RodConfiguration at(int intervals) {
    rod.intervals = intervals;
    return integrate(rod, w);
  }
};

// The tip pose errors against N = 3200 for N = 25 … 200 fall 16-fold per doubling: observed order
// log2(e_N / e_2N) in [3.7, 4.3]. The reference's own error is (3200/200)⁴ ≈ 6.6e4 times below
// e_200, and e_200 ≈ 2e-10 m sits far above round-off (~1e-15 m).
TEST(RodIntegrator, TipPoseConvergesAtFourthOrderWhenTheStepHalves) {
  ConvergenceProblem problem;
  const RodConfiguration reference = problem.at(3200);
  const std::vector<int> Ns = {25, 50, 100, 200};
  std::vector<double> e_p, e_R;
  for (int N : Ns) {
    const RodConfiguration c = problem.at(N);
    e_p.push_back((c.p.back() - reference.p.back()).norm());
    e_R.push_back(angle_between(reference.R.back(), c.R.back()));
  }
  for (size_t k = 0; k + 1 < Ns.size(); ++k) {
    const double order_p = std::log2(e_p[k] / e_p[k + 1]);
    const double order_R = std::log2(e_R[k] / e_R[k + 1]);
    std::printf(
        "  N = %3d -> %3d: order of p(L) %.3f, of R(L) %.3f   (|p_N(L) - p_ref(L)| = %.3e m)\n",
        Ns[k], Ns[k + 1], order_p, order_R, e_p[k]);
    EXPECT_GE(order_p, 3.7) << "N = " << Ns[k];
    EXPECT_LE(order_p, 4.3) << "N = " << Ns[k];
    EXPECT_GE(order_R, 3.7) << "N = " << Ns[k];
    EXPECT_LE(order_R, 4.3) << "N = " << Ns[k];
  }
}

// The tip moment and the energy carry a larger next-order term on this strongly bent rod: their
// observed order from N = 25 rises 3.2 → 3.7 → 3.9 (moment) and 3.0 → 3.7 → 3.9 (energy) towards 4,
// i.e. e = a h⁴ (1 + c κ_max h) with |c| ≈ 3 — pre-asymptotic, not a lower order (a third-order
// quadrature would level off at 3). So we measure them where κ_max h ≤ 0.05: N = 100, 200, 400
// against N = 6400 (reference error 16⁴ below e_400 ≈ 5e-12; round-off ~1e-14).
TEST(RodIntegrator, TipMomentAndEnergyConvergeAtFourthOrder) {
  ConvergenceProblem problem;
  const RodConfiguration reference = problem.at(6400);
  const std::vector<int> Ns = {100, 200, 400};
  std::vector<double> e_m, e_E;
  for (int N : Ns) {
    const RodConfiguration c = problem.at(N);
    e_m.push_back((c.m.back() - reference.m.back()).norm());
    e_E.push_back(std::abs(c.energy - reference.energy));
  }
  for (size_t k = 0; k + 1 < Ns.size(); ++k) {
    const double order_m = std::log2(e_m[k] / e_m[k + 1]);
    const double order_E = std::log2(e_E[k] / e_E[k + 1]);
    std::printf("  N = %3d -> %3d: order of m(L) %.3f, of the energy %.3f\n", Ns[k], Ns[k + 1],
                order_m, order_E);
    EXPECT_GE(order_m, 3.7) << "N = " << Ns[k];
    EXPECT_LE(order_m, 4.3) << "N = " << Ns[k];
    EXPECT_GE(order_E, 3.7) << "N = " << Ns[k];
    EXPECT_LE(order_E, 4.3) << "N = " << Ns[k];
  }
}

// ---- the elliptic-integral oracle itself
// ---------------------------------------------------------

TEST(ElasticaOracle, EllipticIntegralsMatchKnownValues) {
  // K(1/√2) = Γ(1/4)²/(4√π) and E(1/√2) = (K² + π/2)/(2K) (the lemniscate case of Legendre's
  // relation).
  const double K = std::pow(std::tgamma(0.25), 2) / (4.0 * std::sqrt(std::numbers::pi));
  EXPECT_TRUE(
      CompareScalars(testing::complete_elliptic_k(std::numbers::sqrt2 / 2.0), K, 8.0 * kEps));
  EXPECT_TRUE(CompareScalars(testing::complete_elliptic_e(std::numbers::sqrt2 / 2.0),
                             (K * K + std::numbers::pi / 2.0) / (2.0 * K), 8.0 * kEps));
  // F(φ, 0) = φ, E(φ, 0) = φ, F(φ, 1) = atanh(sin φ).
  EXPECT_TRUE(CompareScalars(testing::elliptic_f(1.2, 0.0), 1.2, 4.0 * kEps));
  EXPECT_TRUE(CompareScalars(testing::elliptic_e(1.2, 0.0), 1.2, 4.0 * kEps));
  EXPECT_TRUE(
      CompareScalars(testing::elliptic_f(1.2, 1.0), std::atanh(std::sin(1.2)), 16.0 * kEps));
}

TEST(ElasticaOracle, ReproducesThePublishedBisshoppDruckerRows) {
  for (const auto& row : testing::kBisshoppDruckerRows) {
    const auto tip = testing::cantilever_elastica(row.alpha);
    EXPECT_TRUE(CompareScalars(tip.across, row.across, testing::kBisshoppDruckerHalfUlp))
        << row.alpha;
    EXPECT_TRUE(CompareScalars(tip.shortening(), row.shortening, testing::kBisshoppDruckerHalfUlp))
        << row.alpha;
  }
  // Small loads approach the linear cantilever: y/L = α/3 with a relative correction O(α²).
  const auto small = testing::cantilever_elastica(1e-4);
  EXPECT_TRUE(CompareScalars(small.across, 1e-4 / 3.0, 1e-4 / 3.0 * 1e-7));
}

// ---- through the solver: free tip ---------------------------------------------------------------

ShootingOptions tight_options() {
  ShootingOptions options;
  options.output_derivatives = Derivatives::None;
  return options;
}

// The large-deflection cantilever under a dead tip load P perpendicular to the undeformed rod, on
// the inextensible Kirchhoff model (the elastica's), in both bending planes (load along x bends
// about y, EIy; along y bends about x, EIx). Reference: cantilever_elastica() (elliptic integrals),
// which reproduces Bisshopp and Drucker's printed rows (ElasticaOracle above). Tolerance:
// rk4_error_bound with the largest curvature, at the clamp: κ_max L = √(2α sin θ(L)), plus the
// solver's residual ‖r‖∞ ≤ 1e-10 N (or N·m) times the tip compliance (L³/EI, L²/EI ≤ 1.1 m/N here)
// with a factor 10: 1e-9 m.
TEST(FreeTipSolve, CantileverUnderTipLoadMatchesTheElastica) {
  const double L = 1.3;
  const int N = 200;
  RodDescription d;
  d.length = L;
  d.model = ConstitutiveModel::Kirchhoff;
  d.stiffness.EIx = 5.0;
  d.stiffness.EIy = 2.0;
  d.stiffness.GJ = 1.3;
  ClampedRod rod;
  rod.properties = make_rod_properties(d);
  rod.intervals = N;
  const std::vector<double> alphas = {0.5, 1.0, 2.0, 3.0, 4.0, 5.0, 7.0, 10.0};
  std::printf("  %-6s %-5s %-12s %-12s %-12s %-12s %-10s\n", "alpha", "plane", "y/L ours",
              "y/L ref", "(L-x)/L ours", "(L-x)/L ref", "max |diff|");
  for (int load_axis : {0, 1}) {
    const double EI = load_axis == 0 ? 2.0 : 5.0;  // load along x bends about y
    BaseWrench guess;
    for (double alpha : alphas) {
      const double P = alpha * EI / (L * L);
      const FreeTip tip{{P * Eigen::Vector3d::Unit(load_axis), Eigen::Vector3d::Zero()}};
      const ShootingResult solution = solve_equilibrium(rod, tip, guess, tight_options());
      ASSERT_TRUE(solution.summary.converged())
          << "alpha " << alpha << ": " << solution.summary.brief();
      guess = solution.base_wrench;  // continuation in α, as a user would do
      const auto reference = testing::cantilever_elastica(alpha);
      const Eigen::Vector3d p = solution.configuration.tip().position / L;
      const double across = p(load_axis), along = p.z();
      const double kappa_max = std::sqrt(2.0 * alpha * std::sin(reference.tip_angle)) / L;
      const double tol = rk4_error_bound(L, kappa_max, N) / L + 1e-9 / L;
      std::printf("  %-6.1f %-5s %-12.8f %-12.8f %-12.8f %-12.8f %.2e\n", alpha,
                  load_axis == 0 ? "x-z" : "y-z", across, reference.across, 1.0 - along,
                  reference.shortening(),
                  std::max(std::abs(across - reference.across), std::abs(along - reference.along)));
      EXPECT_TRUE(CompareScalars(across, reference.across, tol)) << "alpha " << alpha;
      EXPECT_TRUE(CompareScalars(along, reference.along, tol)) << "alpha " << alpha;
      EXPECT_NEAR(p(1 - load_axis), 0.0, tol);  // stays in its plane
      const double tip_angle =
          std::acos(std::clamp(solution.configuration.R.back()(2, 2), -1.0, 1.0));
      EXPECT_TRUE(CompareScalars(tip_angle, reference.tip_angle,
                                 rk4_angle_error_bound(L, kappa_max, N) + tol));
      for (const auto& row : testing::kBisshoppDruckerRows) {
        if (row.alpha != alpha) continue;
        EXPECT_TRUE(CompareScalars(across, row.across, testing::kBisshoppDruckerHalfUlp + tol));
        EXPECT_TRUE(
            CompareScalars(1.0 - along, row.shortening, testing::kBisshoppDruckerHalfUlp + tol));
      }
    }
  }
}

// A small uniform load w on a Kirchhoff cantilever: the tip deflects by wL⁴/(8EI). β = wL³/EI =
// 1e-3, so the geometric nonlinearity changes the deflection by a relative c β² (c ≈ 0.11 for the
// analogous tip load, from cantilever_elastica: y/L = α/3 (1 - 0.109 α²…)); we allow c ≤ 2: 2e-6.
// RK4 is negligible here (κL ≤ β/2: error ~1e-17 L), the solver is run to ‖r‖ ≤ 1e-13.
TEST(FreeTipSolve, SmallSelfWeightMatchesLinearCantileverDeflection) {
  const double L = 0.8, EIx = 1.7, beta = 1e-3;
  const double w = beta * EIx / (L * L * L);  // N/m
  ClampedRod rod = make_rod(L, Eigen::Vector3d(EIx, 4.0, 1.0), Eigen::Vector3d::Ones(),
                            ConstitutiveModel::Kirchhoff, 100);
  rod.load = DistributedLoad::gravity(w / 9.81, Eigen::Vector3d(0.0, -9.81, 0.0));  // along -y: EIx
  ShootingOptions options = tight_options();
  options.residual_tolerance = 1e-13;
  const ShootingResult solution = solve_equilibrium(rod, FreeTip{}, {}, options);
  ASSERT_TRUE(solution.summary.converged()) << solution.summary.brief();
  const double deflection = -solution.configuration.tip().position.y();
  const double linear = w * std::pow(L, 4) / (8.0 * EIx);
  EXPECT_TRUE(CompareScalars(deflection, linear, 2e-6 * linear));
  EXPECT_NEAR(solution.configuration.tip().position.x(), 0.0, 1e-15);
  // Base wrench: n(0) = f L (n' = -f and n(L) = 0; the clamp holds the weight with -n(0)), and
  // |m(0)| = wL²/2 about x to the same relative order as the deflection.
  EXPECT_TRUE(CompareMatrices(solution.base_wrench.force, Eigen::Vector3d(0.0, -w * L, 0.0),
                              1e-13 + 4.0 * kEps * w * L));
  EXPECT_TRUE(CompareScalars(std::abs(solution.base_wrench.moment.x()), w * L * L / 2.0,
                             2e-6 * w * L * L / 2.0));
}

// The free-tip solve of a pure end moment and of a general tip wrench returns the base wrench that
// the wrench balance predicts: n(0) = F, m(0) = M + (p(L) - p(0)) × F; for a pure moment, the arc.
TEST(FreeTipSolve, BaseWrenchBalancesTheTipWrench) {
  const double L = 1.3;
  const int N = 50;
  const ClampedRod rod =
      make_rod(L, kAnisotropicBending, kShearAxial, ConstitutiveModel::Cosserat, N);
  const double kappa = 2.5 / L;
  const Eigen::Vector3d M(0.0, kappa * kAnisotropicBending.y(), 0.0);
  const ShootingResult arc =
      solve_equilibrium(rod, FreeTip{{Eigen::Vector3d::Zero(), M}}, {}, tight_options());
  ASSERT_TRUE(arc.summary.converged()) << arc.summary.brief();
  EXPECT_TRUE(
      CompareMatrices(arc.base_wrench.to_vector(), (Vector6d() << 0, 0, 0, M).finished(), 1e-10));
  const auto expected = testing::constant_strain_pose(L, kappa * Eigen::Vector3d::UnitY());
  EXPECT_TRUE(CompareMatrices(arc.configuration.tip().position, expected.position,
                              rk4_error_bound(L, kappa, N) + 1e-9));

  const Wrench tip{{1.5, -2.0, 0.7}, {0.4, 0.9, -0.3}};
  const ShootingResult general = solve_equilibrium(rod, FreeTip{tip}, {}, tight_options());
  ASSERT_TRUE(general.summary.converged()) << general.summary.brief();
  const RodConfiguration& c = general.configuration;
  // The residual tolerance bounds the tip wrench error: 1e-10 N and N·m; the balance itself is
  // exact.
  EXPECT_TRUE(CompareMatrices(general.base_wrench.force, tip.force, 1e-10));
  EXPECT_TRUE(CompareMatrices(general.base_wrench.moment,
                              tip.moment + (c.p.back() - c.p.front()).cross(tip.force),
                              1e-10 * (1.0 + 2.0 * L)));
}

}  // namespace
}  // namespace test_rod_integrator
}  // namespace rodshape
