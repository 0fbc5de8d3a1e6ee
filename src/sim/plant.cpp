// plant.cpp: the real rod followed sample by sample along the commanded path (drive_plant), with
// the energy balance that tells a snap-through from a followed step.
#include "rodshape/sim/plant.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/core/so3.hpp"
#include "rodshape/error.hpp"
#include "rodshape/solvers/stability.hpp"
#include "rodshape/solvers/stable_equilibrium.hpp"
#include "rodshape/solvers/tip_condition.hpp"
#include "validation.hpp"

namespace rodshape {

namespace {

/// The tip condition at a commanded end-effector pose: world_T_tip = world_T_ee · ee_T_tip ·
/// commanded_T_actual, held as the grasp holds it.
TipCondition held_at(const Pose& end_effector, const Grasp& grasp, const Pose& grasp_offset) {
  const Pose tip = compose(compose(end_effector, inverse(grasp.tip_to_end_effector)), grasp_offset);
  if (std::none_of(grasp.released.begin(), grasp.released.end(), [](bool r) { return r; }))
    return ClampedTip{tip};
  return GraspedTip{tip, grasp.released};
}

/// The distributed load's potential, U = -∫ f·p ds (trapezoid over the nodes; f constant).
double load_potential(const ClampedRod& rod, const RodConfiguration& c) {
  if (rod.load.force.isZero()) return 0.0;
  Eigen::Vector3d integral = Eigen::Vector3d::Zero();
  for (int i = 0; i + 1 < c.nodes(); ++i)
    integral += 0.5 * (c.s[i + 1] - c.s[i]) * (c.p[i] + c.p[i + 1]);
  return -rod.load.force.dot(integral);
}

/// Energy released between two equilibria a → b: the grippers' work (trapezoid in the tip's
/// wrench n(L), m(L) over the tip's displacement and world-frame rotation, and with a moving base
/// the clamp's −n(0), −m(0) over the base's) minus the rise of the elastic and load potential
/// energy. ≈ 0 on a followed path, > 0 where the rod snapped.
double energy_released(const ClampedRod& rod,
                       const RodConfiguration& a,
                       const RodConfiguration& b,
                       bool base_moves) {
  const Pose pa = a.tip(), pb = b.tip();
  const Wrench wa = a.tip_wrench(), wb = b.tip_wrench();
  const Eigen::Vector3d rotation = log_so3(pb.rotation * pa.rotation.transpose());
  double work = 0.5 * (wa.force + wb.force).dot(pb.position - pa.position) +
                0.5 * (wa.moment + wb.moment).dot(rotation);
  if (base_moves) {  // the clamp applies −n(0), −m(0) to the rod
    const Eigen::Vector3d turn = log_so3(b.R.front() * a.R.front().transpose());
    work -= 0.5 * (a.n.front() + b.n.front()).dot(b.p.front() - a.p.front()) +
            0.5 * (a.m.front() + b.m.front()).dot(turn);
  }
  return work - (b.energy - a.energy) - (load_potential(rod, b) - load_potential(rod, a));
}

/// One sample of the drive: the time, the commanded tip end-effector pose and, with a moving base,
/// the commanded base gripper pose.
struct DriveSample {
  double t = 0.0;
  Pose end_effector;
  Pose base_end_effector;
};

}  // namespace

Pose pose_at(const std::vector<TimedPose>& path, double t) {
  if (path.empty()) throw InputError("path", ": the commanded path has no sample");
  const auto after = std::upper_bound(path.begin(), path.end(), t,
                                      [](double x, const TimedPose& p) { return x < p.t; });
  if (after == path.begin()) return path.front().pose;
  const TimedPose& a = *(after - 1);
  if (after == path.end() || a.t == t) return a.pose;
  const TimedPose& b = *after;
  return interpolate(a.pose, b.pose, (t - a.t) / (b.t - a.t));
}

Pose BaseGripperPath::at(double t) const { return pose_at(path, t); }

Pose BaseGripperPath::clamp_at(double t) const {
  return compose(at(t), inverse(base_to_end_effector));
}

std::string to_string(PlantEvent::Kind kind) {
  return std::string(name_of(kPlantEventKindNames, kind, "lost"));
}

void PlantOptions::validate() const {
  detail::require_positive("PlantOptions.energy_tolerance", energy_tolerance);
}

std::string PlantRun::brief() const {
  std::ostringstream out;
  out.precision(3);
  out << (lost ? "lost at t = " + std::to_string(last.t) + " s" : "followed the path") << "; "
      << frames << " frames, " << solves << " solves, " << events.size() << " events";
  return out.str();
}

namespace {

/// The run's state between samples: the last equilibrium and the pose that holds it.
class Driver {
 public:
  Driver(const ClampedRod& rod,
         const Grasp& grasp,
         const Pose& grasp_offset,
         const BaseGripperPath& base,
         const std::vector<double>& frame_times,
         const PlantFrameSink& on_frame,
         const PlantOptions& options)
      : rod_(rod),
        rod_now_(rod),
        base_(base),
        grasp_(grasp),
        offset_(grasp_offset),
        frames_(frame_times),
        on_frame_(on_frame),
        options_(options) {
    direct_ = options.shooting;
    direct_.output_derivatives = Derivatives::None;
    base_held_by_ = rod.clamp;
  }

