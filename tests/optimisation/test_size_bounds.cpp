// test_size_bounds.cpp: the optimisation area's bounds on what a user sizes (docs/limits.md,
// "Sizes"): the optimiser's iterations and starts, the target's points, the workspace's sets. Each
// bound is accepted and one past it is refused, naming the field.
#include <gtest/gtest.h>

#include <string>

#include "rodshape/optimisation/shape_optimiser.hpp"
#include "rodshape/optimisation/shape_target.hpp"
#include "rodshape/optimisation/workspace.hpp"
#include "support/input_error.hpp"

namespace rodshape {
namespace test_size_bounds {
namespace {

using testing::input_error_message;

TEST(SizeBounds, OptimiserIterationsAndStartsAreBounded) {
  ShapeOptimiserOptions options;
  options.max_iterations = ShapeOptimiserOptions::kMaxIterations;
  options.multi_starts = ShapeOptimiserOptions::kMaxMultiStarts;
  EXPECT_NO_THROW(options.validate());
  ShapeOptimiserOptions iterations;
  iterations.max_iterations = 1'000'000'000;
  EXPECT_EQ(input_error_message([&] { iterations.validate(); }),
            "ShapeOptimiserOptions.max_iterations = 1000000000 must be <= 10000");
  ShapeOptimiserOptions starts;
  starts.multi_starts = 1'000'000;
  EXPECT_EQ(input_error_message([&] { starts.validate(); }),
            "ShapeOptimiserOptions.multi_starts = 1000000 must be <= 100");
}

TEST(SizeBounds, TargetPointsAreBounded) {
  ShapeTarget target;
  target.points.assign(ShapeTarget::kMaxPoints, Eigen::Vector3d(0.0, 0.0, 0.1));
  EXPECT_NO_THROW(target.validate());
  target.points.assign(10'000, Eigen::Vector3d(0.0, 0.0, 0.1));
  EXPECT_EQ(input_error_message([&] { target.validate(); }),
            "ShapeTarget.points has 10000 points; at most 1000");
}

TEST(SizeBounds, WorkspaceSetsAreBounded) {
  Workspace workspace;
  workspace.inside.assign(Workspace::kMaxSets, {Eigen::Vector3d::Zero(), 1.0});
  workspace.outside.assign(Workspace::kMaxSets, {Eigen::Vector3d::Zero(), 0.1});
  workspace.half_spaces.assign(Workspace::kMaxSets, {Eigen::Vector3d::UnitZ(), 1.0});
  EXPECT_NO_THROW(workspace.validate());
  Workspace balls;
  balls.outside.assign(Workspace::kMaxSets + 1, {Eigen::Vector3d::Zero(), 0.1});
  EXPECT_EQ(input_error_message([&] { balls.validate(); }),
            "Workspace.outside has 101 entries; at most 100");
  Workspace half_spaces;
  half_spaces.half_spaces.assign(Workspace::kMaxSets + 1, {Eigen::Vector3d::UnitZ(), 1.0});
  EXPECT_EQ(input_error_message([&] { half_spaces.validate(); }),
            "Workspace.half_spaces has 101 entries; at most 100");
}

}  // namespace
}  // namespace test_size_bounds
}  // namespace rodshape
