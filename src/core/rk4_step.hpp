// rk4_step.hpp (private): one classical Runge–Kutta step of the Cosserat ODE, optionally with its
// variational equations through the same stages (so the tangent is the exact derivative of the
// step).
#pragma once

#include "cosserat_ode.hpp"

namespace rodshape::detail {

/// The state at a node: y, and its tangent when derivatives are wanted.
struct NodeState {
  OdeState y;
  OdeTangent Y;
};

/// out = Y + a K, element by element (a plain loop, so that it vectorises for the caller's target).
RODSHAPE_ALWAYS_INLINE inline void tangent_stage(const OdeTangent& Y,
                                                 double a,
                                                 const OdeTangent& K,
                                                 OdeTangent& out) {
  for (int k = 0; k < OdeTangent::SizeAtCompileTime; ++k)
    out.data()[k] = Y.data()[k] + a * K.data()[k];
}

/// Y += (h/6)(K1 + 2 (K2 + K3) + K4), element by element in that order (as Eigen's expression was).
RODSHAPE_ALWAYS_INLINE inline void tangent_update(double sixth,
                                                  const OdeTangent& K1,
                                                  const OdeTangent& K2,
                                                  const OdeTangent& K3,
                                                  const OdeTangent& K4,
                                                  OdeTangent& Y) {
  for (int k = 0; k < OdeTangent::SizeAtCompileTime; ++k)
    Y.data()[k] += sixth * (K1.data()[k] + 2.0 * (K2.data()[k] + K3.data()[k]) + K4.data()[k]);
}

/// Advances `state` by h. `start` receives the first stage's evaluation, i.e. R, v, u, ... at the
/// node the step starts from, and `start_theta` the body rotation tangent there (with tangents).
/// LoadForcing: the tangent's six directions are the distributed load's (f, l) instead of the base
/// wrench's (evaluate_tangent). Without Energy, e and its tangent stay where they are.
template <bool WithTangent, bool LoadForcing = false, bool Energy = true>
RODSHAPE_ALWAYS_INLINE inline void rk4_step(
    const CosseratOde& ode, double h, NodeState& state, OdePoint& start, Matrix63d& start_theta) {
  OdeState k1, k2, k3, k4, y_stage;
  OdeTangent K1, K2, K3, K4, Y_stage;
  OdePoint point;
  const double half = 0.5 * h;

  evaluate<Energy>(ode, state.y, k1, start);
  if constexpr (WithTangent)
    start_theta = evaluate_tangent<LoadForcing, Energy>(ode, state.y, start, state.Y, K1);

  y_stage = state.y + half * k1;
  evaluate<Energy>(ode, y_stage, k2, point);
  if constexpr (WithTangent) {
    tangent_stage(state.Y, half, K1, Y_stage);
    evaluate_tangent<LoadForcing, Energy>(ode, y_stage, point, Y_stage, K2);
  }

  y_stage = state.y + half * k2;
  evaluate<Energy>(ode, y_stage, k3, point);
  if constexpr (WithTangent) {
    tangent_stage(state.Y, half, K2, Y_stage);
    evaluate_tangent<LoadForcing, Energy>(ode, y_stage, point, Y_stage, K3);
  }

  y_stage = state.y + h * k3;
  evaluate<Energy>(ode, y_stage, k4, point);
  if constexpr (WithTangent) {
    tangent_stage(state.Y, h, K3, Y_stage);
    evaluate_tangent<LoadForcing, Energy>(ode, y_stage, point, Y_stage, K4);
  }

  const double sixth = h / 6.0;
  state.y += sixth * (k1 + 2.0 * (k2 + k3) + k4);
  if constexpr (WithTangent) tangent_update(sixth, K1, K2, K3, K4, state.Y);
}

/// The node state at s = 0: q from the clamp rotation, p(0), and w = (n(0), m(0)); the tangent is
/// dn(0)/dw = [I 0], dm(0)/dw = [0 I].
inline NodeState initial_node_state(const ClampedRod& rod,
                                    const Eigen::Vector3d& n0,
                                    const Eigen::Vector3d& m0) {
  NodeState state;
  const Eigen::Quaterniond q0(rod.clamp.rotation);
  state.y << q0.w(), q0.x(), q0.y(), q0.z(), rod.clamp.position, n0, m0, 0.0;
  state.Y.setZero();
  state.Y.block<3, 3>(0, Slot::n).setIdentity();
  state.Y.block<3, 3>(3, Slot::m).setIdentity();
  return state;
}

}  // namespace rodshape::detail