  /// The equilibrium at the path's start, solved from `guess` with continuation.
  bool start(const DriveSample& sample, const BaseWrench& guess) {
    move_base(sample);
    state_ = solve(sample.end_effector, guess, true);
    held_by_ = sample.end_effector;
    held_t_ = sample.t;
    if (state_.summary.converged()) return true;
    lose(sample.t,
         "the real rod has no equilibrium at the path's start (" + state_.summary.brief() + ")");
    return false;
  }

  /// The next sample, solved directly from the last equilibrium; false when it is lost.
  bool advance(const DriveSample& sample) {
    emit_frames_before(sample.t, false);
    if (run_.lost) return false;  // unstable, and no stable equilibrium to snap to
    const Pose clamp_before = rod_now_.clamp;
    const Pose base_before = base_held_by_;
    BaseWrench from = state_.base_wrench;
    if (base_.moves()) {
      // The warm start turns with the base: the world wrench rotated by the clamp's ΔR, exact for
      // a rigid motion of both ends, so the rod stays on its branch.
      move_base(sample);
      const Eigen::Matrix3d turn = rod_now_.clamp.rotation * clamp_before.rotation.transpose();
      from.force = turn * from.force;
      from.moment = turn * from.moment;
    }
    ShootingResult next = solve(sample.end_effector, from, false);
    if (!next.summary.converged()) {
      rod_now_.clamp = clamp_before;  // the state stays where it was held
      base_held_by_ = base_before;
      lose(sample.t, "no equilibrium found at t = " + detail::format_value(sample.t) + " s (" +
                         next.summary.brief() + ")");
      return false;
    }
    check_snap(sample.t, next.configuration);
    before_p_ = std::move(state_.configuration.p);  // the sample before, for the velocities
    before_tip_rotation_ = state_.configuration.R.back();
    before_t_ = held_t_;
    state_ = std::move(next);
    held_by_ = sample.end_effector;
    held_t_ = sample.t;
    return true;
  }

  PlantRun finish(double t_end) {
    if (!run_.lost) emit_frames_before(t_end, true);
    run_.last = frame_at(run_.lost ? run_.events.back().t : t_end);
    return std::move(run_);
  }

 private:
  /// The rod's clamp where the base gripper holds it at this sample (a moving base only).
  void move_base(const DriveSample& sample) {
    if (!base_.moves()) return;
    base_held_by_ = sample.base_end_effector;
    rod_now_.clamp = compose(sample.base_end_effector, inverse(base_.base_to_end_effector));
  }

