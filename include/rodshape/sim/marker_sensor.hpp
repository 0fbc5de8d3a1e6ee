// marker_sensor.hpp: the simulated marker camera and wrist sensor: the plant's markers and wrist
// wrench with the noise of a MarkerSensorModel (feedback/marker_measurement.hpp) drawn at random.
// Seeded: the same seed gives the same measurements, bit for bit.
#pragma once

#include <cstdint>
#include <random>

#include "rodshape/feedback/marker_measurement.hpp"
#include "rodshape/sim/plant.hpp"

namespace rodshape {

class MarkerSensor {
 public:
  MarkerSensor(MarkerSensorModel model, std::uint64_t seed);
  /// Measures `frame` of a rod of length `length` (the wrist wrench about the frame's
  /// end-effector pose, where the gripper is).
  SensorFrame observe(const PlantFrame& frame, double length);
  const MarkerSensorModel& model() const { return model_; }

 private:
  MarkerSensorModel model_;
  std::mt19937_64 random_;
  std::normal_distribution<double> normal_{0.0, 1.0};
  std::uniform_real_distribution<double> uniform_{0.0, 1.0};
};

}  // namespace rodshape
