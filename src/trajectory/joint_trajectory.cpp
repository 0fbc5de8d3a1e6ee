// joint_trajectory.cpp: IK along a timed end-effector path, finite-difference velocities and the
// re-timing that keeps them within the joint velocity limits (see joint_trajectory.hpp).
#include "rodshape/trajectory/joint_trajectory.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "rodshape/error.hpp"

namespace rodshape {

namespace {

std::string describe_pose(const Pose& pose) {
  std::ostringstream out;
  out.precision(6);
  const Eigen::Vector4d q = pose.quaternion_wxyz();
  out << "position [" << pose.position.x() << ", " << pose.position.y() << ", " << pose.position.z()
      << "] m, rotation [" << q[0] << ", " << q[1] << ", " << q[2] << ", " << q[3] << "]";
  return out.str();
}

/// Finite-difference velocities: central inside, one-sided at the ends; zero for a single sample.
std::vector<Eigen::VectorXd> differentiate(const std::vector<double>& t,
                                           const std::vector<Eigen::VectorXd>& q) {
  const std::size_t n = q.size();
  std::vector<Eigen::VectorXd> qdot(n);
  if (n == 1) qdot[0] = Eigen::VectorXd::Zero(q[0].size());
  for (std::size_t i = 0; n > 1 && i < n; ++i) {
    const std::size_t before = i == 0 ? 0 : i - 1;
    const std::size_t after = i + 1 == n ? n - 1 : i + 1;
    qdot[i] = (q[after] - q[before]) / (t[after] - t[before]);
  }
  return qdot;
}

/// The least time the step from q0 to q1 takes within the joint velocity limits:
/// max_j |Δq_j| / v_lim,j (an infinite limit needs no time).
double needed_time(const Eigen::VectorXd& limits,
                   const Eigen::VectorXd& q0,
                   const Eigen::VectorXd& q1) {
  const Eigen::VectorXd step = (q1 - q0).cwiseAbs();
  double needed = 0.0;
  for (Eigen::Index j = 0; j < step.size(); ++j) {
    if (std::isfinite(limits(j))) needed = std::max(needed, step(j) / limits(j));
  }
  return needed;
}

}  // namespace

std::string to_string(JointTrajectoryStatus status) {
  return std::string(name_of(kJointTrajectoryStatusNames, status));
}

Eigen::VectorXd JointTrajectoryOptions::first_seed(const ArmModel& arm) const {
  return seed.size() > 0 ? seed : default_seed(arm);
}

JointTrajectoryResult joint_trajectory(const ArmModel& arm,
                                       const std::vector<TimedPose>& path,
                                       const ArmPlacement& placement,
                                       const JointTrajectoryOptions& options) {
  options.ik.validate();
  Eigen::VectorXd seed = options.first_seed(arm);
  arm.check_joint_positions(seed, "seed");

  JointTrajectoryResult result;
  result.joint_names = arm.joint_names();
  if (path.empty()) {
    result.message = "the end-effector path is empty";
    return result;
  }
  result.path_duration = path.back().t - path.front().t;

  // Positions, sample by sample, each IK seeded from the last solution.
  for (std::size_t i = 0; i < path.size(); ++i) {
    const TimedPose& sample = path[i];
    if (!std::isfinite(sample.t) || (i > 0 && !(sample.t > path[i - 1].t)))
      throw InputError("joint_trajectory: the path's sample times must be finite and increasing");
    IkClearance clearance;
    if (options.clearance) {
      clearance.clearance = options.clearance.get();
      clearance.influence = options.clearance_influence;
      if (!options.rods.empty()) {
        const int last = static_cast<int>(options.rods.size()) - 1;
        const int to = std::clamp(
            i < options.sample_waypoint.size() ? options.sample_waypoint[i] : last, 0, last);
        clearance.rods = {&options.rods[static_cast<std::size_t>(std::max(to - 1, 0))],
                          &options.rods[static_cast<std::size_t>(to)]};
      }
      if (i < options.others.size() && !options.others[i].empty())
        clearance.others = &options.others[i];
    }
    const IkResult ik =
        solve_ik(arm, flange_target(placement, sample.pose), seed, options.ik, clearance);
    if (!ik.converged()) {
      std::ostringstream message;
      message.precision(6);
      message << "no inverse kinematics solution at t = " << sample.t << " s (sample " << i
              << ") for the end-effector pose " << describe_pose(sample.pose) << ": " << ik.message;
      result.status = JointTrajectoryStatus::Unreachable;
      result.message = message.str();
      result.failed_sample = static_cast<int>(i);
      return result;
    }
    if (ik.restarts > 0) ++result.ik_restarts;
    if (options.clearance) {
      result.clearance_steps += ik.clearance_steps;
      const LinkGap gap = options.clearance->least_gap(ik.q, clearance.rods);
      if (gap.capsule >= 0 && gap.margin < result.link_gap.margin) {
        result.link_gap = gap;
        result.link_gap_sample = static_cast<int>(i);
      }
    }
    result.max_position_error = std::max(result.max_position_error, ik.position_error);
    result.max_rotation_error = std::max(result.max_rotation_error, ik.rotation_error);
    result.t.push_back(sample.t);
    result.q.push_back(ik.q);
    seed = ik.q;
  }

  // Re-timing: stretch every segment that is faster than the velocity limits allow.
  const Eigen::VectorXd limits = arm.velocity_limits();
  std::vector<double> retimed(result.t.size());
  retimed[0] = result.t[0];
  for (std::size_t i = 0; i + 1 < result.t.size(); ++i) {
    const double dt = result.t[i + 1] - result.t[i];
    const double needed = needed_time(limits, result.q[i], result.q[i + 1]);
    const bool too_fast = needed > dt;
    if (too_fast) result.slowed = true;
    retimed[i + 1] = retimed[i] + (too_fast ? needed : dt);
  }
  if (result.slowed) {
    result.t = std::move(retimed);
    if (result.path_duration > 0.0) result.slowdown = result.duration() / result.path_duration;
  }
  result.qdot = differentiate(result.t, result.q);
  result.status = JointTrajectoryStatus::Complete;
  return result;
}

void retime_together(const ArmModel& arm_a,
                     JointTrajectoryResult& a,
                     const ArmModel& arm_b,
                     JointTrajectoryResult& b,
                     const std::vector<double>& path_t) {
  if (!a.complete() || !b.complete() || a.q.size() != path_t.size() || b.q.size() != path_t.size())
    throw InputError("retime_together: two complete joint trajectories of " +
                     std::to_string(path_t.size()) + " samples each are needed, got " +
                     std::to_string(a.q.size()) + " (" + to_string(a.status) + ") and " +
                     std::to_string(b.q.size()) + " (" + to_string(b.status) + ")");
  const Eigen::VectorXd limits_a = arm_a.velocity_limits();
  const Eigen::VectorXd limits_b = arm_b.velocity_limits();
  std::vector<double> t(path_t.size());
  t[0] = path_t[0];
  bool slowed = false;
  for (std::size_t i = 0; i + 1 < path_t.size(); ++i) {
    const double dt = path_t[i + 1] - path_t[i];
    const double needed = std::max(needed_time(limits_a, a.q[i], a.q[i + 1]),
                                   needed_time(limits_b, b.q[i], b.q[i + 1]));
    const bool too_fast = needed > dt;
    if (too_fast) slowed = true;
    t[i + 1] = t[i] + (too_fast ? needed : dt);
  }
  for (JointTrajectoryResult* result : {&a, &b}) {
    result->t = t;
    result->slowed = slowed;
    result->slowdown =
        slowed && result->path_duration > 0.0 ? result->duration() / result->path_duration : 1.0;
    result->qdot = differentiate(result->t, result->q);
  }
}

std::string JointTrajectoryResult::brief() const {
  if (!complete()) return to_string(status) + ": " + message;
  std::ostringstream out;
  out.precision(3);
  out << "complete: " << t.size() << " samples over " << duration() << " s";
  if (slowed) out << " (slowed ×" << slowdown << ")";
  return out.str();
}

}  // namespace rodshape