  PlantFrame frame_at(double t) const {
    PlantFrame frame;
    frame.t = t;
    frame.end_effector = held_by_;
    frame.base_wrench = state_.base_wrench;
    frame.configuration = state_.configuration;
    frame.clamp = rod_now_.clamp;
    frame.base_end_effector = base_held_by_;
    set_velocities(frame);
    return frame;
  }

  /// The frame's velocities: the held state's backward difference over its sample step (zero
  /// while the first sample is held).
  void set_velocities(PlantFrame& frame) const {
    const std::vector<Eigen::Vector3d>& p = frame.configuration.p;
    frame.node_velocities.assign(p.size(), Eigen::Vector3d::Zero());
    if (p.empty() || before_p_.size() != p.size() || !(held_t_ > before_t_)) return;
    const double dt = held_t_ - before_t_;
    for (std::size_t i = 0; i < p.size(); ++i)
      frame.node_velocities[i] = (p[i] - before_p_[i]) / dt;
    frame.tip_twist << frame.node_velocities.back(),
        log_so3(frame.configuration.R.back() * before_tip_rotation_.transpose()) / dt;
  }

  ShootingResult solve(const Pose& end_effector, const BaseWrench& from, bool continuation) {
    ShootingOptions options = direct_;
    options.continuation = continuation;  // past the start: each sample from the last
    ++run_.solves;
    return solve_equilibrium(rod_now_, held_at(end_effector, grasp_, offset_), from, options);
  }

  void check_snap(double t, const RodConfiguration& next) {
    const double released = energy_released(rod_, state_.configuration, next, base_.moves());
    const double scale = std::max(state_.configuration.energy, next.energy);
    if (released <= options_.energy_tolerance * scale + 1e-9) return;
    run_.events.push_back(
        {PlantEvent::Kind::SnapThrough, t, released,
         "the rod snapped to another equilibrium at t = " + detail::format_value(t) +
             " s, releasing " + detail::format_value(released) + " J"});
  }

  void lose(double t, const std::string& message) {
    run_.lost = true;
    run_.events.push_back({PlantEvent::Kind::Lost, t, 0.0, message});
  }

  /// Frames up to t_end (zero-order hold: the state of the last sample at or before each), after
  /// the state's stability is checked.
  void emit_frames_before(double t_end, bool inclusive) {
    const auto due = [&] {
      return next_frame_ < frames_.size() &&
             (frames_[next_frame_] < t_end || (inclusive && frames_[next_frame_] <= t_end));
    };
    if (due() && options_.check_stability) settle(frames_[next_frame_]);
    while (!run_.lost && due()) {  // handed on, not kept (issue 24: memory per frame)
      if (on_frame_) on_frame_(frame_at(frames_[next_frame_]));
      ++next_frame_;
      ++run_.frames;
    }
  }

  /// A direct solve follows an equilibrium branch past the point where it loses stability; the real
  /// rod does not: it snaps to a stable equilibrium with the same ends (seek_stable_equilibrium).
  void settle(double t) {
    ClampedRod at = rod_now_;
    at.substeps = state_.summary.substeps;
    state_.configuration = integrate(at, state_.base_wrench, Derivatives::AllNodes);
    const TipCondition tip = held_at(held_by_, grasp_, offset_);
    const StabilityResult verdict = assess_stability(at, state_.configuration, tip);
    if (verdict.stable || verdict.degenerate) return;
    StableEquilibriumResult found =
        seek_stable_equilibrium(rod_now_, tip, state_, verdict, direct_);
    if (!found.found) {
      lose(t, "the rod's equilibrium is unstable at t = " + detail::format_value(t) +
                  " s and no stable one was found (" + found.message + ")");
      return;
    }
    const double released = state_.configuration.energy - found.solution.configuration.energy +
                            load_potential(rod_, state_.configuration) -
                            load_potential(rod_, found.solution.configuration);
    run_.events.push_back(
        {PlantEvent::Kind::SnapThrough, t, released,
         "the rod's equilibrium became unstable; by t = " + detail::format_value(t) +
             " s it snapped to a stable one, releasing " + detail::format_value(released) + " J"});
    state_ = std::move(found.solution);
  }

