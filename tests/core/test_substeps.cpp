// test_substeps.cpp: sub-steps inside the intervals (ClampedRod::substeps), the finite() check of a
// configuration, its strain extremes, and re-entering the integration between nodes
// (pose_between_nodes), which the stability test uses.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "rodshape/core/pose_between_nodes.hpp"
#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/core/strain_extremes.hpp"
#include "rodshape/error.hpp"
#include "support/analytic_rods.hpp"

namespace rodshape {
namespace test_substeps {
namespace {

using testing::kEps;

/// The rubber band (L = 0.29 m, EI = 0.04 N·m², GJ = 0.028, GA = 426.7 N, EA = 1280 N).
ClampedRod band(int intervals) {
  ClampedRod rod;
  rod.properties.length = 0.29;
  rod.properties.K_rot = {0.04, 0.04, 0.028};
  rod.properties.K_tra = {3.2e6 / 3.0 * 4e-4, 3.2e6 / 3.0 * 4e-4, 3.2e6 * 4e-4};
  rod.intervals = intervals;
  rod.validate();
  return rod;
}

const BaseWrench kWrench{{0.3, -0.2, 1.5}, {0.02, 0.05, -0.01}};

TEST(Substeps, SubstepsGiveTheNodesOfTheFinerGridAndKeepTheNodeCount) {
  // S sub-steps on N intervals take the same Runge–Kutta steps as N S intervals: the nodes agree
  // with every S-th node of the finer grid to round-off (16 N S ε, the integrator's floor, on
  // quantities of order 1 m, 1 N, 0.1 N·m).
  constexpr int N = 20, S = 4;
  ClampedRod coarse = band(N);
  coarse.substeps = S;
  const RodConfiguration sub = integrate(coarse, kWrench, Derivatives::AllNodes);
  const RodConfiguration fine = integrate(band(N * S), kWrench, Derivatives::AllNodes);
  ASSERT_EQ(sub.nodes(), N + 1);
  const double tol = 16.0 * N * S * kEps;
  for (int i = 0; i <= N; ++i) {
    EXPECT_NEAR(sub.s[i], fine.s[S * i], tol);
    EXPECT_LE((sub.p[i] - fine.p[S * i]).norm(), tol) << i;
    EXPECT_LE((sub.R[i] - fine.R[S * i]).norm(), tol) << i;
    EXPECT_LE((sub.m[i] - fine.m[S * i]).norm(), tol) << i;
    EXPECT_LE((sub.u[i] - fine.u[S * i]).norm(), 1e3 * tol) << i;  // u = m / EI, EI = 0.04
    EXPECT_LE((sub.dp_dw[i] - fine.dp_dw[S * i]).norm(), 1e3 * tol) << i;
  }
  EXPECT_NEAR(sub.energy, fine.energy, tol);
  EXPECT_LE((sub.tip_dtheta_dw - fine.tip_dtheta_dw).norm(), 1e3 * tol);
}

TEST(Substeps, ValidateBoundsTheSubstepCount) {
  ClampedRod rod = band(10);
  rod.substeps = 0;
  EXPECT_THROW(rod.validate(), InputError);
  rod.substeps = ClampedRod::kMaxSubsteps + 1;
  EXPECT_THROW(rod.validate(), InputError);
  rod.substeps = ClampedRod::kMaxSubsteps;
  EXPECT_NO_THROW(rod.validate());
}

TEST(ConfigurationFinite, TrueForAShapeFalseForAnyNonFiniteNodeOrEnergy) {
  const ClampedRod rod = band(10);
  RodConfiguration c = integrate(rod, kWrench);
  EXPECT_TRUE(c.finite());
  c.p[7].x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(c.finite());
  c = integrate(rod, kWrench);
  c.u[10].z() = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(c.finite());
  c = integrate(rod, kWrench);
  c.energy = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(c.finite());
  // A base wrench that overflows the integration (curvature 1e300 / 0.04 per metre).
  EXPECT_FALSE(integrate(rod, BaseWrench{{0, 0, 0}, {1e300, 0, 0}}).finite());
}

// finite() sums x · 0 over each array (0, or NaN for a ±inf or NaN entry): every array, every
// entry of a node's vector or matrix, the first and the last node are looked at; derivatives are
// not, nor the energy of an Output::Tip configuration (not integrated).
TEST(ConfigurationFinite, EveryNodeArrayAndEveryEntryIsLookedAt) {
  const ClampedRod rod = band(10);
  const RodConfiguration shape = integrate(rod, kWrench, Derivatives::AllNodes);
  ASSERT_TRUE(shape.finite());
  const double kInf = std::numeric_limits<double>::infinity();
  const double kNaN = std::numeric_limits<double>::quiet_NaN();
  for (const int i : {0, 5, 10}) {
    for (const double bad : {kNaN, kInf, -kInf}) {
      SCOPED_TRACE("node " + std::to_string(i) + ", value " + std::to_string(bad));
      RodConfiguration c = shape;
      c.s[i] = bad;
      EXPECT_FALSE(c.finite());
      c = shape, c.p[i].z() = bad;
      EXPECT_FALSE(c.finite());
      c = shape, c.R[i](2, 1) = bad;
      EXPECT_FALSE(c.finite());
      c = shape, c.n[i].x() = bad;
      EXPECT_FALSE(c.finite());
      c = shape, c.m[i].y() = bad;
      EXPECT_FALSE(c.finite());
      c = shape, c.v[i].z() = bad;
      EXPECT_FALSE(c.finite());
      c = shape, c.u[i].x() = bad;
      EXPECT_FALSE(c.finite());
      c = shape, c.dp_dw[i](0, 0) = bad;
      EXPECT_TRUE(c.finite());
    }
  }
  RodConfiguration tip;
  integrate(rod, kWrench, tip, Derivatives::None, Output::Tip);
  EXPECT_TRUE(tip.finite());  // energy NaN: not integrated
  tip.m[1].z() = kInf;
  EXPECT_FALSE(tip.finite());
}

TEST(StrainExtremes, AxialForceStretchesByFOverEAAndShearForceShearsByFOverGA) {
  // A straight band under an axial tip force F: v_z - 1 = F / EA at every node; under a small
  // transverse base force the base node shears by F / GA (exactly: R(0) = I).
  const ClampedRod rod = band(10);
  const double F = 64.0;  // N: 5 % of EA
  const StrainExtremes axial =
      strain_extremes(rod.properties, integrate(rod, BaseWrench{{0, 0, F}, {0, 0, 0}}));
  EXPECT_NEAR(axial.max_axial, F / rod.properties.K_tra.z(), 1e-14);
  EXPECT_NEAR(axial.min_axial_stretch, 1.0 + F / rod.properties.K_tra.z(), 1e-14);
  EXPECT_EQ(axial.max_shear, 0.0);
  EXPECT_EQ(axial.max_curvature, 0.0);
  const StrainExtremes compressed =
      strain_extremes(rod.properties, integrate(rod, BaseWrench{{0, 0, -F}, {0, 0, 0}}));
  EXPECT_NEAR(compressed.min_axial_stretch, 1.0 - F / rod.properties.K_tra.z(), 1e-14);

  const double Fx = 1e-3;
  const RodConfiguration sheared = integrate(rod, BaseWrench{{Fx, 0, 0}, {0, 0, 0}});
  const StrainExtremes shear = strain_extremes(rod.properties, sheared);
  EXPECT_GE(shear.max_shear, Fx / rod.properties.K_tra.x() * (1.0 - 1e-9));
  // End moment M about x: curvature M / EI everywhere.
  const double M = 0.01;
  const StrainExtremes bent =
      strain_extremes(rod.properties, integrate(rod, BaseWrench{{0, 0, 0}, {M, 0, 0}}));
  EXPECT_NEAR(bent.max_curvature, M / 0.04, 1e-13);
}

TEST(PoseBetweenNodes, ReproducesTheNextNodeAndItsDerivatives) {
  for (const int substeps : {1, 3}) {
    ClampedRod rod = band(12);
    rod.substeps = substeps;
    const RodConfiguration c = integrate(rod, kWrench, Derivatives::AllNodes);
    for (const int i : {0, 5, 11}) {
      const PoseDerivatives d = pose_between_nodes(rod, c, i, c.s[i + 1]);
      EXPECT_LE((d.pose.position - c.p[i + 1]).norm(), 1e-14) << i;
      EXPECT_LE((d.pose.rotation - c.R[i + 1]).norm(), 1e-13) << i;
      EXPECT_LE((d.dp_dw - c.dp_dw[i + 1]).norm(), 1e-12 * c.dp_dw[i + 1].norm()) << i;
      EXPECT_LE((d.dtheta_dw - c.dtheta_dw[i + 1]).norm(), 1e-12 * c.dtheta_dw[i + 1].norm()) << i;
    }
  }
}

}  // namespace
}  // namespace test_substeps
}  // namespace rodshape
