// Benchmark of the state estimate from a depth camera's cloud (feedback/cloud_estimator.hpp): the
// paper's band (the sample's N) in a 3D bend, 500 points of its surface with Kinect v2 noise, 30 %
// of its length hidden and 10 % outliers (tests/support/surface_cloud.hpp, seeded), the held tip
// known to 5 mm and 0.05 rad (as the closed loop with a grasp offset), warm-started 0.02 bending
// units off (the previous estimate).
#include <benchmark/benchmark.h>

#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/feedback/cloud_estimator.hpp"
#include "rodshape/samples/rubber_band.hpp"
#include "support/surface_cloud.hpp"

namespace {

using namespace rodshape;

void BM_CloudEstimate(benchmark::State& state) {
  const ClampedRod rod = samples::rubber_band();
  const BaseWrench truth{{-0.3, 0.1, 0.0}, {0.0, 0.08, 0.01}};
  const RodConfiguration shape = integrate(rod, truth);
  const DepthSensorModel sensor;
  const CloudFrame cloud =
      testing::surface_cloud(shape, rod.properties.section->circumscribed_radius(), sensor,
                             testing::CloudRecipe{500, 0.35, 0.65, 0.10, true, 1});
  const StatePrior prior{
      BaseWrench::from_vector(truth.to_vector() + 0.02 * rod.properties.bending_wrench_units())};
  EstimationOptions options;
  options.tip_position_sigma = 5e-3;
  options.tip_rotation_sigma = 0.05;
  StateEstimate estimate;
  for (auto _ : state) {
    estimate =
        estimate_state_from_cloud(rod, shape.tip(), shape.tip(), cloud, sensor, prior, options);
    benchmark::DoNotOptimize(estimate);
  }
  state.counters["iterations"] = estimate.iterations;
  state.counters["outliers"] = estimate.outliers;
  state.counters["rms_mm"] = 1e3 * testing::centreline_rms(estimate.configuration, shape);
}

}  // namespace

BENCHMARK(BM_CloudEstimate)->Unit(benchmark::kMillisecond);
