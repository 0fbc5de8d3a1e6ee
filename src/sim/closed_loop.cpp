// closed_loop.cpp: the driver of the closed loop: segment by segment along the controller's
// waypoints, a rest and an averaged measurement at each checkpoint (closed_loop.hpp).
#include "rodshape/sim/closed_loop.hpp"

#include "scene_contact.hpp"
#include "sensor_view.hpp"
#include "two_end_path.hpp"

#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <utility>

#include "rodshape/sim/commanded_path.hpp"
#include "rodshape/sim/quasi_static_plant.hpp"

namespace rodshape {

namespace {

/// The frame times of the global grid k / rate within (t0, t1], and t1 itself.
std::vector<double> frames_within(double t0, double t1, double rate, bool include_start) {
  std::vector<double> times;
  if (include_start) times.push_back(t0);
  for (double k = std::floor(t0 * rate) + 1.0; k / rate < t1; k += 1.0)
    if (k / rate > t0) times.push_back(k / rate);
  if (times.empty() || times.back() < t1) times.push_back(t1);
  return times;
}

class ClosedLoopDriver {
 public:
  ClosedLoopDriver(ShapeController controller,
                   Plant& plant,
                   const std::function<sim_detail::SensorView(const PlanProblem&)>& view)
      : controller_(std::move(controller)),
        problem_(controller_.problem()),
        plant_(plant),
        sensor_(view(problem_)),
        contact_(problem_.scene, plant.setup().rod.clamp.position) {}

  ClosedLoopRun run(const PlanResult& plan) {
    if (drives_joints(problem_, plan)) joints_ = plan.arm->joints.q.front();
    // With a moving base, both ends: the base from where the plan's base path starts.
    const std::vector<TimedPose> base_path = commanded_base_path(problem_, plan);
    if (!base_path.empty())
      base_from_ = plan.base_end_effector_path.empty() ? base_path.front().pose
                                                       : plan.base_end_effector_path.front().pose;
    if (base_from_ && drives_base_joints(problem_, plan))
      base_joints_ = plan.base_arm->joints.q.front();
    run_.base_moved = base_from_.has_value();
    Pose from = plan.end_effector_path.front().pose;
    plant_.reset({plan.initial_wrench});  // each segment from where the last left the plant
    double t = plan.end_effector_path.front().t;
    for (bool first = true;; first = false) {
      const PlannedWaypoint& next = controller_.remaining().front();
      const Pose to = next.end_effector;
      const std::optional<Pose> base_to =
          base_from_ ? std::optional<Pose>(next.base_end_effector) : std::nullopt;
      const PlantRun part = drive_segment(from, to, base_to, t, first);
      if (part.lost) break;
      from = to;
      if (base_to) base_from_ = base_to;
      t = part.last.t;
      if (controller_.remaining().size() == 1) break;  // the last waypoint
      dwell(t);
      run_.checkpoints.push_back(update(t, from));
    }
    run_.driven_by_joints = joints_.has_value();  // reset when a segment had no IK solution
    run_.base_driven_by_joints = base_joints_.has_value();
    run_.last_seen = sensor_.last_markers();
    run_.last_cloud = sensor_.last_cloud();
    run_.min_gap = contact_.min_gap();
    run_.plant.events.insert(run_.plant.events.end(), contact_.contacts().begin(),
                             contact_.contacts().end());
    return std::move(run_);
  }

 private:
  /// The plant from `from` to `to` (and the base from base_from_ to `base_to`, when it moves), its
  /// frames seen and their errors recorded.
  PlantRun drive_segment(
      const Pose& from, const Pose& to, const std::optional<Pose>& base_to, double t, bool first) {
    PlantDrive request;
    std::vector<TimedPose>& path = request.path;
    BaseGripperPath& base = request.base;
    if (base_to) {  // both ends on one clock
      sim_detail::TwoEndPath both = sim_detail::time_two_ends(
          {from, to}, {*base_from_, *base_to}, controller_.planning().end_effector,
          controller_.planning().base_end_effector);
      path = std::move(both.tip);
      base.path = std::move(both.base);
      base.base_to_end_effector = problem_.moving_base->grasp.tip_to_end_effector;
    } else {
      path = time_parameterize({from, to}, controller_.planning().end_effector);
    }
    for (TimedPose& sample : path) sample.t += t;
    for (TimedPose& sample : base.path) sample.t += t;
    if (joints_) path = hand_path(path, *problem_.arm, joints_, "arm");
    if (base_joints_)
      base.path = hand_path(base.path, *problem_.base_arm, base_joints_, "base arm");
    const double t_end = base.moves() ? std::max(path.back().t, base.path.back().t) : path.back().t;
    request.frame_times = frames_within(t, t_end, sensor_.frame_rate(), first);
    PlantRun part = plant_.drive(request, [&](const PlantFrame& frame) { see(frame); });
    append(part);
    return part;
  }

  /// One frame seen and its errors recorded; the frame itself is not kept (issue 24).
  void see(const PlantFrame& frame) {
    contact_.see(frame);
    std::vector<CapsuleObstacle> links;
    if (joints_ && sensor_.sees_cloud()) links = arm_link_capsules(*problem_.arm, *joints_);
    if (base_joints_ && sensor_.sees_cloud()) {
      const std::vector<CapsuleObstacle> base_links =
          arm_link_capsules(*problem_.base_arm, *base_joints_);
      links.insert(links.end(), base_links.begin(), base_links.end());
    }
    run_.times.push_back(frame.t);
    // The rod's first point is the clamp, where the base is held at this frame.
    run_.errors.push_back(sensor_.see(frame, problem_, frame.clamp.position, std::move(links)));
  }

