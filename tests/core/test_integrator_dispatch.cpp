// test_integrator_dispatch.cpp: integrate() runs in a clone chosen at load time (x86-64-v3, i.e.
// AVX2 with FMA, or x86-64-v4 where the CPU has them, the x86-64 baseline elsewhere:
// src/core/rod_integrator.cpp).
// Its results, with and without the tangent, are compared with the same Runge–Kutta steps compiled
// here for the baseline target (this file has no target attribute). The tangent's lanes never mix,
// so on a CPU without FMA (the baseline clone) they are bitwise equal. The FMA clone fuses a·b + c,
// which rounds once instead of twice: each fused operation moves its result by at most one
// rounding, ε|result|. Bound: every RK4 step has fewer than kOpsPerStep = 4 stages × 64 operations
// on the chain of any one output, each perturbed by ε relative to the largest value of that
// quantity; over `steps` steps that gives steps · kOpsPerStep · ε · max|value|, times a factor 4
// for the growth of early perturbations along the rod (the tangent's norm, below 4 here). Every
// path has an x86-64-v4 clone too (AVX-512, with the same fused operations; the tangent's paths
// form the state's stages behind a barrier, rk4_step.hpp's Pinned): the shape without the tangent
// is asserted bitwise the tangent path's shape, which the solvers rely on.
// White-box: the steps are those of src/core/rk4_step.hpp.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/rk4_step.hpp"
#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/samples/rubber_band.hpp"

