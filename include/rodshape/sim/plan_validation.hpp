// plan_validation.hpp: the paper's experiment in simulation. The plan's commanded end-effector path
// drives the plant (the real rod, drive_plant); the sensor sees it at its frame rate; at every
// frame the paper's error (mean distance from the objective points to the measured curve, in 3D and
// in the image plane) and the true error (to the plant's own curve) are computed. Repeats differ in
// the sensor's noise only (run k uses seed + k): the plant is deterministic.
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "rodshape/core/clamped_rod.hpp"
#include "rodshape/enum_names.hpp"
#include "rodshape/feedback/sensor_model.hpp"
#include "rodshape/sim/closed_loop.hpp"
#include "rodshape/sim/marker_sensor.hpp"
#include "rodshape/sim/plant.hpp"
#include "rodshape/sim/plant_interface.hpp"
#include "rodshape/sim/plant_model.hpp"
#include "rodshape/sim/shape_error.hpp"
#include "rodshape/trajectory/plan_problem.hpp"
#include "rodshape/trajectory/plan_result.hpp"

namespace rodshape {

struct ValidationOptions {
  static constexpr int kMaxRuns = 1000;
  static constexpr int kMaxJobs = 256;
  /// Frames of all runs together (runs × duration × frame rate; closed loop, with the rests at
  /// the checkpoints): each keeps about 40 bytes of series and writes about 200 bytes of
  /// validation.json and validation.csv (docs/limits.md).
  static constexpr double kMaxFrames = 1e6;
  /// A depth camera's points pooled over a closed loop's rest (checkpoint_frames × points): the
  /// cloud one estimate fits (24 bytes a point; docs/limits.md).
  static constexpr double kMaxRestPoints = 1e6;
  int runs = 1;            // 1 ≤ runs ≤ kMaxRuns
  std::uint64_t seed = 1;  // run k's sensor is seeded with seed + k
  PlantOptions plant;
  /// Close the loop: a checkpoint at every waypoint (estimate, re-plan the rest: run_closed_loop).
  /// Each run then drives its own plant, since what it sees changes what it does.
  bool closed_loop = false;
  ClosedLoopOptions loop;
  PlanOptions planning;  // the options of the closed loop's re-plans (the plan's own)
  /// Threads that carry out the closed loop's runs at once, 1 ≤ jobs ≤ kMaxJobs (run k is seeded
  /// as ever: the result is the same for every jobs). Open loop, the runs observe one plant driven
  /// in one thread, and jobs is not used.
  int jobs = 1;
  /// Called as the work advances, with (done, total): closed loop the runs done, open loop the
  /// plant's frames driven (at most about 100 calls). Never two calls at once, done increasing;
  /// the last call has done = total. Empty: nothing called.
  std::function<void(int done, int total)> progress;
  /// Throws InputError naming the field.
  void validate() const;
};

/// One run: the errors at each frame, and after the last waypoint. The per-frame series are all
/// it keeps of a frame (about 36 bytes); the plant's shapes and the markers are not kept.
struct ValidationRun {
  std::uint64_t seed = 0;
  std::vector<double> time, error_3d, error_2d, true_error;  // s, m, m, m
  std::vector<int> visible_markers;
  SensorFrame last_seen;  // what the marker camera saw at the last frame
  CloudFrame last_cloud;  // what the depth camera saw at the last frame (sensor.kind: depth)
  ShapeError final;       // at the last frame
  bool closed_loop = false;
  std::vector<Checkpoint> checkpoints;  // closed loop: one per waypoint but the last
  std::vector<PlantEvent> events;       // the plant's, in this run (contacts with the scene too)
  /// The least gap between the plant's rod and the plan's scene over the frames, m (+inf without
  /// a scene).
  double min_gap = std::numeric_limits<double>::infinity();
  PlantFrame plant_final;  // the plant's last equilibrium in this run
  /// The plant followed the arm's joint trajectory through its forward kinematics (closed loop:
  /// every segment's, by IK from the arm's joints; see ClosedLoopRun).
  bool driven_by_joints = false;
  /// The base end was driven by a moving gripper (a plan with a moving base and its base path).
  bool base_moved = false;
  /// ... along the base arm's joint trajectory through its forward kinematics (commanded_base()).
  bool base_driven_by_joints = false;
};

enum class ValidationStatus {
  Complete,     // the plant followed the whole path
  SnapThrough,  // it did, but snapped between samples (see plant.events)
  Lost,         // no equilibrium at some sample: the run stops there
  Contact,      // it did, but its rod would touch an obstacle of the plan's scene (runs' events)
};
/// The names of ValidationStatus, in its order (to_string; validation.json's "status").
inline constexpr EnumNames<ValidationStatus, 4> kValidationStatusNames = {{
    {ValidationStatus::Complete, "complete"},
    {ValidationStatus::SnapThrough, "snap_through"},
    {ValidationStatus::Lost, "lost"},
    {ValidationStatus::Contact, "contact"},
}};
std::string to_string(ValidationStatus status);  // "complete", "snap_through", "lost", "contact"

struct ValidationResult {
  ValidationStatus status = ValidationStatus::Lost;
  std::string message;
  ClampedRod real_rod;  // the plant's rod (PlantModel::real_rod of the planner's)
  PlantRun plant;       // its events and last equilibrium (closed loop: the first run's)
  std::vector<ValidationRun> runs;
  /// Every run's plant followed the arm's joint trajectory through its forward kinematics (a plan
  /// with an arm and a complete joint trajectory; commanded_path()), else the end-effector path.
  bool driven_by_joints() const;
  /// "complete: final 3D error 1.2 mm (2D 0.8 mm, true 0.4 mm), 1 run"; over several runs the
  /// median and the worst of each ("final 3D error median 2.4 mm, worst 10.3 mm (2D median …;
  /// true median …), 8 runs"; each run's own in `runs`).
  std::string brief() const;
};

/// The frame times of a path from t0 to t1 at `rate`: t0 + k / rate, and t1 if not among them.
std::vector<double> frame_times(double t0, double t1, double rate);

/// Validates `plan` (of `problem`, with a non-empty end-effector path) on `plant` seen by
/// `sensor`, driven along commanded_path(). Throws InputError for bad input (a plan without a path,
/// a plant that cannot be held at the start is a status, not an error).
/// The sensor is a marker camera or a depth camera (sim/depth_camera.hpp: it needs the rod's
/// radius, problem.scene.rod_radius > 0 from rod.section, and sees the plan's scene and arm).
ValidationResult validate_plan(const PlanProblem& problem,
                               const PlanResult& plan,
                               const PlantModel& plant,
                               const SensorModel& sensor,
                               const ValidationOptions& options = {});
/// The same on the plants `make` makes (for plant.model, validate_plan above uses plant_maker()) of
/// PlantSetup{plant.real_rod(problem.rod), problem.grasp, plant.grasp_offset, options.plant}: open
/// loop one, driven once along the commanded path; closed loop one per run.
ValidationResult validate_plan(const PlanProblem& problem,
                               const PlanResult& plan,
                               const PlantModel& plant,
                               const SensorModel& sensor,
                               const ValidationOptions& options,
                               const PlantMaker& make);

}  // namespace rodshape
