// test_solve_output.cpp: solve_equilibrium's configuration is integrate(rod, base_wrench,
// options.output_derivatives), bit for bit, whether the solver integrated it once more or kept its
// last integration (a chord step's without derivatives, or a Levenberg–Marquardt evaluation's with
// tip derivatives when none are asked for), for each output level.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <numbers>

#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/samples/rubber_band.hpp"
#include "rodshape/solvers/shooting_solver.hpp"

namespace rodshape {
namespace test_solve_output {
namespace {

template <class A>
void expect_same(const A& got, const A& want, const char* what) {
  EXPECT_TRUE(got == want) << what;
}

void expect_same_configuration(const RodConfiguration& got, const RodConfiguration& want) {
  ASSERT_EQ(got.nodes(), want.nodes());
  EXPECT_EQ(got.derivatives, want.derivatives);
  EXPECT_EQ(got.s, want.s);
  for (int i = 0; i < got.nodes(); ++i) {
    SCOPED_TRACE(::testing::Message() << "node " << i);
    expect_same(got.p[i], want.p[i], "p");
    expect_same(got.R[i], want.R[i], "R");
    expect_same(got.n[i], want.n[i], "n");
    expect_same(got.m[i], want.m[i], "m");
    expect_same(got.v[i], want.v[i], "v");
    expect_same(got.u[i], want.u[i], "u");
  }
  EXPECT_EQ(got.energy, want.energy);
  expect_same(got.tip_dp_dw, want.tip_dp_dw, "tip_dp_dw");
  expect_same(got.tip_dtheta_dw, want.tip_dtheta_dw, "tip_dtheta_dw");
  expect_same(got.tip_dn_dw, want.tip_dn_dw, "tip_dn_dw");
  expect_same(got.tip_dm_dw, want.tip_dm_dw, "tip_dm_dw");
  expect_same(got.denergy_dw, want.denergy_dw, "denergy_dw");
  ASSERT_EQ(got.dp_dw.size(), want.dp_dw.size());
  for (std::size_t i = 0; i < got.dp_dw.size(); ++i) {
    expect_same(got.dp_dw[i], want.dp_dw[i], "dp_dw");
    expect_same(got.dtheta_dw[i], want.dtheta_dw[i], "dtheta_dw");
  }
}

using samples::bent_tip;

TEST(SolveOutput, ConfigurationIsTheIntegrationOfTheSolutionAtEachLevel) {
  const ClampedRod rod = samples::rubber_band(ConstitutiveModel::Cosserat, 40);
  ShootingOptions options;
  options.residual_tolerance = 1e-10;
  const BaseWrench solved = solve_equilibrium(rod, ClampedTip{bent_tip()}, {}, options).base_wrench;
  Pose moved = bent_tip();
  moved.position.x() += 1e-3;
  for (const Derivatives level : {Derivatives::None, Derivatives::Tip, Derivatives::AllNodes}) {
    options.output_derivatives = level;
    // Cold (Levenberg–Marquardt, then the chord endgame) and warm (the endgame at once).
    for (const BaseWrench& guess : {BaseWrench{}, solved}) {
      SCOPED_TRACE(::testing::Message() << "level " << static_cast<int>(level) << ", "
                                        << (guess.force.isZero() ? "cold" : "warm"));
      const ShootingResult result = solve_equilibrium(rod, ClampedTip{moved}, guess, options);
      ASSERT_TRUE(result.summary.converged()) << result.summary.brief();
      expect_same_configuration(result.configuration, integrate(rod, result.base_wrench, level));
    }
  }
}

}  // namespace
}  // namespace test_solve_output
}  // namespace rodshape
