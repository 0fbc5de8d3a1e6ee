#include <gtest/gtest.h>

#include "rodshape/error.hpp"
#include "rodshape/trajectory/intermediate_targets.hpp"

namespace rodshape {
namespace {

TEST(IntermediateTargets, LastStepIsTheObjectiveAndStepsAreEvenlySpaced) {
  const PointSet initial = {{0, 0, 0.1}, {0, 0, 0.2}};
  const PointSet objective = {{0.07, 0, 0.1}, {0.1, 0.03, 0.15}};
  const auto steps = intermediate_targets(initial, objective, 7);
  ASSERT_EQ(steps.size(), 7u);
  for (std::size_t k = 0; k < objective.size(); ++k) {
    EXPECT_EQ(steps.back()[k], objective[k]);  // exactly, not one step short
    for (int i = 1; i <= 7; ++i)
      EXPECT_TRUE(
          steps[i - 1][k].isApprox(initial[k] + i / 7.0 * (objective[k] - initial[k]), 1e-15));
  }
}

TEST(IntermediateTargets, OneStepGoesStraightToTheObjective) {
  const PointSet initial = {{0, 0, 0.1}};
  const PointSet objective = {{0.05, 0, 0.1}};
  const auto steps = intermediate_targets(initial, objective, 1);
  ASSERT_EQ(steps.size(), 1u);
  EXPECT_EQ(steps[0][0], objective[0]);
}

TEST(IntermediateTargets, FewerThanOneStepNamesTheField) {
  try {
    intermediate_targets({}, {}, 0);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("n_inter"), std::string::npos);
  }
}

}  // namespace
}  // namespace rodshape
