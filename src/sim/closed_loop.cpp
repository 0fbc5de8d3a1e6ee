// closed_loop.cpp: segment by segment along the waypoints, with an estimate and a re-plan at each
// checkpoint (closed_loop.hpp).
#include "rodshape/sim/closed_loop.hpp"

#include "scene_contact.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <string>

#include "closed_loop_beliefs.hpp"
#include "replan_gentleness.hpp"
#include "rodshape/error.hpp"
#include "rodshape/sim/commanded_path.hpp"
#include "rodshape/trajectory/plan.hpp"

namespace rodshape {

namespace {

using closed_loop_detail::planned_waypoint;

/// The frame times of the global grid k / rate within (t0, t1], and t1 itself.
std::vector<double> frames_within(double t0, double t1, double rate, bool include_start) {
  std::vector<double> times;
  if (include_start) times.push_back(t0);
  for (double k = std::floor(t0 * rate) + 1.0; k / rate < t1; k += 1.0)
    if (k / rate > t0) times.push_back(k / rate);
  if (times.empty() || times.back() < t1) times.push_back(t1);
  return times;
}

class Loop {
 public:
  Loop(const PlanProblem& problem,
       const PlanOptions& options,
       const ClampedRod& rod,
       const Pose& offset,
       MarkerSensor& sensor,
       const ClosedLoopOptions& loop,
       const PlantOptions& plant)
      : problem_(problem),
        options_(options),
        rod_(rod),
        plant_offset_(offset),
        sensor_(sensor),
        loop_(loop),
        plant_(plant),
        contact_(problem.scene, rod.clamp.position) {}

  ClosedLoopRun run(const PlanResult& plan) {
    if (drives_joints(problem_, plan)) joints_ = plan.arm->joints.q.front();
    if (plan.arm) shell_ = plan.arm->shell;
    for (const PlanStep& step : plan.steps) remaining_.push_back(planned_waypoint(step));
    fresh_ = static_cast<int>(plan.steps.size());
    Pose from = plan.end_effector_path.front().pose;
    BaseWrench w = plan.initial_wrench;
    double t = plan.end_effector_path.front().t;
    for (int waypoint = 1; !remaining_.empty(); ++waypoint) {
      const PlantRun part = drive_segment(from, w, t, waypoint == 1);
      if (part.lost) break;
      from = remaining_.front().end_effector;
      w = part.last.base_wrench;
      t = part.last.t;
      const BaseWrench planned = remaining_.front().wrench;
      remaining_.erase(remaining_.begin());
      fresh_ = std::max(0, fresh_ - 1);
      if (!remaining_.empty()) checkpoint(t, waypoint, from, planned);
    }
    run_.driven_by_joints = joints_.has_value();  // reset when a segment had no IK solution
    run_.min_gap = contact_.min_gap();
    run_.plant.events.insert(run_.plant.events.end(), contact_.contacts().begin(),
                             contact_.contacts().end());
    return std::move(run_);
  }

 private:
  /// The plant from `from` to the next waypoint, its frames seen and their errors recorded.
  PlantRun drive_segment(const Pose& from, const BaseWrench& w, double t, bool first) {
    std::vector<TimedPose> path =
        time_parameterize({from, remaining_.front().end_effector}, options_.end_effector);
    for (TimedPose& sample : path) sample.t += t;
    if (joints_) path = hand_path(path);
    const double rate = sensor_.model().frame_rate;
    PlantRun part = drive_plant(
        rod_, problem_.grasp, plant_offset_, path, w, frames_within(t, path.back().t, rate, first),
        [&](const PlantFrame& frame) { see(frame); }, plant_);
    append(part);
    return part;
  }

  /// One frame seen and its errors recorded; the frame itself is not kept (issue 24).
  void see(const PlantFrame& frame) {
    contact_.see(frame);
    run_.last_seen = sensor_.observe(frame, rod_.properties.length);
    run_.times.push_back(frame.t);
    run_.errors.push_back(shape_error(problem_.target.points, rod_.clamp.position, run_.last_seen,
                                      frame.configuration, sensor_.model().camera));
  }

