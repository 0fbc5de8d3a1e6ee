// plant.hpp: the simulated plant: the real rod driven by the commanded end-effector path. At each
// sample of the path the held equilibrium is solved directly from the last one (quasi-static, as
// the paper assumes: the rod stays on its branch while the gripper moves slowly). A snap-through
// (the rod jumps to another equilibrium between two samples) and a lost equilibrium are events
// with their time, never a crash. The direct solves would follow a branch past the point where it
// loses stability; the state's stability is checked at every camera frame and, where it is lost,
// the rod snaps to a stable equilibrium with the same ends (seek_stable_equilibrium).
//
// Either end may be driven (issue 21): with a moving base the rod's clamp at each sample is the
// commanded base gripper pose composed with inverse(base_T_ee), and each sample's direct solve
// starts from the last base wrench turned with the base (world wrench rotated by the clamp's ΔR),
// so that a rigid motion of both ends is followed exactly and the rod stays on its branch. The
// solver clamps the rod at s = 0 (solvers/tip_condition.hpp: only the tip end has free
// components), so the base grasp's released components are not modelled: the base is held
// clamped.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "rodshape/core/clamped_rod.hpp"
#include "rodshape/core/pose.hpp"
#include "rodshape/core/rod_configuration.hpp"
#include "rodshape/core/wrench.hpp"
#include "rodshape/enum_names.hpp"
#include "rodshape/optimisation/shape_constraints.hpp"
#include "rodshape/solvers/shooting_solver.hpp"
#include "rodshape/trajectory/end_effector_path.hpp"

