// estimate_task.cpp: an estimate task's cloud fitted from the task's own equilibrium
// (estimate_task.hpp).
#include "rodshape/io/estimate_task.hpp"

#include <variant>

#include "rodshape/error.hpp"
#include "rodshape/solvers/shooting_solver.hpp"

namespace rodshape {

namespace {

/// The held tip's pose (a clamped or grasped tip).
Pose held_pose(const TipCondition& tip) {
  if (const auto* clamped = std::get_if<ClampedTip>(&tip)) return clamped->pose;
  if (const auto* grasped = std::get_if<GraspedTip>(&tip)) return grasped->pose;
  throw InputError("EstimateTask.tip", ": the estimate needs a held tip (its pose is the prior)");
}

/// The cloud in the world frame: world_T_camera applied to each point.
CloudFrame world_cloud(const Pose& camera, const std::vector<Eigen::Vector3d>& points) {
  CloudFrame frame;
  frame.points.reserve(points.size());
  for (const Eigen::Vector3d& p : points)
    frame.points.push_back(camera.rotation * p + camera.position);
  return frame;
}

}  // namespace

CloudEstimate estimate_from_cloud(const EstimateTask& task,
                                  const std::vector<Eigen::Vector3d>& camera_points) {
  const EquilibriumTask& e = task.equilibrium;
  const Pose tip = held_pose(e.tip);
  task.sensor.validate();
  CloudEstimate result;
  result.prior = solve_equilibrium(e.rod, e.tip, e.initial_wrench, e.options);
  if (!result.prior.summary.converged()) {
    result.estimate.status = SolveStatus::NotRun;
    result.estimate.message =
        "the task's own equilibrium (the fit's start) did not converge: " + result.prior.brief();
    result.unexplained = result.estimate.message;
    return result;
  }
  result.estimate =
      estimate_state_from_cloud(e.rod, tip, tip, world_cloud(task.sensor.camera, camera_points),
                                task.sensor, {result.prior.base_wrench}, task.options);
  result.unexplained = unexplained(result.estimate, task.max_residual);
  return result;
}

}  // namespace rodshape