  const ClampedRod& rod_;
  ClampedRod rod_now_;  // the rod with its clamp where the base is held now
  const BaseGripperPath& base_;
  const Grasp& grasp_;
  const Pose& offset_;
  const std::vector<double>& frames_;
  const PlantFrameSink& on_frame_;
  const PlantOptions& options_;
  ShootingOptions direct_;
  ShootingResult state_;
  Pose held_by_;
  double held_t_ = 0.0;  // the held state's sample time
  // The nodes and the tip's rotation at the sample before the held one (none at the first).
  std::vector<Eigen::Vector3d> before_p_;
  Eigen::Matrix3d before_tip_rotation_ = Eigen::Matrix3d::Identity();
  double before_t_ = 0.0;
  Pose base_held_by_;  // the base gripper's commanded pose (the clamp's with a fixed clamp)
  std::size_t next_frame_ = 0;
  PlantRun run_;
};

}  // namespace

namespace {

/// The times of the drive's samples with a moving base: every time of either path (merged in
/// order, equal times once). (With a fixed clamp the tip path's own samples are driven.)
std::vector<double> drive_times(const std::vector<TimedPose>& path, const BaseGripperPath& base) {
  std::vector<double> times;
  times.reserve(path.size() + base.path.size());
  for (const TimedPose& p : path) times.push_back(p.t);
  for (const TimedPose& p : base.path) times.push_back(p.t);
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  return times;
}

}  // namespace

PlantRun drive_plant(const ClampedRod& rod,
                     const Grasp& grasp,
                     const Pose& grasp_offset,
                     const std::vector<TimedPose>& path,
                     const BaseGripperPath& base,
                     const BaseWrench& guess,
                     const std::vector<double>& frame_times,
                     const PlantFrameSink& on_frame,
                     const PlantOptions& options) {
  options.validate();
  rod.validate();
  if (path.empty()) throw InputError("path", ": the commanded path has no sample");
  if (!std::is_sorted(frame_times.begin(), frame_times.end()))
    throw InputError("frame_times", ": must be increasing");
  if (!std::is_sorted(base.path.begin(), base.path.end(),
                      [](const TimedPose& a, const TimedPose& b) { return a.t < b.t; }))
    throw InputError("BaseGripperPath.path", ": its times must be increasing");
  if (base.moves())
    detail::require_pose("BaseGripperPath.base_to_end_effector", base.base_to_end_effector);
  Driver driver(rod, grasp, grasp_offset, base, frame_times, on_frame, options);
  if (!base.moves()) {  // the tip path's samples, as they are
    const auto sample = [&](std::size_t k) { return DriveSample{path[k].t, path[k].pose, {}}; };
    if (driver.start(sample(0), guess))
      for (std::size_t k = 1; k < path.size() && driver.advance(sample(k)); ++k) {
      }
    return driver.finish(path.back().t);
  }
  // Each end at its own path's pose at every time of either.
  const std::vector<double> times = drive_times(path, base);
  const auto sample = [&](std::size_t k) {
    return DriveSample{times[k], pose_at(path, times[k]), base.at(times[k])};
  };
  if (driver.start(sample(0), guess))
    for (std::size_t k = 1; k < times.size() && driver.advance(sample(k)); ++k) {
    }
  return driver.finish(times.back());
}

PlantRun drive_plant(const ClampedRod& rod,
                     const Grasp& grasp,
                     const Pose& grasp_offset,
                     const std::vector<TimedPose>& path,
                     const BaseWrench& guess,
                     const std::vector<double>& frame_times,
                     const PlantFrameSink& on_frame,
                     const PlantOptions& options) {
  return drive_plant(rod, grasp, grasp_offset, path, BaseGripperPath{}, guess, frame_times,
                     on_frame, options);
}

}  // namespace rodshape