namespace rodshape {

struct PlantEvent {
  enum class Kind {
    SnapThrough,  // the rod jumped to another equilibrium, releasing energy
    Lost,         // no equilibrium was found at a sample: the run stops there
    Contact,      // the rod's surface would touch an obstacle of the plan's scene (validation)
  };
  Kind kind = Kind::Lost;
  double t = 0.0;                // s: the sample (or, for a contact, the frame) where it happened
  double energy_released = 0.0;  // J (SnapThrough)
  std::string message;
  int obstacle = -1;   // Contact: index into the scene's obstacles
  double depth = 0.0;  // Contact: the deepest overlap of that contact, m
};
/// The names of PlantEvent::Kind, in its order (to_string; the events' "kind").
inline constexpr EnumNames<PlantEvent::Kind, 3> kPlantEventKindNames = {{
    {PlantEvent::Kind::SnapThrough, "snap_through"},
    {PlantEvent::Kind::Lost, "lost"},
    {PlantEvent::Kind::Contact, "contact"},
}};
std::string to_string(PlantEvent::Kind kind);  // "snap_through", "lost", "contact"

/// The plant as a camera frame sees it.
struct PlantFrame {
  double t = 0.0;                  // s
  Pose end_effector;               // the commanded end-effector pose the rod is held by
  BaseWrench base_wrench;          // n(0), m(0)
  RodConfiguration configuration;  // without derivatives
  /// The rod's base (clamp) pose, world_T_base: the fixed clamp, or where the base gripper holds
  /// it.
  Pose clamp{};
  /// The commanded base gripper pose (clamp · base_T_ee); with a fixed clamp, the clamp's pose.
  Pose base_end_effector{};
  /// The tip's twist [v; ω] (world frame, v the velocity of the tip's origin, m/s and rad/s) and
  /// each node's velocity (m/s). The quasi-static plant has no velocities of its own: drive_plant's
  /// are the backward differences of the held state over its sample step, (p − p_before) /
  /// (t − t_before), p_before the nodes at the sample before the held one (ω: log(R R_beforeᵀ) of
  /// the tip over the same step); zero while the path's first sample is held.
  Vector6d tip_twist = Vector6d::Zero();
  std::vector<Eigen::Vector3d> node_velocities;
};

struct PlantOptions {
  /// A step between samples releases energy when the gripper's work exceeds the rise of the elastic
  /// and load potential energy: more than energy_tolerance × the larger elastic energy (plus
  /// 1e-9 J) is a snap-through. On a followed path the balance holds to the trapezoid rule's
  /// O(Δ²) relative error (Δ the step over the rod's length: ~1e-6 at the paper's speeds).
  double energy_tolerance = 1e-3;
  /// Check the state's stability at every camera frame: a direct solve follows a branch past the
  /// point where it loses stability, the real rod snaps to a stable equilibrium (sought as
  /// seek_stable_equilibrium does; an event with the energy released). One stability test per
  /// frame (~0.2 ms on the band at N = 100).
  bool check_stability = true;
  /// Each sample's direct solve (continuation is not used past the start).
  ShootingOptions shooting;
  void validate() const;
};

/// The base end (s = 0) held by a moving gripper: its commanded poses (world_T_ee, at increasing
/// times; usually the tip path's times, sample for sample) and base_T_ee. The rod's clamp at time
/// t is path(t) · inverse(base_to_end_effector), path(t) the sample at t or, between samples, the
/// pose interpolated (line and slerp) between the two around it; past the ends the first or last.
/// An empty path is a fixed clamp at the rod's own `clamp`.
struct BaseGripperPath {
  Pose base_to_end_effector;  // base_T_ee (MovingBase::grasp.tip_to_end_effector)
  std::vector<TimedPose> path;
  bool moves() const { return !path.empty(); }
  /// The commanded base gripper pose at time t (path non-empty).
  Pose at(double t) const;
  /// The rod's clamp pose at time t: at(t) · inverse(base_to_end_effector).
  Pose clamp_at(double t) const;
};

/// Receives each camera frame as the plant reaches it. drive_plant() keeps no frame (a frame
/// holds the whole rod, some 15 kB at 101 nodes): what a caller needs of one, it takes here.
using PlantFrameSink = std::function<void(const PlantFrame&)>;

struct PlantRun {
  int frames = 0;  // frame times reached, each handed to the sink
  std::vector<PlantEvent> events;
  bool lost = false;  // a Lost event ended the run
  PlantFrame last;    // the last equilibrium (at the path's end unless lost)
  int solves = 0;     // samples solved
  std::string brief() const;
};

/// Drives `rod` (the real one) held by `grasp` (released axes, tip_T_ee) with the tip where
/// `grasp_offset` puts it in the commanded tip frame, along `path` (at least one sample), from the
/// equilibrium at path[0] solved from `guess`. Frames are taken at `frame_times` (increasing,
/// within the path's span; zero-order hold: the state of the last sample at or before each), each
/// handed to `on_frame` as it is reached.
PlantRun drive_plant(const ClampedRod& rod,
                     const Grasp& grasp,
                     const Pose& grasp_offset,
                     const std::vector<TimedPose>& path,
                     const BaseWrench& guess,
                     const std::vector<double>& frame_times,
                     const PlantFrameSink& on_frame,
                     const PlantOptions& options = {});

/// The same with the base end driven along `base` too: the plant is solved at every sample time
/// of `path` and of `base.path` (the union; the same when they share their times), the tip at
/// `path` and the clamp at `base` there (each interpolated between its own samples). With
/// `base.path` empty this is the call above, bit for bit. The energy balance counts both
/// grippers' work (the base gripper applies −n(0), −m(0) to the rod).
PlantRun drive_plant(const ClampedRod& rod,
                     const Grasp& grasp,
                     const Pose& grasp_offset,
                     const std::vector<TimedPose>& path,
                     const BaseGripperPath& base,
                     const BaseWrench& guess,
                     const std::vector<double>& frame_times,
                     const PlantFrameSink& on_frame,
                     const PlantOptions& options = {});

/// A commanded path's pose at time t: the sample at t, or the pose interpolated (line and slerp)
/// between the samples around it; before the first or past the last, that one (path non-empty).
Pose pose_at(const std::vector<TimedPose>& path, double t);

}  // namespace rodshape
