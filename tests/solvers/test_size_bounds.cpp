// test_size_bounds.cpp: the solvers area's bounds on what a user sizes (docs/limits.md, "Sizes"):
// the shooting solver's iterations and continuation steps, the substeps of follow_equilibrium. Each
// bound is accepted and one past it is refused, naming the field.
#include <gtest/gtest.h>

#include <string>

#include "rodshape/solvers/follow_equilibrium.hpp"
#include "rodshape/solvers/shooting_solver.hpp"
#include "support/input_error.hpp"
#include "support/solver_fixtures.hpp"

namespace rodshape {
namespace test_size_bounds {
namespace {

using testing::input_error_message;

TEST(SizeBounds, ShootingIterationsAndContinuationStepsAreBounded) {
  ShootingOptions options;
  options.max_iterations = ShootingOptions::kMaxIterations;
  options.max_continuation_steps = ShootingOptions::kMaxContinuationSteps;
  EXPECT_NO_THROW(options.validate());
  ShootingOptions iterations;
  iterations.max_iterations = 1'000'000'000;
  EXPECT_EQ(input_error_message([&] { iterations.validate(); }),
            "ShootingOptions.max_iterations = 1000000000 must be <= 10000");
  ShootingOptions steps;
  steps.max_continuation_steps = ShootingOptions::kMaxContinuationSteps + 1;
  EXPECT_EQ(input_error_message([&] { steps.validate(); }),
            "ShootingOptions.max_continuation_steps = 4097 must be <= 4096");
}

TEST(SizeBounds, FollowSubstepsAreBounded) {
  FollowOptions options;
  options.substeps = FollowOptions::kMaxSubsteps;
  options.max_substeps = FollowOptions::kMaxSubsteps;
  EXPECT_NO_THROW(options.validate());
  FollowOptions substeps;
  substeps.substeps = FollowOptions::kMaxSubsteps + 1;
  EXPECT_EQ(input_error_message([&] { substeps.validate(); }),
            "FollowOptions.substeps = 4097 must be <= 4096");
  FollowOptions adaptive;
  adaptive.max_substeps = 1'000'000'000;
  EXPECT_EQ(input_error_message([&] { adaptive.validate(); }),
            "FollowOptions.max_substeps = 1000000000 must be <= 4096");
}

TEST(SizeBounds, NodesTimesIterationsOrSubstepsIsBoundedByTheTimeOfASolve) {
  ClampedRod rod = testing::rubber_band();
  rod.intervals = ClampedRod::kMaxIntervals;
  ShootingOptions options;  // 100 iterations, 64 sub-steps: 39.5 s and 102 s measured at worst
  EXPECT_NEAR(estimated_failing_solve_seconds(rod, options), 46.4 + 128.0, 1e-9);
  EXPECT_NO_THROW(check_solve_cost(rod, options));
  options.max_iterations = ShootingOptions::kMaxIterations;  // each within its bound
  ASSERT_NO_THROW(options.validate());
  EXPECT_EQ(testing::input_error_message(
                [&] { solve_equilibrium(rod, FreeTip{}, BaseWrench{}, options); }),
            "ShootingOptions.max_iterations = 10000 with 100001 rod nodes: a solve could take "
            "about 4768 s (4640 s to fail in ShootingOptions.max_iterations = 10000, 128 s for "
            "ShootingOptions.max_substeps = 64); at most 300 s (docs/limits.md): lower one of "
            "them");
  ShootingOptions substeps;
  substeps.max_substeps = ClampedRod::kMaxSubsteps;
  ASSERT_NO_THROW(substeps.validate());
  EXPECT_TRUE(testing::input_error_message([&] { check_solve_cost(rod, substeps); })
                  .starts_with("ShootingOptions.max_substeps = 4096 with 100001 rod nodes: a "
                               "solve could take about 8238 s"));
}

}  // namespace
}  // namespace test_size_bounds
}  // namespace rodshape
