// test_size_bounds.cpp: the core area's bound on the rod's discretisation (docs/limits.md,
// "Sizes"): ClampedRod::kMaxIntervals is accepted, one more is refused, naming the field.
#include <gtest/gtest.h>

#include <string>

#include "rodshape/core/clamped_rod.hpp"
#include "support/input_error.hpp"
#include "support/solver_fixtures.hpp"

namespace rodshape {
namespace test_size_bounds {
namespace {

TEST(SizeBounds, IntervalsAreBounded) {
  ClampedRod rod = testing::rubber_band();
  rod.intervals = ClampedRod::kMaxIntervals;
  EXPECT_NO_THROW(rod.validate());
  rod.intervals = 999'999;
  EXPECT_EQ(testing::input_error_message([&] { rod.validate(); }),
            "ClampedRod.intervals = 999999 must be <= 100000");
}

}  // namespace
}  // namespace test_size_bounds
}  // namespace rodshape
