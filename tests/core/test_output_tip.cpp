// test_output_tip.cpp: integrate(..., Output::Tip) (rod_configuration.hpp) stores the base and the
// tip only and skips the energy; the steps are those of Output::Full, so every value it stores is
// bitwise Output::Full's at the same node (no tolerance: the same operations in the same order).
#include <gtest/gtest.h>

#include <cmath>

#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/samples/rubber_band.hpp"

namespace rodshape {
namespace test_output_tip {
namespace {

/// == element by element (bitwise but for ±0, which does not arise here).
template <class A, class B>
void expect_same(const A& got, const B& want, const char* what) {
  for (Eigen::Index i = 0; i < got.rows(); ++i)
    for (Eigen::Index j = 0; j < got.cols(); ++j)
      EXPECT_EQ(got(i, j), want(i, j)) << what << "(" << i << ", " << j << ")";
}

/// Node `i` of `tip` equals node `j` of `full`.
void expect_same_node(const RodConfiguration& tip, int i, const RodConfiguration& full, int j) {
  EXPECT_EQ(tip.s[i], full.s[j]);
  expect_same(tip.p[i], full.p[j], "p");
  expect_same(tip.R[i], full.R[j], "R");
  expect_same(tip.n[i], full.n[j], "n");
  expect_same(tip.m[i], full.m[j], "m");
  expect_same(tip.v[i], full.v[j], "v");
  expect_same(tip.u[i], full.u[j], "u");
}

TEST(OutputTip, StoresTheBaseAndTheTipOfTheFullIntegration) {
  const BaseWrench w{{0.3, -0.2, 0.5}, {0.02, -0.03, 0.01}};
  for (const ConstitutiveModel model :
       {ConstitutiveModel::Cosserat, ConstitutiveModel::Kirchhoff}) {
    for (const int substeps : {1, 2}) {
      for (const Derivatives derivatives : {Derivatives::None, Derivatives::Tip}) {
        ClampedRod rod = samples::rubber_band(model, 37);
        rod.substeps = substeps;
        rod.load.force = {0.0, 0.0, -0.4};
        SCOPED_TRACE(::testing::Message()
                     << "Kirchhoff " << (model == ConstitutiveModel::Kirchhoff) << ", substeps "
                     << substeps << ", derivatives " << static_cast<int>(derivatives));
        const RodConfiguration full = integrate(rod, w, derivatives);
        const RodConfiguration tip = integrate(rod, w, derivatives, Output::Tip);
        ASSERT_EQ(tip.nodes(), 2);
        EXPECT_EQ(tip.output, Output::Tip);
        EXPECT_EQ(full.output, Output::Full);
        expect_same_node(tip, 0, full, 0);
        expect_same_node(tip, 1, full, rod.intervals);
        EXPECT_EQ(tip.length(), rod.properties.length);
        EXPECT_TRUE(std::isnan(tip.energy));  // not integrated
        EXPECT_TRUE(std::isfinite(full.energy));
        EXPECT_TRUE(tip.finite());  // the energy is not looked at
        if (derivatives == Derivatives::Tip) {
          expect_same(tip.tip_dp_dw, full.tip_dp_dw, "dp/dw");
          expect_same(tip.tip_dtheta_dw, full.tip_dtheta_dw, "dtheta/dw");
          expect_same(tip.tip_dn_dw, full.tip_dn_dw, "dn/dw");
          expect_same(tip.tip_dm_dw, full.tip_dm_dw, "dm/dw");
          EXPECT_TRUE(tip.denergy_dw.array().isNaN().all());
        }
      }
    }
  }
}

TEST(OutputTip, AllNodeDerivativesStoreEveryNode) {
  const ClampedRod rod = samples::rubber_band(ConstitutiveModel::Cosserat, 20);
  const RodConfiguration c =
      integrate(rod, {{0.3, -0.2, 0.5}, {0.02, -0.03, 0.01}}, Derivatives::AllNodes, Output::Tip);
  EXPECT_EQ(c.nodes(), rod.nodes());
  EXPECT_EQ(c.output, Output::Full);
  EXPECT_EQ(static_cast<int>(c.dp_dw.size()), rod.nodes());
  EXPECT_TRUE(std::isfinite(c.energy));
}

}  // namespace
}  // namespace test_output_tip
}  // namespace rodshape
