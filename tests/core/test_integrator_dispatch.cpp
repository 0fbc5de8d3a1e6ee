// test_integrator_dispatch.cpp: integrate() runs in a clone chosen at load time (AVX2 where the
// CPU has it, the x86-64 baseline elsewhere: src/core/rod_integrator.cpp). Its results, with and
// without the tangent, must be bitwise those of the same Runge–Kutta steps compiled here for the
// baseline target (this file has no target attribute): the clone fuses no multiply-add and the
// tangent's lanes never mix, so there is no tolerance. White-box: the steps are those of
// src/core/rk4_step.hpp.
#include <gtest/gtest.h>

#include "core/rk4_step.hpp"
#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/samples/rubber_band.hpp"

namespace rodshape {
namespace {

/// Bitwise equality of two matrices (==, so +0 and -0 would pass: neither occurs here by chance).
template <class A, class B>
void expect_bitwise(const A& got, const B& want, const char* what) {
  ASSERT_EQ(got.rows(), want.rows()) << what;
  ASSERT_EQ(got.cols(), want.cols()) << what;
  for (Eigen::Index i = 0; i < got.rows(); ++i)
    for (Eigen::Index j = 0; j < got.cols(); ++j)
      EXPECT_EQ(got(i, j), want(i, j)) << what << "(" << i << ", " << j << ")";
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
  expect_bitwise(out.p.back(), ref.tip.y.segment<3>(Slot::p), "p(L)");
  expect_bitwise(out.n.back(), ref.tip.y.segment<3>(Slot::n), "n(L)");
  expect_bitwise(out.m.back(), ref.tip.y.segment<3>(Slot::m), "m(L)");
  EXPECT_EQ(out.energy, ref.tip.y[Slot::e]);
  expect_bitwise(out.tip_dp_dw, Y.middleCols<3>(Slot::p).transpose(), "dp/dw");
  expect_bitwise(out.tip_dn_dw, Y.middleCols<3>(Slot::n).transpose(), "dn/dw");
  expect_bitwise(out.tip_dm_dw, Y.middleCols<3>(Slot::m).transpose(), "dm/dw");
  expect_bitwise(out.tip_dtheta_dw, ref.tip_theta.transpose(), "dtheta/dw");
  expect_bitwise(out.denergy_dw, Y.col(Slot::e).transpose(), "de/dw");

  // Without the tangent: the shape's own path (its own clone), every node.
  const RodConfiguration shape = integrate(rod, w, Derivatives::None);
  expect_bitwise(shape.p.back(), out.p.back(), "p(L) without the tangent");
  expect_bitwise(shape.m.back(), out.m.back(), "m(L) without the tangent");
  EXPECT_EQ(shape.energy, out.energy);
  for (int i = 0; i < shape.nodes(); ++i) {
    expect_bitwise(shape.R[i], out.R[i], "R_i");
    expect_bitwise(shape.u[i], out.u[i], "u_i");
  }
}

TEST(IntegratorDispatch, TangentPathIsBitwiseTheBaselineSteps) {
  RecordProperty("avx2_clone", __builtin_cpu_supports("avx2") ? "yes" : "no");
  // A generic 3D wrench (bending about both axes, torsion, shear, tension), Cosserat and
  // Kirchhoff (whose δv = 0 takes other lanes' zeros), one and two sub-steps per interval.
  const BaseWrench w{{0.3, -0.2, 0.5}, {0.02, -0.03, 0.01}};
  for (const ConstitutiveModel model :
       {ConstitutiveModel::Cosserat, ConstitutiveModel::Kirchhoff}) {
    for (const int substeps : {1, 2}) {
      ClampedRod rod = samples::rubber_band(model, 37);
      rod.substeps = substeps;
      rod.load.force = {0.0, 0.0, -0.4};  // its weight, roughly: n' ≠ 0
      SCOPED_TRACE(testing::Message() << "Kirchhoff " << (model == ConstitutiveModel::Kirchhoff)
                                      << ", substeps " << substeps);
      expect_dispatched_equals_reference(rod, w);
    }
  }
}

}  // namespace
}  // namespace rodshape
