// Benchmark of the paper's experiment: the rubber band at rest (N = 100), ten objective points,
// n_inter = 7 optimal shapes warm-started one from the other, the timed end-effector path and the
// tracking of the equilibrium between waypoints.
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>

#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/io/task_reader.hpp"
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

/// The paper's experiment: the band at N = 100 and the ten points, W1 = 1e-3, W2 = 1.
PlanProblem paper_request() {
  PlanProblem request;
  request.rod = rubber_band(100);
  request.target.points = target_points();
  request.target.energy_weight = 1e-3;
  request.target.distance_weight = 1.0;
  return request;
}

void plan_experiment(benchmark::State& state, bool track) {
  const PlanProblem request = paper_request();
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
/// BM_PlanPaperExperiment planned by 1 and by 2 threads at once, each its own plans. Google
/// Benchmark divides the threads' wall time by the plans of both: 2 × threads:2 / threads:1 is what
/// two plans at once cost against one (1 when they overlap perfectly, 2 one after the other).
void BM_PlanPaperExperimentInThreads(benchmark::State& state) { plan_experiment(state, true); }

/// The paper's experiment in a cell: a table 3 cm under the clamp and five obstacles (balls, a box,
/// a pole) near the way the rod goes without them, each placed 8 mm or more clear of every shape
/// of that plan beside a node of one of them; the obstacles the steps keep clear of are counted.
Scene scene_near(const PlanResult& free_plan) {
  Scene scene;
  scene.rod_radius = 0.5 * std::hypot(0.02, 0.02);  // the band's 2 cm square section
  scene.obstacles.push_back({"table", HalfSpaceObstacle{{0.0, 0.0, -1.0}, 0.03}});
  const auto clear_of_plan = [&](const Obstacle& obstacle) {
    Scene one = scene;
    one.obstacles = {obstacle};
    for (const PlanStep& step : free_plan.steps)
      if (one.least_gap(step.solution.configuration.p, {0.0}).gap < 0.008) return false;
    return one.least_gap(free_plan.initial_configuration.p, {0.0}).gap >= 0.008;
  };
  const struct {
    int step, node, axis;
  } near[5] = {{1, 60, 0}, {3, 90, 1}, {4, 40, 0}, {6, 70, 1}, {7, 100, 0}};
  for (int k = 0; k < 5; ++k) {
    const RodConfiguration& c = free_plan.steps[near[k].step - 1].solution.configuration;
    const Eigen::Vector3d side = c.R[near[k].node].col(near[k].axis);
    for (double away = 0.03;; away += 0.005) {  // outwards until clear of the whole plan
      const Eigen::Vector3d at = c.p[near[k].node] + away * side;
      Obstacle obstacle{"obstacle " + std::to_string(k), SphereObstacle{at, 0.01}};
      if (k == 2) obstacle.shape = BoxObstacle{at, {0.02, 0.02, 0.02}, c.R[near[k].node]};
      if (k == 4) obstacle.shape = CapsuleObstacle{at - 0.02 * side, at + 0.02 * side, 0.008};
      if (clear_of_plan(obstacle)) {
        scene.obstacles.push_back(obstacle);
        break;
      }
    }
  }
  return scene;
}

void BM_PlanWithScene(benchmark::State& state) {
  PlanProblem request = paper_request();
  PlanOptions options;
  options.steps = 7;
  request.scene = scene_near(rodshape::plan(request, options));
  PlanResult plan;
  for (auto _ : state) {
    plan = rodshape::plan(request, options);
    if (plan.status != PlanStatus::Complete) state.SkipWithError(plan.message.c_str());
  }
  if (!plan.scene) return;
  state.counters["min_gap_mm"] = 1e3 * plan.scene->min_gap;
  int rows = 0;
  for (int n : plan.scene->obstacles_per_step) rows += n;
  state.counters["obstacles_per_step"] = plan.scene->obstacles_per_step.empty()
                                             ? 0.0
                                             : double(rows) / plan.scene->obstacles_per_step.size();
}

/// examples/plan_around_post.yaml: the C of plan_c_arc past a post that needs a detour.
void BM_PlanAroundPost(benchmark::State& state) {
  const PlanTask task =
      read_plan_task(std::string(RODSHAPE_SOURCE_DIR) + "/examples/plan_around_post.yaml");
  const PlanProblem& request = task.problem;
  const PlanOptions& options = task.options;
  PlanResult plan;
  for (auto _ : state) {
    plan = rodshape::plan(request, options);
    if (plan.status != PlanStatus::Complete) state.SkipWithError(plan.message.c_str());
  }
  int detour = 0;
  for (const PlanStep& step : plan.steps) detour += step.detour ? 1 : 0;
  state.counters["detour_steps"] = detour;
  if (plan.scene) state.counters["min_gap_mm"] = 1e3 * plan.scene->min_gap;
}

/// examples/plan_two_pandas.yaml: the S made by two Pandas, one at each end (issue 21: both ends
/// optimised, tracked and timed together, both arms' IK and joint trajectories).
void BM_PlanTwoArms(benchmark::State& state) {
  const PlanTask task =
      read_plan_task(std::string(RODSHAPE_SOURCE_DIR) + "/examples/plan_two_pandas.yaml");
  PlanResult plan;
  for (auto _ : state) {
    plan = rodshape::plan(task.problem, task.options);
    if (plan.status != PlanStatus::Complete) state.SkipWithError(plan.message.c_str());
  }
  state.counters["steps"] = static_cast<double>(plan.steps.size());
  state.counters["both_arms_reachable"] =
      plan.arm && plan.base_arm && plan.arm->reachable() && plan.base_arm->reachable();
}

BENCHMARK(BM_PlanPaperExperiment)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PlanTwoArms)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PlanWithScene)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PlanAroundPost)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_PlanPaperExperimentWithoutTracking)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PlanPaperExperimentInThreads)
    ->Threads(1)
    ->Threads(2)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace
