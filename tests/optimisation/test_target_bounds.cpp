// test_target_bounds.cpp: an objective point far beyond any rod is refused naming it (issue 24,
// item 5; docs/limits.md, "Physical sizes"): [1e300, 0, 0] was "inf m from the clamp".
#include <gtest/gtest.h>

#include "rodshape/optimisation/shape_target.hpp"
#include "support/input_error.hpp"

namespace rodshape {
namespace test_target_bounds {
namespace {

TEST(TargetBounds, APointFartherThanThePositionRangeIsRefusedNamingIt) {
  ShapeTarget target;
  target.points = {{0.0, 0.0, 0.1}, {1e300, 0.0, 0.0}};
  const std::string message = testing::input_error_message([&] { target.validate(); });
  EXPECT_EQ(message.rfind("ShapeTarget.points[1] has magnitude 1e+300 m; at most 10000 m", 0), 0u)
      << message;
  target.points[1] = {1e4, 0.0, 0.0};
  EXPECT_NO_THROW(target.validate());
}

}  // namespace
}  // namespace test_target_bounds
}  // namespace rodshape
