// closed_loop.hpp: the closed loop in simulation. The driver carries out a plan on the plant (the
// real rod) segment by segment; at each waypoint but the last the arm rests for
// ClosedLoopOptions::checkpoint_frames frames, the markers seen are averaged (a depth camera's
// clouds pooled), and the measurement is handed to the ShapeController
// (feedback/shape_controller.hpp), whose waypoints ahead (the plan's, or corrected) the driver then
// follows. Every frame is seen by the sensor and its errors recorded.
#pragma once

#include <limits>
#include <vector>

#include "rodshape/core/clamped_rod.hpp"
#include "rodshape/core/pose.hpp"
#include "rodshape/feedback/shape_controller.hpp"
#include "rodshape/sim/depth_camera.hpp"
#include "rodshape/sim/marker_sensor.hpp"
#include "rodshape/sim/plant.hpp"
#include "rodshape/sim/plant_interface.hpp"
#include "rodshape/sim/shape_error.hpp"

namespace rodshape {

/// The quasi-static plant a closed loop drives (run_closed_loop's convenience form): the real rod,
/// where the gripper really holds it (the tip's actual pose in the commanded tip frame, which the
/// controller does not know) and how it is followed.
struct ClosedLoopPlant {
  ClampedRod rod;
  Pose grasp_offset;
  PlantOptions options;
};

/// A closed-loop run: the plant as driven, what the sensor saw and the errors at each frame, the
/// checkpoints.
struct ClosedLoopRun {
  PlantRun plant;  // its events include the contacts with the plan's scene
  double min_gap = std::numeric_limits<double>::infinity();  // to the plan's scene, m
  std::vector<double> times;                                 // s, one per frame
  std::vector<ShapeError> errors;  // one per frame (the frames themselves are not kept)
  SensorFrame last_seen;           // what the marker camera saw at the last frame
  CloudFrame last_cloud;           // what the depth camera saw at the last frame
  std::vector<Checkpoint> checkpoints;
  /// With an arm (a plan with a complete joint trajectory), each segment is solved by IK from the
  /// arm's joints and the plant follows the hand's poses (commanded_path.hpp). A segment without
  /// an IK solution and the rest of the run follow the end-effector poses: false, and the
  /// checkpoint before it says so.
  bool driven_by_joints = false;
  /// With a moving base (a plan with a base path): both ends driven, the base to each waypoint's
  /// base_end_effector on the tip's clock (each segment takes the longer of the two ends' times);
  /// with a base arm, through its IK and FK as for the tip's arm (base_driven_by_joints).
  bool base_moved = false;
  bool base_driven_by_joints = false;
};

/// Carries out `plan` with `controller` (built from it, not yet updated) on `plant` seen by
/// `sensor`, with a checkpoint at every waypoint but the last: the plant reset to the plan's start
/// (its initial wrench), driven segment by segment and held at each rest. Its setup is the real
/// rod, its grasp the plan's.
ClosedLoopRun run_closed_loop(const PlanResult& plan,
                              ShapeController controller,
                              Plant& plant,
                              MarkerSensor& sensor);
/// The same on a QuasiStaticPlant of `plant` and the plan's grasp.
ClosedLoopRun run_closed_loop(const PlanResult& plan,
                              ShapeController controller,
                              const ClosedLoopPlant& plant,
                              MarkerSensor& sensor);
/// The same seen by a depth camera (in the plan's scene, with the arm's links when it has an arm:
/// where the arm stands at the end of the segment it is on, exact at the rests where the
/// controller is updated). The clouds of a rest are pooled into one measurement.
ClosedLoopRun run_closed_loop(const PlanResult& plan,
                              ShapeController controller,
                              Plant& plant,
                              DepthCamera& camera);
ClosedLoopRun run_closed_loop(const PlanResult& plan,
                              ShapeController controller,
                              const ClosedLoopPlant& plant,
                              DepthCamera& camera);

}  // namespace rodshape
