// test_plant_seam.cpp: the plant seam (issue 44, item 5). The validation's drivers take any Plant:
// one that counts its calls and forwards to the quasi-static plant gives the default's result bit
// for bit, open and closed loop (on threads); the quasi-static frames' velocities are the backward
// differences of the held samples; the factory knows its plants by name.
#include <gtest/gtest.h>

#include <atomic>
#include <memory>
#include <string>
#include <vector>

#include "rodshape/core/so3.hpp"
#include "rodshape/error.hpp"
#include "rodshape/sim/plan_validation.hpp"
#include "rodshape/sim/plant_factory.hpp"
#include "rodshape/sim/quasi_static_plant.hpp"
#include "rodshape/trajectory/plan.hpp"
#include "support/band_problem.hpp"

namespace rodshape {
namespace test_plant_seam {
namespace {

using testing::band_problem;

struct Calls {
  std::atomic<int> made{0}, resets{0}, drives{0}, holds{0};
};

/// A test-only plant: the quasi-static one, its calls counted.
class CountingPlant final : public Plant {
 public:
  CountingPlant(const PlantSetup& setup, Calls& calls) : inner_(setup), calls_(calls) {
    ++calls_.made;
  }
  std::string name() const override { return "counting"; }
  const PlantSetup& setup() const override { return inner_.setup(); }
  void reset(const PlantStart& start) override {
    ++calls_.resets;
    inner_.reset(start);
  }
  PlantRun drive(const PlantDrive& request, const PlantFrameSink& on_frame) override {
    ++calls_.drives;
    return inner_.drive(request, on_frame);
  }
  PlantRun hold(double t_end,
                const std::vector<double>& frame_times,
                const PlantFrameSink& on_frame) override {
    ++calls_.holds;
    return inner_.hold(t_end, frame_times, on_frame);
  }

