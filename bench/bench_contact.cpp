// Benchmarks of the equilibrium resting on a table (issue 45): examples/cable_lifted_from_table's
// 1 m nylon cable (2 mm diameter, E = 2.5 GPa, ν = 0.4, 1150 kg/m³) clamped on a frictionless
// table and lifted 20 mm at its end by a gripper that lets it slide along its tangent, at N
// intervals. Counter x_cold: the case's CPU time over the free clamped–clamped cold solve of the
// rubber band at the same N (BM_SolveClampedClampedCold's case), measured right after the loop
// for as long, so that the ratio compares with this moment's machine.
#include <benchmark/benchmark.h>

#include <ctime>

#include <algorithm>
#include <numbers>

#include "rodshape/samples/rubber_band.hpp"
#include "rodshape/solvers/contact_equilibrium.hpp"
#include "support/contact_cases.hpp"

namespace {

using namespace rodshape;

constexpr double kRadius = 0.001, kYoung = 2.5e9, kPoisson = 0.4, kDensity = 1150.0;

double thread_seconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

using testing::along_x;

/// The example's cable: EI = E π r⁴/4, GJ = EI/(1 + ν), EA = E π r², GA = G A (Cosserat).
ClampedRod nylon_cable(int intervals) {
  const double A = std::numbers::pi * kRadius * kRadius, I = 0.25 * A * kRadius * kRadius;
  const double G = kYoung / (2.0 * (1.0 + kPoisson));
  ClampedRod rod;
  rod.properties.length = 1.0;
  rod.properties.model = ConstitutiveModel::Cosserat;
  rod.properties.K_rot = Eigen::Vector3d(kYoung * I, kYoung * I, 2.0 * G * I);
  rod.properties.K_tra = Eigen::Vector3d(G * A, G * A, kYoung * A);
  rod.properties.section = CrossSection::circle(kRadius);
  rod.load.force = Eigen::Vector3d(0.0, 0.0, -kDensity * A * 9.81);
  rod.clamp = {Eigen::Vector3d(0.0, 0.0, kRadius), along_x()};
  rod.intervals = intervals;
  return rod;
}

ShootingOptions bench_options() {
  ShootingOptions options;
  options.residual_tolerance = 1e-10;
  options.output_derivatives = Derivatives::None;
  return options;
}

/// The free cold clamped–clamped solve's CPU time per run at `intervals`, s, over at least
/// `seconds`.
double cold_solve_seconds(int intervals, double seconds) {
  const ClampedRod band = samples::rubber_band(ConstitutiveModel::Cosserat, intervals);
  const TipCondition tip = ClampedTip{samples::bent_tip()};
  const ShootingOptions options = bench_options();
  long runs = 0;
  const double start = thread_seconds();
  double elapsed = 0.0;
  do {
    benchmark::DoNotOptimize(solve_equilibrium(band, tip, BaseWrench{}, options).base_wrench);
    ++runs;
    elapsed = thread_seconds() - start;
  } while (elapsed < seconds);
  return elapsed / static_cast<double>(runs);
}

void BM_SolveLiftedCable(benchmark::State& state) {
  const int intervals = static_cast<int>(state.range(0));
  const ClampedRod rod = nylon_cable(intervals);
  GraspedTip tip;
  tip.pose = {Eigen::Vector3d(1.0, 0.0, kRadius + 0.02), along_x()};
  tip.released[2] = true;
  const Scene scene = testing::table_scene();
  const ShootingOptions options = bench_options();
  ContactEquilibriumResult result;
  const double start = thread_seconds();
  for (auto _ : state) {
    result = solve_contact_equilibrium(rod, tip, scene, BaseWrench{}, options);
    if (!result.shooting.summary.converged() || result.contacts.size() != 1)
      state.SkipWithError("the lifted cable was not solved with one lying segment");
  }
  const double elapsed = thread_seconds() - start;
  if (state.iterations() == 0) return;
  state.counters["x_cold"] = elapsed / static_cast<double>(state.iterations()) /
                             cold_solve_seconds(intervals, std::max(elapsed, 0.01));
  state.counters["newton_iterations"] = result.newton_iterations;
  state.counters["active_set_iterations"] = result.active_set_iterations;
  state.counters["integrations"] = result.shooting.summary.integrations;
}

BENCHMARK(BM_SolveLiftedCable)->Arg(100)->Unit(benchmark::kMillisecond);

}  // namespace
