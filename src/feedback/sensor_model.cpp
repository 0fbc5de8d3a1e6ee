// sensor_model.cpp: the sensor's kind by name (sensor_model.hpp).
#include "rodshape/feedback/sensor_model.hpp"

namespace rodshape {

std::string to_string(SensorKind kind) {
  return std::string(name_of(kSensorKindNames, kind, "markers"));
}

SensorKind kind_of(const SensorModel& sensor) {
  return std::holds_alternative<DepthSensorModel>(sensor) ? SensorKind::Depth : SensorKind::Markers;
}

}  // namespace rodshape
