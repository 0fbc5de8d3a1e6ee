// Tests of the simulated experiment: the plant model, the plant driven along a plan's path, the
// sensor and the paper's error metric.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/error.hpp"
#include "rodshape/io/task_reader.hpp"
#include "rodshape/samples/rubber_band.hpp"
#include "rodshape/sim/commanded_path.hpp"
#include "rodshape/sim/plan_validation.hpp"
#include "rodshape/trajectory/plan.hpp"
#include "support/band_problem.hpp"
#include "support/eigen_compare.hpp"

namespace rodshape {
namespace test_plan_validation {
namespace {

using testing::band_problem;
using testing::CompareMatrices;

const PlanResult& band_plan() {
  static const PlanResult plan = [] {
    PlanOptions options;
    options.steps = 3;
    return rodshape::plan(band_problem(), options);
  }();
  return plan;
}

/// The largest distance between the nodes of two configurations of the same rod.
double max_node_distance(const RodConfiguration& a, const RodConfiguration& b) {
  double distance = 0.0;
  for (int i = 0; i < a.nodes(); ++i) distance = std::max(distance, (a.p[i] - b.p[i]).norm());
  return distance;
}

/// The paper's mismatch (docs/validation.md): 15 % softer, the weight the planner neglects, the
/// tip held 2 mm off along its x axis.
PlantModel paper_mismatch() {
  PlantModel plant;
  plant.stiffness_scale = 0.85;
  plant.gravity = Eigen::Vector3d(0.0, 0.0, -9.81);
  plant.grasp_offset.position = {0.002, 0.0, 0.0};
  return plant;
}

MarkerSensorModel noiseless() {
  MarkerSensorModel sensor;
  sensor.in_plane_noise = 0.0;
  sensor.depth_noise = 0.0;
  return sensor;
}

TEST(PlantModel, ScalesTheStiffnessesAndAddsTheWeight) {
  const ClampedRod planned = samples::rubber_band();
  PlantModel plant;
  plant.stiffness_scale = 0.85;
  plant.factors.GJ = 2.0;
  plant.gravity = Eigen::Vector3d(0.0, 0.0, -9.81);
  const ClampedRod real = plant.real_rod(planned);
  EXPECT_DOUBLE_EQ(real.properties.K_rot.x(), 0.85 * 0.04);
  EXPECT_DOUBLE_EQ(real.properties.K_rot.z(), 0.85 * 2.0 * 0.028);
  EXPECT_DOUBLE_EQ(real.properties.K_tra.z(), 0.85 * planned.properties.K_tra.z());
  // ρA g: 1392 kg/m³ × 4e-4 m² × 9.81 m/s² = 5.46 N/m, the paper's 1.6 N over 0.29 m.
  EXPECT_NEAR(real.load.force.z(), -1392 * 4e-4 * 9.81, 1e-9);
  EXPECT_NEAR(-real.load.force.z() * real.properties.length, 1.58, 0.01);
}

TEST(PlantModel, OneGravityActsOnTheRealRod) {
  // Issue 24: the plant's weight was added to the planner's (twice the weight when both were
  // given), and under the planner's gravity the plant's mass per length changed nothing.
  ClampedRod planned = samples::rubber_band();
  const Eigen::Vector3d g(0.0, 0.0, -9.81), push(0.1, 0.0, 0.0);  // push: a load, not weight
  const double m = planned.properties.mass_per_length;
  planned.load = DistributedLoad::gravity(m, g);
  planned.load.force += push;
  PlantModel plant;
  plant.planner_gravity = g;
  EXPECT_EQ(plant.real_rod(planned).load.force, planned.load.force);  // the planner's rod, exactly
  plant.gravity = g;
  EXPECT_TRUE(CompareMatrices(plant.real_rod(planned).load.force, m * g + push, 1e-12));
  plant.mass_per_length = 2.0 * m;
  EXPECT_TRUE(CompareMatrices(plant.real_rod(planned).load.force, 2.0 * m * g + push, 1e-12));
  plant.mass_per_length = 0.0;
  EXPECT_TRUE(CompareMatrices(plant.real_rod(planned).load.force, push, 1e-12));
  plant.gravity.reset();  // the planner's gravity, on the plant's own mass
  plant.mass_per_length = 3.0 * m;
  EXPECT_TRUE(CompareMatrices(plant.real_rod(planned).load.force, 3.0 * m * g + push, 1e-12));
  EXPECT_EQ(plant.acting_gravity(), g);
}

TEST(PlantModel, BadParametersNameTheField) {
  PlantModel plant;
  plant.stiffness_scale = 0.0;
  try {
    (void)plant.real_rod(samples::rubber_band());
    FAIL() << "a plant of zero stiffness cannot hold the rod";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()).rfind("PlantModel.stiffness_scale", 0), 0u) << error.what();
  }
  PlantModel heavy;
  heavy.gravity = Eigen::Vector3d(0.0, 0.0, -9.81);
  ClampedRod massless = samples::rubber_band();
  massless.properties.mass_per_length = 0.0;
  EXPECT_THROW((void)heavy.real_rod(massless), InputError);
  MarkerSensorModel sensor;
  sensor.markers = 1;
  EXPECT_THROW(sensor.validate(), InputError);
  sensor = {};
  sensor.dropout = 1.5;
  EXPECT_THROW(sensor.validate(), InputError);
  sensor = {};
  sensor.depth_noise = -1e-3;
  EXPECT_THROW(sensor.validate(), InputError);
}

TEST(MarkerSensor, ACameraThatSeesNoMarkerNeedsAWristSensor) {
  // Issue 24: dropout 1 without a wrist sensor measured nothing, yet a closed loop reported every
  // estimate converged and consistent.
  MarkerSensorModel sensor;
  sensor.dropout = 1.0;
  try {
    sensor.validate();
    FAIL() << "a sensor that measures nothing was accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.field(), "MarkerSensorModel.dropout") << error.what();
  }
  sensor.wrist = WristNoise{0.05, 0.005};  // the wrist wrench alone fixes the shape
  EXPECT_NO_THROW(sensor.validate());
}

TEST(ShapeError, NoMarkerSeenIsNoMeasuredError) {
  // Without a visible marker the measured curve is the clamp alone: its distances are not an
  // error of the shape (they were reported as one, 155 mm); the true error is still known.
  const ClampedRod rod = samples::rubber_band();
  const RodConfiguration straight = integrate(rod, BaseWrench{});
  MarkerSensorModel model = noiseless();
  model.dropout = 1.0;
  model.wrist = WristNoise{0.0, 0.0};
  MarkerSensor sensor(model, 1);
  PlantFrame frame;
  frame.configuration = straight;
  const SensorFrame seen = sensor.observe(frame, 0.29);
  ASSERT_EQ(seen.visible(), 0);
  const ShapeError error =
      shape_error({{0.003, 0.0, 0.1}}, rod.clamp.position, seen, straight, model.camera);
  EXPECT_TRUE(std::isnan(error.error_3d));
  EXPECT_TRUE(std::isnan(error.error_2d));
  EXPECT_NEAR(error.true_error, 0.003, 1e-12);
  EXPECT_EQ(error.visible_markers, 0);
}

TEST(PlanValidation, ABriefWithoutAMarkerSeenSaysNothingWasMeasured) {
  ValidationResult result;
  result.status = ValidationStatus::Complete;
  ValidationRun& run = result.runs.emplace_back();
  run.final.error_3d = run.final.error_2d = std::numeric_limits<double>::quiet_NaN();
  run.final.true_error = 2e-4;
  EXPECT_EQ(result.brief(),
            "complete: final true error 0.2 mm (no marker seen: no measured error), 1 run");
}

// Issue 43, 4d: the brief said run 1's errors alone (2.52 mm of 8 runs at 2.19 ... 10.3 mm); it
// says the median and the worst over the runs.
TEST(PlanValidation, ABriefOfSeveralRunsSaysTheirMedianAndWorst) {
  ValidationResult result;
  result.status = ValidationStatus::Complete;
  for (const double mm : {2.52, 2.19, 10.3, 2.4, 2.6, 3.0, 2.3, 2.8}) {
    ValidationRun& run = result.runs.emplace_back();
    run.final.error_3d = 1e-3 * mm;
    run.final.error_2d = 0.5e-3 * mm;
    run.final.true_error = 0.1e-3 * mm;
  }
  // Sorted: 2.19 2.3 2.4 2.52 2.6 2.8 3.0 10.3: the median (2.52 + 2.6) / 2 = 2.56.
  EXPECT_EQ(result.brief(),
            "complete: final 3D error median 2.56 mm, worst 10.3 mm (2D median 1.28 mm, worst "
            "5.15 mm; true median 0.256 mm, worst 1.03 mm), 8 runs");
  // A run that saw no marker at the end is left out of the measured errors, and said so.
  result.runs[2].final.error_3d = result.runs[2].final.error_2d =
      std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(result.brief(),
            "complete: final 3D error median 2.52 mm, worst 3 mm (2D median 1.26 mm, worst 1.5 mm; "
            "true median 0.256 mm, worst 1.03 mm) (1 of 8 runs saw no marker at the end: not in "
            "the measured errors), 8 runs");
}

TEST(ShapeError, PolylineDistanceByHand) {
  const std::vector<Eigen::Vector3d> polyline{{0, 0, 0}, {0, 0, 1}, {1, 0, 1}};
  EXPECT_DOUBLE_EQ(polyline_distance(polyline, Eigen::Vector3d(0.5, 0, 0.5)), 0.5);
  EXPECT_DOUBLE_EQ(polyline_distance(polyline, Eigen::Vector3d(0.5, 0.3, 1.4)), 0.5);
  EXPECT_DOUBLE_EQ(polyline_distance(polyline, Eigen::Vector3d(0, 0, -2)), 2.0);  // the clamp end
  EXPECT_DOUBLE_EQ(polyline_distance(polyline, Eigen::Vector3d(2, 0, 1)), 1.0);   // beyond the tip
}

TEST(ShapeError, StraightRodSeenWithoutNoise) {
  // The unloaded band along +z; points 3 mm aside along x at s = 0.1 and 0.2. The markers lie on
  // the rod, so the measured polyline is the rod itself: every error is 3 mm; in the image plane
  // (x–z) too, since the offset is in it.
  const ClampedRod rod = samples::rubber_band();
  const RodConfiguration straight = integrate(rod, BaseWrench{});
  PlantFrame frame;
  frame.configuration = straight;
  MarkerSensor sensor(noiseless(), 1);
  const SensorFrame seen = sensor.observe(frame, rod.properties.length);
  ASSERT_EQ(seen.visible(), 10);
  EXPECT_NEAR(seen.markers.back()->z(), 0.29, 1e-12);  // the last marker at the tip
  const PointSet points{{0.003, 0.0, 0.1}, {0.003, 0.0, 0.2}};
  const ShapeError error =
      shape_error(points, rod.clamp.position, seen, straight, noiseless().camera);
  EXPECT_NEAR(error.error_3d, 0.003, 1e-12);
  EXPECT_NEAR(error.error_2d, 0.003, 1e-12);
  EXPECT_NEAR(error.true_error, 0.003, 1e-12);
  EXPECT_NEAR(error.true_max_distance, 0.003, 1e-12);
  // An offset along the camera's depth (y) is invisible in the image plane.
  const ShapeError deep =
      shape_error({{0.0, 0.003, 0.1}}, rod.clamp.position, seen, straight, noiseless().camera);
  EXPECT_NEAR(deep.error_3d, 0.003, 1e-12);
  EXPECT_NEAR(deep.error_2d, 0.0, 1e-12);
}

TEST(PlanValidation, IdenticalPlantFollowsThePlanAndItsTrueErrorIsThePlans) {
  const PlanResult& plan = band_plan();
  ASSERT_EQ(plan.status, PlanStatus::Complete) << plan.message;
  const ValidationResult result = validate_plan(band_problem(), plan, {}, noiseless());
  ASSERT_EQ(result.status, ValidationStatus::Complete) << result.brief();
  EXPECT_TRUE(result.plant.events.empty());
  // The plant's last equilibrium is the plan's last shape: the same rod held at the same pose,
  // followed on the same branch; they agree to the solvers' tolerance (residual 1e-10, scaled).
  EXPECT_LT(
      max_node_distance(result.plant.last.configuration, plan.steps.back().solution.configuration),
      1e-8);
  // So the true final error is the plan's mean distance (to that tolerance).
  const ShapeCostBreakdown& cost = plan.steps.back().solution.cost;
  double mean = 0.0;
  for (double d : cost.distances) mean += d / static_cast<double>(cost.distances.size());
  ASSERT_EQ(result.runs.size(), 1u);
  EXPECT_NEAR(result.runs[0].final.true_error, mean, 1e-8);
  EXPECT_NEAR(result.runs[0].final.true_max_distance, cost.max_distance, 1e-8);
  // Frames at 30 Hz over the path, the last after the last waypoint.
  const double duration = plan.end_effector_path.back().t;
  EXPECT_EQ(result.runs[0].time.size(), static_cast<std::size_t>(std::floor(duration * 30.0)) + 1 +
                                            (std::fmod(duration * 30.0, 1.0) > 0.0));
  EXPECT_DOUBLE_EQ(result.runs[0].time.back(), duration);
  // The error falls from the straight rod's to the plan's.
  EXPECT_GT(result.runs[0].true_error.front(), 10.0 * result.runs[0].true_error.back());
}

TEST(PlanValidation, AFixedSeedRepeatsBitForBit) {
  MarkerSensorModel sensor;  // 1 mm in plane, 3 mm in depth
  sensor.dropout = 0.1;
  sensor.wrist = WristNoise{0.05, 0.005};
  ValidationOptions options;
  options.runs = 2;
  options.seed = 42;
  const ValidationResult a = validate_plan(band_problem(), band_plan(), {}, sensor, options);
  const ValidationResult b = validate_plan(band_problem(), band_plan(), {}, sensor, options);
  ASSERT_EQ(a.runs.size(), 2u);
  EXPECT_EQ(a.runs[0].error_3d, b.runs[0].error_3d);
  EXPECT_EQ(a.runs[1].error_2d, b.runs[1].error_2d);
  EXPECT_EQ(a.runs[1].visible_markers, b.runs[1].visible_markers);
  EXPECT_EQ(a.runs[0].seed, 42u);
  EXPECT_EQ(a.runs[1].seed, 43u);
  // Different seeds see different noise; the truth is the same.
  EXPECT_NE(a.runs[0].error_3d, a.runs[1].error_3d);
  EXPECT_EQ(a.runs[0].true_error, a.runs[1].true_error);
  // About 10 % of the markers drop out.
  double seen = 0.0, total = 0.0;
  for (int v : a.runs[0].visible_markers) {
    seen += v;
    total += 10.0;
  }
  EXPECT_NEAR(seen / total, 0.9, 0.03);
  ASSERT_TRUE(a.runs[0].last_seen.wrist.has_value());
}

TEST(PlanValidation, ASeedThatWouldWrapIsBadInput) {
  // Issue 24: run k is seeded with seed + k - 1, and 2^64 - 1 with two runs wrapped to 0.
  ValidationOptions options;
  options.runs = 2;
  options.seed = std::numeric_limits<std::uint64_t>::max();
  try {
    options.validate();
    FAIL() << "a seed that wraps was accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.field(), "ValidationOptions.seed") << error.what();
  }
  options.seed -= 1;
  EXPECT_NO_THROW(options.validate());
}

TEST(PlanValidation, AWeakerHeavierPlantMissesThePoints) {
  // The paper's mismatch: 15 % softer, and gravity the planner neglected: the true final error
  // grows well beyond the plan's.
  PlantModel plant;
  plant.stiffness_scale = 0.85;
  plant.gravity = Eigen::Vector3d(0.0, 0.0, -9.81);
  const ValidationResult nominal = validate_plan(band_problem(), band_plan(), {}, noiseless());
  const ValidationResult mismatched =
      validate_plan(band_problem(), band_plan(), plant, noiseless());
  ASSERT_EQ(mismatched.status, ValidationStatus::Complete) << mismatched.brief();
  EXPECT_GT(mismatched.runs[0].final.true_error, 2.0 * nominal.runs[0].final.true_error);
}

}  // namespace
}  // namespace test_plan_validation
}  // namespace rodshape