  /// The rest's measurement handed to the controller at time `t`, the arm at `at` (and the base
  /// gripper at base_from_, when it moves); the checkpoint with what its estimate was made from
  /// and how far it is from the plant's rod.
  Checkpoint update(double t, const Pose& at) {
    const ArmState arm{at, base_from_};
    Checkpoint checkpoint;
    if (sensor_.sees_cloud()) {
      CloudMeasurement measurement = sensor_.rest_cloud();
      measurement.frame.t = t;
      checkpoint = controller_.update(measurement, arm).checkpoint;
      checkpoint.points = static_cast<int>(measurement.frame.points.size());
    } else {
      MarkerMeasurement measurement = sensor_.rest_markers();
      measurement.frame.t = t;
      checkpoint = controller_.update(measurement, arm).checkpoint;
      checkpoint.points = measurement.frame.visible();
    }
    checkpoint.shape_rms =
        centreline_rms(checkpoint.estimate.configuration, run_.plant.last.configuration);
    return checkpoint;
  }

  /// The segment as the hand of `arm` (the tip's or the base's, its joints `joints`) moves along
  /// it: IK at every sample, from the joints the arm has (joint_trajectory(), re-timed where the
  /// joints' velocity limits ask: the plant then takes each end at its own time), through the
  /// arm's FK.
  std::vector<TimedPose> hand_path(const std::vector<TimedPose>& path,
                                   const PlanArm& arm,
                                   std::optional<Eigen::VectorXd>& joints,
                                   const std::string& which) {
    JointTrajectoryOptions options = controller_.planning().arm.joints;
    options.seed = *joints;
    const JointTrajectoryResult trajectory =
        joint_trajectory(arm.model, path, arm.placement, options);
    if (trajectory.complete()) {
      joints = trajectory.q.back();
      return hand_poses(arm, trajectory);
    }
    joints.reset();
    if (!run_.checkpoints.empty())
      run_.checkpoints.back().message +=
          "; the " + which + " has no joint path to the next waypoint (" + trajectory.message +
          "): the rest is driven along the end-effector poses";
    return path;
  }

  void append(const PlantRun& part) {
    PlantRun& all = run_.plant;
    all.frames += part.frames;
    all.events.insert(all.events.end(), part.events.begin(), part.events.end());
    all.solves += part.solves;
    all.lost = part.lost;
    all.last = part.last;
  }

  /// The arm rests at the waypoint for checkpoint_frames frames (the plant held, its frames
  /// recorded with their errors), the sensor putting them together; `t` moves to the end of the
  /// rest.
  void dwell(double& t) {
    const int n = controller_.options().checkpoint_frames;
    const double rate = sensor_.frame_rate();
    std::vector<double> times;
    for (int k = 1; k < n; ++k) times.push_back(t + k / rate);
    sensor_.start_rest();
    t += (n - 1) / rate;
    append(plant_.hold(t, times, [&](const PlantFrame& frame) { see(frame); }));
  }

  ShapeController controller_;
  const PlanProblem& problem_;  // the controller's
  Plant& plant_;                // the real rod and grasp, which the controller does not know
  sim_detail::SensorView sensor_;
  std::optional<Eigen::VectorXd> joints_;       // the arm's joints at the last waypoint
  std::optional<Pose> base_from_;               // the base gripper's pose there (a moving base)
  std::optional<Eigen::VectorXd> base_joints_;  // the base arm's joints there
  sim_detail::SceneContact contact_;            // the plant against the plan's scene
  ClosedLoopRun run_;
};

}  // namespace

ClosedLoopRun run_closed_loop(const PlanResult& plan,
                              ShapeController controller,
                              Plant& plant,
                              MarkerSensor& sensor) {
  const double length = plant.setup().rod.properties.length;
  ClosedLoopDriver driver(std::move(controller), plant, [&](const PlanProblem&) {
    return sim_detail::SensorView(sensor, length);
  });
  return driver.run(plan);
}

ClosedLoopRun run_closed_loop(const PlanResult& plan,
                              ShapeController controller,
                              Plant& plant,
                              DepthCamera& camera) {
  ClosedLoopDriver driver(std::move(controller), plant, [&](const PlanProblem& problem) {
    return sim_detail::SensorView(camera, problem);
  });
  return driver.run(plan);
}

namespace {

QuasiStaticPlant quasi_static_of(const ClosedLoopPlant& plant, const ShapeController& controller) {
  return QuasiStaticPlant(
      {plant.rod, controller.problem().grasp, plant.grasp_offset, plant.options});
}

}  // namespace

ClosedLoopRun run_closed_loop(const PlanResult& plan,
                              ShapeController controller,
                              const ClosedLoopPlant& plant,
                              MarkerSensor& sensor) {
  QuasiStaticPlant real = quasi_static_of(plant, controller);
  return run_closed_loop(plan, std::move(controller), real, sensor);
}

ClosedLoopRun run_closed_loop(const PlanResult& plan,
                              ShapeController controller,
                              const ClosedLoopPlant& plant,
                              DepthCamera& camera) {
  QuasiStaticPlant real = quasi_static_of(plant, controller);
  return run_closed_loop(plan, std::move(controller), real, camera);
}

}  // namespace rodshape
