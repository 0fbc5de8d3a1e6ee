// Benchmarks of the closed loop's checkpoint on the paper's experiment (the band at N = 100, ten
// objective points, seven steps): the state estimate from ten markers, and the re-plan of the
// remaining steps from it (all of them, or the next only: the closed loop's default horizon). One
// checkpoint is one estimate plus one re-plan. And one frame of the simulated depth camera.
#include <benchmark/benchmark.h>

#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/feedback/shape_controller.hpp"
#include "rodshape/feedback/state_estimator.hpp"
#include "rodshape/samples/rubber_band.hpp"
#include "rodshape/sim/depth_camera.hpp"
#include "rodshape/sim/marker_sensor.hpp"
#include "rodshape/trajectory/plan.hpp"

namespace {

using namespace rodshape;

/// The plant's frame of a planned step at t = 0 (no velocities: a sensor reads the shape).
PlantFrame frame_of(const PlanStep& step) {
  PlantFrame frame;
  frame.end_effector = step.end_effector;
  frame.configuration = step.solution.configuration;
  return frame;
}

struct Scene {
  PlanProblem problem;
  PlanResult plan;
  Scene() {
    problem.rod = samples::rubber_band();
    const RodConfiguration fine = integrate(samples::rubber_band(ConstitutiveModel::Cosserat, 200),
                                            {{-0.6, 0.2, 0.0}, {0.02, 0.12, 0.01}});
    for (int i = 0; i < 10; ++i) problem.target.points.push_back(fine.p[20 * i + 10]);
    problem.target.energy_weight = 1e-3;
    problem.target.distance_weight = 1.0;
    PlanOptions options;
    options.steps = 7;
    plan = rodshape::plan(problem, options);
  }
};

const Scene& scene() {
  static const Scene s;
  return s;
}

/// The state at waypoint 1 as the camera sees it (Kinect-like noise, seeded), the weight and the
/// grasp offset estimated too, as the closed loop does.
void BM_CheckpointEstimate(benchmark::State& state) {
  const Scene& s = scene();
  const PlanStep& step = s.plan.steps.front();
  MarkerSensor sensor(MarkerSensorModel{}, 1);
  const RodConfiguration& c = step.solution.configuration;
  const SensorFrame seen = sensor.observe(frame_of(step), 0.29);
  EstimationOptions options;
  options.gravity = Eigen::Vector3d(0.0, 0.0, -9.81);
  options.tip_position_sigma = 5e-3;
  options.tip_rotation_sigma = 0.05;
  StateEstimate estimate;
  for (auto _ : state) {
    estimate = estimate_state(s.problem.rod, c.tip(), step.end_effector, seen, MarkerSensorModel{},
                              {step.solution.base_wrench}, options);
    benchmark::DoNotOptimize(estimate);
  }
  state.counters["iterations"] = estimate.iterations;
}

/// The re-plan of the last `range(0)` steps from the equilibrium before them (no tracking, as the
/// closed loop re-plans), all of them (`range(1)` = 0) or the next only (a horizon of 1).
void BM_CheckpointReplan(benchmark::State& state) {
  const Scene& s = scene();
  const int remaining = static_cast<int>(state.range(0));
  const int horizon = static_cast<int>(state.range(1));
  const PlanStep& here = s.plan.steps[s.plan.steps.size() - remaining - 1];
  PlanProblem rest = s.problem;
  rest.initial = InitialState::equilibrium(here.solution.base_wrench);
  PlanOptions options;
  options.steps = remaining;
  options.horizon = horizon;
  options.track_between_waypoints = false;
  for (auto _ : state) {
    const PlanResult again = rodshape::plan(rest, options);
    if (again.status != PlanStatus::Complete) state.SkipWithError(again.message.c_str());
    benchmark::DoNotOptimize(again);
  }
}

/// One whole checkpoint of the controller (ShapeController::update at waypoint 1): the estimate as
/// above and, acting on every estimate (significance < 0), the re-plan of the next step (a horizon
/// of 1). The controller is copied, untimed, before each update (an update moves it on).
void BM_ShapeControllerUpdate(benchmark::State& state) {
  const Scene& s = scene();
  const PlanStep& step = s.plan.steps.front();
  MarkerSensor sensor(MarkerSensorModel{}, 1);
  MarkerMeasurement measurement{sensor.observe(frame_of(step), 0.29), MarkerSensorModel{}};
  ClosedLoopOptions options;
  options.estimation.gravity = Eigen::Vector3d(0.0, 0.0, -9.81);
  options.significance = -1.0;
  PlanOptions planning;
  planning.steps = static_cast<int>(s.plan.steps.size());
  const ShapeController fresh(s.problem, s.plan, planning, options);
  bool replanned = true;
  for (auto _ : state) {
    state.PauseTiming();
    ShapeController controller = fresh;
    state.ResumeTiming();
    const ControllerOutput output = controller.update(measurement, {step.end_effector});
    replanned = replanned && output.recalculated();
    benchmark::DoNotOptimize(output);
  }
  if (!replanned) state.SkipWithError("an update did not re-plan");
}

/// One frame of the simulated Kinect v2 (512 × 424, 500 points) of the band at waypoint 1, 1 m
/// away, its section's circumscribed radius (14.1 mm), a board hiding part of it: the capsules
/// splatted and cast against, the occlusion test, the noise. The validation draws one per frame.
void BM_DepthCameraFrame(benchmark::State& state) {
  const Scene& s = scene();
  const PlanStep& step = s.plan.steps.front();
  const PlantFrame frame = frame_of(step);
  DepthSensorModel model;
  model.outliers = 0.02;
  DepthCamera camera(model, 1);
  DepthOccluders occluders;
  occluders.obstacles = {{"board", BoxObstacle{{0.1, -0.5, 0.09}, {0.6, 0.02, 0.05}}}};
  std::size_t points = 0;
  for (auto _ : state) {
    const CloudFrame cloud = camera.observe(frame, 0.0141, occluders);
    points = cloud.points.size();
    benchmark::DoNotOptimize(cloud);
  }
  state.counters["points"] = static_cast<double>(points);
  const int visible = camera.visible_pixels();
  camera.observe(frame, 0.0141);
  state.counters["visible_pixels"] = visible;
  state.counters["hidden_fraction"] = 1.0 - visible / static_cast<double>(camera.visible_pixels());
}

BENCHMARK(BM_CheckpointEstimate)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DepthCameraFrame)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ShapeControllerUpdate)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CheckpointReplan)
    ->ArgNames({"remaining", "horizon"})
    ->Args({1, 0})
    ->Args({3, 0})
    ->Args({6, 0})
    ->Args({3, 1})
    ->Args({6, 1})
    ->Unit(benchmark::kMillisecond);

}  // namespace
