// test_size_bounds.cpp: the solvers area's bounds on what a user sizes (docs/limits.md, "Sizes"):
// the shooting solver's iterations and continuation steps, the substeps of follow_equilibrium. Each
// bound is accepted and one past it is refused, naming the field.
#include <gtest/gtest.h>

#include <string>

#include "rodshape/solvers/follow_equilibrium.hpp"
#include "rodshape/solvers/shooting_solver.hpp"
#include "support/input_error.hpp"

namespace rodshape {
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

}  // namespace
}  // namespace rodshape