namespace rodshape {
namespace test_plan_validation {
namespace {

TEST(PlanValidation, ThePlantSnapsWhereThePaperSchemePlanWouldJump) {
  // plan_c_arc with the paper's objective sets (projection): its tracking finds a jump towards
  // waypoint 4 (status snap_through). Driven along that plan's path, the plant (the same rod) snaps
  // or loses its equilibrium there too (direct solves would follow the unstable branch; the
  // plant's stability check at each frame catches it): an event with its time, not a crash.
  PlanProblem problem;  // examples/plan_c_arc.yaml
  problem.rod = samples::rubber_band();
  problem.target.points = {{0.003, 0.0, 0.028}, {0.012, 0.0, 0.055}, {0.027, 0.0, 0.080},
                           {0.047, 0.0, 0.101}, {0.070, 0.0, 0.118}, {0.097, 0.0, 0.128},
                           {0.126, 0.0, 0.133}, {0.155, 0.0, 0.132}, {0.183, 0.0, 0.124},
                           {0.208, 0.0, 0.110}};
  problem.target.energy_weight = 1e-3;
  problem.target.distance_weight = 1.0;
  PlanOptions options;
  options.steps = 7;
  options.interpolation = ObjectiveInterpolation::Projection;
  const PlanResult plan = rodshape::plan(problem, options);
  ASSERT_EQ(plan.status, PlanStatus::SnapThrough) << plan.message;
  ASSERT_FALSE(plan.end_effector_path.empty());
  MarkerSensorModel sensor = noiseless();
  sensor.frame_rate = 5.0;  // a stability check per frame: fewer frames, a quicker test
  const ValidationResult result = validate_plan(problem, plan, {}, sensor);
  ASSERT_NE(result.status, ValidationStatus::Complete) << result.brief();
  ASSERT_FALSE(result.plant.events.empty());
  const PlantEvent& event = result.plant.events.front();
  EXPECT_GT(event.t, 0.0);
  EXPECT_LE(event.t, plan.end_effector_path.back().t);
  if (event.kind == PlantEvent::Kind::SnapThrough) {
    EXPECT_GT(event.energy_released, 0.0);
  }
  // The plan's tracking found the rod unstable on arrival at waypoint 4: the plant's event lies
  // between the start of segment 4 and the end of the path.
  EXPECT_EQ(plan.tracking.jump_step, 3);
}

}  // namespace
}  // namespace test_plan_validation
}  // namespace rodshape

