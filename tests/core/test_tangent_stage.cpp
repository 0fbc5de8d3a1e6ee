// test_tangent_stage.cpp: the tangent's Runge–Kutta stages are formed where evaluate_tangent reads
// them (TangentStage: Y + a K lane by lane, src/core/cosserat_ode.hpp), and rk4_step's update
// leaves the columns whose rate is zero (δn for the base-wrench directions). Both are bitwise what
// forming the stage whole and adding the zero rates gives: same operations per lane, compiled here
// for one target. White-box: the functions of src/core/rk4_step.hpp.
#include <gtest/gtest.h>

#include "core/rk4_step.hpp"
#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/samples/rubber_band.hpp"

namespace rodshape {
namespace test_tangent_stage {
namespace {

using detail::OdeTangent;
using detail::Slot;

/// A stage away from the base: the rubber band's state and tangent after 40 steps of a 3D wrench.
detail::NodeState state_along_the_rod(const ClampedRod& rod) {
  detail::NodeState state = detail::initial_node_state(rod, {0.3, -0.2, 0.5}, {0.02, -0.03, 0.01});
  const detail::CosseratOde ode(rod);
  detail::OdePoint point;
  detail::Matrix63d theta;
  for (int k = 0; k < 40; ++k) detail::rk4_step<true>(ode, rod.step(), state, point, theta);
  return state;
}

TEST(TangentStage, FormedWhereReadIsBitwiseTheStageFormedWhole) {
  const ClampedRod rod = samples::rubber_band(ConstitutiveModel::Cosserat, 100);
  const detail::CosseratOde ode(rod);
  const detail::NodeState state = state_along_the_rod(rod);
  detail::OdeState k1;
  detail::OdePoint point;
  detail::evaluate(ode, state.y, k1, point);
  OdeTangent K1;
  detail::evaluate_tangent(ode, state.y, point, {state.Y}, K1);
  const double a = 0.5 * rod.step();
  const detail::OdeState y_stage = state.y + a * k1;
  detail::OdePoint stage_point;
  detail::OdeState k2;
  detail::evaluate(ode, y_stage, k2, stage_point);
  // The stage formed whole, element by element (as rk4_step did), then evaluated ...
  OdeTangent Y_stage;
  for (int i = 0; i < OdeTangent::SizeAtCompileTime; ++i)
    Y_stage.data()[i] = state.Y.data()[i] + a * K1.data()[i];
  OdeTangent whole, lazy;
  const detail::Matrix63d theta_whole =
      detail::evaluate_tangent(ode, y_stage, stage_point, {Y_stage}, whole);
  // ... and formed where it is read.
  const detail::Matrix63d theta_lazy =
      detail::evaluate_tangent(ode, y_stage, stage_point, {state.Y, &K1, a}, lazy);
  for (int k = 0; k < OdeTangent::ColsAtCompileTime; ++k) {
    if (k >= Slot::n && k < Slot::n + 3) continue;  // δn' is not written (zero)
    for (int j = 0; j < 6; ++j) EXPECT_EQ(lazy(j, k), whole(j, k)) << "(" << j << ", " << k << ")";
  }
  for (int i = 0; i < theta_whole.size(); ++i)
    EXPECT_EQ(theta_lazy.data()[i], theta_whole.data()[i]);
  EXPECT_NE(lazy.col(Slot::m).norm(), 0.0);  // the compared rates are not trivially zero
}

TEST(TangentStage, BaseForceDirectionsKeepTheirUnitForceAtEveryNode) {
  // δn' = 0 for the base-wrench directions, so dn/dw = [I 0] exactly all along the rod: the update
  // leaves those columns untouched (adding the zero rates gave the same bits).
  const ClampedRod rod = samples::rubber_band(ConstitutiveModel::Cosserat, 50);
  const RodConfiguration c =
      integrate(rod, BaseWrench{{0.3, -0.2, 0.5}, {0.02, -0.03, 0.01}}, Derivatives::AllNodes);
  Eigen::Matrix<double, 3, 6> unit_force = Eigen::Matrix<double, 3, 6>::Zero();
  unit_force.leftCols<3>().setIdentity();
  for (int i = 0; i < rod.nodes(); ++i) EXPECT_EQ(c.dn_dw[i], unit_force) << "node " << i;
  EXPECT_EQ(c.tip_dn_dw, unit_force);
}

}  // namespace
}  // namespace test_tangent_stage
}  // namespace rodshape
