// test_target_behind_clamp.cpp: a target straight below a clamp that points up (issue 24, item
// 5) ended as "IPOPT Maximum_Iterations_Exceeded" without a word on why; the plan's message now
// says the target lies behind the clamp and why it is not planned. A target in front of the clamp
// gets no such note.
#include <gtest/gtest.h>

#include <numbers>
#include <string>

#include "rodshape/samples/rubber_band.hpp"
#include "rodshape/trajectory/plan.hpp"
#include "trajectory/target_behind_clamp.hpp"

namespace rodshape {
namespace test_target_behind_clamp {
namespace {

PlanProblem band_towards(const PointSet& points) {
  PlanProblem problem;
  problem.rod = samples::rubber_band();
  problem.target.points = points;
  problem.target.energy_weight = 1e-3;
  return problem;
}

TEST(TargetBehindClamp, AnglesFromTheClampsTangent) {
  EXPECT_NEAR(plan_stages::first_point_angle(band_towards({{0.0, 0.0, -0.05}})), std::numbers::pi,
              1e-15);
  EXPECT_NEAR(plan_stages::first_point_angle(band_towards({{0.1, 0.0, 0.0}})), std::numbers::pi / 2,
              1e-15);
  EXPECT_EQ(plan_stages::behind_clamp_note(band_towards({{0.1, 0.0, 0.1}})), "");
}

TEST(TargetBehindClamp, APlanStraightBelowTheClampSaysWhyItStops) {
  // The band, clamped at the origin pointing up (+z), towards two points 5 and 10 cm below the
  // clamp: a U-turn of 0.29 m could pass there, the plan stops or would jump.
  const PlanProblem problem = band_towards({{0.0, 0.0, -0.05}, {0.0, 0.0, -0.1}});
  PlanOptions options;
  options.steps = 7;
  // auto tries pose, projection and search too; projection's steps all succeed with the rod left
  // straight, 10 cm off the points: partial, beyond the reach tolerance; search has no optimum to
  // go to.
  const PlanResult result = plan(problem, options);
  EXPECT_NE(result.status, PlanStatus::Complete);
  ASSERT_EQ(result.interpolation.tried.size(), 4u);
  EXPECT_EQ(result.interpolation.tried[2].status, PlanStatus::Partial);
  EXPECT_NE(result.interpolation.tried[2].note.find("beyond the reach tolerance"),
            std::string::npos)
      << result.interpolation.tried[2].note;
  EXPECT_EQ(result.interpolation.tried[3].scheme, ObjectiveInterpolation::Search);
  EXPECT_NE(result.interpolation.tried[3].status, PlanStatus::Complete);
  EXPECT_NE(result.message.find("ShapeTarget.points[0] lies 180 degrees from the rod's direction "
                                "at the clamp (behind the clamp)"),
            std::string::npos)
      << result.message;
}

}  // namespace
}  // namespace test_target_behind_clamp
}  // namespace rodshape
