// test_plan_reader.cpp: the plan task file. One case per kind of bad plan field, each asserting
// that the one-line message names the file, the line and the field; the sections a plan adds read
// into the request and options they describe; the bundled plan examples read.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "rodshape/io/task_reader.hpp"
#include "rodshape/io/validation_output.hpp"
#include "rodshape/trajectory/plan.hpp"
#include "support/eigen_compare.hpp"
#include "support/input_error.hpp"
#include "support/task_text.hpp"

namespace rodshape {
namespace test_plan_reader {
namespace {

using testing::CompareMatrices;

// Line numbers below refer to this text.
const std::string kPlan = R"(rod:
  length: 0.29
  nodes: 51
  section: {shape: rectangle, width: 0.02, height: 0.02}
  material: {young_modulus: 3.2e6, poisson_ratio: 0.5, density: 1392}
  stiffness: {EIx: 0.04, EIy: 0.04, GJ: 0.028}
target:
  points:
    - [0.003, 0.000, 0.028]
    - [0.047, 0.000, 0.101]
    - [0.126, 0.000, 0.133]
weights:
  energy: 0.001
  distance: 1
workspace:
  box: {lower: [-1, -1, 0.05], upper: [1, 1, 1]}
  inside:
    - {center: [0, 0, 0], radius: 0.5}
trajectory:
  steps: 3
)";

/// kPlan with the first occurrence of `from` replaced by `to`.
std::string plan_with(const std::string& from, const std::string& to) {
  return testing::replaced_first(kPlan, from, to);
}

/// The message of the InputError that plan() throws for the task `text`, located by
/// PlanTask::locate, or "" if it plans (with one step, checked only that it throws).
std::string plan_error_of(const std::string& text) {
  PlanTask task = parse_plan_task(text, "plan.yaml");
  task.options.steps = 1;
  const std::string message = testing::input_error_message([&] {
    try {
      plan(task.problem, task.options);
    } catch (const InputError& error) {
      throw InputError(task.locate(error));
    }
  });
  EXPECT_EQ(message.find('\n'), std::string::npos) << "not one line: " << message;
  return message;
}

/// The message of the InputError that reading `text` throws, or "" if it reads.
std::string error_of(const std::string& text) {
  const std::string message =
      testing::input_error_message([&] { parse_plan_task(text, "plan.yaml"); });
  EXPECT_EQ(message.find('\n'), std::string::npos) << "not one line: " << message;
  return message;
}

// ---- bad input: one case per field --------------------------------------------------------------

TEST(PlanReader, EmptyPointListIsNamedAtItsLine) {
  const std::string message =
      error_of(plan_with("  points:\n    - [0.003, 0.000, 0.028]\n    - [0.047, 0.000, 0.101]\n"
                         "    - [0.126, 0.000, 0.133]\n",
                         "  points: []\n"));
  EXPECT_EQ(message, "plan.yaml:8: target.points is empty: give at least one objective point");
}

TEST(PlanReader, MissingTargetIsRequired) {
  std::string text = kPlan;
  text.erase(text.find("target:"), text.find("weights:") - text.find("target:"));
  EXPECT_EQ(error_of(text), "plan.yaml: target is required");
}

TEST(PlanReader, BadPointIsNamedWithItsIndex) {
  const std::string message = error_of(plan_with("[0.047, 0.000, 0.101]", "[0.047, 0.101]"));
  EXPECT_EQ(message,
            "plan.yaml:10: target.points[1]: expected a list of 3 numbers [x, y, z], got a list "
            "of 2");
}

TEST(PlanReader, NegativeWeightIsNamed) {
  const std::string message = error_of(plan_with("energy: 0.001", "energy: -1"));
  EXPECT_EQ(message, "plan.yaml:13: weights.energy = -1 must be >= 0");
}

TEST(PlanReader, BothWeightsZeroIsNamed) {
  const std::string message =
      error_of(plan_with("energy: 0.001\n  distance: 1", "energy: 0\n  distance: 0"));
  EXPECT_EQ(
      message,
      "plan.yaml:13: weights.energy and weights.distance are both 0: at least one must be > 0");
}

TEST(PlanReader, ZeroStepsIsNamed) {
  const std::string message = error_of(plan_with("steps: 3", "steps: 0"));
  EXPECT_EQ(message, "plan.yaml:20: trajectory.steps = 0 must be >= 1");
}

TEST(PlanReader, FractionalStepsIsNamed) {
  const std::string message = error_of(plan_with("steps: 3", "steps: 2.5"));
  EXPECT_EQ(message, "plan.yaml:20: trajectory.steps = 2.5 must be a whole number");
}

TEST(PlanReader, BadWorkspaceRadiusIsNamedWithItsIndex) {
  const std::string message = error_of(plan_with("radius: 0.5", "radius: -0.5"));
  EXPECT_EQ(message, "plan.yaml:18: workspace.inside[0].radius = -0.5 must be > 0");
}

TEST(PlanReader, InvertedWorkspaceBoxIsNamed) {
  const std::string message = error_of(plan_with("upper: [1, 1, 1]", "upper: [1, -2, 1]"));
  EXPECT_TRUE(message.starts_with("plan.yaml:16: workspace.box: lower[1] = -1 is above upper[1]"))
      << message;
}

TEST(PlanReader, WorkspaceExcludingTheRestingTipIsNamed) {
  // The band at rest has its tip at z = 0.29, above this box.
  // plan() finds it (the reader does not solve equilibria); PlanTask::locate says it in the file's
  // names and at the workspace's line.
  const std::string message = plan_error_of(plan_with("upper: [1, 1, 1]", "upper: [1, 1, 0.2]"));
  EXPECT_EQ(message,
            "plan.yaml:15: workspace excludes the initial tip at [0, 0, 0.29] (the rod at rest; "
            "set initial.tip)");
}

TEST(PlanReader, WorkspaceExcludingTheInitialTipIsNamed) {
  // A moment bending the band into a half circle (κ L = m L / EI = π) puts its tip at z ≈ 0,
  // below the box.
  const std::string message =
      plan_error_of(kPlan + "initial:\n  base_wrench: {moment: [0, 0.4333, 0]}\n");
  EXPECT_TRUE(message.starts_with("plan.yaml:15: workspace excludes the initial tip at ["))
      << message;
  EXPECT_TRUE(message.ends_with("(initial)")) << message;
}

TEST(PlanReader, AnInitialTipWithNoEquilibriumIsNamedAtItsLine) {
  // 0.6 m from the clamp: further than the rod (0.29 m) can reach.
  const std::string message =
      plan_error_of(kPlan + "initial:\n  tip: {position: [0.6, 0, 0.1], rotation: [1, 0, 0, 0]}\n");
  // Said before solving (issue 24, item 5), with the reach: 0.29 m × √(1.5² + 0.5² + 0.5²).
  EXPECT_TRUE(
      message.starts_with("plan.yaml:22: initial.tip: the position is 0.608276 m from the "
                          "clamp, out of reach"))
      << message;
  EXPECT_TRUE(message.ends_with("reaches at most 0.480911 m")) << message;
}

TEST(PlanReader, TipSectionIsRejectedWithTheReason) {
  const std::string message = error_of(kPlan + "tip:\n  position: [0.1, 0, 0.2]\n");
  EXPECT_EQ(message,
            "plan.yaml:21: tip: unknown key; a plan decides the tip pose itself: give the pose the "
            "robot starts from as initial.tip, and what the grasp cannot transmit as "
            "grasp.zero_wrench");
}

TEST(PlanReader, SolverSectionPointsToOptimizer) {
  const std::string message = error_of(kPlan + "solver: {max_iterations: 3}\n");
  EXPECT_TRUE(message.starts_with("plan.yaml:21: solver: unknown key; solver is the equilibrium"))
      << message;
  EXPECT_NE(message.find("optimizer"), std::string::npos) << message;
}

TEST(PlanReader, UnknownKeySuggestsTheAllowedOne) {
  EXPECT_EQ(error_of(plan_with("steps: 3", "stesp: 3")),
            "plan.yaml:20: trajectory.stesp: unknown key; did you mean 'steps'?");
  EXPECT_EQ(error_of(plan_with("weights:", "wieghts:")),
            "plan.yaml:12: wieghts: unknown key; did you mean 'weights'?");
  EXPECT_EQ(error_of(kPlan + "optimiser: {max_iterations: 3}\n"),
            "plan.yaml:21: optimiser: unknown key; did you mean 'optimizer'?");
}

TEST(PlanReader, WeightsUnderTargetSayWhereTheyBelong) {
  const std::string message = error_of(plan_with("  points:\n", "  energy: 1\n  points:\n"));
  EXPECT_EQ(message,
            "plan.yaml:8: target.energy: unknown key; energy belongs in the top-level section "
            "weights");
}

TEST(PlanReader, BadGraspAxisIsNamed) {
  const std::string message = error_of(kPlan + "grasp: {zero_wrench: [mx, rx]}\n");
  EXPECT_TRUE(message.starts_with("plan.yaml:21: grasp.zero_wrench[1] = rx is not"));
}

TEST(PlanReader, NonPositiveStrainLimitIsNamed) {
  const std::string message = error_of(kPlan + "limits:\n  max_curvature: 0\n");
  EXPECT_EQ(message, "plan.yaml:22: limits.max_curvature = 0 must be > 0");
}

TEST(PlanReader, NonPositiveSpeedIsNamed) {
  const std::string message = error_of(plan_with("steps: 3", "steps: 3\n  max_linear_speed: 0"));
  EXPECT_EQ(message, "plan.yaml:21: trajectory.max_linear_speed = 0 must be > 0");
}

TEST(PlanReader, NegativeOptimizerIterationsIsNamed) {
  const std::string message = error_of(kPlan + "optimizer: {max_iterations: -1}\n");
  EXPECT_EQ(message, "plan.yaml:21: optimizer.max_iterations = -1 must be >= 0");
}

// ---- sizes: every count a user sets has a bound (docs/limits.md, "Sizes") ---------------------

TEST(PlanReader, SizesBeyondTheirBoundsAreNamedAsWritten) {
  struct Bad {
    std::string text;
    const char* message;
  };
  const std::vector<Bad> cases = {
      {plan_with("steps: 3", "steps: 1e9"), "plan.yaml:20: trajectory.steps = 1e9 must be <= 1000"},
      {plan_with("steps: 3", "steps: 3\n  tracking_substeps: 1e9"),
       "plan.yaml:21: trajectory.tracking_substeps = 1e9 must be <= 1000"},
      {plan_with("steps: 3", "steps: 3\n  max_refinements: 101"),
       "plan.yaml:21: trajectory.max_refinements = 101 must be <= 100"},
      {plan_with("steps: 3", "steps: 3\n  rate: 1e9"),
       "plan.yaml:21: trajectory.rate = 1e9 must be <= 10000"},
      {kPlan + "optimizer: {max_iterations: 10001}\n",
       "plan.yaml:21: optimizer.max_iterations = 10001 must be <= 10000"},
      {kPlan + "optimizer: {multi_starts: 1e6}\n",
       "plan.yaml:21: optimizer.multi_starts = 1e6 must be <= 100"},
      {plan_with("nodes: 51", "nodes: 5002"),
       "plan.yaml:3: rod.nodes = 5002 must be <= 5001 for a plan"},
  };
  for (const Bad& bad : cases) {
    SCOPED_TRACE(bad.message);
    EXPECT_EQ(error_of(bad.text), bad.message);
  }
}

// trajectory.interpolation: every scheme's name reads as that scheme, auto by default; anything
// else is named with the choices.
TEST(PlanReader, InterpolationNamesReadAndAMisspellingIsNamed) {
  EXPECT_EQ(parse_plan_task(kPlan, "plan.yaml").options.interpolation,
            ObjectiveInterpolation::Auto);
  for (ObjectiveInterpolation scheme :
       {ObjectiveInterpolation::Auto, ObjectiveInterpolation::Shape,
        ObjectiveInterpolation::ArcLength, ObjectiveInterpolation::Projection,
        ObjectiveInterpolation::Pose, ObjectiveInterpolation::Search}) {
    const std::string text =
        plan_with("steps: 3", "steps: 3\n  interpolation: " + to_string(scheme));
    EXPECT_EQ(parse_plan_task(text, "plan.yaml").options.interpolation, scheme)
        << to_string(scheme);
  }
  const std::string message = error_of(plan_with("steps: 3", "steps: 3\n  interpolation: posture"));
  EXPECT_NE(message.find("plan.yaml:21: trajectory.interpolation"), std::string::npos) << message;
  EXPECT_NE(message.find("pose"), std::string::npos) << message;
}

TEST(PlanReader, SizesAtTheirBoundsRead) {
  const PlanTask big_rod = parse_plan_task(plan_with("nodes: 51", "nodes: 5001"), "plan.yaml");
  EXPECT_EQ(big_rod.problem.rod.intervals, PlanProblem::kMaxIntervals);
  // Two nodes, so that the sizes' product stays within the estimated-time bound.
  const PlanTask bounds = parse_plan_task(
      testing::replaced_first(plan_with("nodes: 51", "nodes: 2"), "steps: 3",
                              "steps: 1000\n  tracking_substeps: 1000\n  max_refinements: 100\n"
                              "  rate: 10000\n  max_linear_speed: 0.1") +
          "optimizer: {max_iterations: 10000, multi_starts: 100}\n",
      "plan.yaml");
  EXPECT_EQ(bounds.options.steps, PlanOptions::kMaxSteps);
  EXPECT_EQ(bounds.options.tracking_substeps, PlanOptions::kMaxTrackingSubsteps);
  EXPECT_EQ(bounds.options.max_refinements, PlanOptions::kMaxRefinements);
  EXPECT_EQ(bounds.options.end_effector.sample_rate, EndEffectorLimits::kMaxSampleRate);
  EXPECT_EQ(bounds.options.optimiser.multi_starts, ShapeOptimiserOptions::kMaxMultiStarts);
}

TEST(PlanReader, SizesWhoseProductWouldTakeTooLongAreNamedWithTheEstimate) {
  const std::string big_rod = plan_with("nodes: 51", "nodes: 5001");
  const std::string message = error_of(testing::replaced_first(big_rod, "steps: 3", "steps: 10") +
                                       "optimizer: {multi_starts: 100}\n");
  EXPECT_EQ(message,
            "plan.yaml: the plan would take about 6.3e+02 s, estimated from trajectory.steps = 10, "
            "optimizer.multi_starts = 100, 5001 rod nodes, 3 target.points and "
            "trajectory.tracking_substeps = 10; at most 300 s (docs/limits.md): lower one of them");
}

TEST(PlanReader, SlowLimitsAreNamedWithWhatTheyWouldCost) {
  EXPECT_EQ(error_of(plan_with("steps: 3", "steps: 3\n  max_linear_speed: 1e-12")),
            "plan.yaml:21: trajectory.max_linear_speed = 1e-12: a move of 1 m from rest to rest "
            "would take 1e+12 s, 1e+14 samples at trajectory.rate = 100 Hz; an end-effector path "
            "has at most 1e+06 samples");
  EXPECT_EQ(
      error_of(plan_with("steps: 3", "steps: 3\n  max_angular_acceleration: 1e-12")),
      "plan.yaml:21: trajectory.max_angular_acceleration = 1e-12: a move of 1 rad from rest "
      "to rest would take 2e+06 s, 2e+08 samples at trajectory.rate = 100 Hz; an end-effector "
      "path has at most 1e+06 samples");
}

TEST(PlanReader, TooManyTargetPointsOrWorkspaceSetsAreNamed) {
  std::string points;
  for (int i = 0; i < 1001; ++i) points += "    - [0.003, 0.000, 0.028]\n";
  const std::string many_points =
      kPlan.substr(0, kPlan.find("    - [0.003")) + points + kPlan.substr(kPlan.find("weights:"));
  EXPECT_EQ(error_of(many_points), "plan.yaml:8: target.points has 1001 entries; at most 1000");
  std::string balls;
  for (int i = 0; i < 101; ++i) balls += "    - {center: [0, 0, 0], radius: 0.5}\n";
  EXPECT_EQ(error_of(plan_with("    - {center: [0, 0, 0], radius: 0.5}\n", balls)),
            "plan.yaml:17: workspace.inside has 101 entries; at most 100");
}

TEST(PlanReader, InvertedWrenchBoundIsNamed) {
  const std::string message = error_of(
      kPlan + "wrench_bounds:\n  lower: {force: [0, 0, 1]}\n  upper: {force: [1, 1, 0]}\n");
  EXPECT_EQ(message, "plan.yaml:21: wrench_bounds: lower.force[2] is above upper.force[2]");
}

TEST(PlanReader, EquilibriumTaskRejectsPlanSectionsWithTheReason) {
  const std::string band =
      "rod:\n  length: 0.29\n  stiffness: {EA: 1e3, GA: 1e3, EIx: 0.04, EIy: 0.04, GJ: 0.028}\n"
      "tip:\n  position: [0.12, 0, 0.22]\ntarget:\n  points: [[0, 0, 0.1]]\n";
  EXPECT_EQ(testing::input_error_message([&] { parse_equilibrium_task(band, "eq.yaml"); }),
            "eq.yaml:6: target: unknown key; target is a section of plan tasks (rodshape plan), "
            "not of equilibrium");
}

// ---- good input ---------------------------------------------------------------------------------

TEST(PlanReader, SectionsReadIntoTheRequestAndOptions) {
  const std::string text =
      kPlan +
      "  max_linear_speed: 0.05\n  max_angular_speed: 0.3\n"
      "  max_linear_acceleration: 0.2\n  max_angular_acceleration: 2\n"
      "  rate: 50\n  track: false\n  tracking_substeps: 4\n"
      "grasp:\n  zero_wrench: [mx, fy]\n"
      "  tip_to_end_effector: {position: [0, 0, 0.03]}\n"
      "initial:\n  tip: {position: [0.05, 0, 0.28]}\n"
      "limits: {max_curvature: 12, max_axial_strain: 0.05}\n"
      "wrench_bounds:\n  lower: {moment: [-1, -1, -1]}\n"
      "optimizer: {max_iterations: 40, tolerance: 1e-7, "
      "constraint_tolerance: 1e-8, multi_starts: 2, confine_to_scale: false}\n";
  const PlanTask task = parse_plan_task(text, "plan.yaml");
  const PlanProblem& problem = task.problem;
  EXPECT_EQ(task.source, "plan.yaml");
  EXPECT_EQ(problem.rod.intervals, 50);
  ASSERT_EQ(problem.target.points.size(), 3u);
  EXPECT_TRUE(CompareMatrices(problem.target.points[1], Eigen::Vector3d(0.047, 0, 0.101), 0.0));
  EXPECT_EQ(problem.target.energy_weight, 0.001);
  EXPECT_EQ(problem.target.distance_weight, 1.0);
  EXPECT_FALSE(problem.target.squared_distances);
  ASSERT_TRUE(problem.workspace.box.has_value());
  EXPECT_TRUE(CompareMatrices(problem.workspace.box->lower, Eigen::Vector3d(-1, -1, 0.05), 0.0));
  ASSERT_EQ(problem.workspace.inside.size(), 1u);
  EXPECT_EQ(problem.workspace.inside[0].radius, 0.5);
  const std::array<bool, 6> released{false, true, false, true, false, false};
  EXPECT_EQ(problem.grasp.released, released);
  EXPECT_TRUE(CompareMatrices(problem.grasp.tip_to_end_effector.position,
                              Eigen::Vector3d(0, 0, 0.03), 0.0));
  ASSERT_EQ(problem.initial.kind, InitialState::Kind::HeldTip);
  EXPECT_TRUE(CompareMatrices(problem.initial.tip.position, Eigen::Vector3d(0.05, 0, 0.28), 0.0));
  EXPECT_EQ(problem.limits.max_curvature, 12.0);
  EXPECT_EQ(problem.limits.max_axial_strain, 0.05);
  EXPECT_EQ(problem.wrench_bounds.lower(3), -1.0);
  EXPECT_EQ(problem.wrench_bounds.lower(0), -std::numeric_limits<double>::infinity());
  EXPECT_EQ(problem.wrench_bounds.upper(5), std::numeric_limits<double>::infinity());

  const PlanOptions& options = task.options;
  EXPECT_EQ(options.steps, 3);
  EXPECT_EQ(options.end_effector.max_linear_speed, 0.05);
  EXPECT_EQ(options.end_effector.max_angular_speed, 0.3);
  EXPECT_EQ(options.end_effector.max_linear_acceleration, 0.2);
  EXPECT_EQ(options.end_effector.max_angular_acceleration, 2.0);
  EXPECT_EQ(options.end_effector.sample_rate, 50.0);
  EXPECT_FALSE(options.track_between_waypoints);
  EXPECT_EQ(options.tracking_substeps, 4);
  EXPECT_EQ(options.optimiser.max_iterations, 40);
  EXPECT_EQ(options.optimiser.tolerance, 1e-7);
  EXPECT_EQ(options.optimiser.constraint_tolerance, 1e-8);
  EXPECT_EQ(options.optimiser.multi_starts, 2);
  EXPECT_FALSE(options.optimiser.confine_to_scale);
}

TEST(PlanReader, DefaultsApplyWhenLeftOut) {
  const std::string text =
      "rod:\n  length: 0.29\n  stiffness: {EA: 1e3, GA: 1e3, EIx: 0.04, EIy: 0.04, GJ: 0.028}\n"
      "target:\n  points: [[0.01, 0, 0.1]]\n";
  const PlanTask task = parse_plan_task(text, "plan.yaml");
  const PlanOptions defaults;
  EXPECT_EQ(task.problem.target.energy_weight, 1e-3);  // the task file's default, not the library's
  EXPECT_EQ(task.problem.target.distance_weight, 1.0);
  EXPECT_TRUE(task.problem.workspace.unbounded());
  EXPECT_EQ(task.problem.initial.kind, InitialState::Kind::Rest);
  EXPECT_FALSE(task.problem.limits.max_curvature.has_value());
  EXPECT_EQ(task.problem.grasp.released, (std::array<bool, 6>{}));
  EXPECT_EQ(task.options.steps, defaults.steps);
  EXPECT_EQ(task.options.optimiser.max_iterations, defaults.optimiser.max_iterations);
  EXPECT_EQ(task.options.end_effector.max_linear_speed, defaults.end_effector.max_linear_speed);
  EXPECT_EQ(task.options.track_between_waypoints, defaults.track_between_waypoints);
}

TEST(PlanReader, BundledPlanExamplesRead) {
  const std::filesystem::path examples = std::filesystem::path(RODSHAPE_SOURCE_DIR) / "examples";
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(examples)) {
    const std::string name = entry.path().filename().string();
    if (!(name.starts_with("plan_") || name.starts_with("validate_")) ||
        entry.path().extension() != ".yaml")
      continue;
    SCOPED_TRACE(name);
    const PlanTask task = read_plan_task(entry.path().string());
    // Ten points, as the paper's markers, except the hook over part of the band.
    EXPECT_EQ(task.problem.target.points.size(), name == "plan_partial_hook.yaml" ? 5u : 10u);
    EXPECT_EQ(task.options.steps, name == "plan_cable_helix.yaml" ? 10 : 7);
    EXPECT_EQ(task.problem.arm.has_value(), name.starts_with("plan_panda_") ||
                                                name.starts_with("plan_fr3_") ||
                                                name == "plan_two_pandas.yaml");
    // The two with a moving base (issue 21), each with a base arm.
    const bool moving = name == "plan_two_pandas.yaml" || name == "plan_base_arm.yaml";
    EXPECT_EQ(task.problem.base_moves(), moving);
    EXPECT_EQ(task.problem.base_arm.has_value(), moving);
    if (name == "plan_panda_closed_loop.yaml") {  // the one with every section of `validate`
      EXPECT_DOUBLE_EQ(task.plant.stiffness_scale, 0.85);
      EXPECT_DOUBLE_EQ(task.plant.grasp_offset.position.x(), 0.002);
      EXPECT_DOUBLE_EQ(task.sensor.dropout, 0.05);
      EXPECT_TRUE(task.sensor.wrist.has_value());
      EXPECT_TRUE(task.closed_loop.estimation.gravity.has_value());
    }
    // Only the depth camera's example is seen by one, the others by markers (sensor.kind).
    EXPECT_EQ(task.depth_sensor.has_value(), name == "validate_depth_camera.yaml");
    if (name == "plan_panda_shelf.yaml") {  // the arm in a scene, its links kept clear
      ASSERT_EQ(task.problem.scene.obstacles.size(), 4u);
      EXPECT_EQ(task.problem.scene.obstacles[1].name, "board");
      EXPECT_TRUE(task.options.arm.link_clearance);
      EXPECT_DOUBLE_EQ(task.options.arm.link_influence, 0.03);
      EXPECT_EQ(task.problem.arm->model.link_capsules().size(), 14u);
    }
    if (name == "plan_fr3_s_curve.yaml") {  // the bundled FR3, by name
      EXPECT_EQ(task.problem.arm->model.robot_name(), "fr3");
    }
    if (name == "plan_around_post.yaml") {  // the one with a scene
      ASSERT_EQ(task.problem.scene.obstacles.size(), 2u);
      EXPECT_EQ(task.problem.scene.obstacles[1].name, "post");
      EXPECT_DOUBLE_EQ(task.problem.scene.clearance, 0.005);
      EXPECT_DOUBLE_EQ(task.problem.scene.rod_radius, 0.5 * std::hypot(0.02, 0.02));
    }
    ++count;
  }
  EXPECT_EQ(count, 17);  // 16 plan_*.yaml and validate_depth_camera.yaml
}

// ---- the plant's weight (issue 24, item 2)
// -------------------------------------------------------

/// The load of the plant's rod for kPlan with `extra` appended.
Eigen::Vector3d plant_load(const std::string& extra) {
  const PlanTask task = parse_plan_task(kPlan + extra, "plan.yaml");
  return task.plant.real_rod(task.problem.rod).load.force;
}

TEST(PlanReader, OneGravityActsOnThePlant) {
  const double rho_a = 1392 * 0.02 * 0.02;  // kg/m, the planner's
  const Eigen::Vector3d g(0.0, 0.0, -9.81);
  // The task's gravity alone: the plant carries the planner's weight, once.
  EXPECT_TRUE(CompareMatrices(plant_load("gravity: [0, 0, -9.81]\n"), rho_a * g, 1e-12));
  // plant.gravity replaces the task's (it was added to it: twice the weight).
  EXPECT_TRUE(CompareMatrices(
      plant_load("gravity: [0, 0, -9.81]\nplant: {gravity: [0, 0, -9.81]}\n"), rho_a * g, 1e-12));
  EXPECT_TRUE(
      CompareMatrices(plant_load("gravity: [0, 0, -9.81]\nplant: {gravity: [0, -9.81, 0]}\n"),
                      Eigen::Vector3d(0.0, -9.81 * rho_a, 0.0), 1e-12));
  // A weightless planner, a heavy plant (the paper's mismatch).
  EXPECT_TRUE(CompareMatrices(plant_load("plant: {gravity: [0, 0, -9.81]}\n"), rho_a * g, 1e-12));
  // plant.mass_per_length is the plant's own under the task's gravity (0 and double the
  // planner's gave the same plant).
  EXPECT_TRUE(CompareMatrices(plant_load("gravity: [0, 0, -9.81]\nplant: {mass_per_length: 0}\n"),
                              Eigen::Vector3d::Zero(), 1e-12));
  EXPECT_TRUE(CompareMatrices(plant_load("gravity: [0, 0, -9.81]\nplant: {mass_per_length: " +
                                         std::to_string(2 * rho_a) + "}\n"),
                              2 * rho_a * g, 1e-9));
}

TEST(PlanReader, ValidationJsonReportsTheWeightThePlantCarried) {
  const PlanTask task =
      parse_plan_task(kPlan + "gravity: [0, 0, -9.81]\nplant: {mass_per_length: 1}\n", "plan.yaml");
  ValidationResult result;
  result.real_rod = task.plant.real_rod(task.problem.rod);
  const nlohmann::json j = nlohmann::json::parse(validation_json(result, PlanResult{}, task));
  EXPECT_EQ(j["plant"]["gravity"], nlohmann::json::parse("[0, 0, -9.81]"));
  EXPECT_EQ(j["plant"]["mass_per_length"], 1.0);
}

// ---- the robot section --------------------------------------------------------------------------

const std::string kPanda = std::string(RODSHAPE_SOURCE_DIR) + "/data/robots/panda.urdf";

/// kPlan with a robot section (from line 21 on) whose other lines are `fields`.
std::string plan_with_robot(const std::string& fields) {
  return kPlan + "robot:\n  urdf: " + kPanda + "\n" + fields;
}

TEST(PlanReader, WithoutARobotSectionThereIsNoRobot) {
  EXPECT_FALSE(parse_plan_task(kPlan, "plan.yaml").problem.arm.has_value());
}

TEST(PlanReader, RobotSectionReadsTheArmItsPlacementAndSeed) {
  const PlanTask task = parse_plan_task(
      plan_with_robot("  base_link: panda_link0\n  tip_link: panda_link8\n"
                      "  base: {position: [-0.45, 0, -0.2]}\n"
                      "  flange_to_end_effector: {position: [0, 0, 0.1], rotation: [0, 1, 0, 0]}\n"
                      "  seed: [0, -0.5, 0, -2, 0, 1.5, 0.5]\n"),
      "plan.yaml");
  ASSERT_TRUE(task.problem.arm.has_value());
  EXPECT_EQ(task.problem.arm->model.joints(), 7);
  EXPECT_EQ(task.problem.arm->model.tip_link(), "panda_link8");
  EXPECT_TRUE(CompareMatrices(task.problem.arm->placement.world_T_base.position,
                              Eigen::Vector3d(-0.45, 0, -0.2), 0.0));
  EXPECT_TRUE(CompareMatrices(task.problem.arm->placement.flange_T_ee.position,
                              Eigen::Vector3d(0, 0, 0.1), 0.0));
  const Eigen::Matrix3d turn = Eigen::Vector3d(1, -1, -1).asDiagonal();  // π about x
  EXPECT_TRUE(CompareMatrices(task.problem.arm->placement.flange_T_ee.rotation, turn, 1e-15));
  ASSERT_EQ(task.options.arm.joints.seed.size(), 7);
  EXPECT_EQ(task.options.arm.joints.seed(3), -2.0);
}

TEST(PlanReader, RobotDefaultsAreIdentityPlacementAndNoSeed) {
  const PlanTask task = parse_plan_task(plan_with_robot(""), "plan.yaml");
  ASSERT_TRUE(task.problem.arm.has_value());
  EXPECT_TRUE(task.problem.arm->placement.world_T_base.rotation.isIdentity(0.0));
  EXPECT_TRUE(task.problem.arm->placement.flange_T_ee.position.isZero(0.0));
  EXPECT_EQ(task.options.arm.joints.seed.size(), 0);
}

TEST(PlanReader, RobotUrdfIsRelativeToTheTaskFile) {
  const std::string task_file = std::string(RODSHAPE_SOURCE_DIR) + "/examples/some_plan.yaml";
  const PlanTask task =
      parse_plan_task(kPlan + "robot:\n  urdf: ../data/robots/panda.urdf\n", task_file);
  ASSERT_TRUE(task.problem.arm.has_value());
  EXPECT_EQ(task.problem.arm->model.robot_name(), "panda");
}

TEST(PlanReader, RobotReachSectionReadsItsOptions) {
  const PlanTask defaults = parse_plan_task(plan_with_robot(""), "plan.yaml");
  EXPECT_TRUE(defaults.options.arm.use_reach);
  const PlanTask task = parse_plan_task(
      plan_with_robot("  reach: {use: false, margin: 0.05, tightening: 0.01, max_replans: 5, "
                      "samples: 100}\n"),
      "plan.yaml");
  const ArmPlanOptions& options = task.options.arm;
  EXPECT_FALSE(options.use_reach);
  EXPECT_EQ(options.reach_margin, 0.05);
  EXPECT_EQ(options.replan_tightening, 0.01);
  EXPECT_EQ(options.max_replans, 5);
  EXPECT_EQ(options.reach.samples, 100);
}

TEST(PlanReader, BadRobotFieldsAreNamedAtTheirLine) {
  EXPECT_EQ(error_of(plan_with_robot("  reach: {margin: -0.1}\n"))
                .rfind("plan.yaml:23: robot.reach.margin = -0.1 must be >= 0", 0),
            0u)
      << error_of(plan_with_robot("  reach: {margin: -0.1}\n"));
  EXPECT_EQ(error_of(plan_with_robot("  reach: {max_replans: -1}\n"))
                .rfind("plan.yaml:23: robot.reach.max_replans", 0),
            0u);
  EXPECT_NE(error_of(plan_with_robot("  reach: {marg: 0.1}\n")).find("robot.reach.marg"),
            std::string::npos);
  EXPECT_EQ(
      error_of(plan_with_robot("  tip_link: panda_hand\n"))
          .rfind("plan.yaml:23: robot.tip_link: " + kPanda + ": unknown tip link 'panda_hand'", 0),
      0u);
  EXPECT_EQ(error_of(plan_with_robot("  base_link: nowhere\n"))
                .rfind("plan.yaml:23: robot.base_link: ", 0),
            0u);
  EXPECT_NE(error_of(plan_with_robot("  bse: {position: [0, 0, 0]}\n")).find("robot.bse"),
            std::string::npos);
  EXPECT_EQ(error_of(plan_with_robot("  seed: [0, 0, 0]\n")).rfind("plan.yaml:23: robot.seed", 0),
            0u);
  EXPECT_EQ(error_of(kPlan + "robot:\n  urdf: /nowhere/arm.urdf\n")
                .rfind("plan.yaml:22: robot.urdf: /nowhere/arm.urdf: cannot read", 0),
            0u);
  EXPECT_NE(error_of(kPlan + "robot:\n  base_link: panda_link0\n").find("robot.urdf is required"),
            std::string::npos);
}

}  // namespace
}  // namespace test_plan_reader
}  // namespace rodshape
