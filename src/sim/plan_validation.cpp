// plan_validation.cpp: the experiment in stages: the real rod, the plant driven along the plan's
// path, the sensor's runs, the errors at each frame.
#include "rodshape/sim/plan_validation.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "plant_reach.hpp"
#include "rodshape/error.hpp"
#include "rodshape/sim/commanded_path.hpp"
#include "validation.hpp"

namespace rodshape {

namespace {

/// Stage 3: one run of the sensor over the plant's frames, with the errors at each frame.
ValidationRun observe_run(const ValidationResult& result,
                          const PointSet& points,
                          const MarkerSensorModel& sensor,
                          std::uint64_t seed) {
  ValidationRun run;
  run.seed = seed;
  MarkerSensor camera(sensor, seed);
  const Eigen::Vector3d clamp = result.real_rod.clamp.position;
  for (const PlantFrame& frame : result.plant.frames) {
    SensorFrame seen = camera.observe(frame, result.real_rod.properties.length);
    const ShapeError error = shape_error(points, clamp, seen, frame.configuration, sensor.camera);
    run.time.push_back(frame.t);
    run.error_3d.push_back(error.error_3d);
    run.error_2d.push_back(error.error_2d);
    run.true_error.push_back(error.true_error);
    run.visible_markers.push_back(error.visible_markers);
    run.frames.push_back(std::move(seen));
    run.final = error;
  }
  run.events = result.plant.events;
  run.plant_final = result.plant.last;
  return run;
}

/// One closed-loop run: its own plant, driven segment by segment with a checkpoint at each
/// waypoint.
ValidationRun closed_loop_run(const PlanProblem& problem,
                              const PlanResult& plan,
                              const PlantModel& plant,
                              const MarkerSensorModel& sensor,
                              const ValidationOptions& options,
                              const ClampedRod& real,
                              std::uint64_t seed,
                              PlantRun& plant_run) {
  MarkerSensor camera(sensor, seed);
  ClosedLoopRun loop = run_closed_loop(problem, options.planning, plan, real, plant.grasp_offset,
                                       camera, options.loop, options.plant);
  ValidationRun run;
  run.seed = seed;
  run.closed_loop = true;
  for (std::size_t k = 0; k < loop.errors.size(); ++k) {
    const ShapeError& error = loop.errors[k];
    run.time.push_back(loop.frames[k].t);
    run.error_3d.push_back(error.error_3d);
    run.error_2d.push_back(error.error_2d);
    run.true_error.push_back(error.true_error);
    run.visible_markers.push_back(error.visible_markers);
    run.final = error;
  }
  run.frames = std::move(loop.frames);
  run.checkpoints = std::move(loop.checkpoints);
  run.events = loop.plant.events;
  run.plant_final = loop.plant.last;
  run.driven_by_joints = loop.driven_by_joints;
  plant_run = std::move(loop.plant);
  return run;
}

/// Stage 4: the status from the plant's events in every run (a loss outweighs a snap).
void judge(ValidationResult& result) {
  result.status = ValidationStatus::Complete;
  result.message = "the plant followed the whole path";
  for (const ValidationRun& run : result.runs) {
    for (const PlantEvent& event : run.events) {
      if (event.kind == PlantEvent::Kind::Lost) {
        result.status = ValidationStatus::Lost;
        result.message = event.message;
        return;
      }
      if (result.status == ValidationStatus::Complete) {
        result.status = ValidationStatus::SnapThrough;
        result.message = event.message;
      }
    }
  }
}

}  // namespace

void ValidationOptions::validate() const {
  if (runs < 1 || runs > kMaxRuns)
    throw InputError("ValidationOptions.runs", " = " + std::to_string(runs) + " must be in [1, " +
                                                   std::to_string(kMaxRuns) + "]");
  plant.validate();
}

std::string to_string(ValidationStatus status) {
  switch (status) {
    case ValidationStatus::Complete:
      return "complete";
    case ValidationStatus::SnapThrough:
      return "snap_through";
    case ValidationStatus::Lost:
      return "lost";
  }
  return "lost";
}

std::string ValidationResult::brief() const {
  std::ostringstream out;
  out.precision(3);
  out << to_string(status);
  if (!runs.empty()) {
    const ShapeError& e = runs.front().final;
    out << ": final 3D error " << 1e3 * e.error_3d << " mm (2D " << 1e3 * e.error_2d << " mm, true "
        << 1e3 * e.true_error << " mm)";
  }
  out << ", " << runs.size() << (runs.size() == 1 ? " run" : " runs");
  if (status != ValidationStatus::Complete) out << "; " << message;
  return out.str();
}

std::vector<double> frame_times(double t0, double t1, double rate) {
  const double count = std::floor((t1 - t0) * rate);
  if (!(count <= ValidationOptions::kMaxFrames))
    throw InputError("MarkerSensorModel.frame_rate",
                     ": the path of " + detail::format_value(t1 - t0) + " s at " +
                         detail::format_value(rate) + " Hz would have " +
                         detail::format_value(count + 1) + " frames; at most " +
                         detail::format_value(ValidationOptions::kMaxFrames));
  std::vector<double> times;
  for (int k = 0; k <= static_cast<int>(count); ++k) times.push_back(t0 + k / rate);
  if (times.back() < t1) times.push_back(t1);  // after the last waypoint
  return times;
}

bool ValidationResult::driven_by_joints() const {
  return std::all_of(runs.begin(), runs.end(),
                     [](const ValidationRun& run) { return run.driven_by_joints; });
}

ValidationResult validate_plan(const PlanProblem& problem,
                               const PlanResult& plan,
                               const PlantModel& plant,
                               const MarkerSensorModel& sensor,
                               const ValidationOptions& options) {
  options.validate();
  sensor.validate();
  if (plan.end_effector_path.empty())
    throw InputError("PlanResult.end_effector_path", ": the plan has no path to carry out");
  ValidationResult result;
  // Stage 1: the real rod. Stage 2 (open loop): the plant along the commanded path, from the
  // plan's start; the runs differ in what the sensor sees. Closed loop: each run drives its own.
  result.real_rod = plant.real_rod(problem.rod);
  check_plant_reach(result.real_rod, plan, plant, problem.validity);
  if (!options.closed_loop) {
    const std::vector<TimedPose> path = commanded_path(problem, plan);
    result.plant =
        drive_plant(result.real_rod, problem.grasp, plant.grasp_offset, path, plan.initial_wrench,
                    frame_times(path.front().t, path.back().t, sensor.frame_rate), options.plant);
  }
  const bool open_loop_by_joints = drives_joints(problem, plan);
  for (int k = 0; k < options.runs; ++k) {
    const std::uint64_t seed = options.seed + static_cast<std::uint64_t>(k);
    if (!options.closed_loop) {
      result.runs.push_back(observe_run(result, problem.target.points, sensor, seed));
      result.runs.back().driven_by_joints = open_loop_by_joints;
      continue;
    }
    PlantRun plant_run;
    result.runs.push_back(
        closed_loop_run(problem, plan, plant, sensor, options, result.real_rod, seed, plant_run));
    if (k == 0) result.plant = std::move(plant_run);
  }
  judge(result);
  return result;
}

}  // namespace rodshape
