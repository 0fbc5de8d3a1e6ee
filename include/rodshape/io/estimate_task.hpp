// estimate_task.hpp: what `rodshape estimate` (and Python's rodshape.estimate) is given: an
// equilibrium task (the rod, the clamp, the held tip: the fit's prior) with a depth camera, and
// one cloud in that camera's frame; and what it makes of them: the rod's estimated equilibrium
// (feedback/cloud_estimator.hpp), starting from the task's own equilibrium. docs/estimate.md.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "rodshape/feedback/cloud_estimator.hpp"
#include "rodshape/feedback/cloud_measurement.hpp"
#include "rodshape/io/equilibrium_task.hpp"
#include "rodshape/solvers/shooting_solver.hpp"

namespace rodshape {

struct EstimateTask {
  EquilibriumTask equilibrium;  // rod (with its section), base, tip (held: the prior), solver
  DepthSensorModel sensor;      // sensor.kind: depth; sensor.camera: world_T_camera
  EstimationOptions options;    // the defaults (the held tip known to 0.1 mm and 1 mrad)
  /// The largest residual (about 1 at the camera's noise) of a fit the model explains
  /// (ClosedLoopOptions::max_residual's default).
  double max_residual = 2.0;
};

struct CloudEstimate {
  ShootingResult prior;  // the task's equilibrium: where the fit starts and what it is pulled to
  StateEstimate estimate;
  /// Empty when the model explains the cloud (unexplained()), else why not.
  std::string unexplained;
  bool explained() const { return unexplained.empty(); }
};

/// The estimate from `camera_points` (the cloud in the camera's frame; non-finite points are bad
/// input, at most kMaxCloudPoints): the task's equilibrium solved (its tip pose the fit's prior,
/// its base wrench the start), the points moved to the world frame by sensor.camera, then
/// estimate_state_from_cloud. A task whose own equilibrium does not converge gives a NotRun
/// estimate saying so. Throws InputError for bad input.
CloudEstimate estimate_from_cloud(const EstimateTask& task,
                                  const std::vector<Eigen::Vector3d>& camera_points);

}  // namespace rodshape
