// test_sensor_section.cpp: the task file's `sensor` section with its two kinds: markers (the
// default, today's keys) and depth (the depth camera's keys under sensor.depth). Good keys read
// into the models; a bad one is named, on one line, with the file and line.
#include <gtest/gtest.h>

#include <string>

#include "rodshape/io/task_reader.hpp"
#include "support/input_error.hpp"

namespace rodshape {
namespace test_sensor_section {
namespace {

// Line numbers below refer to this text with the sensor section appended (line 15 on).
const std::string kPlan = R"(rod:
  length: 0.29
  nodes: 51
  section: {shape: rectangle, width: 0.02, height: 0.02}
  material: {young_modulus: 3.2e6, poisson_ratio: 0.5, density: 1392}
  stiffness: {EIx: 0.04, EIy: 0.04, GJ: 0.028}
target:
  points:
    - [0.003, 0.000, 0.028]
    - [0.047, 0.000, 0.101]
    - [0.126, 0.000, 0.133]
weights: {energy: 0.001, distance: 1}
workspace:
  box: {lower: [-1, -1, 0.05], upper: [1, 1, 1]}
)";

PlanTask read_with_sensor(const std::string& sensor) {
  return parse_plan_task(kPlan + sensor, "plan.yaml");
}

std::string error_with_sensor(const std::string& sensor) {
  const std::string message = testing::input_error_message([&] { read_with_sensor(sensor); });
  EXPECT_EQ(message.find('\n'), std::string::npos) << "not one line: " << message;
  return message;
}

TEST(SensorSection, MarkersAreTheDefaultKind) {
  const PlanTask task = read_with_sensor("sensor:\n  markers: 7\n  dropout: 0.1\n");
  EXPECT_FALSE(task.depth_sensor.has_value());
  EXPECT_EQ(task.sensor.markers, 7);
  EXPECT_DOUBLE_EQ(task.sensor.dropout, 0.1);
  EXPECT_EQ(kind_of(task.sensor_model()), SensorKind::Markers);
  const PlanTask explicit_kind = read_with_sensor("sensor:\n  kind: markers\n  markers: 5\n");
  EXPECT_EQ(explicit_kind.sensor.markers, 5);
  EXPECT_FALSE(explicit_kind.depth_sensor.has_value());
}

TEST(SensorSection, DepthKeysReadIntoTheDepthCamera) {
  const PlanTask task = read_with_sensor(R"(sensor:
  kind: depth
  frame_rate: 15
  camera: {position: [0, -0.8, 0.1], rotation: [[1, 0, 0], [0, 0, 1], [0, -1, 0]]}
  wrench_noise: {force: 0.01, moment: 0.001}
  depth:
    resolution: [640, 480]
    field_of_view: [60, 45]
    range: [0.3, 3]
    points: 800
    noise: {a0: 0.001, a1: 0, a2: 0.002, incidence: 0, lateral_pixels: 0.5}
    outliers: 0.05
)");
  ASSERT_TRUE(task.depth_sensor.has_value());
  EXPECT_EQ(kind_of(task.sensor_model()), SensorKind::Depth);
  const DepthSensorModel& depth = *task.depth_sensor;
  EXPECT_EQ(depth.width, 640);
  EXPECT_EQ(depth.height, 480);
  EXPECT_DOUBLE_EQ(depth.fov_x_deg, 60.0);
  EXPECT_DOUBLE_EQ(depth.fov_y_deg, 45.0);
  EXPECT_DOUBLE_EQ(depth.min_range, 0.3);
  EXPECT_DOUBLE_EQ(depth.max_range, 3.0);
  EXPECT_EQ(depth.points, 800);
  EXPECT_DOUBLE_EQ(depth.noise.a0, 0.001);
  EXPECT_DOUBLE_EQ(depth.noise.a1, 0.0);
  EXPECT_DOUBLE_EQ(depth.noise.a2, 0.002);
  EXPECT_DOUBLE_EQ(depth.noise.incidence, 0.0);
  EXPECT_DOUBLE_EQ(depth.noise.lateral_pixels, 0.5);
  EXPECT_DOUBLE_EQ(depth.outliers, 0.05);
  EXPECT_DOUBLE_EQ(depth.frame_rate, 15.0);
  EXPECT_DOUBLE_EQ(depth.camera.position.y(), -0.8);
  ASSERT_TRUE(depth.wrist.has_value());
  EXPECT_DOUBLE_EQ(depth.wrist->force, 0.01);
}

TEST(SensorSection, DepthDefaultsAreTheKinectV2) {
  const PlanTask task = read_with_sensor("sensor:\n  kind: depth\n");
  ASSERT_TRUE(task.depth_sensor.has_value());
  EXPECT_EQ(task.depth_sensor->width, 512);
  EXPECT_EQ(task.depth_sensor->height, 424);
  EXPECT_EQ(task.depth_sensor->points, 500);
  EXPECT_DOUBLE_EQ(task.depth_sensor->noise.axial_sigma(1.0), 1.3e-3);  // Fankhauser et al. 2015
  EXPECT_FALSE(task.depth_sensor->wrist.has_value());
}

TEST(SensorSection, MarkerKeysWithKindDepthAreNamed) {
  for (const char* key : {"markers: 10", "noise: {in_plane: 0.001, depth: 0.003}", "dropout: 0"}) {
    const std::string message = error_with_sensor("sensor:\n  kind: depth\n  " + std::string(key));
    EXPECT_NE(message.find("plan.yaml:17"), std::string::npos) << message;
    EXPECT_NE(message.find("sensor." + std::string(key).substr(0, std::string(key).find(':'))),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("sensor.depth"), std::string::npos) << message;
  }
}

TEST(SensorSection, DepthSectionWithoutKindDepthIsNamed) {
  const std::string message = error_with_sensor("sensor:\n  depth: {points: 100}\n");
  EXPECT_NE(message.find("plan.yaml:16"), std::string::npos) << message;
  EXPECT_NE(message.find("kind: depth"), std::string::npos) << message;
}

TEST(SensorSection, UnknownKindIsNamedWithTheChoices) {
  const std::string message = error_with_sensor("sensor:\n  kind: lidar\n");
  EXPECT_NE(message.find("sensor.kind"), std::string::npos) << message;
  EXPECT_NE(message.find("depth"), std::string::npos) << message;
}

TEST(SensorSection, BadDepthValuesAreNamedAsWritten) {
  const auto depth_error = [](const std::string& depth) {
    return error_with_sensor("sensor:\n  kind: depth\n  depth:\n    " + depth + "\n");
  };
  EXPECT_NE(depth_error("points: 0").find("sensor.depth.points = 0 must be in [1, 100000]"),
            std::string::npos)
      << depth_error("points: 0");
  EXPECT_NE(depth_error("resolution: [0, 424]").find("sensor.depth.resolution[0]"),
            std::string::npos)
      << depth_error("resolution: [0, 424]");
  EXPECT_NE(depth_error("resolution: [512]").find("sensor.depth.resolution"), std::string::npos);
  EXPECT_NE(depth_error("field_of_view: [70, 180]").find("sensor.depth.field_of_view[1]"),
            std::string::npos)
      << depth_error("field_of_view: [70, 180]");
  EXPECT_NE(depth_error("range: [2, 1]").find("sensor.depth.range[1]"), std::string::npos)
      << depth_error("range: [2, 1]");
  EXPECT_NE(depth_error("outliers: 1").find("sensor.depth.outliers"), std::string::npos);
  EXPECT_NE(depth_error("noise: {a0: -0.01}").find("sensor.depth.noise"), std::string::npos);
  EXPECT_NE(depth_error("noise: {incidence: -1}").find("sensor.depth.noise.incidence"),
            std::string::npos)
      << depth_error("noise: {incidence: -1}");
  EXPECT_NE(depth_error("nois: {a0: 0}").find("did you mean 'noise'"), std::string::npos)
      << depth_error("nois: {a0: 0}");
}

}  // namespace
}  // namespace test_sensor_section
}  // namespace rodshape
