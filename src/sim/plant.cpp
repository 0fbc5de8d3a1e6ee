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

/// Energy released between two equilibria a → b: the gripper's work (trapezoid in its wrench
/// n(L), m(L) over the tip's displacement and world-frame rotation) minus the rise of the elastic
/// and load potential energy. ≈ 0 on a followed path, > 0 where the rod snapped.
double energy_released(const ClampedRod& rod,
                       const RodConfiguration& a,
                       const RodConfiguration& b) {
  const Pose pa = a.tip(), pb = b.tip();
  const Wrench wa = a.tip_wrench(), wb = b.tip_wrench();
  const Eigen::Vector3d rotation = log_so3(pb.rotation * pa.rotation.transpose());
  const double work = 0.5 * (wa.force + wb.force).dot(pb.position - pa.position) +
                      0.5 * (wa.moment + wb.moment).dot(rotation);
  return work - (b.energy - a.energy) - (load_potential(rod, b) - load_potential(rod, a));
}

PlantFrame frame_at(double t, const Pose& end_effector, const ShootingResult& state) {
  return {t, end_effector, state.base_wrench, state.configuration};
}

}  // namespace

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
         const std::vector<double>& frame_times,
         const PlantFrameSink& on_frame,
         const PlantOptions& options)
      : rod_(rod),
        grasp_(grasp),
        offset_(grasp_offset),
        frames_(frame_times),
        on_frame_(on_frame),
        options_(options) {
    direct_ = options.shooting;
    direct_.output_derivatives = Derivatives::None;
  }

  /// The equilibrium at the path's start, solved from `guess` with continuation.
  bool start(const TimedPose& sample, const BaseWrench& guess) {
    state_ = solve(sample.pose, guess, true);
    held_by_ = sample.pose;
    if (state_.summary.converged()) return true;
    lose(sample.t,
         "the real rod has no equilibrium at the path's start (" + state_.summary.brief() + ")");
    return false;
  }

  /// The next sample, solved directly from the last equilibrium; false when it is lost.
  bool advance(const TimedPose& sample) {
    emit_frames_before(sample.t, false);
    if (run_.lost) return false;  // unstable, and no stable equilibrium to snap to
    ShootingResult next = solve(sample.pose, state_.base_wrench, false);
    if (!next.summary.converged()) {
      lose(sample.t, "no equilibrium found at t = " + detail::format_value(sample.t) + " s (" +
                         next.summary.brief() + ")");
      return false;
    }
    check_snap(sample.t, next.configuration);
    state_ = std::move(next);
    held_by_ = sample.pose;
    return true;
  }

  PlantRun finish(double t_end) {
    if (!run_.lost) emit_frames_before(t_end, true);
    run_.last = frame_at(run_.lost ? run_.events.back().t : t_end, held_by_, state_);
    return std::move(run_);
  }

 private:
  ShootingResult solve(const Pose& end_effector, const BaseWrench& from, bool continuation) {
    ShootingOptions options = direct_;
    options.continuation = continuation;  // past the start: each sample from the last
    ++run_.solves;
    return solve_equilibrium(rod_, held_at(end_effector, grasp_, offset_), from, options);
  }

  void check_snap(double t, const RodConfiguration& next) {
    const double released = energy_released(rod_, state_.configuration, next);
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
      if (on_frame_) on_frame_(frame_at(frames_[next_frame_], held_by_, state_));
      ++next_frame_;
      ++run_.frames;
    }
  }

  /// A direct solve follows an equilibrium branch past the point where it loses stability; the real
  /// rod does not: it snaps to a stable equilibrium with the same ends (seek_stable_equilibrium).
  void settle(double t) {
    ClampedRod at = rod_;
    at.substeps = state_.summary.substeps;
    state_.configuration = integrate(at, state_.base_wrench, Derivatives::AllNodes);
    const TipCondition tip = held_at(held_by_, grasp_, offset_);
    const StabilityResult verdict = assess_stability(at, state_.configuration, tip);
    if (verdict.stable || verdict.degenerate) return;
    StableEquilibriumResult found = seek_stable_equilibrium(rod_, tip, state_, verdict, direct_);
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
  const Grasp& grasp_;
  const Pose& offset_;
  const std::vector<double>& frames_;
  const PlantFrameSink& on_frame_;
  const PlantOptions& options_;
  ShootingOptions direct_;
  ShootingResult state_;
  Pose held_by_;
  std::size_t next_frame_ = 0;
  PlantRun run_;
};

}  // namespace

PlantRun drive_plant(const ClampedRod& rod,
                     const Grasp& grasp,
                     const Pose& grasp_offset,
                     const std::vector<TimedPose>& path,
                     const BaseWrench& guess,
                     const std::vector<double>& frame_times,
                     const PlantFrameSink& on_frame,
                     const PlantOptions& options) {
  options.validate();
  rod.validate();
  if (path.empty()) throw InputError("path", ": the commanded path has no sample");
  if (!std::is_sorted(frame_times.begin(), frame_times.end()))
    throw InputError("frame_times", ": must be increasing");
  Driver driver(rod, grasp, grasp_offset, frame_times, on_frame, options);
  if (driver.start(path.front(), guess))
    for (std::size_t k = 1; k < path.size() && driver.advance(path[k]); ++k) {
    }
  return driver.finish(path.back().t);
}

}  // namespace rodshape
