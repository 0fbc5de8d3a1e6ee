// plan_task.hpp: what a plan task file describes: the rod and its clamp (as for `equilibrium`), the
// target shape, the weights of the cost, what the shapes must respect (workspace, grasp, strain
// limits), the initial state, and the options of the optimiser and of the trajectory. See
// docs/task-file.md for the file format. An optional robot section places an arm (URDF) in the
// world (PlanProblem::arm, with its reach and re-plan options in PlanOptions::arm). With a moving
// base (base.moving, issue 21) the base end is held by a gripper too (PlanProblem::moving_base),
// optionally carried by a second arm (base_robot: PlanProblem::base_arm; its seed in
// PlanOptions::arm.base_seed, its other options shared with the tip's arm).
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "rodshape/error.hpp"
#include "rodshape/feedback/closed_loop_options.hpp"
#include "rodshape/feedback/marker_measurement.hpp"
#include "rodshape/feedback/sensor_model.hpp"
#include "rodshape/sim/plant_model.hpp"
#include "rodshape/trajectory/plan.hpp"

namespace rodshape {

struct PlanTask {
  PlanProblem problem;  // rod, target, workspace, grasp, limits, initial state, arm
  PlanOptions options;  // trajectory.steps (n_inter), optimizer, end-effector limits, robot.reach
  PlantModel plant;     // the real rod of `rodshape validate` (the planner's by default)
  MarkerSensorModel sensor;  // what sees it (10 markers, a Kinect-like camera, no wrist sensor)
  /// `sensor.kind: depth`: the depth camera that sees it instead of `sensor`'s markers.
  std::optional<DepthSensorModel> depth_sensor;
  ClosedLoopOptions closed_loop;  // `rodshape validate --closed-loop`: estimation and re-plans
  std::string source;             // the file name that messages name
  /// The files the task was read from (the task file, robot.urdf): never an output of its run.
  std::vector<std::string> input_files;
  /// The line of each key of the file, two levels deep ("initial" → 14, "initial.tip" → 15).
  std::map<std::string, int> lines;

  /// The sensor `rodshape validate` uses: the depth camera if the task has one, else the markers.
  SensorModel sensor_model() const {
    return depth_sensor ? SensorModel(*depth_sensor) : SensorModel(sensor);
  }
  /// The message of an InputError that plan() threw for this task, as the task file says it:
  /// "<source>:<line>: <task field><problem>", the line that of the deepest key of the field that
  /// the file has (none when it has none of it).
  std::string locate(const InputError& error) const;
  /// An infeasible target (plan.status Infeasible) is bad input like any other: the error names
  /// the offending point (target.points[i]) and its line, and the reason.
  InputError infeasible_target(const PlanResult& plan) const;
};

}  // namespace rodshape
