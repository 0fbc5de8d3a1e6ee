#include "rodshape/core/rod_integrator.hpp"

#include <limits>

#include "load_tangent.hpp"
#include "rk4_step.hpp"

namespace rodshape {

namespace {

using detail::Matrix63d;
using detail::NodeState;
using detail::OdePoint;
using detail::Slot;

/// s, p, n, m at node i (before the step that leaves it).
void store_node_state(const NodeState& state, int i, double s, RodConfiguration& out) {
  out.s[i] = s;
  out.p[i] = state.y.segment<3>(Slot::p);
  out.n[i] = state.y.segment<3>(Slot::n);
  out.m[i] = state.y.segment<3>(Slot::m);
}

/// R, v, u at node i, from the step's first stage.
void store_node_point(const OdePoint& point, int i, RodConfiguration& out) {
  out.R[i] = point.R;
  out.v[i] = point.v;
  out.u[i] = point.u;
}

/// dp, dn, dm at node i (before the step).
void store_node_tangent(const NodeState& state, int i, RodConfiguration& out) {
  out.dp_dw[i] = state.Y.middleCols<3>(Slot::p).transpose();
  out.dn_dw[i] = state.Y.middleCols<3>(Slot::n).transpose();
  out.dm_dw[i] = state.Y.middleCols<3>(Slot::m).transpose();
}

/// LoadForcing: the tangent is with respect to the distributed load (f, l) (load_tangent.hpp).
/// TipOnly (Output::Tip): node 0 and the tip only, at indices 0 and 1, and no energy.
template <bool WithTangent, bool LoadForcing = false, bool TipOnly = false>
RODSHAPE_ALWAYS_INLINE inline void integrate_nodes(const ClampedRod& rod,
                                                   NodeState& state,
                                                   RodConfiguration& out) {
  constexpr bool energy = !TipOnly;
  const detail::CosseratOde ode(rod);
  const int N = rod.intervals;
  const double h = rod.step();
  // One step per interval unless the rod asks for sub-steps (same h, bitwise, when substeps = 1).
  const double h_step = rod.properties.length / (static_cast<double>(N) * rod.substeps);
  const bool all_nodes = !TipOnly && out.derivatives == Derivatives::AllNodes;
  OdePoint point, inner_point;
  Matrix63d theta, inner_theta;
  for (int i = 0; i < N; ++i) {
    const bool stored = !TipOnly || i == 0;
    if (stored) store_node_state(state, i, i * h, out);
    if (WithTangent && all_nodes) store_node_tangent(state, i, out);
    // One call site, so that the step stays inlined; the first sub-step's start is node i.
    detail::OdePoint* start = &point;
    Matrix63d* start_theta = &theta;
    for (int k = 0; k < rod.substeps; ++k) {
      detail::rk4_step<WithTangent, LoadForcing, energy, WithTangent>(ode, h_step, state, *start,
                                                                      *start_theta);
      start = &inner_point;
      start_theta = &inner_theta;
    }
    if (stored) store_node_point(point, i, out);  // `point` and `theta` are at node i
    if (WithTangent && all_nodes) out.dtheta_dw[i] = theta.transpose();
  }
  // The tip: one more evaluation for R, v, u at s = L (no step).
  const int tip = TipOnly ? 1 : N;
  detail::OdeState unused;
  detail::evaluate<energy>(ode, state.y, unused, point);
  store_node_state(state, tip, rod.properties.length, out);
  store_node_point(point, tip, out);
  constexpr double not_integrated = std::numeric_limits<double>::quiet_NaN();
  out.energy = energy ? state.y[Slot::e] : not_integrated;
  if constexpr (WithTangent) {
    theta = detail::body_rotation_tangent(state.y.segment<4>(Slot::q), point.q_scale, state.Y);
    if (all_nodes) {
      store_node_tangent(state, N, out);
      out.dtheta_dw[N] = theta.transpose();
    }
    out.tip_dp_dw = state.Y.middleCols<3>(Slot::p).transpose();
    out.tip_dtheta_dw = theta.transpose();
    out.tip_dn_dw = state.Y.middleCols<3>(Slot::n).transpose();
    out.tip_dm_dw = state.Y.middleCols<3>(Slot::m).transpose();
    if constexpr (energy)
      out.denergy_dw = state.Y.col(Slot::e).transpose();
    else
      out.denergy_dw.setConstant(not_integrated);
  }
}

// Runtime dispatch (GCC's function multiversioning): every path (also the load tangent's) is
// compiled for the x86-64 baseline, x86-64-v3 (AVX2 with FMA) and x86-64-v4 (AVX-512), and the
// loader picks the clone for the CPU it runs on, so the portable build puts the tangent's
// directions in 256-bit registers and fuses a·b + c where the CPU can. The fused clones round once
// where the baseline rounds twice: their results are the baseline's within a bound derived from
// the number of operations (tests/core/test_integrator_dispatch.cpp; 5e-17 relative at the tip
// seen on the test rod); a CPU without FMA gets the baseline, bitwise. On Zen 4 the v4 clone made
// BM_Forward/100 11.2 -> 9.4 us and, for the tangent's paths, BM_ForwardWithDerivatives/100
// 31 -> 27-29 us. The tangent's paths form the state's stages entry by entry behind an empty asm
// (Pinned in rk4_step.hpp): without it GCC 12's SLP vectoriser grouped some of the shape's stage
// entries in one path and not in the other, and the shape must be bitwise the same with and
// without the tangent (the solvers reuse their last integration). The shape paths keep their code
// (the barrier made them slower). All paths share the clones, so Output::Tip stays bitwise
// Output::Full at the tip (BENCHMARKS.md, "The tangent's paths in the AVX-512 clone"). A build for
// one CPU (RODSHAPE_NATIVE) has no clones. Nor has a ThreadSanitizer build: with GCC 12 the clones'
// resolver runs before TSan's run time is set up and the program crashes at load (segfault, seen
// with a 5-line program).
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && !defined(__AVX2__) && \
    !defined(__SANITIZE_THREAD__)
#define RODSHAPE_DISPATCHED \
  __attribute__((target_clones("default", "arch=x86-64-v3", "arch=x86-64-v4")))
#else
#define RODSHAPE_DISPATCHED
#endif

RODSHAPE_DISPATCHED void integrate_with_tangent(const ClampedRod& rod,
                                                NodeState& state,
                                                RodConfiguration& out) {
  integrate_nodes<true>(rod, state, out);
}

RODSHAPE_DISPATCHED void integrate_without_tangent(const ClampedRod& rod,
                                                   NodeState& state,
                                                   RodConfiguration& out) {
  integrate_nodes<false>(rod, state, out);
}

RODSHAPE_DISPATCHED void integrate_tip_with_tangent(const ClampedRod& rod,
                                                    NodeState& state,
                                                    RodConfiguration& out) {
  integrate_nodes<true, false, true>(rod, state, out);
}

RODSHAPE_DISPATCHED void integrate_tip_without_tangent(const ClampedRod& rod,
                                                       NodeState& state,
                                                       RodConfiguration& out) {
  integrate_nodes<false, false, true>(rod, state, out);
}

RODSHAPE_DISPATCHED void integrate_with_load_tangent(const ClampedRod& rod,
                                                     NodeState& state,
                                                     RodConfiguration& out) {
  integrate_nodes<true, true>(rod, state, out);
}

}  // namespace

namespace detail {

void integrate_load_tangent(const ClampedRod& rod,
                            const BaseWrench& base_wrench,
                            RodConfiguration& out) {
  out.resize(rod.nodes(), Derivatives::AllNodes);
  NodeState state = initial_node_state(rod, base_wrench.force, base_wrench.moment);
  state.Y.setZero();  // the base wrench does not depend on the load
  integrate_with_load_tangent(rod, state, out);
}

}  // namespace detail

void integrate(const ClampedRod& rod,
               const BaseWrench& base_wrench,
               RodConfiguration& out,
               Derivatives derivatives,
               Output stored) {
  const bool tip_only = stored == Output::Tip && derivatives != Derivatives::AllNodes;
  out.resize(tip_only ? 2 : rod.nodes(), derivatives, tip_only ? Output::Tip : Output::Full);
  NodeState state = detail::initial_node_state(rod, base_wrench.force, base_wrench.moment);
  const bool tangent = derivatives != Derivatives::None;
  if (tip_only) {
    tangent ? integrate_tip_with_tangent(rod, state, out)
            : integrate_tip_without_tangent(rod, state, out);
  } else {
    tangent ? integrate_with_tangent(rod, state, out) : integrate_without_tangent(rod, state, out);
  }
}

RodConfiguration integrate(const ClampedRod& rod,
                           const BaseWrench& base_wrench,
                           Derivatives derivatives,
                           Output stored) {
  RodConfiguration out;
  integrate(rod, base_wrench, out, derivatives, stored);
  return out;
}

}  // namespace rodshape
