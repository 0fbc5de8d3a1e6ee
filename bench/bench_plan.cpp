// Benchmark of the paper's experiment: the rubber band at rest (N = 100), ten objective points,
// n_inter = 7 optimal shapes warm-started one from the other, the timed end-effector path and the
// tracking of the equilibrium between waypoints.
#include <benchmark/benchmark.h>

#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/samples/rubber_band.hpp"
#include "rodshape/trajectory/plan.hpp"

namespace {

using namespace rodshape;

ClampedRod rubber_band(int intervals) {
  return samples::rubber_band(ConstitutiveModel::Cosserat, intervals);
}

/// Ten points at s = (i + ½) L / 10 on the rod bent by a tip load and moment in 3D (the target
/// shape of the benchmark: a C-like bend with some twist out of plane).
PointSet target_points() {
  const RodConfiguration fine = integrate(rubber_band(200), {{-0.6, 0.2, 0.0}, {0.02, 0.12, 0.01}});
  PointSet points;
  for (int i = 0; i < 10; ++i) points.push_back(fine.p[20 * i + 10]);
  return points;
}

void plan_experiment(benchmark::State& state, bool track) {
  PlanProblem request;
  request.rod = rubber_band(100);
  request.target.points = target_points();
  request.target.energy_weight = 1e-3;
  request.target.distance_weight = 1.0;
  PlanOptions options;
  options.steps = 7;
  options.track_between_waypoints = track;
  PlanResult plan;
  for (auto _ : state) {
    plan = rodshape::plan(request, options);
    if (plan.status != PlanStatus::Complete) state.SkipWithError(plan.message.c_str());
  }
  int iterations = 0;
  double max_distance = 0.0;
  for (const PlanStep& step : plan.steps) iterations += step.solution.ipopt.iterations;
  if (!plan.steps.empty()) max_distance = plan.steps.back().solution.cost.max_distance;
  state.counters["ipopt_iterations"] = iterations;
  state.counters["iterations_per_step"] = plan.steps.empty() ? 0.0 : iterations / 7.0;
  state.counters["final_max_distance_mm"] = 1e3 * max_distance;
}

void BM_PlanPaperExperiment(benchmark::State& state) { plan_experiment(state, true); }
void BM_PlanPaperExperimentWithoutTracking(benchmark::State& state) {
  plan_experiment(state, false);
}

BENCHMARK(BM_PlanPaperExperiment)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PlanPaperExperimentWithoutTracking)->Unit(benchmark::kMillisecond);

}  // namespace
