// The shape controller's online update (shape_controller.hpp): handed the markers of the planned
// state, it keeps the plan; at the plan's last waypoint nothing is left to control.
#include <gtest/gtest.h>

#include <string>

#include "rodshape/error.hpp"
#include "rodshape/feedback/shape_controller.hpp"
#include "rodshape/optimisation/curve_distance.hpp"
#include "rodshape/trajectory/plan.hpp"
#include "support/band_problem.hpp"

namespace rodshape {
namespace test_shape_controller {
namespace {

using testing::band_problem;

const PlanResult& band_plan() {
  static const PlanResult plan = [] {
    PlanOptions options;
    options.steps = 3;
    return rodshape::plan(band_problem(), options);
  }();
  return plan;
}

/// The markers of `shape`, exactly where the sensor's arc lengths put them, seen at `t`.
MarkerMeasurement exact_markers(const RodConfiguration& shape,
                                const MarkerSensorModel& sensor,
                                double length,
                                double t) {
  MarkerMeasurement measurement{{}, sensor};
  measurement.frame.t = t;
  for (const double s : sensor.arc_lengths(length))
    measurement.frame.markers.emplace_back(curve_point(shape, s));
  return measurement;
}

TEST(ShapeController, KeepsThePlanWhenTheRodIsWhereThePlanSaysAndStopsAtTheLastWaypoint) {
  const PlanProblem problem = band_problem();
  const PlanResult& plan = band_plan();
  ASSERT_EQ(plan.status, PlanStatus::Complete) << plan.brief();
  ASSERT_EQ(plan.steps.size(), 3u);
  PlanOptions planning;
  planning.steps = 3;
  ShapeController controller(problem, plan, planning);
  ASSERT_EQ(controller.remaining().size(), 3u);
  // The Kinect-like noise (σ 1 mm in the plane, 3 mm in depth), averaged over 15 frames.
  MarkerSensorModel sensor;
  sensor.in_plane_noise /= std::sqrt(15.0);
  sensor.depth_noise /= std::sqrt(15.0);
  for (std::size_t k = 0; k + 1 < plan.steps.size(); ++k) {
    const PlanStep& step = plan.steps[k];
    const ControllerOutput out = controller.update(
        exact_markers(step.solution.configuration, sensor, problem.rod.properties.length, 1.0 + k),
        {step.end_effector});
    const Checkpoint& c = out.checkpoint;
    EXPECT_EQ(c.waypoint, static_cast<int>(k) + 1);
    EXPECT_DOUBLE_EQ(c.t, 1.0 + k);
    EXPECT_EQ(c.estimate.status, SolveStatus::Converged) << c.estimate.message;
    EXPECT_TRUE(c.consistent) << c.estimate.residual;
    // Exact markers: the fit moves from the plan's state by a fraction of the noise, not beyond.
    EXPECT_FALSE(c.significant) << c.estimate.prior_chi2 - c.estimate.chi2;
    EXPECT_FALSE(out.recalculated()) << out.reason();
    EXPECT_NE(out.reason().find("within the noise"), std::string::npos) << out.reason();
    ASSERT_EQ(out.remaining.size(), plan.steps.size() - k - 1);
    ASSERT_EQ(controller.remaining().size(), out.remaining.size());
    for (std::size_t j = 0; j < out.remaining.size(); ++j)
      EXPECT_EQ(out.remaining[j].end_effector.position,
                plan.steps[k + 1 + j].end_effector.position);
  }
  // Only the last waypoint is ahead: nothing is left to control.
  try {
    controller.update(exact_markers(plan.steps.back().solution.configuration, sensor,
                                    problem.rod.properties.length, 3.0),
                      {plan.steps.back().end_effector});
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("ShapeController.update"), std::string::npos) << e.what();
  }
}

TEST(ShapeController, APlanWithoutStepsOrBadOptionsIsBadInput) {
  const PlanProblem problem = band_problem();
  EXPECT_THROW(ShapeController(problem, PlanResult{}, PlanOptions{}), InputError);
  ClosedLoopOptions options;
  options.max_energy_ratio = 0.5;
  try {
    ShapeController(problem, band_plan(), PlanOptions{}, options);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("ClosedLoopOptions.max_energy_ratio"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace test_shape_controller
}  // namespace rodshape
