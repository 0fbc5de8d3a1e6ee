// plant_interface.hpp: the plant seam (issue 44). A Plant is the real rod as the validation's
// drivers (the open loop, the closed loop) drive it: reset to a start, then driven along timed
// paths one after another, carrying its state from one drive to the next, its frames handed on as
// they are reached. What stays fixed over a run is its PlantSetup, given when it is made
// (make_plant); what each drive varies is a PlantDrive. The quasi-static plant (drive_plant) is
// one implementation (quasi_static_plant.hpp); a dynamic rod is another.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "rodshape/core/clamped_rod.hpp"
#include "rodshape/core/pose.hpp"
#include "rodshape/core/wrench.hpp"
#include "rodshape/optimisation/shape_constraints.hpp"
#include "rodshape/sim/plant.hpp"
#include "rodshape/trajectory/end_effector_path.hpp"

namespace rodshape {

/// What a plant keeps over its runs: the real rod, the grasp holding its tip (released axes,
/// tip_T_ee), where the gripper really holds it (the tip's actual pose in the commanded tip frame)
/// and how it is followed.
struct PlantSetup {
  ClampedRod rod;
  Grasp grasp;
  Pose grasp_offset;
  PlantOptions options;
};

/// Where a run starts: the plant at rest, its first drive's start equilibrium solved from `guess`
/// (the plan's initial base wrench).
struct PlantStart {
  BaseWrench guess;
};

/// One drive: the tip's commanded end-effector path (at least one sample, starting where the last
/// drive ended), the base gripper's (empty: a fixed clamp) and the frame times (increasing, within
/// the paths' span; the first drive's may include its start).
struct PlantDrive {
  std::vector<TimedPose> path;
  BaseGripperPath base;
  std::vector<double> frame_times;
};

class Plant {
 public:
  virtual ~Plant() = default;
  /// The name make_plant() knows it by ("quasi_static").
  virtual std::string name() const = 0;
  virtual const PlantSetup& setup() const = 0;
  /// Back to the start of a run: no drive yet.
  virtual void reset(const PlantStart& start) = 0;
  /// Drives the plant along `request` from its state (after reset(): the start), each frame handed
  /// to `on_frame` as it is reached and not kept. Its run's `last` is the state the next drive
  /// continues from; a lost run ends the plant's run (drive no more).
  virtual PlantRun drive(const PlantDrive& request, const PlantFrameSink& on_frame) = 0;
  /// The grippers held still where the last drive left them until `t_end` (a closed loop's rest at
  /// a checkpoint), frames at `frame_times` (increasing, in (the last drive's end, t_end]).
  virtual PlantRun hold(double t_end,
                        const std::vector<double>& frame_times,
                        const PlantFrameSink& on_frame) = 0;
};

/// Makes a plant of `setup` at rest; may be called from several threads at once (the closed loop's
/// runs, ValidationOptions::jobs).
using PlantMaker = std::function<std::unique_ptr<Plant>(const PlantSetup& setup)>;

}  // namespace rodshape
