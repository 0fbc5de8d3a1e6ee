// closed_loop.cpp: the driver of the closed loop: segment by segment along the controller's
// waypoints, a rest and an averaged measurement at each checkpoint (closed_loop.hpp).
#include "rodshape/sim/closed_loop.hpp"

#include "scene_contact.hpp"
#include "sensor_view.hpp"

#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <utility>

#include "rodshape/sim/commanded_path.hpp"

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

class Driver {
 public:
  Driver(ShapeController controller,
         const ClosedLoopPlant& plant,
         const std::function<sim_detail::SensorView(const PlanProblem&)>& view)
      : controller_(std::move(controller)),
        problem_(controller_.problem()),
        plant_(plant),
        sensor_(view(problem_)),
        contact_(problem_.scene, plant.rod.clamp.position) {}

  ClosedLoopRun run(const PlanResult& plan) {
    if (drives_joints(problem_, plan)) joints_ = plan.arm->joints.q.front();
    Pose from = plan.end_effector_path.front().pose;
    BaseWrench w = plan.initial_wrench;
    double t = plan.end_effector_path.front().t;
    for (bool first = true;; first = false) {
      const Pose to = controller_.remaining().front().end_effector;
      const PlantRun part = drive_segment(from, to, w, t, first);
      if (part.lost) break;
      from = to;
      w = part.last.base_wrench;
      t = part.last.t;
      if (controller_.remaining().size() == 1) break;  // the last waypoint
      dwell(t);
      run_.checkpoints.push_back(update(t, from));
    }
    run_.driven_by_joints = joints_.has_value();  // reset when a segment had no IK solution
    run_.last_seen = sensor_.last_markers();
    run_.last_cloud = sensor_.last_cloud();
    run_.min_gap = contact_.min_gap();
    run_.plant.events.insert(run_.plant.events.end(), contact_.contacts().begin(),
                             contact_.contacts().end());
    return std::move(run_);
  }

 private:
  /// The plant from `from` to `to`, its frames seen and their errors recorded.
  PlantRun drive_segment(
      const Pose& from, const Pose& to, const BaseWrench& w, double t, bool first) {
    std::vector<TimedPose> path =
        time_parameterize({from, to}, controller_.planning().end_effector);
    for (TimedPose& sample : path) sample.t += t;
    if (joints_) path = hand_path(path);
    const double rate = sensor_.frame_rate();
    PlantRun part = drive_plant(
        plant_.rod, problem_.grasp, plant_.grasp_offset, path, w,
        frames_within(t, path.back().t, rate, first), [&](const PlantFrame& frame) { see(frame); },
        plant_.options);
    append(part);
    return part;
  }

  /// One frame seen and its errors recorded; the frame itself is not kept (issue 24).
  void see(const PlantFrame& frame) {
    contact_.see(frame);
    std::vector<CapsuleObstacle> links;
    if (joints_ && sensor_.sees_cloud()) links = arm_link_capsules(*problem_.arm, *joints_);
    run_.times.push_back(frame.t);
    run_.errors.push_back(
        sensor_.see(frame, problem_, plant_.rod.clamp.position, std::move(links)));
  }

  /// The rest's measurement handed to the controller at time `t`, the arm at `at`; the
  /// checkpoint with what its estimate was made from and how far it is from the plant's rod.
  Checkpoint update(double t, const Pose& at) {
    Checkpoint checkpoint;
    if (sensor_.sees_cloud()) {
      CloudMeasurement measurement = sensor_.rest_cloud();
      measurement.frame.t = t;
      checkpoint = controller_.update(measurement, {at}).checkpoint;
      checkpoint.points = static_cast<int>(measurement.frame.points.size());
    } else {
      MarkerMeasurement measurement = sensor_.rest_markers();
      measurement.frame.t = t;
      checkpoint = controller_.update(measurement, {at}).checkpoint;
      checkpoint.points = measurement.frame.visible();
    }
    checkpoint.shape_rms =
        centreline_rms(checkpoint.estimate.configuration, run_.plant.last.configuration);
    return checkpoint;
  }

  /// The segment as the hand moves along it: IK at every sample, from the joints the arm has
  /// (joint_trajectory(), re-timed where the joints' velocity limits ask), through the arm's FK.
  std::vector<TimedPose> hand_path(const std::vector<TimedPose>& path) {
    JointTrajectoryOptions options = controller_.planning().arm.joints;
    options.seed = *joints_;
    const PlanArm& arm = *problem_.arm;
    const JointTrajectoryResult trajectory =
        joint_trajectory(arm.model, path, arm.placement, options);
    if (trajectory.complete()) {
      joints_ = trajectory.q.back();
      return hand_poses(arm, trajectory);
    }
    joints_.reset();
    if (!run_.checkpoints.empty())
      run_.checkpoints.back().message += "; the arm has no joint path to the next waypoint (" +
                                         trajectory.message +
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

  /// The arm rests at the waypoint for checkpoint_frames frames (recorded with their errors), the
  /// sensor putting them together; `t` moves to the end of the rest.
  void dwell(double& t) {
    const int n = controller_.options().checkpoint_frames;
    const double rate = sensor_.frame_rate();
    PlantFrame still = run_.plant.last;
    sensor_.start_rest();
    for (int k = 1; k < n; ++k) {
      still.t = t + k / rate;
      see(still);
      ++run_.plant.frames;
    }
    t += (n - 1) / rate;
    run_.plant.last.t = t;
  }

  ShapeController controller_;
  const PlanProblem& problem_;    // the controller's
  const ClosedLoopPlant& plant_;  // the real rod and grasp, which the controller does not know
  sim_detail::SensorView sensor_;
  std::optional<Eigen::VectorXd> joints_;  // the arm's joints at the last waypoint
  sim_detail::SceneContact contact_;       // the plant against the plan's scene
  ClosedLoopRun run_;
};

}  // namespace

ClosedLoopRun run_closed_loop(const PlanResult& plan,
                              ShapeController controller,
                              const ClosedLoopPlant& plant,
                              MarkerSensor& sensor) {
  const double length = plant.rod.properties.length;
  Driver driver(std::move(controller), plant,
                [&](const PlanProblem&) { return sim_detail::SensorView(sensor, length); });
  return driver.run(plan);
}

ClosedLoopRun run_closed_loop(const PlanResult& plan,
                              ShapeController controller,
                              const ClosedLoopPlant& plant,
                              DepthCamera& camera) {
  Driver driver(std::move(controller), plant, [&](const PlanProblem& problem) {
    return sim_detail::SensorView(camera, problem);
  });
  return driver.run(plan);
}

}  // namespace rodshape