 private:
  QuasiStaticPlant inner_;
  Calls& calls_;
};

PlantMaker counting(Calls& calls) {
  return
      [&calls](const PlantSetup& setup) { return std::make_unique<CountingPlant>(setup, calls); };
}

const PlanResult& band_plan() {
  static const PlanResult plan = [] {
    PlanOptions options;
    options.steps = 2;
    return rodshape::plan(band_problem(), options);
  }();
  return plan;
}

PlantModel mismatch() {
  PlantModel plant;
  plant.stiffness_scale = 0.85;
  plant.gravity = Eigen::Vector3d(0.0, 0.0, -9.81);
  return plant;
}

void expect_same_frame(const PlantFrame& a, const PlantFrame& b) {
  EXPECT_EQ(a.t, b.t);
  EXPECT_EQ(a.base_wrench.force, b.base_wrench.force);
  EXPECT_EQ(a.base_wrench.moment, b.base_wrench.moment);
  EXPECT_EQ(a.configuration.p, b.configuration.p);
  EXPECT_EQ(a.end_effector.position, b.end_effector.position);
  EXPECT_EQ(a.tip_twist, b.tip_twist);
  EXPECT_EQ(a.node_velocities, b.node_velocities);
}

/// Every series, event, checkpoint and the plant's run: bit for bit.
void expect_same(const ValidationResult& a, const ValidationResult& b) {
  EXPECT_EQ(a.status, b.status);
  EXPECT_EQ(a.message, b.message);
  EXPECT_EQ(a.plant.frames, b.plant.frames);
  EXPECT_EQ(a.plant.solves, b.plant.solves);
  EXPECT_EQ(a.plant.lost, b.plant.lost);
  expect_same_frame(a.plant.last, b.plant.last);
  ASSERT_EQ(a.runs.size(), b.runs.size());
  for (std::size_t k = 0; k < a.runs.size(); ++k) {
    SCOPED_TRACE(k);
    const ValidationRun &x = a.runs[k], &y = b.runs[k];
    EXPECT_EQ(x.time, y.time);
    EXPECT_EQ(x.error_3d, y.error_3d);
    EXPECT_EQ(x.error_2d, y.error_2d);
    EXPECT_EQ(x.true_error, y.true_error);
    EXPECT_EQ(x.visible_markers, y.visible_markers);
    EXPECT_EQ(x.min_gap, y.min_gap);
    ASSERT_EQ(x.events.size(), y.events.size());
    for (std::size_t e = 0; e < x.events.size(); ++e) {
      EXPECT_EQ(x.events[e].t, y.events[e].t);
      EXPECT_EQ(x.events[e].message, y.events[e].message);
    }
    ASSERT_EQ(x.checkpoints.size(), y.checkpoints.size());
    for (std::size_t c = 0; c < x.checkpoints.size(); ++c) {
      EXPECT_EQ(x.checkpoints[c].grasp_offset.position, y.checkpoints[c].grasp_offset.position);
      EXPECT_EQ(x.checkpoints[c].shape_rms, y.checkpoints[c].shape_rms);
    }
    expect_same_frame(x.plant_final, y.plant_final);
  }
}

TEST(PlantSeam, OpenLoopOnAnotherPlantIsTheDefaultsBitForBit) {
  ValidationOptions options;
  options.runs = 2;
  const ValidationResult expected =
      validate_plan(band_problem(), band_plan(), mismatch(), {}, options);
  Calls calls;
  const ValidationResult seen =
      validate_plan(band_problem(), band_plan(), mismatch(), {}, options, counting(calls));
  expect_same(seen, expected);
  EXPECT_EQ(calls.made.load(), 1);  // open loop: one plant, driven once, seen by every run
  EXPECT_EQ(calls.resets.load(), 1);
  EXPECT_EQ(calls.drives.load(), 1);
  EXPECT_EQ(calls.holds.load(), 0);
}

TEST(PlantSeam, ClosedLoopOnThreadsOnAnotherPlantIsTheDefaultsBitForBit) {
  ValidationOptions options;
  options.closed_loop = true;
  options.runs = 2;
  options.jobs = 2;
  options.planning.steps = 2;
  options.loop.estimation.gravity = Eigen::Vector3d(0.0, 0.0, -9.81);
  const ValidationResult expected =
      validate_plan(band_problem(), band_plan(), mismatch(), {}, options);
  ASSERT_EQ(expected.status, ValidationStatus::Complete) << expected.brief();
  Calls calls;
  const ValidationResult seen =
      validate_plan(band_problem(), band_plan(), mismatch(), {}, options, counting(calls));
  expect_same(seen, expected);
  // One plant a run, reset once, a drive a segment (one more than the checkpoints) and a hold at
  // each checkpoint.
  int checkpoints = 0;
  for (const ValidationRun& run : seen.runs)
    checkpoints += static_cast<int>(run.checkpoints.size());
  ASSERT_GT(checkpoints, 0);
  EXPECT_EQ(calls.made.load(), 2);
  EXPECT_EQ(calls.resets.load(), 2);
  EXPECT_EQ(calls.drives.load(), checkpoints + 2);
  EXPECT_EQ(calls.holds.load(), checkpoints);
}

TEST(PlantSeam, QuasiStaticVelocitiesAreTheBackwardDifferencesOfTheSamples) {
  const PlanProblem problem = band_problem();
  const PlanResult& plan = band_plan();
  PlantDrive request;
  request.path = plan.end_effector_path;
  ASSERT_GT(request.path.size(), 3u);
  // A frame at every sample's time holds that sample (the last at or before it).
  for (const TimedPose& sample : request.path) request.frame_times.push_back(sample.t);
  QuasiStaticPlant plant({problem.rod, problem.grasp, Pose{}, PlantOptions{}});
  EXPECT_EQ(plant.name(), "quasi_static");
  plant.reset({plan.initial_wrench});
  std::vector<PlantFrame> frames;
  const PlantRun run = plant.drive(request, [&](const PlantFrame& f) { frames.push_back(f); });
  ASSERT_FALSE(run.lost) << run.brief();
  ASSERT_TRUE(run.events.empty()) << run.events.front().message;  // no snap: the held samples
  ASSERT_EQ(frames.size(), request.path.size());
  const std::size_t nodes = frames.front().configuration.p.size();
  double fastest = 0.0;
  for (std::size_t k = 0; k < frames.size(); ++k) {
    SCOPED_TRACE(k);
    const PlantFrame& frame = frames[k];
    ASSERT_EQ(frame.node_velocities.size(), nodes);
    if (k == 0) {  // the first sample: no sample before it
      EXPECT_TRUE(frame.tip_twist.isZero(0.0));
      for (const Eigen::Vector3d& v : frame.node_velocities) EXPECT_TRUE(v.isZero(0.0));
      continue;
    }
    const PlantFrame& before = frames[k - 1];
    const double dt = frame.t - before.t;
    for (std::size_t i = 0; i < nodes; ++i) {
      const Eigen::Vector3d difference =
          (frame.configuration.p[i] - before.configuration.p[i]) / dt;
      EXPECT_LE((frame.node_velocities[i] - difference).norm(), 1e-12 * (1.0 + difference.norm()));
      fastest = std::max(fastest, difference.norm());
    }
    const Eigen::Vector3d spin =
        log_so3(frame.configuration.R.back() * before.configuration.R.back().transpose()) / dt;
    EXPECT_LE((frame.tip_twist.head<3>() - frame.node_velocities.back()).norm(), 0.0);
    EXPECT_LE((frame.tip_twist.tail<3>() - spin).norm(), 1e-12 * (1.0 + spin.norm()));
  }
  EXPECT_GT(fastest, 1e-4);  // the rod moved: the velocities are not all zero
  expect_same_frame(run.last, frames.back());
  // Held still: the last frame at rest.
  std::vector<PlantFrame> rest;
  const double t = run.last.t;
  const PlantRun held =
      plant.hold(t + 0.2, {t + 0.1, t + 0.2}, [&](const PlantFrame& f) { rest.push_back(f); });
  ASSERT_EQ(rest.size(), 2u);
  EXPECT_EQ(held.frames, 2);
  EXPECT_EQ(held.solves, 0);
  EXPECT_EQ(held.last.t, t + 0.2);
  EXPECT_EQ(rest[1].t, t + 0.2);
  EXPECT_EQ(rest[1].configuration.p, run.last.configuration.p);
  EXPECT_TRUE(rest[1].tip_twist.isZero(0.0));
  for (const Eigen::Vector3d& v : rest[1].node_velocities) EXPECT_TRUE(v.isZero(0.0));
}

TEST(PlantSeam, TheFactoryKnowsTheQuasiStaticPlantAndNamesAnUnknownOne) {
  EXPECT_EQ(plant_names(), std::vector<std::string>{"quasi_static"});
  const PlanProblem problem = band_problem();
  const std::unique_ptr<Plant> plant =
      make_plant("quasi_static", {problem.rod, problem.grasp, Pose{}, PlantOptions{}});
  ASSERT_NE(plant, nullptr);
  EXPECT_EQ(plant->name(), "quasi_static");
  EXPECT_EQ(plant->setup().rod.properties.length, problem.rod.properties.length);
  PlantModel model;
  model.model = "dynamic";
  try {
    model.validate();
    FAIL() << "an unknown plant was accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.field(), "PlantModel.model") << error.what();
    EXPECT_NE(std::string(error.what()).find("quasi_static"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace test_plant_seam
}  // namespace rodshape
