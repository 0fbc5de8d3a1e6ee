// test_validation_threads.cpp: a closed-loop validation's runs carried out by several threads
// (ValidationOptions::jobs) are bit for bit those of one thread, and the progress callback counts
// the work. Named "Threads" so that the ThreadSanitizer job of CI runs it (ctest -R Threads).
#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "rodshape/error.hpp"
#include "rodshape/sim/plan_validation.hpp"
#include "rodshape/trajectory/plan.hpp"
#include "support/band_problem.hpp"

namespace rodshape {
namespace test_validation_threads {
namespace {

using testing::band_problem;

const PlanResult& band_plan() {
  static const PlanResult plan = [] {
    PlanOptions options;
    options.steps = 2;
    return rodshape::plan(band_problem(), options);
  }();
  return plan;
}

/// The paper's mismatch, closed loop, noisy markers: each run re-plans from what it saw.
ValidationOptions closed_loop(int jobs) {
  ValidationOptions options;
  options.closed_loop = true;
  options.runs = 3;
  options.seed = 5;
  options.jobs = jobs;
  options.planning.steps = 2;
  options.loop.estimation.gravity = Eigen::Vector3d(0.0, 0.0, -9.81);
  return options;
}

PlantModel mismatch() {
  PlantModel plant;
  plant.stiffness_scale = 0.85;
  plant.gravity = Eigen::Vector3d(0.0, 0.0, -9.81);
  return plant;
}

TEST(ValidationThreads, ClosedLoopRunsOnThreeThreadsAreThoseOfOne) {
  const ValidationResult serial =
      validate_plan(band_problem(), band_plan(), mismatch(), {}, closed_loop(1));
  std::vector<std::pair<int, int>> calls;
  ValidationOptions options = closed_loop(3);
  options.progress = [&calls](int done, int total) { calls.emplace_back(done, total); };
  const ValidationResult parallel =
      validate_plan(band_problem(), band_plan(), mismatch(), {}, options);
  EXPECT_EQ(parallel.status, serial.status);
  ASSERT_EQ(parallel.runs.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    SCOPED_TRACE(k);
    const ValidationRun &a = parallel.runs[k], &b = serial.runs[k];
    EXPECT_EQ(a.seed, 5u + k);
    EXPECT_EQ(a.time, b.time);
    EXPECT_EQ(a.error_3d, b.error_3d);
    EXPECT_EQ(a.true_error, b.true_error);
    EXPECT_EQ(a.visible_markers, b.visible_markers);
    ASSERT_EQ(a.checkpoints.size(), b.checkpoints.size());
    for (std::size_t c = 0; c < a.checkpoints.size(); ++c)
      EXPECT_EQ(a.checkpoints[c].grasp_offset.position, b.checkpoints[c].grasp_offset.position);
  }
  // The runs differ (their noise does), so the comparison above is not of three copies of one.
  EXPECT_NE(serial.runs[0].error_3d, serial.runs[1].error_3d);
  EXPECT_EQ(parallel.plant.frames, serial.plant.frames);
  const std::vector<std::pair<int, int>> expected = {{1, 3}, {2, 3}, {3, 3}};
  EXPECT_EQ(calls, expected);
}

TEST(ValidationThreads, OpenLoopProgressCountsTheFramesAndEndsAtTheTotal) {
  std::vector<std::pair<int, int>> calls;
  ValidationOptions options;
  options.runs = 2;
  options.progress = [&calls](int done, int total) { calls.emplace_back(done, total); };
  const ValidationResult result = validate_plan(band_problem(), band_plan(), {}, {}, options);
  ASSERT_FALSE(calls.empty());
  const int total = calls.front().second;
  EXPECT_EQ(static_cast<std::size_t>(total), result.runs[0].time.size());
  EXPECT_EQ(calls.back(), std::make_pair(total, total));
  EXPECT_LE(calls.size(), 101u);
  for (std::size_t k = 1; k < calls.size(); ++k) EXPECT_GT(calls[k].first, calls[k - 1].first);
}

TEST(ValidationThreads, JobsOutsideTheirBoundIsBadInputNamingTheField) {
  for (int jobs : {0, ValidationOptions::kMaxJobs + 1}) {
    ValidationOptions options;
    options.jobs = jobs;
    try {
      options.validate();
      ADD_FAILURE() << "jobs = " << jobs << " was accepted";
    } catch (const InputError& error) {
      EXPECT_EQ(error.field(), "ValidationOptions.jobs") << error.what();
    }
  }
  ValidationOptions options;
  options.jobs = ValidationOptions::kMaxJobs;
  EXPECT_NO_THROW(options.validate());
}

}  // namespace
}  // namespace test_validation_threads
}  // namespace rodshape
