// sensor_model.hpp: which camera sees the rod: a marker camera (marker_measurement.hpp) or a depth
// camera (cloud_measurement.hpp), the task file's `sensor.kind` (docs/task-file.md, "sensor").
#pragma once

#include <string>
#include <variant>

#include "rodshape/enum_names.hpp"
#include "rodshape/feedback/cloud_measurement.hpp"
#include "rodshape/feedback/marker_measurement.hpp"

namespace rodshape {

enum class SensorKind { Markers, Depth };
/// The names of SensorKind, in its order (the task file's `sensor.kind`, validation.json's).
inline constexpr EnumNames<SensorKind, 2> kSensorKindNames = {{
    {SensorKind::Markers, "markers"},
    {SensorKind::Depth, "depth"},
}};
std::string to_string(SensorKind kind);  // "markers", "depth"

/// A marker camera or a depth camera, each with its optional wrist sensor.
using SensorModel = std::variant<MarkerSensorModel, DepthSensorModel>;

SensorKind kind_of(const SensorModel& sensor);

}  // namespace rodshape