namespace rodshape {
namespace test_plan_validation {
namespace {

TEST(ClosedLoop, ReducesTheFinalErrorOfAMismatchedPlant) {
  // The paper's mismatch: 15 % softer, gravity the planner neglects, the tip held 2 mm off. Open
  // loop, the plant ends on a shape the plan did not mean; closing the loop at each waypoint
  // (estimate the wrench, the weight and the grasp offset; re-plan the rest) brings the true final
  // error well below it. Noise-free markers, so that the comparison is exact.
  const PlantModel plant = paper_mismatch();
  ValidationOptions open;
  const ValidationResult open_loop =
      validate_plan(band_problem(), band_plan(), plant, noiseless(), open);
  ValidationOptions closed;
  closed.closed_loop = true;
  closed.planning.steps = 3;
  closed.loop.estimation.gravity = Eigen::Vector3d(0.0, 0.0, -9.81);
  const ValidationResult closed_loop =
      validate_plan(band_problem(), band_plan(), plant, noiseless(), closed);
  ASSERT_EQ(closed_loop.status, ValidationStatus::Complete) << closed_loop.brief();
  const ValidationRun& run = closed_loop.runs.front();
  EXPECT_TRUE(run.closed_loop);
  ASSERT_EQ(run.checkpoints.size(), 2u);  // at waypoints 1 and 2 of 3
  for (const Checkpoint& c : run.checkpoints) {
    EXPECT_TRUE(c.estimate.converged()) << c.message;
    EXPECT_TRUE(c.replanned) << c.message;
  }
  // The grasp offset is found to a fraction of a millimetre.
  EXPECT_NEAR(run.checkpoints.back().grasp_offset.position.x(), 0.002, 3e-4);
  EXPECT_LT(run.final.true_error, 0.5 * open_loop.runs.front().final.true_error)
      << "closed " << run.final.true_error << " m, open "
      << open_loop.runs.front().final.true_error;
}

TEST(ClosedLoop, EstimatesWithinTheNoiseOfAnExactPlanChangeNothing) {
  // The plant is the planner's model: the estimates differ from the plan's states by the averaged
  // markers' noise only (their drop of χ² from the plan's state is about χ² with k degrees of
  // freedom), so none passes the gate (k + 3√(2k)) and the plant ends exactly where the open loop's
  // does. Acting on every estimate instead re-plans from noisy states and moves the end.
  ValidationOptions options;
  const ValidationResult open =
      validate_plan(band_problem(), band_plan(), PlantModel{}, MarkerSensorModel{}, options);
  options.closed_loop = true;
  options.planning.steps = 3;
  const ValidationResult gated =
      validate_plan(band_problem(), band_plan(), PlantModel{}, MarkerSensorModel{}, options);
  ASSERT_EQ(gated.status, ValidationStatus::Complete) << gated.brief();
  for (const Checkpoint& c : gated.runs.front().checkpoints) {
    EXPECT_TRUE(c.estimate.converged()) << c.message;
    EXPECT_FALSE(c.significant) << c.estimate.prior_chi2 - c.estimate.chi2;
    EXPECT_FALSE(c.replanned) << c.message;
    EXPECT_LT(c.estimate.chi2, c.estimate.prior_chi2);  // the fit is at least as good as the prior
  }
  // The same final pose; the closed loop drives the plant segment by segment, so its solves run
  // along other samples and agree to the shooting tolerance (1e-10), not bit for bit.
  EXPECT_NEAR(gated.runs.front().final.true_error, open.runs.front().final.true_error, 1e-9);
  options.loop.significance = -1.0;
  const ValidationResult always =
      validate_plan(band_problem(), band_plan(), PlantModel{}, MarkerSensorModel{}, options);
  for (const Checkpoint& c : always.runs.front().checkpoints) EXPECT_TRUE(c.replanned) << c.message;
  EXPECT_GT(std::abs(always.runs.front().final.true_error - open.runs.front().final.true_error),
            1e-6);
}

TEST(ClosedLoop, AHorizonOfOneStepGivesTheSameRunAsReplanningEverything) {
  // At a checkpoint, the next waypoint's step starts from the estimate towards the same objective
  // set whatever the horizon, and the later steps are re-planned at later checkpoints: the runs are
  // equal bit for bit, with one optimisation per checkpoint instead of one per remaining step.
  PlantModel plant;
  plant.stiffness_scale = 0.85;
  plant.grasp_offset.position = {0.002, 0.0, 0.0};
  ValidationOptions options;
  options.closed_loop = true;
  options.planning.steps = 3;
  MarkerSensorModel sensor;  // with noise: the estimates differ from the truth, equally in both
  options.loop.horizon = 0;  // re-plan every remaining step
  const ValidationResult all = validate_plan(band_problem(), band_plan(), plant, sensor, options);
  options.loop.horizon = 1;
  const ValidationResult next = validate_plan(band_problem(), band_plan(), plant, sensor, options);
  ASSERT_EQ(all.status, ValidationStatus::Complete) << all.brief();
  ASSERT_EQ(next.status, ValidationStatus::Complete) << next.brief();
  const ValidationRun &a = all.runs.front(), &b = next.runs.front();
  ASSERT_EQ(a.checkpoints.size(), 2u);
  ASSERT_EQ(b.checkpoints.size(), 2u);
  for (std::size_t k = 0; k < a.checkpoints.size(); ++k) {
    EXPECT_TRUE(b.checkpoints[k].replanned) << b.checkpoints[k].message;
    EXPECT_EQ(a.checkpoints[k].estimate.base_wrench.to_vector(),
              b.checkpoints[k].estimate.base_wrench.to_vector());
  }
  EXPECT_NE(b.checkpoints.front().message.find("a horizon of 1"), std::string::npos)
      << b.checkpoints.front().message;
  EXPECT_EQ(a.error_3d, b.error_3d);
  EXPECT_EQ(a.true_error, b.true_error);
  EXPECT_EQ(a.final.true_error, b.final.true_error);
  options.loop.horizon = -1;
  EXPECT_THROW(validate_plan(band_problem(), band_plan(), plant, sensor, options), InputError);
}

TEST(ClosedLoop, FusedEstimatesAddUpAcrossCheckpoints) {
  // The paper's mismatch seen through the Kinect-like noise, with a checkpoint at each of 5
  // waypoints. Each estimate alone knows the weight and the grasp offset to the averaged markers'
  // noise; fused (each posterior the next prior) the information of the checkpoints adds up, so the
  // beliefs the plan ends with are tighter and the plant ends nearer the points (the mean over 6
  // seeds; measured 0.16 against 0.28 mm). The posterior of the weight's factor shrinks from
  // checkpoint to checkpoint.
  const PlantModel plant = paper_mismatch();
  ValidationOptions options;
  options.closed_loop = true;
  options.runs = 6;
  options.planning.steps = 6;
  options.loop.estimation.gravity = Eigen::Vector3d(0.0, 0.0, -9.81);
  PlanOptions planning;
  planning.steps = 6;
  const PlanResult plan = rodshape::plan(band_problem(), planning);
  ASSERT_EQ(plan.status, PlanStatus::Complete) << plan.brief();
  auto mean_final = [&](bool fuse) {
    options.loop.fuse = fuse;
    const ValidationResult result =
        validate_plan(band_problem(), plan, plant, MarkerSensorModel{}, options);
    EXPECT_EQ(result.status, ValidationStatus::Complete) << result.brief();
    double mean = 0.0;
    for (const ValidationRun& run : result.runs) mean += run.final.true_error / options.runs;
    for (const ValidationRun& run : result.runs) {
      for (std::size_t k = 1; fuse && k < run.checkpoints.size(); ++k) {
        EXPECT_LT(run.checkpoints[k].estimate.load_factor_sigma,
                  run.checkpoints[k - 1].estimate.load_factor_sigma);
      }
    }
    return mean;
  };
  const double fused = mean_final(true), alone = mean_final(false);
  EXPECT_LT(fused, alone) << "fused " << fused << " m, each estimate alone " << alone << " m";
}

TEST(ClosedLoop, APerfectSensorIsTheEasyCase) {
  // Issue 22: with zero marker noise the estimates' residuals were in units of a 1 µm σ, so under
  // a plant the model cannot match exactly (the paper's mismatch, a rest curvature and unequal
  // bending stiffnesses: docs/validation.md's unmodelled plant) every estimate was "not
  // explained" and discarded, and the closed loop ended where the open loop does, worse than with
  // the Kinect-like noise. With the sigmas floored (EstimationOptions::min_marker_sigma, 0.1 mm)
  // the perfect sensor's estimates are used and the run ends at least as near as the noisy ones.
  PlanTask task = read_plan_task(std::string(RODSHAPE_SOURCE_DIR) + "/examples/plan_c_arc.yaml");
  const PlanResult plan = rodshape::plan(task.problem, task.options);
  ASSERT_EQ(plan.status, PlanStatus::Complete) << plan.brief();
  PlantModel plant = paper_mismatch();
  plant.rest_curvature = Eigen::Vector3d(0.5, 0.3, 0.0);
  plant.factors.EIx = 1.2;
  plant.factors.EIy = 0.9;
  ValidationOptions options;
  options.closed_loop = true;
  options.planning = task.options;
  options.loop = task.closed_loop;
  options.loop.estimation.gravity = Eigen::Vector3d(0.0, 0.0, -9.81);
  const ValidationResult perfect = validate_plan(task.problem, plan, plant, noiseless(), options);
  options.runs = 2;
  const ValidationResult noisy =
      validate_plan(task.problem, plan, plant, MarkerSensorModel{}, options);
  ASSERT_EQ(perfect.status, ValidationStatus::Complete) << perfect.brief();
  ASSERT_EQ(noisy.status, ValidationStatus::Complete) << noisy.brief();
  const ValidationRun& run = perfect.runs.front();
  ASSERT_FALSE(run.checkpoints.empty());
  for (const Checkpoint& c : run.checkpoints) {
    EXPECT_TRUE(c.consistent) << c.message;  // the residual is in units the model can meet
    EXPECT_LE(c.estimate.residual, options.loop.max_residual) << c.message;
  }
  for (const ValidationRun& other : noisy.runs)
    EXPECT_LE(run.final.true_error, other.final.true_error)
        << "perfect " << run.final.true_error << " m, noisy " << other.final.true_error << " m";
}

// With an arm, the plant is driven by the joint trajectory through the arm's forward kinematics:
// the poses the hand really takes. IK holds each sample to 1e-10 m and rad (IkOptions), so the
// plant ends where the end-effector path would have driven it, to the plant's solver tolerance.
TEST(PlanValidation, AnArmsPlanDrivesThePlantByItsJoints) {
  const PlanTask task =
      read_plan_task(std::string(RODSHAPE_SOURCE_DIR) + "/examples/plan_panda_s_curve.yaml");
  const PlanResult plan = rodshape::plan(task.problem, task.options);
  ASSERT_EQ(plan.status, PlanStatus::Complete) << plan.message;
  ASSERT_TRUE(plan.arm && plan.arm->joints.complete());
  const JointTrajectoryResult& joints = plan.arm->joints;
  ASSERT_TRUE(drives_joints(task.problem, plan));
  const std::vector<TimedPose> commanded = commanded_path(task.problem, plan);
  ASSERT_EQ(commanded.size(), joints.t.size());
  for (std::size_t k = 0; k < commanded.size(); ++k) EXPECT_EQ(commanded[k].t, joints.t[k]);
  const Pose& planned_end = plan.end_effector_path.back().pose;
  EXPECT_LE((commanded.back().pose.position - planned_end.position).norm(), 1e-9);
  EXPECT_LE(testing::rotation_angle(commanded.back().pose.rotation, planned_end.rotation), 1e-9);

  const ValidationResult by_joints = validate_plan(task.problem, plan, {}, noiseless());
  ASSERT_EQ(by_joints.status, ValidationStatus::Complete) << by_joints.brief();
  EXPECT_TRUE(by_joints.driven_by_joints());
  EXPECT_EQ(by_joints.plant.solves, static_cast<int>(commanded.size()));
  PlanResult without_joints = plan;
  without_joints.arm->joints.status = JointTrajectoryStatus::NotRun;
  EXPECT_FALSE(drives_joints(task.problem, without_joints));
  const ValidationResult by_path = validate_plan(task.problem, without_joints, {}, noiseless());
  ASSERT_EQ(by_path.status, ValidationStatus::Complete) << by_path.brief();
  EXPECT_FALSE(by_path.driven_by_joints());
  // Same rod, same final pose to 1e-9 m: the same last equilibrium (residual 1e-10, scaled).
  EXPECT_LT(max_node_distance(by_joints.plant.last.configuration, by_path.plant.last.configuration),
            1e-8);
  EXPECT_NEAR(by_joints.runs[0].final.true_error, by_path.runs[0].final.true_error, 1e-8);
  // The closed loop solves each segment's joints from the arm's as it goes: with an exact plant
  // and noise-free markers it changes nothing, and ends on the same equilibrium.
  ValidationOptions closed;
  closed.closed_loop = true;
  const ValidationResult loop = validate_plan(task.problem, plan, {}, noiseless(), closed);
  ASSERT_EQ(loop.status, ValidationStatus::Complete) << loop.brief();
  EXPECT_TRUE(loop.driven_by_joints());
  for (const Checkpoint& c : loop.runs[0].checkpoints) EXPECT_FALSE(c.replanned) << c.message;
  EXPECT_LT(max_node_distance(loop.plant.last.configuration, by_joints.plant.last.configuration),
            1e-8);
  // An arm that cannot reach the path (its base moved 1 m away after planning): the closed loop's
  // IK fails and the plant follows the end-effector poses instead, to the same end.
  PlanProblem moved = task.problem;
  moved.arm->placement.world_T_base.position.x() -= 1.0;
  const ValidationResult unreachable = validate_plan(moved, plan, {}, noiseless(), closed);
  ASSERT_EQ(unreachable.status, ValidationStatus::Complete) << unreachable.brief();
  EXPECT_FALSE(unreachable.driven_by_joints());
  EXPECT_LT(
      max_node_distance(unreachable.plant.last.configuration, by_path.plant.last.configuration),
      1e-8);
}

// Found by a mismatch the model cannot absorb (a rest curvature and unequal bending stiffnesses in
// the plant, besides the paper's mismatch): in run 8 of plan_c_arc, a re-plan's next step came out
// of IPOPT as a coiled optimum of 3.68 J where the plan's had 0.06 J, the plant was bent towards
// it, and the run ended 8.2 mm off (25 mm once the estimates the model could not explain were no
// longer used). A re-planned step with more than max_energy_ratio × the energy of the step it
// replaces is refused, and the run ends within a millimetre, like the other seeds.
// Which optimum IPOPT reaches depends on its path: the coil came with MUMPS as its linear solver;
// since small KKT systems go to the dense solver (issue 26), no re-plan of this run coils (nor of
// seeds 1-12, nor with other rest curvatures tried), so the run is the same with the test and
// without it. The refusal itself is tested in tests/feedback/test_replan_gentleness.cpp; here,
// whichever path IPOPT takes, a refused re-plan must have been a shape the model cannot explain.
TEST(ClosedLoop, ARePlanThatIsNotGentleIsRefused) {
  PlanTask task = read_plan_task(std::string(RODSHAPE_SOURCE_DIR) + "/examples/plan_c_arc.yaml");
  task.plant = paper_mismatch();
  task.plant.rest_curvature = Eigen::Vector3d(0.5, 0.3, 0.0);
  task.plant.factors.EIx = 1.2;
  task.plant.factors.EIy = 0.9;
  task.closed_loop.estimation.gravity = Eigen::Vector3d(0.0, 0.0, -9.81);
  const PlanResult plan = rodshape::plan(task.problem, task.options);
  ASSERT_EQ(plan.status, PlanStatus::Complete) << plan.message;
  ValidationOptions options;
  options.closed_loop = true;
  options.loop = task.closed_loop;
  options.planning = task.options;
  options.seed = 8;
  const ValidationResult result =
      validate_plan(task.problem, plan, task.plant, task.sensor, options);
  ASSERT_EQ(result.status, ValidationStatus::Complete) << result.brief();
  EXPECT_LT(result.runs[0].final.true_error, 1e-3);  // issue 10's aim
  bool refused = false;
  for (const Checkpoint& c : result.runs[0].checkpoints) {
    EXPECT_TRUE(c.consistent) << c.message;
    refused = refused || c.message.find("the re-plan was refused") != std::string::npos;
  }
  options.loop.max_energy_ratio = 1e9;
  const ValidationResult coiled =
      validate_plan(task.problem, plan, task.plant, task.sensor, options);
  if (!refused) {  // nothing for the test to refuse: the same run without it
    EXPECT_EQ(coiled.runs[0].final.true_error, result.runs[0].final.true_error);
    return;
  }
  // Without the test, the plant bent towards the coiled step is a shape the model cannot explain
  // (residuals of 50-70 σ): those estimates are neither fused nor acted on (max_residual).
  int inconsistent = 0;
  for (const Checkpoint& c : coiled.runs[0].checkpoints) {
    if (c.consistent) continue;
    ++inconsistent;
    EXPECT_GT(c.estimate.residual, options.loop.max_residual);
    EXPECT_FALSE(c.significant);
    EXPECT_NE(c.message.find("the model does not explain the markers"), std::string::npos)
        << c.message;
  }
  EXPECT_GT(inconsistent, 0);
  EXPECT_GT(coiled.runs[0].final.true_error, 1e-3);  // beyond issue 10's aim
}

}  // namespace
}  // namespace test_plan_validation
}  // namespace rodshape
