// Tests of the plant driven by both ends (issue 21, item 6): the base gripper moving the rod's
// clamp along its own path, a rigid motion of both ends, the base alone on a line against an
// independently solved clamped–clamped equilibrium, the energy balance with the base's work, and
// the two ends timed on one clock.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/core/so3.hpp"
#include "rodshape/samples/rubber_band.hpp"
#include "rodshape/sim/plant.hpp"
#include "rodshape/solvers/shooting_solver.hpp"
#include "sim/two_end_path.hpp"

namespace rodshape {
namespace test_two_end_plant {
namespace {

Pose pose_of(const Eigen::Vector3d& position, const Eigen::Vector3d& rotation_vector) {
  return {position, exp_so3(rotation_vector)};
}

/// A rigid motion of the world, σ ∈ [0, 1] of the way: a translation on a line and a rotation
/// about a fixed axis (through the origin).
Pose rigid_motion(double sigma) {
  return pose_of(sigma * Eigen::Vector3d(0.05, -0.02, 0.03),
                 sigma * Eigen::Vector3d(0.3, -0.2, 0.5));
}

std::vector<double> times_of(const std::vector<TimedPose>& path) {
  std::vector<double> times;
  for (const TimedPose& sample : path) times.push_back(sample.t);
  return times;
}

TEST(TwoEndPlant, ARigidMotionOfBothEndsMovesTheShapeRigidly) {
  const ClampedRod rod = samples::rubber_band(ConstitutiveModel::Cosserat, 50);  // no load
  const BaseWrench w0{{-0.3, 0.0, 0.0}, {0.0, 0.05, 0.0}};
  const RodConfiguration bent = integrate(rod, w0);
  Grasp grasp;
  grasp.tip_to_end_effector = pose_of({0.0, 0.01, 0.02}, {0.0, 0.0, 0.3});
  BaseGripperPath base;
  base.base_to_end_effector = pose_of({0.01, 0.0, -0.03}, {0.2, 0.0, 0.4});
  const Pose tip_ee = compose(bent.tip(), grasp.tip_to_end_effector);
  const Pose base_ee = compose(rod.clamp, base.base_to_end_effector);
  std::vector<TimedPose> path;
  const int samples = 20;
  for (int k = 0; k <= samples; ++k) {
    const double sigma = static_cast<double>(k) / samples, t = 0.05 * k;
    path.push_back({t, compose(rigid_motion(sigma), tip_ee)});
    base.path.push_back({t, compose(rigid_motion(sigma), base_ee)});
  }
  std::vector<PlantFrame> frames;
  const PlantRun run = drive_plant(rod, grasp, Pose{}, path, base, w0, times_of(path),
                                   [&](const PlantFrame& frame) { frames.push_back(frame); });
  ASSERT_FALSE(run.lost) << run.brief();
  EXPECT_TRUE(run.events.empty()) << run.events.front().message;
  ASSERT_EQ(frames.size(), path.size());
  const RodConfiguration& start = frames.front().configuration;
  const double energy = start.energy;
  ASSERT_GT(energy, 1e-4);
  double worst_node = 0.0, worst_wrench = 0.0, worst_energy = 0.0;
  for (int k = 0; k <= samples; ++k) {
    const PlantFrame& frame = frames[static_cast<std::size_t>(k)];
    const Pose motion = rigid_motion(static_cast<double>(k) / samples);
    // The shape in the moving frame is the start's: each node moved by the same rigid motion.
    for (int i = 0; i < start.nodes(); ++i)
      worst_node =
          std::max(worst_node, (frame.configuration.p[i] -
                                compose(motion, {start.p[i], Eigen::Matrix3d::Identity()}).position)
                                   .norm());
    // The base wrench turned with the base.
    worst_wrench = std::max(
        worst_wrench,
        (frame.base_wrench.force - motion.rotation * frames[0].base_wrench.force).norm() +
            (frame.base_wrench.moment - motion.rotation * frames[0].base_wrench.moment).norm());
    worst_energy = std::max(worst_energy, std::abs(frame.configuration.energy - energy));
    // The clamp is where the base gripper holds it.
    EXPECT_LT((frame.clamp.position - compose(motion, rod.clamp).position).norm(), 1e-15);
    EXPECT_LT(
        (frame.base_end_effector.position - base.path[static_cast<std::size_t>(k)].pose.position)
            .norm(),
        1e-15);
  }
  RecordProperty("worst_node_fm", std::to_string(worst_node * 1e15));
  RecordProperty("worst_wrench", std::to_string(worst_wrench * 1e12));
  RecordProperty("worst_energy", std::to_string(worst_energy / energy * 1e15));
  EXPECT_LT(worst_node, 1e-9);
  EXPECT_LT(worst_wrench, 1e-9);
  EXPECT_LT(worst_energy, 1e-9 * energy);
  EXPECT_LT(
      (run.last.configuration.p.front() - compose(rigid_motion(1.0), rod.clamp).position).norm(),
      1e-15);
}

/// The straight band held clamped at both ends, its tip still and its base moved 4 cm across
/// on a line (base_T_ee not the identity), sampled at `samples` + 1 poses.
struct BaseOnALine {
  ClampedRod rod = samples::rubber_band(ConstitutiveModel::Cosserat, 50);
  Grasp grasp;  // clamped, tip_T_ee = identity
  Pose tip;     // the straight band's tip
  BaseGripperPath base;
  std::vector<TimedPose> path;
  Pose final_clamp;

