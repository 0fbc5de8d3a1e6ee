// test_size_bounds.cpp: the robot area's bounds on what a user sizes (docs/limits.md, "Sizes"): the
// reach's samples and refinement steps, the IK's iterations and restarts. Each bound is accepted
// and one past it is refused, naming the field.
#include <gtest/gtest.h>

#include <string>

#include "rodshape/robot/arm_reach.hpp"
#include "rodshape/robot/inverse_kinematics.hpp"
#include "support/input_error.hpp"

namespace rodshape {
namespace test_size_bounds {
namespace {

using testing::input_error_message;

TEST(SizeBounds, ReachSamplesAndRefinementStepsAreBounded) {
  ArmReachOptions options;
  options.samples = ArmReachOptions::kMaxSamples;
  options.refinement_steps = ArmReachOptions::kMaxRefinementSteps;
  EXPECT_NO_THROW(options.validate());
  ArmReachOptions samples;
  samples.samples = 1'000'000'000;
  EXPECT_EQ(input_error_message([&] { samples.validate(); }),
            "ArmReachOptions.samples = 1000000000 must be <= 1000000");
  ArmReachOptions steps;
  steps.refinement_steps = ArmReachOptions::kMaxRefinementSteps + 1;
  EXPECT_EQ(input_error_message([&] { steps.validate(); }),
            "ArmReachOptions.refinement_steps = 100001 must be <= 100000");
}

TEST(SizeBounds, IkIterationsAndRestartsAreBounded) {
  IkOptions options;
  options.max_iterations = IkOptions::kMaxIterations;
  options.max_restarts = IkOptions::kMaxRestarts;
  EXPECT_NO_THROW(options.validate());
  IkOptions iterations;
  iterations.max_iterations = IkOptions::kMaxIterations + 1;
  EXPECT_EQ(input_error_message([&] { iterations.validate(); }),
            "IkOptions.max_iterations = 10001 must be <= 10000");
  IkOptions restarts;
  restarts.max_restarts = IkOptions::kMaxRestarts + 1;
  EXPECT_EQ(input_error_message([&] { restarts.validate(); }),
            "IkOptions.max_restarts = 1001 must be <= 1000");
}

}  // namespace
}  // namespace test_size_bounds
}  // namespace rodshape
