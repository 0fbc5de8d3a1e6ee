// plan_validation.cpp: the experiment in stages: the real rod, the plant driven along the plan's
// path, the sensor's runs, the errors at each frame.
#include "rodshape/sim/plan_validation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <sstream>

#include "parallel_runs.hpp"
#include "plant_reach.hpp"
#include "rodshape/error.hpp"
#include "rodshape/sim/commanded_path.hpp"
#include "rodshape/sim/plant_factory.hpp"
#include "scene_contact.hpp"
#include "sensor_view.hpp"
#include "validation.hpp"

namespace rodshape {

namespace {

/// Run k's sensor (its own random stream) and the view the drivers see it through. Holds pointers
/// into itself: neither copied nor moved.
class RunSensor {
 public:
  RunSensor(const SensorModel& model,
            std::uint64_t seed,
            double length,
            const PlanProblem& problem) {
    if (const auto* markers = std::get_if<MarkerSensorModel>(&model)) {
      view_.emplace(markers_.emplace(*markers, seed), length);
    } else {
      view_.emplace(depth_.emplace(std::get<DepthSensorModel>(model), seed), problem);
    }
  }
  RunSensor(const RunSensor&) = delete;
  RunSensor& operator=(const RunSensor&) = delete;
  sim_detail::SensorView& view() { return *view_; }
  /// The closed loop carried out with this sensor.
  ClosedLoopRun run_closed_loop(const PlanResult& plan, ShapeController controller, Plant& plant) {
    if (markers_) return rodshape::run_closed_loop(plan, std::move(controller), plant, *markers_);
    return rodshape::run_closed_loop(plan, std::move(controller), plant, *depth_);
  }