  explicit BaseOnALine(int samples) {
    tip = integrate(rod, BaseWrench{}).tip();
    base.base_to_end_effector = pose_of({0.01, 0.0, -0.03}, {0.0, 0.0, 0.4});
    const Eigen::Vector3d across(0.04, 0.01, 0.0);
    for (int k = 0; k <= samples; ++k) {
      const double sigma = static_cast<double>(k) / samples, t = 0.1 * k;
      const Pose clamp{rod.clamp.position + sigma * across, rod.clamp.rotation};
      path.push_back({t, tip});
      base.path.push_back({t, compose(clamp, base.base_to_end_effector)});
      final_clamp = clamp;
    }
  }
};

TEST(TwoEndPlant, TheBaseAloneOnALineEndsAtTheClampedClampedEquilibrium) {
  const BaseOnALine drive(40);
  std::vector<PlantFrame> frames;
  const PlantRun run =
      drive_plant(drive.rod, drive.grasp, Pose{}, drive.path, drive.base, BaseWrench{},
                  times_of(drive.path), [&](const PlantFrame& frame) { frames.push_back(frame); });
  ASSERT_FALSE(run.lost) << run.brief();
  EXPECT_TRUE(run.events.empty()) << run.events.front().message;
  // The same equilibrium solved on its own: the rod clamped at the final base pose, the tip held
  // where it was, from rest (continuation).
  ClampedRod final_rod = drive.rod;
  final_rod.clamp = drive.final_clamp;
  ShootingOptions options;
  options.output_derivatives = Derivatives::None;
  const ShootingResult alone = solve_equilibrium(final_rod, ClampedTip{drive.tip}, {}, options);
  ASSERT_TRUE(alone.summary.converged()) << alone.brief();
  double distance = 0.0;
  for (int i = 0; i < final_rod.nodes(); ++i)
    distance = std::max(distance, (run.last.configuration.p[i] - alone.configuration.p[i]).norm());
  EXPECT_LT(distance, 1e-9);  // both solves' residuals are ≤ 1e-10 (m, rad)
  EXPECT_LT((run.last.configuration.p.front() - drive.final_clamp.position).norm(), 1e-15);
  EXPECT_LT((run.last.configuration.tip().position - drive.tip.position).norm(), 1e-9);
  EXPECT_GT(alone.configuration.energy, 1e-4);  // bent into an S: the base did work on it

  // The energy balance: the tip is still, so the base gripper's work (the clamp applies −n(0),
  // −m(0) to the rod; trapezoid over the samples) is the rise of the elastic energy.
  double work = 0.0;
  for (std::size_t k = 1; k < frames.size(); ++k) {
    const RodConfiguration &a = frames[k - 1].configuration, &b = frames[k].configuration;
    work -= 0.5 * (a.n.front() + b.n.front()).dot(b.p.front() - a.p.front()) +
            0.5 * (a.m.front() + b.m.front()).dot(log_so3(b.R.front() * a.R.front().transpose()));
  }
  const double rise = frames.back().configuration.energy - frames.front().configuration.energy;
  RecordProperty("work_minus_rise_ppm", std::to_string((work - rise) / rise * 1e6));
  RecordProperty("node_distance_fm", std::to_string(distance * 1e15));
  EXPECT_NEAR(work, rise, 1e-3 * rise);
}

TEST(TwoEndPlant, TheBasesSamplesBetweenTheTipsAreDrivenToo) {
  // The base's path sampled four times as finely as the tip's (which is still): the plant is
  // solved at every time of either, and ends where the finely sampled drive ends.
  const BaseOnALine fine(40);
  BaseOnALine coarse(40);
  std::vector<TimedPose> tip_path;
  for (std::size_t k = 0; k < coarse.path.size(); k += 4) tip_path.push_back(coarse.path[k]);
  const PlantRun both =
      drive_plant(fine.rod, fine.grasp, Pose{}, fine.path, fine.base, BaseWrench{}, {}, nullptr);
  const PlantRun sparse = drive_plant(coarse.rod, coarse.grasp, Pose{}, tip_path, coarse.base,
                                      BaseWrench{}, {}, nullptr);
  EXPECT_EQ(sparse.solves, both.solves);
  ASSERT_FALSE(sparse.lost);
  double distance = 0.0;
  for (int i = 0; i < fine.rod.nodes(); ++i)
    distance =
        std::max(distance, (both.last.configuration.p[i] - sparse.last.configuration.p[i]).norm());
  EXPECT_LT(distance, 1e-9);
}

TEST(TwoEndPlant, PoseAtInterpolatesBetweenSamplesAndHoldsPastTheEnds) {
  const std::vector<TimedPose> path = {{0.0, pose_of({0.0, 0.0, 0.0}, {0.0, 0.0, 0.0})},
                                       {1.0, pose_of({1.0, 0.0, 0.0}, {0.0, 0.0, 1.0})}};
  EXPECT_EQ(pose_at(path, -1.0).position, path[0].pose.position);
  EXPECT_EQ(pose_at(path, 1.0).position, path[1].pose.position);
  EXPECT_EQ(pose_at(path, 2.0).position, path[1].pose.position);
  const Pose half = pose_at(path, 0.25);
  EXPECT_NEAR(half.position.x(), 0.25, 1e-15);
  EXPECT_NEAR(log_so3(half.rotation).z(), 0.25, 1e-12);
}

TEST(TwoEndPlant, BothEndsAreTimedOnOneClockTheSlowerSetsIt) {
  EndEffectorLimits limits;
  const std::vector<Pose> tip = {Pose{}, pose_of({0.01, 0.0, 0.0}, {0.0, 0.0, 0.0}),
                                 pose_of({0.01, 0.0, 0.0}, {0.0, 0.0, 0.0})};
  const std::vector<Pose> base = {Pose{}, pose_of({0.0, 0.0, 0.005}, {0.0, 0.0, 0.0}),
                                  pose_of({0.0, 0.03, 0.005}, {0.0, 0.0, 0.0})};
  const sim_detail::TwoEndPath both = sim_detail::time_two_ends(tip, base, limits, limits);
  ASSERT_EQ(both.tip.size(), both.base.size());
  // Segment 1: the tip's 1 cm is the slower; segment 2: only the base moves (3 cm).
  const double t1 = time_parameterize({tip[0], tip[1]}, limits).back().t;
  const double t2 = time_parameterize({base[1], base[2]}, limits).back().t;
  EXPECT_DOUBLE_EQ(both.tip.back().t, t1 + t2);
  for (std::size_t k = 0; k < both.tip.size(); ++k) {
    EXPECT_EQ(both.tip[k].t, both.base[k].t);
    // The base moves at the tip's σ on segment 1: its z is half the tip's x.
    if (both.tip[k].t <= t1) {
      EXPECT_NEAR(both.base[k].pose.position.z(), 0.5 * both.tip[k].pose.position.x(), 1e-15);
    }
  }
  EXPECT_EQ(both.tip.back().pose.position, tip[2].position);
  EXPECT_EQ(both.base.back().pose.position, base[2].position);
}

}  // namespace
}  // namespace test_two_end_plant
}  // namespace rodshape
