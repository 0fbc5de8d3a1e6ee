// shape_error.hpp: the paper's error metric: the mean, over the objective points, of the distance
// from the point to the object's curve. Measured: the curve is the polyline from the clamp through
// the visible markers in arc-length order, in 3D and in 2D (both projected on the camera's image
// plane, where a Kinect's depth noise does not enter); true: the plant's own curve (the Hermite
// curve of its nodes, no noise), so that sensor noise and model error can be told apart. A depth
// camera's cloud has no curve: its measured error is the distance to the cloud, less the radius.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "rodshape/core/pose.hpp"
#include "rodshape/core/rod_configuration.hpp"
#include "rodshape/feedback/cloud_measurement.hpp"
#include "rodshape/sim/marker_sensor.hpp"
#include "rodshape/trajectory/intermediate_targets.hpp"

namespace rodshape {

struct ShapeError {
  double error_3d = 0.0;           // m: mean distance to the measured polyline
  double error_2d = 0.0;           // m: the same in the camera's image plane
  double true_error = 0.0;         // m: mean distance to the plant's curve
  double true_max_distance = 0.0;  // m: the largest of those
  int visible_markers = 0;
};

/// Distance from a point to a polyline (at least one vertex), in any dimension.
template <int D>
double polyline_distance(const std::vector<Eigen::Matrix<double, D, 1>>& polyline,
                         const Eigen::Matrix<double, D, 1>& point);

/// The errors of one frame: `clamp` the rod's first point (known, not measured), `points` p_obj.
ShapeError shape_error(const PointSet& points,
                       const Eigen::Vector3d& clamp,
                       const SensorFrame& seen,
                       const RodConfiguration& plant,
                       const Pose& camera);

/// The errors of a depth camera's frame: measured, the distance from p_obj to the cloud's nearest
/// point less the rod's `radius` (at least 0: the cloud lies on the surface, p_obj on the
/// centreline), in 3D and in the camera's image plane; true as for markers; visible_markers the
/// cloud's points. Without a point the measured errors are NaN.
ShapeError shape_error(const PointSet& points,
                       const CloudFrame& seen,
                       const RodConfiguration& plant,
                       const Pose& camera,
                       double radius);

/// The RMS, over the nodes of `estimate`, of their distance to the curve of `plant`: how far an
/// estimated centreline lies from the true one (a simulation-only truth; NaN without nodes).
double centreline_rms(const RodConfiguration& estimate, const RodConfiguration& plant);

}  // namespace rodshape
