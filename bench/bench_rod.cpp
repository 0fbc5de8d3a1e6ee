// Benchmarks of the rod model and the equilibrium solvers on the paper's rubber band (L = 0.29 m,
// EIx = EIy = 0.04 N·m², GJ = 0.028 N·m², 0.02 × 0.02 m section, E = 3.2 MPa, ν = 0.5), at N = 50,
// 100 and 200 intervals. Names are stable so that figures compare from one change to the next.
#include <benchmark/benchmark.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/samples/rubber_band.hpp"
#include "rodshape/solvers/shooting_solver.hpp"

namespace {

using namespace rodshape;

ClampedRod rubber_band(int intervals) {
  return samples::rubber_band(ConstitutiveModel::Cosserat, intervals);
}

/// The bundled example's target: the tip 0.12 m aside, 0.22 m up, turned 90° about y.
Pose bent_tip() {
  Pose pose;
  pose.position = {0.12, 0.0, 0.22};
  pose.rotation =
      Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitY()).toRotationMatrix();
  return pose;
}

/// A generic 3D wrench: bending about both axes, torsion, shear and tension.
BaseWrench generic_wrench() { return {{0.3, -0.2, 0.5}, {0.02, -0.03, 0.01}}; }

void BM_Forward(benchmark::State& state) {
  const ClampedRod rod = rubber_band(static_cast<int>(state.range(0)));
  RodConfiguration out;
  const BaseWrench w = generic_wrench();
  integrate(rod, w, out);
  for (auto _ : state) {
    integrate(rod, w, out);
    benchmark::DoNotOptimize(out.p.back().data());
  }
  state.SetComplexityN(state.range(0));
}

void BM_ForwardWithDerivatives(benchmark::State& state) {
  const ClampedRod rod = rubber_band(static_cast<int>(state.range(0)));
  RodConfiguration out;
  const BaseWrench w = generic_wrench();
  integrate(rod, w, out, Derivatives::Tip);
  for (auto _ : state) {
    integrate(rod, w, out, Derivatives::Tip);
    benchmark::DoNotOptimize(out.tip_dp_dw.data());
  }
  state.SetComplexityN(state.range(0));
}

void BM_ForwardWithAllNodeDerivatives(benchmark::State& state) {
  const ClampedRod rod = rubber_band(static_cast<int>(state.range(0)));
  RodConfiguration out;
  const BaseWrench w = generic_wrench();
  integrate(rod, w, out, Derivatives::AllNodes);
  for (auto _ : state) {
    integrate(rod, w, out, Derivatives::AllNodes);
    benchmark::DoNotOptimize(out.dp_dw.back().data());
  }
}

ShootingOptions bench_options() {
  ShootingOptions options;
  options.residual_tolerance = 1e-10;
  options.output_derivatives = Derivatives::None;  // the solve, not the final report
  return options;
}

/// The solver's own counts, as benchmark counters.
void report(benchmark::State& state, const ShootingSummary& summary) {
  state.counters["lm_iterations"] = summary.iterations;
  state.counters["chord_steps"] = summary.chord_steps;
  state.counters["integrations"] = summary.integrations;
  state.counters["with_derivatives"] = summary.jacobian_evaluations;
}

void BM_SolveClampedClampedCold(benchmark::State& state) {
  const ClampedRod rod = rubber_band(static_cast<int>(state.range(0)));
  const TipCondition tip = ClampedTip{bent_tip()};
  const ShootingOptions options = bench_options();
  ShootingSummary summary;
  for (auto _ : state) {
    const ShootingResult solution = solve_equilibrium(rod, tip, BaseWrench{}, options);
    if (!solution.summary.converged()) state.SkipWithError("cold solve did not converge");
    summary = solution.summary;
  }
  report(state, summary);
}

void BM_SolveClampedClampedWarm(benchmark::State& state) {
  const ClampedRod rod = rubber_band(static_cast<int>(state.range(0)));
  const ShootingOptions options = bench_options();
  const ShootingResult solved = solve_equilibrium(rod, ClampedTip{bent_tip()}, {}, options);
  Pose moved = bent_tip();
  moved.position += Eigen::Vector3d(1e-3, 0.0, 0.0);  // the tip moved by 1 mm
  const TipCondition tip = ClampedTip{moved};
  ShootingSummary summary;
  for (auto _ : state) {
    const ShootingResult solution = solve_equilibrium(rod, tip, solved.base_wrench, options);
    if (!solution.summary.converged()) state.SkipWithError("warm solve did not converge");
    summary = solution.summary;
  }
  report(state, summary);
}

BENCHMARK(BM_Forward)->Arg(50)->Arg(100)->Arg(200)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ForwardWithDerivatives)->Arg(50)->Arg(100)->Arg(200)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ForwardWithAllNodeDerivatives)->Arg(100)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SolveClampedClampedCold)->Arg(50)->Arg(100)->Arg(200)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SolveClampedClampedWarm)->Arg(50)->Arg(100)->Arg(200)->Unit(benchmark::kMicrosecond);

}  // namespace
