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

/// An empty asm that takes `x` in a vector register and gives it back: GCC's SLP vectoriser cannot
/// group the entries around it, so each entry of the state's stage is formed on its own.
RODSHAPE_ALWAYS_INLINE inline void pin_scalar(double& x) {
#if defined(__GNUC__) && defined(__x86_64__)
  asm("" : "+x"(x));
#else
  (void)x;
#endif
}

/// Y += (h/6)(K1 + 2 (K2 + K3) + K4), element by element in that order (as Eigen's expression was),
/// column by column in the pieces evaluate_tangent stores (directions 0–3 and 4–5), so that each
/// load reads what one store wrote and is forwarded from the store buffer (a plain loop's 4-wide
/// loads spanned two of those stores in two of every three). Columns whose rate is zero are left
/// as they are (bitwise what adding zero gives: their entries are finite and not -0): δn for the
/// base-wrench directions (VaryingN false: δn' = 0) and δe without the energy.
template <bool VaryingN, bool Energy>
RODSHAPE_ALWAYS_INLINE inline void tangent_update(double sixth,
                                                  const OdeTangent& K1,
                                                  const OdeTangent& K2,
                                                  const OdeTangent& K3,
                                                  const OdeTangent& K4,
                                                  OdeTangent& Y) {
  const auto piece = [&](auto lanes_tag, int c, int j) RODSHAPE_ALWAYS_INLINE {
    using V = typename decltype(lanes_tag)::type;
    V y, k1, k2, k3, k4;
    load(y, Y.data() + c, j), load(k1, K1.data() + c, j), load(k2, K2.data() + c, j);
    load(k3, K3.data() + c, j), load(k4, K4.data() + c, j);
    store(Y.data() + c, j, y + sixth * (k1 + 2.0 * (k2 + k3) + k4));
  };
  for (int k = 0; k < OdeTangent::ColsAtCompileTime; ++k) {
    if ((!VaryingN && k >= Slot::n && k < Slot::n + 3) || (!Energy && k == Slot::e)) continue;
    piece(std::type_identity<Lanes4>{}, OdeTangent::RowsAtCompileTime * k, 0);
    piece(std::type_identity<Lanes2>{}, OdeTangent::RowsAtCompileTime * k, 4);
  }
}

/// out = y + a k, entry by entry and fully unrolled, so that the 14 entries stay scalars:
/// evaluate() writes k and reads the stage one entry at a time, and a vector load spanning several
/// scalar stores waits for them to reach the cache instead of being forwarded (Eigen's packets here
/// made BM_Forward 24 % slower; BENCHMARKS.md, "The state's stages as scalars").
template <bool Pinned = false>
RODSHAPE_ALWAYS_INLINE inline void state_stage(const OdeState& y,
                                               double a,
                                               const OdeState& k,
                                               OdeState& out) {
#pragma GCC unroll 14
  for (int i = 0; i < OdeState::SizeAtCompileTime; ++i) {
    double entry = y.data()[i] + a * k.data()[i];
    if constexpr (Pinned) pin_scalar(entry);
    out.data()[i] = entry;
  }
}

/// y += (h/6)(k1 + 2 (k2 + k3) + k4), entry by entry in that order (as Eigen's expression was),
/// unrolled as state_stage is.
template <bool Pinned = false>
RODSHAPE_ALWAYS_INLINE inline void state_update(double sixth,
                                                const OdeState& k1,
                                                const OdeState& k2,
                                                const OdeState& k3,
                                                const OdeState& k4,
                                                OdeState& y) {
#pragma GCC unroll 14
  for (int i = 0; i < OdeState::SizeAtCompileTime; ++i) {
    double entry =
        y.data()[i] + sixth * (k1.data()[i] + 2.0 * (k2.data()[i] + k3.data()[i]) + k4.data()[i]);
    if constexpr (Pinned) pin_scalar(entry);
    y.data()[i] = entry;
  }
}

/// Advances `state` by h. `start` receives the first stage's evaluation, i.e. R, v, u, ... at the
/// node the step starts from, and `start_theta` the body rotation tangent there (with tangents).
/// LoadForcing: the tangent's six directions are the distributed load's (f, l) instead of the base
/// wrench's (evaluate_tangent). Without Energy, e and its tangent stay where they are. Pinned: the
/// state's stages and update entry by entry behind pin_scalar (the same operations per entry), so
/// that the shape rounds as in the shape's own path whatever else the path computes.
template <bool WithTangent, bool LoadForcing = false, bool Energy = true, bool Pinned = false>
RODSHAPE_ALWAYS_INLINE inline void rk4_step(
    const CosseratOde& ode, double h, NodeState& state, OdePoint& start, Matrix63d& start_theta) {
  OdeState k1, k2, k3, k4, y_stage;
  OdeTangent K1, K2, K3, K4;
  OdePoint point;
  const double half = 0.5 * h;

  evaluate<Energy>(ode, state.y, k1, start);
  if constexpr (WithTangent)
    start_theta = evaluate_tangent<LoadForcing, Energy>(ode, state.y, start, {state.Y}, K1);

  state_stage<Pinned>(state.y, half, k1, y_stage);
  evaluate<Energy>(ode, y_stage, k2, point);
  if constexpr (WithTangent)
    evaluate_tangent<LoadForcing, Energy>(ode, y_stage, point, {state.Y, &K1, half}, K2);

  state_stage<Pinned>(state.y, half, k2, y_stage);
  evaluate<Energy>(ode, y_stage, k3, point);
  if constexpr (WithTangent)
    evaluate_tangent<LoadForcing, Energy>(ode, y_stage, point, {state.Y, &K2, half}, K3);

  state_stage<Pinned>(state.y, h, k3, y_stage);
  evaluate<Energy>(ode, y_stage, k4, point);
  if constexpr (WithTangent)
    evaluate_tangent<LoadForcing, Energy>(ode, y_stage, point, {state.Y, &K3, h}, K4);

  const double sixth = h / 6.0;
  state_update<Pinned>(sixth, k1, k2, k3, k4, state.y);
  if constexpr (WithTangent) tangent_update<LoadForcing, Energy>(sixth, K1, K2, K3, K4, state.Y);
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
