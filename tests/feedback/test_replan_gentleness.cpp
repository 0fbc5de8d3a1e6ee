// The closed loop's gentleness test of a re-plan (src/feedback/replan_gentleness.hpp): a re-planned
// step is refused when its energy exceeds ratio × max(the replaced step's, the start's).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "feedback/replan_gentleness.hpp"

namespace rodshape::feedback_detail {
namespace test_replan_gentleness {
namespace {

std::vector<PlanStep> steps_of(const std::vector<double>& energies) {
  std::vector<PlanStep> steps(energies.size());
  for (std::size_t k = 0; k < energies.size(); ++k)
    steps[k].solution.configuration.energy = energies[k];
  return steps;
}

/// The waypoints ahead, planned with these energies.
std::vector<PlannedWaypoint> ahead(const std::vector<double>& energies) {
  std::vector<PlannedWaypoint> waypoints;
  for (const PlanStep& step : steps_of(energies)) waypoints.push_back(planned_waypoint(step));
  return waypoints;
}

TEST(ReplanGentleness, StepsWithinTheRatioOfTheStepsTheyReplacePass) {
  EXPECT_EQ(not_gentle(steps_of({0.06, 0.11}), 0.027, ahead({0.0615, 0.1094}), 1.5), "");
  // Exactly at the bound passes; the bound is ratio × the replaced step's energy.
  EXPECT_EQ(not_gentle(steps_of({0.15}), 0.0, ahead({0.1}), 1.5), "");
}

TEST(ReplanGentleness, ACoiledStepIsRefusedAndNamed) {
  // The case found in a closed loop on plan_c_arc: 3.68 J where the plan had 0.0615 J.
  const std::string why = not_gentle(steps_of({0.06, 3.68}), 0.027, ahead({0.0615, 0.1094}), 1.5);
  EXPECT_NE(why.find("step 2 is not gentle"), std::string::npos) << why;
  EXPECT_NE(why.find("3.68 J"), std::string::npos) << why;
  EXPECT_NE(why.find("1.5 x 0.109 J"), std::string::npos) << why;
}

TEST(ReplanGentleness, TheStartBoundsAStepThatUnbends) {
  // A step back towards the straight rod replaces a step of less energy than the start's.
  EXPECT_EQ(not_gentle(steps_of({0.2}), 0.3, ahead({0.01}), 1.1), "");
  EXPECT_NE(not_gentle(steps_of({0.34}), 0.3, ahead({0.01}), 1.1), "");
}

TEST(ReplanGentleness, StepsBeyondTheReplacedOnesAreNotJudged) {
  EXPECT_EQ(not_gentle(steps_of({0.1, 50.0}), 0.1, ahead({0.1}), 1.5), "");
}

}  // namespace
}  // namespace test_replan_gentleness
}  // namespace rodshape::feedback_detail
