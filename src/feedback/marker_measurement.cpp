// marker_measurement.cpp: the marker camera's and wrist sensor's model checked, the markers' arc
// lengths, the image plane (marker_measurement.hpp).
#include "rodshape/feedback/marker_measurement.hpp"

#include <string>

#include "rodshape/core/physical_bounds.hpp"
#include "rodshape/error.hpp"
#include "validation.hpp"

namespace rodshape {

void MarkerSensorModel::validate() const {
  if (markers < 2 || markers > kMaxMarkers)
    throw InputError(
        "MarkerSensorModel.markers",
        " = " + std::to_string(markers) + " must be in [2, " + std::to_string(kMaxMarkers) + "]");
  detail::require_non_negative("MarkerSensorModel.in_plane_noise", in_plane_noise);
  detail::require_non_negative("MarkerSensorModel.depth_noise", depth_noise);
  require_in_range("MarkerSensorModel.in_plane_noise", in_plane_noise, bounds::kMarkerNoise);
  require_in_range("MarkerSensorModel.depth_noise", depth_noise, bounds::kMarkerNoise);
  detail::require_finite("MarkerSensorModel.dropout", dropout);
  if (dropout < 0.0 || dropout > 1.0)
    throw InputError("MarkerSensorModel.dropout",
                     " = " + detail::format_value(dropout) + " must be in [0, 1]");
  // A camera that never sees a marker, and no wrist sensor: nothing would be measured (issue 24).
  if (dropout == 1.0 && !wrist)
    throw InputError("MarkerSensorModel.dropout",
                     " = 1 hides every marker, and there is no wrist sensor "
                     "(MarkerSensorModel.wrist): nothing would be measured");
  detail::require_positive("MarkerSensorModel.frame_rate", frame_rate);
  if (frame_rate > kMaxFrameRate)
    throw InputError("MarkerSensorModel.frame_rate",
                     " = " + detail::format_value(frame_rate) +
                         " must be <= " + detail::format_value(kMaxFrameRate));
  detail::require_pose("MarkerSensorModel.camera", camera);
  require_magnitude_at_most("MarkerSensorModel.camera.position", camera.position,
                            bounds::kMaxPosition, "m");
  if (wrist) {
    detail::require_non_negative("MarkerSensorModel.wrist.force", wrist->force);
    detail::require_non_negative("MarkerSensorModel.wrist.moment", wrist->moment);
    require_in_range("MarkerSensorModel.wrist.force", wrist->force, {0.0, bounds::kMaxForce, "N"});
    require_in_range("MarkerSensorModel.wrist.moment", wrist->moment,
                     {0.0, bounds::kMaxForce, "N*m"});
  }
}

std::vector<double> MarkerSensorModel::arc_lengths(double length) const {
  std::vector<double> s(static_cast<std::size_t>(markers));
  for (int j = 0; j < markers; ++j) s[static_cast<std::size_t>(j)] = (j + 1) * length / markers;
  return s;
}

int SensorFrame::visible() const {
  int count = 0;
  for (const auto& marker : markers) count += marker.has_value();
  return count;
}

Eigen::Vector2d image_point(const Pose& camera, const Eigen::Vector3d& world_point) {
  return (camera.rotation.transpose() * (world_point - camera.position)).head<2>();
}

}  // namespace rodshape