 private:
  std::optional<MarkerSensor> markers_;
  std::optional<DepthCamera> depth_;
  std::optional<sim_detail::SensorView> view_;
};

/// The arm's joints at time t along a joint trajectory: its last sample at or before t.
const Eigen::VectorXd& joints_at(const JointTrajectoryResult& joints, double t) {
  const auto after = std::upper_bound(joints.t.begin(), joints.t.end(), t);
  const auto k = after == joints.t.begin() ? 0 : (after - joints.t.begin()) - 1;
  return joints.q[static_cast<std::size_t>(k)];
}

double frame_rate_of(const SensorModel& sensor) {
  return std::visit([](const auto& model) { return model.frame_rate; }, sensor);
}

/// The library's name of the sensor's frame rate, for messages.
std::string frame_rate_field(const SensorModel& sensor) {
  return kind_of(sensor) == SensorKind::Depth ? "DepthSensorModel.frame_rate"
                                              : "MarkerSensorModel.frame_rate";
}

/// A frame's errors appended to a run's series.
void record(ValidationRun& run, double t, const ShapeError& error) {
  run.time.push_back(t);
  run.error_3d.push_back(error.error_3d);
  run.error_2d.push_back(error.error_2d);
  run.true_error.push_back(error.true_error);
  run.visible_markers.push_back(error.visible_markers);
  run.final = error;
}

/// Stages 2 and 3, open loop: the plant driven once along the commanded path, each frame seen by
/// every run's sensor (run k's own random stream) as it is reached and then dropped: a run keeps
/// only its series (issue 24: the frames of 1e6 frames do not fit in memory).
void drive_and_observe(ValidationResult& result,
                       const PlanProblem& problem,
                       const PlanResult& plan,
                       Plant& plant,
                       const SensorModel& sensor,
                       const ValidationOptions& options,
                       const PlantDrive& request) {
  const std::vector<double>& times = request.frame_times;
  const double length = plant.setup().rod.properties.length;
  std::vector<std::unique_ptr<RunSensor>> cameras;
  for (int k = 0; k < options.runs; ++k) {
    ValidationRun& run = result.runs.emplace_back();
    run.seed = options.seed + static_cast<std::uint64_t>(k);
    for (auto* series : {&run.time, &run.error_3d, &run.error_2d, &run.true_error})
      series->reserve(times.size());
    run.visible_markers.reserve(times.size());
    cameras.push_back(std::make_unique<RunSensor>(sensor, run.seed, length, problem));
  }
  const bool clouds_see_arm = kind_of(sensor) == SensorKind::Depth && drives_joints(problem, plan);
  const bool clouds_see_base_arm =
      kind_of(sensor) == SensorKind::Depth && drives_base_joints(problem, plan);
  sim_detail::SceneContact contact(problem.scene, plant.setup().rod.clamp.position);
  const int total = static_cast<int>(times.size());
  int driven = 0, reported_percent = -1;
  const auto see = [&](const PlantFrame& frame) {
    ++driven;
    if (options.progress && (100 * driven / total > reported_percent || driven == total)) {
      reported_percent = 100 * driven / total;
      options.progress(driven, total);
    }
    contact.see(frame);
    std::vector<CapsuleObstacle> links;
    if (clouds_see_arm)
      links = arm_link_capsules(*problem.arm, joints_at(plan.arm->joints, frame.t));
    if (clouds_see_base_arm) {
      const std::vector<CapsuleObstacle> base_links =
          arm_link_capsules(*problem.base_arm, joints_at(plan.base_arm->joints, frame.t));
      links.insert(links.end(), base_links.begin(), base_links.end());
    }
    // The rod's first point: the clamp, where the base is held at this frame.
    for (std::size_t k = 0; k < cameras.size(); ++k)
      record(result.runs[k], frame.t,
             cameras[k]->view().see(frame, problem, frame.clamp.position, links));
  };
  plant.reset({plan.initial_wrench});
  result.plant = plant.drive(request, see);
  if (options.progress && driven < total) options.progress(total, total);  // lost on the way
  for (std::size_t k = 0; k < cameras.size(); ++k) {
    ValidationRun& run = result.runs[k];
    run.last_seen = cameras[k]->view().last_markers();
    run.last_cloud = cameras[k]->view().last_cloud();
    run.events = result.plant.events;
    run.events.insert(run.events.end(), contact.contacts().begin(), contact.contacts().end());
    run.min_gap = contact.min_gap();
    run.plant_final = result.plant.last;
  }
}

/// One closed-loop run: its own plant, driven segment by segment with a checkpoint at each
/// waypoint.
ValidationRun closed_loop_run(const PlanProblem& problem,
                              const PlanResult& plan,
                              Plant& plant,
                              const SensorModel& sensor,
                              const ValidationOptions& options,
                              std::uint64_t seed,
                              PlantRun& plant_run) {
  RunSensor camera(sensor, seed, plant.setup().rod.properties.length, problem);
  ClosedLoopRun loop = camera.run_closed_loop(
      plan, ShapeController(problem, plan, options.planning, options.loop), plant);
  ValidationRun run;
  run.seed = seed;
  run.closed_loop = true;
  for (auto* series : {&run.time, &run.error_3d, &run.error_2d, &run.true_error})
    series->reserve(loop.errors.size());
  run.visible_markers.reserve(loop.errors.size());
  for (std::size_t k = 0; k < loop.errors.size(); ++k) record(run, loop.times[k], loop.errors[k]);
  loop.times = {};
  loop.errors = {};
  run.last_seen = std::move(loop.last_seen);
  run.last_cloud = std::move(loop.last_cloud);
  run.checkpoints = std::move(loop.checkpoints);
  run.events = loop.plant.events;
  run.min_gap = loop.min_gap;
  run.plant_final = loop.plant.last;
  run.driven_by_joints = loop.driven_by_joints;
  run.base_moved = loop.base_moved;
  run.base_driven_by_joints = loop.base_driven_by_joints;
  plant_run = std::move(loop.plant);
  return run;
}

/// The frames of all runs within ValidationOptions::kMaxFrames, before any is driven: each keeps
/// its series and writes its lines (docs/limits.md). Closed loop, the rests at the checkpoints
/// count too (the re-plans' paths may differ a little from the plan's: an estimate).
void check_frames(const PlanResult& plan,
                  const SensorModel& sensor,
                  const ValidationOptions& options) {
  const double duration = plan.end_effector_path.back().t - plan.end_effector_path.front().t;
  const double rate = frame_rate_of(sensor);
  double per_run = std::floor(duration * rate) + 2.0;
  if (options.closed_loop)
    per_run += static_cast<double>(plan.steps.size()) * (options.loop.checkpoint_frames + 1);
  const double all = per_run * options.runs;
  if (all <= ValidationOptions::kMaxFrames) return;
  throw InputError(frame_rate_field(sensor),
                   ": the path of " + detail::format_value(duration) + " s at " +
                       detail::format_value(rate) + " Hz" +
                       (options.closed_loop ? " with the rests at the checkpoints" : "") +
                       ", with ValidationOptions.runs = " + std::to_string(options.runs) +
                       ", would have " + detail::format_value(all) + " frames; at most " +
                       detail::format_value(ValidationOptions::kMaxFrames) +
                       " in all: lower the frame rate or the runs");
}

/// A plant of `setup` made by `make`, which must make one.
std::unique_ptr<Plant> made_plant(const PlantMaker& make, const PlantSetup& setup) {
  std::unique_ptr<Plant> plant = make ? make(setup) : nullptr;
  if (!plant) throw InputError("PlantMaker", ": made no plant");
  return plant;
}

/// Stage 4: the status from the plant's events in every run (a loss outweighs a contact, a contact
/// a snap).
void judge(ValidationResult& result) {
  const auto rank = [](ValidationStatus status) {
    switch (status) {
      case ValidationStatus::Complete:
        return 0;
      case ValidationStatus::SnapThrough:
        return 1;
      case ValidationStatus::Contact:
        return 2;
      case ValidationStatus::Lost:
        break;
    }
    return 3;
  };
  result.status = ValidationStatus::Complete;
  result.message = "the plant followed the whole path";
  for (const ValidationRun& run : result.runs) {
    for (const PlantEvent& event : run.events) {
      const ValidationStatus status = event.kind == PlantEvent::Kind::Lost ? ValidationStatus::Lost
                                      : event.kind == PlantEvent::Kind::Contact
                                          ? ValidationStatus::Contact
                                          : ValidationStatus::SnapThrough;
      if (rank(status) > rank(result.status)) {
        result.status = status;
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
  if (jobs < 1 || jobs > kMaxJobs)
    throw InputError("ValidationOptions.jobs", " = " + std::to_string(jobs) + " must be in [1, " +
                                                   std::to_string(kMaxJobs) + "]");
  plant.validate();
  // Run k is seeded with seed + k - 1: the last must not wrap past 2^64 - 1.
  if (seed > std::numeric_limits<std::uint64_t>::max() - static_cast<std::uint64_t>(runs - 1))
    throw InputError("ValidationOptions.seed",
                     " = " + std::to_string(seed) + " with ValidationOptions.runs = " +
                         std::to_string(runs) + " would wrap past 2^64 - 1; at most " +
                         std::to_string(std::numeric_limits<std::uint64_t>::max() -
                                        static_cast<std::uint64_t>(runs - 1)));
}

std::string to_string(ValidationStatus status) {
  return std::string(name_of(kValidationStatusNames, status, "lost"));
}

namespace {

/// The median and the largest of `values` (finite, not empty).
struct RunSpread {
  double median = 0.0, worst = 0.0;
};
RunSpread run_spread(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return {n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]), values.back()};
}

}  // namespace

std::string ValidationResult::brief() const {
  std::ostringstream out;
  out.precision(3);
  out << to_string(status);
  std::vector<double> e3, e2;  // the final measured errors of the runs that saw a marker
  std::vector<double> true_error;
  std::size_t unseen = 0;  // runs that saw no marker at the last frame
  for (const ValidationRun& run : runs) {
    const ShapeError& e = run.final;
    if (std::isfinite(e.error_3d)) {
      e3.push_back(e.error_3d);
      e2.push_back(e.error_2d);
    } else {  // no marker seen at the last frame: nothing measured (shape_error())
      ++unseen;
    }
    true_error.push_back(e.true_error);
  }
  if (runs.size() == 1) {
    const ShapeError& e = runs.front().final;
    if (!e3.empty())
      out << ": final 3D error " << 1e3 * e.error_3d << " mm (2D " << 1e3 * e.error_2d
          << " mm, true " << 1e3 * e.true_error << " mm)";
    else
      out << ": final true error " << 1e3 * e.true_error
          << " mm (no marker seen: no measured error)";
  } else if (!runs.empty()) {  // over the runs: the median and the worst (per run: the runs)
    const auto mm = [&out](const char* what, const std::vector<double>& values) {
      const RunSpread s = run_spread(values);
      out << what << "median " << 1e3 * s.median << " mm, worst " << 1e3 * s.worst << " mm";
    };
    if (!e3.empty()) {
      mm(": final 3D error ", e3);
      mm(" (2D ", e2);
      mm("; true ", true_error);
      out << ")";
      if (unseen > 0)
        out << " (" << unseen << " of " << runs.size()
            << " runs saw no marker at the end: not in the measured errors)";
    } else {
      mm(": final true error ", true_error);
      out << " (no marker seen: no measured error)";
    }
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
                               const SensorModel& sensor,
                               const ValidationOptions& options) {
  return validate_plan(problem, plan, plant, sensor, options, plant_maker(plant.model));
}

ValidationResult validate_plan(const PlanProblem& problem,
                               const PlanResult& plan,
                               const PlantModel& plant,
                               const SensorModel& sensor,
                               const ValidationOptions& options,
                               const PlantMaker& make) {
  options.validate();
  std::visit([](const auto& model) { model.validate(); }, sensor);
  if (kind_of(sensor) == SensorKind::Depth && !(problem.scene.rod_radius > 0.0))
    throw InputError("Scene.rod_radius",
                     ": the depth camera sees the rod's surface, which needs the section's "
                     "radius (rod.section)");
  if (const auto* depth = std::get_if<DepthSensorModel>(&sensor); depth && options.closed_loop) {
    const double pooled = static_cast<double>(options.loop.checkpoint_frames) * depth->points;
    if (pooled > ValidationOptions::kMaxRestPoints)
      throw InputError("DepthSensorModel.points",
                       " = " + std::to_string(depth->points) + " with ClosedLoopOptions." +
                           "checkpoint_frames = " + std::to_string(options.loop.checkpoint_frames) +
                           " would pool " + detail::format_value(pooled) +
                           " points at a rest; at most " +
                           detail::format_value(ValidationOptions::kMaxRestPoints));
  }
  if (plan.end_effector_path.empty())
    throw InputError("PlanResult.end_effector_path", ": the plan has no path to carry out");
  ValidationResult result;
  // Stage 1: the real rod. Stage 2 (open loop): the plant along the commanded path, from the
  // plan's start; the runs differ in what the sensor sees. Closed loop: each run drives its own.
  result.real_rod = plant.real_rod(problem.rod);
  check_plant_reach(result.real_rod, plan, plant, problem.validity);
  check_frames(plan, sensor, options);
  const PlantSetup setup{result.real_rod, problem.grasp, plant.grasp_offset, options.plant};
  if (!options.closed_loop) {
    PlantDrive request{commanded_path(problem, plan), commanded_base(problem, plan), {}};
    const std::vector<TimedPose>& path = request.path;
    const BaseGripperPath& base = request.base;  // empty: a fixed clamp
    const double t_end = base.moves() ? std::max(path.back().t, base.path.back().t) : path.back().t;
    request.frame_times = frame_times(path.front().t, t_end, frame_rate_of(sensor));
    drive_and_observe(result, problem, plan, *made_plant(make, setup), sensor, options, request);
    for (ValidationRun& run : result.runs) {
      run.driven_by_joints = drives_joints(problem, plan);
      run.base_moved = base.moves();
      run.base_driven_by_joints = base.moves() && drives_base_joints(problem, plan);
    }
  }
  if (options.closed_loop) {
    // Each run drives its own plant: the runs are independent, carried out by options.jobs threads.
    result.runs.resize(static_cast<std::size_t>(options.runs));
    std::mutex progress_mutex;
    int done = 0;
    sim_detail::parallel_runs(options.runs, options.jobs, [&](int k) {
      const std::uint64_t seed = options.seed + static_cast<std::uint64_t>(k);
      PlantRun plant_run;
      result.runs[static_cast<std::size_t>(k)] = closed_loop_run(
          problem, plan, *made_plant(make, setup), sensor, options, seed, plant_run);
      if (k == 0) result.plant = std::move(plant_run);
      if (options.progress) {
        const std::lock_guard<std::mutex> lock(progress_mutex);
        options.progress(++done, options.runs);
      }
    });
  }
  judge(result);
  return result;
}

}  // namespace rodshape
