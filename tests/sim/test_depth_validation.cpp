// test_depth_validation.cpp: the paper's experiment watched by the depth camera
// (examples/validate_depth_camera.yaml). Its board hides about a third of the band; open loop,
// each frame's cloud is the model's points and the true errors are the marker camera's (the plant
// does not depend on what sees it); a depth camera without the rod's radius, and a rest's pooled
// cloud beyond its bound, are bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "rodshape/io/task_reader.hpp"
#include "rodshape/sim/depth_camera.hpp"
#include "rodshape/sim/plan_validation.hpp"
#include "rodshape/trajectory/plan.hpp"
#include "support/input_error.hpp"

namespace rodshape {
namespace test_depth_validation {
namespace {

struct Example {
  PlanTask task;
  PlanResult plan;
  Example()
      : task(read_plan_task(std::string(RODSHAPE_SOURCE_DIR) +
                            "/examples/validate_depth_camera.yaml")),
        plan(rodshape::plan(task.problem, task.options)) {}
};

const Example& example() {
  static const Example e;
  return e;
}

TEST(DepthValidation, TheExamplesBoardHidesAboutAThirdOfTheBand) {
  const Example& e = example();
  ASSERT_TRUE(e.plan.complete()) << e.plan.message;
  ASSERT_TRUE(e.task.depth_sensor.has_value());
  const PlanStep& last = e.plan.steps.back();
  PlantFrame frame;
  frame.end_effector = last.end_effector;
  frame.base_wrench = last.solution.base_wrench;
  frame.configuration = last.solution.configuration;
  const double radius = e.task.problem.scene.rod_radius;
  EXPECT_NEAR(radius, 0.01 * std::sqrt(2.0), 1e-12);  // the 2 × 2 cm section's half diagonal
  DepthCamera camera(*e.task.depth_sensor, 1);
  camera.observe(frame, radius);
  const double all = camera.visible_pixels();
  DepthOccluders occluders;
  occluders.obstacles = e.task.problem.scene.obstacles;
  camera.observe(frame, radius, occluders);
  const double hidden = 1.0 - camera.visible_pixels() / all;
  EXPECT_GT(all, 1000.0);
  EXPECT_GT(hidden, 0.2);
  EXPECT_LT(hidden, 0.45);
  RecordProperty("hidden_fraction", std::to_string(hidden));
}

TEST(DepthValidation, OpenLoopSeesCloudsAndTheMarkersTrueErrors) {
  const Example& e = example();
  ValidationOptions options;
  const ValidationResult depth =
      validate_plan(e.task.problem, e.plan, e.task.plant, *e.task.depth_sensor, options);
  MarkerSensorModel markers;
  markers.camera = e.task.depth_sensor->camera;
  const ValidationResult seen_by_markers =
      validate_plan(e.task.problem, e.plan, e.task.plant, markers, options);
  ASSERT_EQ(depth.status, ValidationStatus::Complete) << depth.message;
  ASSERT_EQ(depth.runs.size(), 1u);
  const ValidationRun& run = depth.runs.front();
  EXPECT_EQ(run.last_cloud.points.size(), static_cast<std::size_t>(e.task.depth_sensor->points));
  EXPECT_TRUE(run.last_seen.markers.empty());
  EXPECT_EQ(run.true_error, seen_by_markers.runs.front().true_error);  // bit for bit
  // The measured error: to the cloud, less the radius; the hidden third of the band is far from
  // its points, so above the true error, but finite and within a few mm at the end.
  EXPECT_TRUE(std::isfinite(run.final.error_3d));
  EXPECT_GT(run.final.error_3d, run.final.true_error);
  EXPECT_LT(run.final.error_3d, 0.01);
}

TEST(DepthValidation, ADepthCameraNeedsTheRodsRadius) {
  const Example& e = example();
  PlanProblem problem = e.task.problem;
  problem.scene.rod_radius = 0.0;
  const std::string message = testing::input_error_message(
      [&] { validate_plan(problem, e.plan, e.task.plant, *e.task.depth_sensor); });
  EXPECT_EQ(message.rfind("Scene.rod_radius", 0), 0u) << message;
}

TEST(DepthValidation, ARestsPooledCloudIsBounded) {
  const Example& e = example();
  DepthSensorModel sensor = *e.task.depth_sensor;
  sensor.points = DepthSensorModel::kMaxPoints;  // 100,000 × 15 frames: 1.5e6 > 1e6
  ValidationOptions options;
  options.closed_loop = true;
  const std::string message = testing::input_error_message(
      [&] { validate_plan(e.task.problem, e.plan, e.task.plant, sensor, options); });
  EXPECT_EQ(message.rfind("DepthSensorModel.points = 100000 with ClosedLoopOptions."
                          "checkpoint_frames = 15 would pool 1.5e+06 points",
                          0),
            0u)
      << message;
}

}  // namespace
}  // namespace test_depth_validation
}  // namespace rodshape
