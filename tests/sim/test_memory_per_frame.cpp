// test_memory_per_frame.cpp: issue 24, item 3. A validation kept every frame's rod and markers
// (about 78 kB a frame: 160,000 frames peaked at 12.3 GB, 939,000 ended in std::bad_alloc). Now a
// frame leaves only the series the outputs need (four errors and the markers seen: 36 bytes a
// run): the heap's peak, measured through operator new, grows by at most a few hundred bytes per
// frame. Measured as the difference between two frame rates on the same plan (the plan, the path
// and the solvers' work are the same), so no test allocates more than a few megabytes.
#include <gtest/gtest.h>

#include <cstddef>
#include <functional>

#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/error.hpp"
#include "rodshape/samples/rubber_band.hpp"
#include "rodshape/sim/plan_validation.hpp"
#include "rodshape/trajectory/plan.hpp"
#include "support/band_problem.hpp"
#include "support/heap_peak.hpp"

namespace rodshape {
namespace test_memory_per_frame {
namespace {

using testing::band_problem;

struct Measured {
  long long peak_bytes = 0;  // above what was live before
  std::size_t frames = 0;    // of all runs
};

/// The heap's peak while `problem`'s plan is validated at `frame_rate`.
Measured validate_at(const PlanProblem& problem,
                     const PlanResult& plan,
                     double frame_rate,
                     const ValidationOptions& options) {
  MarkerSensorModel sensor;
  sensor.frame_rate = frame_rate;
  const long long before = testing::reset_heap_peak();
  Measured measured;
  {
    const ValidationResult result = validate_plan(problem, plan, {}, sensor, options);
    EXPECT_EQ(result.status, ValidationStatus::Complete) << result.brief();
    for (const ValidationRun& run : result.runs) measured.frames += run.time.size();
  }
  measured.peak_bytes = testing::g_heap_peak.load() - before;
  return measured;
}

/// The heap's growth per frame between 30 and 300 frames a second.
double bytes_per_frame(const ValidationOptions& options) {
  const PlanProblem problem = band_problem();
  PlanOptions planning;
  planning.steps = 3;
  const PlanResult plan = rodshape::plan(problem, planning);
  EXPECT_EQ(plan.status, PlanStatus::Complete) << plan.message;
  ValidationOptions with_planning = options;
  with_planning.planning = planning;
  const Measured slow = validate_at(problem, plan, 30.0, with_planning);
  const Measured fast = validate_at(problem, plan, 300.0, with_planning);
  EXPECT_GT(fast.frames, slow.frames + 500) << "too few frames to measure";
  return static_cast<double>(fast.peak_bytes - slow.peak_bytes) /
         static_cast<double>(fast.frames - slow.frames);
}

// The series kept: 4 doubles and an int a frame and run (36 bytes), and the frame times while the
// plant is driven (8 bytes); closed loop, each frame's errors wait in the loop's own series
// (48 bytes) until the run takes them. A few hundred bytes is the bound.
constexpr double kMaxBytesPerFrame = 300.0;

TEST(MemoryPerFrame, OpenLoopKeepsOnlyTheSeries) {
  ValidationOptions options;
  options.runs = 2;
  const double bytes = bytes_per_frame(options);
  EXPECT_LE(bytes, kMaxBytesPerFrame);
  RecordProperty("bytes_per_frame", std::to_string(bytes));
}

TEST(MemoryPerFrame, ClosedLoopKeepsOnlyTheSeries) {
  ValidationOptions options;
  options.closed_loop = true;
  const double bytes = bytes_per_frame(options);
  EXPECT_LE(bytes, kMaxBytesPerFrame);
  RecordProperty("bytes_per_frame", std::to_string(bytes));
}

TEST(MemoryPerFrame, TheFramesOfAllRunsAreBoundedBeforeAnyIsDriven) {
  // 1e6 frames a run were allowed and 1000 runs: 1e9 frames' series (36 GB) and lines. The bound
  // is on all runs together, checked before the plant moves (the path here is never driven).
  const PlanProblem problem = band_problem();
  Pose tip;
  tip.position = Eigen::Vector3d(0.0, 0.0, 0.29);
  PlanResult plan;
  plan.end_effector_path = {{0.0, tip}, {600.0, tip}};
  MarkerSensorModel sensor;
  sensor.frame_rate = 1000.0;  // 600,002 frames a run: within the old per-run bound
  ValidationOptions options;
  options.runs = 2;
  options.plant.shooting.max_iterations = 1;  // were it driven, it would be lost at once
  options.plant.shooting.max_continuation_steps = 1;
  try {
    (void)validate_plan(problem, plan, {}, sensor, options);
    FAIL() << "1.2e6 frames in all were accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.field(), "MarkerSensorModel.frame_rate") << error.what();
    EXPECT_NE(std::string(error.what()).find("ValidationOptions.runs = 2, would have"),
              std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace test_memory_per_frame
}  // namespace rodshape