namespace rodshape {
namespace test_integrator_dispatch {
namespace {

/// Operations on the chain of one output per RK4 step (4 stages, each under 64), see above.
constexpr double kOpsPerStep = 4.0 * 64.0;
/// Growth of a perturbation from one step to the tip (above the tangent's norm here).
constexpr double kGrowth = 4.0;

/// The relative tolerance of the FMA clone after `steps` steps (0 on a CPU without FMA: the
/// baseline clone is bitwise).
double fused_tolerance(int steps) {
  const bool fma_clone = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  return fma_clone ? kGrowth * steps * kOpsPerStep * std::numeric_limits<double>::epsilon() : 0.0;
}

/// |got - want| ≤ tolerance · max|want| element by element (== when the tolerance is 0, so +0 and
/// -0 would pass: neither occurs here by chance).
template <class A, class B>
void expect_within(const A& got, const B& want, double tolerance, const char* what) {
  ASSERT_EQ(got.rows(), want.rows()) << what;
  ASSERT_EQ(got.cols(), want.cols()) << what;
  const double bound = tolerance * want.cwiseAbs().maxCoeff();
  for (Eigen::Index i = 0; i < got.rows(); ++i)
    for (Eigen::Index j = 0; j < got.cols(); ++j) {
      if (bound == 0.0)
        EXPECT_EQ(got(i, j), want(i, j)) << what << "(" << i << ", " << j << ")";
      else
        EXPECT_LE(std::abs(got(i, j) - want(i, j)), bound) << what << "(" << i << ", " << j << ")";
    }
}

/// Bitwise equality (two results of the same clone).
template <class A, class B>
void expect_bitwise(const A& got, const B& want, const char* what) {
  expect_within(got, want, 0.0, what);
}

/// The tip of integrate(rod, w, Derivatives::Tip), computed by the steps of rk4_step.hpp in this
/// translation unit.
struct Reference {
  detail::NodeState tip;
  detail::Matrix63d tip_theta;
};

Reference reference_tip(const ClampedRod& rod, const BaseWrench& w) {
  const detail::CosseratOde ode(rod);
  Reference ref{detail::initial_node_state(rod, w.force, w.moment), {}};
  const double h_step = rod.properties.length / (static_cast<double>(rod.intervals) * rod.substeps);
  detail::OdePoint point;
  detail::Matrix63d theta;
  for (int step = 0; step < rod.intervals * rod.substeps; ++step)
    detail::rk4_step<true>(ode, h_step, ref.tip, point, theta);
  detail::OdeState unused;
  detail::evaluate(ode, ref.tip.y, unused, point);
  ref.tip_theta = detail::body_rotation_tangent(ref.tip.y.segment<4>(0), point.q_scale, ref.tip.Y);
  return ref;
}

void expect_dispatched_equals_reference(const ClampedRod& rod, const BaseWrench& w) {
#if defined(__FMA__)
  GTEST_SKIP() << "built for a CPU with FMA (RODSHAPE_NATIVE): no dispatch, and the compiler may "
                  "fuse this file's arithmetic differently from the library's";
#endif
  using detail::Slot;
  const RodConfiguration out = integrate(rod, w, Derivatives::Tip);
  const Reference ref = reference_tip(rod, w);
  const detail::OdeTangent& Y = ref.tip.Y;
  const double tol = fused_tolerance(rod.intervals * rod.substeps);
  expect_within(out.p.back(), ref.tip.y.segment<3>(Slot::p), tol, "p(L)");
  expect_within(out.n.back(), ref.tip.y.segment<3>(Slot::n), tol, "n(L)");
  expect_within(out.m.back(), ref.tip.y.segment<3>(Slot::m), tol, "m(L)");
  expect_within(Eigen::Matrix<double, 1, 1>(out.energy), ref.tip.y.segment<1>(Slot::e), tol, "E");
  expect_within(out.tip_dp_dw, Y.middleCols<3>(Slot::p).transpose(), tol, "dp/dw");
  expect_within(out.tip_dn_dw, Y.middleCols<3>(Slot::n).transpose(), tol, "dn/dw");
  expect_within(out.tip_dm_dw, Y.middleCols<3>(Slot::m).transpose(), tol, "dm/dw");
  expect_within(out.tip_dtheta_dw, ref.tip_theta.transpose(), tol, "dtheta/dw");
  expect_within(out.denergy_dw, Y.col(Slot::e).transpose(), tol, "de/dw");
  // The observed distance, for the record (relative to max|p|).
  ::testing::Test::RecordProperty(
      "p_relative_difference",
      ::testing::PrintToString((out.p.back() - ref.tip.y.segment<3>(Slot::p)).norm() /
                               ref.tip.y.segment<3>(Slot::p).norm()));

  // Without the tangent: the shape's own path (no barrier in its stages), every node, bitwise the
  // tangent path's shape.
  const RodConfiguration shape = integrate(rod, w, Derivatives::None);
  expect_bitwise(shape.p.back(), out.p.back(), "p(L) without the tangent");
  expect_bitwise(shape.m.back(), out.m.back(), "m(L) without the tangent");
  EXPECT_EQ(shape.energy, out.energy);
  for (int i = 0; i < shape.nodes(); ++i) {
    expect_bitwise(shape.R[i], out.R[i], "R_i");
    expect_bitwise(shape.u[i], out.u[i], "u_i");
  }
}

TEST(IntegratorDispatch, TangentPathIsTheBaselineStepsWithinFusedRounding) {
  RecordProperty("fma_clone", fused_tolerance(1) > 0.0 ? "yes" : "no");
  // A generic 3D wrench (bending about both axes, torsion, shear, tension), Cosserat and
  // Kirchhoff (whose δv = 0 takes other lanes' zeros), one and two sub-steps per interval.
  const BaseWrench w{{0.3, -0.2, 0.5}, {0.02, -0.03, 0.01}};
  for (const ConstitutiveModel model :
       {ConstitutiveModel::Cosserat, ConstitutiveModel::Kirchhoff}) {
    for (const int substeps : {1, 2}) {
      ClampedRod rod = samples::rubber_band(model, 37);
      rod.substeps = substeps;
      rod.load.force = {0.0, 0.0, -0.4};  // its weight, roughly: n' ≠ 0
      SCOPED_TRACE(::testing::Message() << "Kirchhoff " << (model == ConstitutiveModel::Kirchhoff)
                                        << ", substeps " << substeps);
      expect_dispatched_equals_reference(rod, w);
    }
  }
}

}  // namespace
}  // namespace test_integrator_dispatch
}  // namespace rodshape
