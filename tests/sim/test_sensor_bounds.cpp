// test_sensor_bounds.cpp: the simulated sensor's sizes have ranges (issue 24, item 5;
// docs/limits.md, "Physical sizes"): marker noise of 1e300 m was run and reported "complete".
#include <gtest/gtest.h>

#include <string>

#include "rodshape/sim/marker_sensor.hpp"
#include "support/input_error.hpp"

namespace rodshape {
namespace test_sensor_bounds {
namespace {

TEST(SensorBounds, NoiseAndCameraBeyondTheirRangesAreRefusedNamingThem) {
  MarkerSensorModel sensor;
  sensor.in_plane_noise = 1e300;
  std::string message = testing::input_error_message([&] { sensor.validate(); });
  EXPECT_EQ(message.rfind("MarkerSensorModel.in_plane_noise = 1e+300 must be in [0, 1] m", 0), 0u)
      << message;
  sensor = MarkerSensorModel{};
  sensor.camera.position = {0.0, -1e300, 0.0};
  message = testing::input_error_message([&] { sensor.validate(); });
  EXPECT_EQ(message.rfind("MarkerSensorModel.camera.position has magnitude 1e+300 m", 0), 0u)
      << message;
  sensor = MarkerSensorModel{};
  sensor.depth_noise = 1.0;  // the end of the range
  EXPECT_NO_THROW(sensor.validate());
}

}  // namespace
}  // namespace test_sensor_bounds
}  // namespace rodshape