  /// The segment as the hand moves along it: IK at every sample, from the joints the arm has
  /// (joint_trajectory(), re-timed where the joints' velocity limits ask), through the arm's FK.
  std::vector<TimedPose> hand_path(const std::vector<TimedPose>& path) {
    JointTrajectoryOptions options = options_.arm.joints;
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

  /// The arm rests at the waypoint for checkpoint_frames frames (recorded with their errors); the
  /// markers seen are averaged. Returns the averaged frame; `t` moves to the end of the rest.
  SensorFrame dwell(double& t) {
    const int n = loop_.checkpoint_frames;
    const double rate = sensor_.model().frame_rate;
    PlantFrame still = run_.plant.last;
    std::vector<Eigen::Vector3d> sum(run_.last_seen.markers.size(), Eigen::Vector3d::Zero());
    std::vector<int> count(sum.size(), 0);
    SensorFrame mean = run_.last_seen;
    for (int k = 0; k < n; ++k) {
      if (k > 0) {
        still.t = t + k / rate;
        see(still);
        ++run_.plant.frames;
      }
      const SensorFrame& seen = run_.last_seen;
      for (std::size_t j = 0; j < sum.size(); ++j)
        if (seen.markers[j]) {
          sum[j] += *seen.markers[j];
          ++count[j];
        }
    }
    for (std::size_t j = 0; j < sum.size(); ++j)
      mean.markers[j] =
          count[j] > 0 ? std::optional<Eigen::Vector3d>(sum[j] / count[j]) : std::nullopt;
    t += (n - 1) / rate;
    run_.plant.last.t = t;
    return mean;
  }

  /// Estimate from the frames at rest; re-plan the remaining steps from the estimate.
  void checkpoint(double& t, int waypoint, const Pose& end_effector, const BaseWrench& planned) {
    const SensorFrame seen = dwell(t);
    MarkerSensorModel averaged = sensor_.model();  // the weights of the averaged markers
    const double root_n = std::sqrt(static_cast<double>(loop_.checkpoint_frames));
    averaged.in_plane_noise /= root_n;
    averaged.depth_noise /= root_n;
    Checkpoint c;
    c.t = t;
    c.waypoint = waypoint;
    // The tip where the gripper is believed to hold it.
    const Pose commanded = compose(end_effector, inverse(problem_.grasp.tip_to_end_effector));
    c.estimate =
        estimate_state(problem_.rod, compose(commanded, beliefs_.fused.offset), end_effector, seen,
                       averaged, beliefs_.prior(planned), beliefs_.estimation(loop_, commanded),
                       beliefs_.hypothesis(planned));
    c.consistent = c.estimate.converged && c.estimate.residual <= loop_.max_residual;
    c.significant = c.consistent && significant(c.estimate);
    if (c.consistent && (c.significant || loop_.fuse)) beliefs_.take(c.estimate, commanded, loop_);
    if (c.significant) beliefs_.acting = beliefs_.fused;  // the rod is not as the plan believes
    c.grasp_offset = beliefs_.acting.offset;
    c.message = kept_message(c);
    if (loop_.replan && c.significant)
      replan(c, c.estimate.base_wrench);
    else if (loop_.replan && fresh_ == 0) {  // the next step was planned with other beliefs
      const std::string kept = c.message;
      replan(c, planned);
      c.message = kept +
                  "; the next step, made before the last correction, made again from the plan's "
                  "state: " +
                  c.message;
    }
    run_.checkpoints.push_back(std::move(c));
  }

  /// Why an estimate not acted on was not.
  std::string kept_message(const Checkpoint& c) const {
    if (c.significant) return "plan kept";
    if (!c.estimate.converged) return "plan kept: " + c.estimate.message;
    if (!c.consistent) {
      std::ostringstream out;
      out.precision(3);
      out << "plan kept: the model does not explain the markers (residual " << c.estimate.residual
          << " > max_residual " << loop_.max_residual << "); the estimate is not used";
      return out.str();
    }
    return "plan kept: the estimate is within the noise of the plan's state";
  }

  /// The fit's drop of χ² from the plan's state beyond k + significance · √(2k).
  bool significant(const StateEstimate& e) const {
    if (loop_.significance < 0.0) return true;
    const double k = e.parameters;
    return e.prior_chi2 - e.chi2 > k + loop_.significance * std::sqrt(2.0 * k);
  }

  /// The remaining steps made again from the equilibrium of `from` with the beliefs so far (the
  /// first `horizon` of them optimised; those are then fresh).
  void replan(Checkpoint& c, const BaseWrench& from) {
    PlanProblem rest = problem_;
    rest.rod = estimated_rod(problem_.rod, beliefs_.acting.stiffness_scale,
                             beliefs_.acting.load_factor, loop_.estimation.gravity);
    rest.initial = InitialState::equilibrium(from);
    // Commanded end-effector poses that put the real tip (commanded · offset) where the plan wants.
    rest.grasp.tip_to_end_effector =
        compose(inverse(beliefs_.acting.offset), problem_.grasp.tip_to_end_effector);
    // The arm's own planning (its reach, IK checks and joints) is not re-run; its reach shell is
    // kept in the workspace, and each segment's joints are solved as the arm gets there.
    rest.arm.reset();
    if (shell_) rest.workspace.reach = shell_;
    PlanOptions options = options_;
    options.steps = static_cast<int>(remaining_.size());
    options.horizon = std::min(loop_.horizon, options.steps);
    options.track_between_waypoints = false;
    try {
      const PlanResult again = plan(rest, options);
      c.message = again.brief(options.steps);
      if (again.status != PlanStatus::Complete) return;
      if (const std::string coiled = closed_loop_detail::not_gentle(
              again.steps, again.initial_configuration.energy, remaining_, loop_.max_energy_ratio);
          !coiled.empty()) {
        c.message = "plan kept: " + coiled + " (" + c.message + ")";
        return;
      }
      // The first steps re-planned; those beyond the re-plan's horizon are kept until their turn.
      for (std::size_t k = 0; k < again.steps.size() && k < remaining_.size(); ++k)
        remaining_[k] = planned_waypoint(again.steps[k]);
      fresh_ = static_cast<int>(again.steps.size());
      c.replanned = true;
    } catch (const InputError& error) {
      c.message = std::string("plan kept: the re-plan was refused: ") + error.what();
    }
  }

  const PlanProblem& problem_;
  const PlanOptions& options_;
  const ClampedRod& rod_;
  const Pose& plant_offset_;  // the real one, which the plant has and the loop does not know
  MarkerSensor& sensor_;
  const ClosedLoopOptions& loop_;
  const PlantOptions& plant_;
  std::vector<closed_loop_detail::PlannedWaypoint> remaining_;  // the waypoints still ahead
  /// How many of the remaining steps were planned with the beliefs held now (the rest were made
  /// before the last correction, beyond a re-plan's horizon).
  int fresh_ = 0;
  std::optional<Eigen::VectorXd> joints_;       // the arm's joints at the last waypoint
  std::optional<Workspace::ReachShell> shell_;  // the plan's reach shell
  closed_loop_detail::Beliefs beliefs_;  // the model's corrections and the grasp offset so far
  sim_detail::SceneContact contact_;     // the plant against the plan's scene
  ClosedLoopRun run_;
};

}  // namespace

void ClosedLoopOptions::validate() const {
  estimation.validate();
  if (!std::isfinite(significance))
    throw InputError("ClosedLoopOptions.significance", " must be finite");
  if (!(max_residual > 0.0) || !std::isfinite(max_residual))
    throw InputError("ClosedLoopOptions.max_residual", " must be finite and > 0");
  if (!(max_energy_ratio >= 1.0) || !std::isfinite(max_energy_ratio))
    throw InputError("ClosedLoopOptions.max_energy_ratio", " must be finite and >= 1");
  if (horizon < 0 || horizon > PlanOptions::kMaxSteps)
    throw InputError("ClosedLoopOptions.horizon", " = " + std::to_string(horizon) +
                                                      " must be in [0, " +
                                                      std::to_string(PlanOptions::kMaxSteps) + "]");
  if (checkpoint_frames < 1 || checkpoint_frames > 1000)
    throw InputError("ClosedLoopOptions.checkpoint_frames",
                     " = " + std::to_string(checkpoint_frames) + " must be in [1, 1000]");
  if (!(grasp_offset_position_sigma > 0.0) || !std::isfinite(grasp_offset_position_sigma))
    throw InputError("ClosedLoopOptions.grasp_offset_position_sigma", " must be finite and > 0");
  if (!(grasp_offset_rotation_sigma > 0.0) || !std::isfinite(grasp_offset_rotation_sigma))
    throw InputError("ClosedLoopOptions.grasp_offset_rotation_sigma", " must be finite and > 0");
}

ClosedLoopRun run_closed_loop(const PlanProblem& problem,
                              const PlanOptions& options,
                              const PlanResult& plan,
                              const ClampedRod& rod,
                              const Pose& grasp_offset,
                              MarkerSensor& sensor,
                              const ClosedLoopOptions& loop,
                              const PlantOptions& plant_options) {
  loop.validate();
  if (plan.end_effector_path.empty() || plan.steps.empty())
    throw InputError("PlanResult.steps", ": the plan has no step to carry out");
  Loop runner(problem, options, rod, grasp_offset, sensor, loop, plant_options);
  return runner.run(plan);
}

}  // namespace rodshape
