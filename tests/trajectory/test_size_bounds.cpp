// test_size_bounds.cpp: the trajectory area's bounds on what a user sizes (docs/limits.md,
// "Sizes"): PlanOptions' steps, tracking substeps, refinements and re-plans; the end-effector
// path's rate, the cost of its limits checked before planning, and its sample count checked before
// sampling; the intervals of a plan's rod. Each bound is accepted and one past it is refused,
// naming the field.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "rodshape/trajectory/end_effector_path.hpp"
#include "rodshape/trajectory/plan.hpp"
#include "support/input_error.hpp"
#include "support/solver_fixtures.hpp"

namespace rodshape {
namespace test_size_bounds {
namespace {

using testing::input_error_message;

TEST(SizeBounds, PlanOptionsCountsAreBounded) {
  PlanOptions options;
  options.steps = PlanOptions::kMaxSteps;
  options.tracking_substeps = PlanOptions::kMaxTrackingSubsteps;
  options.max_refinements = PlanOptions::kMaxRefinements;
  options.arm.max_replans = ArmPlanOptions::kMaxReplans;
  EXPECT_NO_THROW(options.validate());

  PlanOptions steps;
  steps.steps = 1'000'000'000;
  EXPECT_EQ(input_error_message([&] { steps.validate(); }),
            "PlanOptions.steps = 1000000000 must be <= 1000");
  PlanOptions substeps;
  substeps.tracking_substeps = PlanOptions::kMaxTrackingSubsteps + 1;
  EXPECT_EQ(input_error_message([&] { substeps.validate(); }),
            "PlanOptions.tracking_substeps = 1001 must be <= 1000");
  PlanOptions refinements;
  refinements.max_refinements = PlanOptions::kMaxRefinements + 1;
  EXPECT_EQ(input_error_message([&] { refinements.validate(); }),
            "PlanOptions.max_refinements = 101 must be <= 100");
  PlanOptions replans;
  replans.arm.max_replans = ArmPlanOptions::kMaxReplans + 1;
  EXPECT_EQ(input_error_message([&] { replans.validate(); }),
            "ArmPlanOptions.max_replans = 11 must be <= 10");
}

TEST(SizeBounds, SampleRateIsBounded) {
  EndEffectorLimits limits;
  limits.sample_rate = EndEffectorLimits::kMaxSampleRate;
  EXPECT_NO_THROW(limits.validate());
  limits.sample_rate = 1e9;
  EXPECT_EQ(input_error_message([&] { limits.validate(); }),
            "EndEffectorLimits.sample_rate = 1e+09 must be <= 10000");
}

TEST(SizeBounds, LimitsThatMakeAMetreCostTooManySamplesAreRefusedBeforePlanning) {
  EndEffectorLimits slow;
  slow.max_linear_speed = 1e-12;
  EXPECT_EQ(input_error_message([&] { slow.validate(); }),
            "EndEffectorLimits.max_linear_speed = 1e-12: a move of 1 m from rest to rest would "
            "take 1e+12 s, 1e+14 samples at EndEffectorLimits.sample_rate = 100 Hz; an "
            "end-effector path has at most 1e+06 samples");
  // A triangular profile: the acceleration is what makes it slow, and is named.
  EndEffectorLimits sluggish;
  sluggish.max_linear_acceleration = 1e-9;
  EXPECT_TRUE(input_error_message([&] {
                sluggish.validate();
              }).starts_with("EndEffectorLimits.max_linear_acceleration = 1e-09: a move of 1 m"));
  EndEffectorLimits turning;
  turning.max_angular_speed = 1e-9;
  EXPECT_TRUE(input_error_message([&] {
                turning.validate();
              }).starts_with("EndEffectorLimits.max_angular_speed = 1e-09: a move of 1 rad"));
  // Just inside: 1 m at 1e-4 m/s and 100 Hz is 1e4 s, 1e6 samples (plus the acceleration's 1e-3 s).
  EndEffectorLimits edge;
  edge.max_linear_speed = 1.0001e-4;
  EXPECT_NO_THROW(edge.validate());
}

TEST(SizeBounds, PathSizeIsCountedWithoutSampling) {
  EndEffectorLimits limits;  // 0.02 m/s, 0.1 m/s², 100 Hz
  const std::vector<Pose> waypoints = {Pose{}, Pose{{1.0, 0.0, 0.0}, Eigen::Matrix3d::Identity()}};
  const PathSize size = path_size(waypoints, limits);
  EXPECT_NEAR(size.duration, 1.0 / 0.02 + 0.02 / 0.1, 1e-9);  // trapezoid: d/v + v/a
  const std::vector<TimedPose> path = time_parameterize(waypoints, limits);
  EXPECT_NEAR(size.samples, static_cast<double>(path.size()), 1.0);
}

TEST(SizeBounds, APathWithTooManySamplesIsRefusedBeforeSampling) {
  // Each limit passes on its own (1 m takes 10 s, 1e5 samples at 10 kHz), but 20 m take 2e6.
  EndEffectorLimits limits;
  limits.max_linear_speed = 0.1;
  limits.max_linear_acceleration = 1e3;
  limits.sample_rate = 1e4;
  ASSERT_NO_THROW(limits.validate());
  const std::vector<Pose> waypoints = {Pose{}, Pose{{20.0, 0.0, 0.0}, Eigen::Matrix3d::Identity()}};
  EXPECT_EQ(input_error_message([&] { time_parameterize(waypoints, limits); }),
            "EndEffectorLimits: the end-effector path would have 2e+06 samples (duration 200 s at "
            "EndEffectorLimits.sample_rate = 10000 Hz); at most 1e+06: raise the speed or "
            "acceleration limits, or lower EndEffectorLimits.sample_rate");
}

TEST(SizeBounds, APlansRodHasAtMostFiveThousandIntervals) {
  PlanProblem problem;
  problem.rod = testing::rubber_band();
  problem.target.points = {{0.0, 0.0, 0.1}};
  problem.rod.intervals = PlanProblem::kMaxIntervals;
  EXPECT_NO_THROW(problem.validate());
  problem.rod.intervals = PlanProblem::kMaxIntervals + 1;
  EXPECT_EQ(input_error_message([&] { problem.validate(); }),
            "PlanProblem.rod.intervals = 5001 must be <= 5000");
}

TEST(SizeBounds, TheProductOfThePlansSizesIsBoundedByItsEstimatedTime) {
  PlanProblem problem;
  problem.rod = testing::rubber_band();  // 100 intervals
  problem.target.points.assign(10, Eigen::Vector3d(0.0, 0.0, 0.1));
  PlanOptions options;  // 7 steps, no extra start, 10 tracking substeps: the bundled plans
  // 100 × 7 × (1.5e-4 + 1.4e-5) s; the bundled plans take 0.08–0.27 s.
  EXPECT_NEAR(estimated_plan_seconds(problem, options), 0.1148, 1e-4);
  EXPECT_NO_THROW(check_plan_cost(problem, options));
  // Each size within its own bound, their product far beyond.
  problem.rod.intervals = PlanProblem::kMaxIntervals;
  options.steps = PlanOptions::kMaxSteps;
  options.optimiser.multi_starts = ShapeOptimiserOptions::kMaxMultiStarts;
  ASSERT_NO_THROW(options.validate());
  ASSERT_NO_THROW(problem.validate());
  const std::string message = input_error_message([&] { plan(problem, options); });
  EXPECT_TRUE(
      message.starts_with("the plan would take about 7.6e+04 s, estimated from "
                          "PlanOptions.steps = 1000, ShapeOptimiserOptions.multi_starts = "
                          "100, 5001 rod nodes, 10 ShapeTarget.points and "
                          "PlanOptions.tracking_substeps = 10; at most 300 s"))
      << message;
}

}  // namespace
}  // namespace test_size_bounds
}  // namespace rodshape
