// test_task_reader.cpp: the task-file reader. One case per kind of bad input, each asserting that
// the one-line message names the file, the line and the field; and the good cases: the bundled
// examples read into the expected rod, and equivalent spellings give equal tasks.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <variant>

#include "rodshape/io/task_reader.hpp"
#include "support/eigen_compare.hpp"
#include "support/input_error.hpp"
#include "support/task_text.hpp"

namespace rodshape {
namespace test_task_reader {
namespace {

using testing::CompareMatrices;
using testing::kBandTask;

::testing::AssertionResult StartsWith(const std::string& text, const std::string& prefix) {
  if (text.starts_with(prefix)) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "\"" << text << "\" does not start with \"" << prefix << "\"";
}

::testing::AssertionResult Contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "\"" << text << "\" does not contain \"" << part << "\"";
}

/// testing::kBandTask (line numbers below refer to it) with the first occurrence of `from` replaced
/// by `to`.
std::string band_with(const std::string& from, const std::string& to) {
  return testing::replaced_first(kBandTask, from, to);
}

/// The message of the InputError that reading `text` throws, or "" if it reads.
std::string error_of(const std::string& text) {
  const std::string message =
      testing::input_error_message([&] { parse_equilibrium_task(text, "task.yaml"); });
  EXPECT_EQ(message.find('\n'), std::string::npos) << "not one line: " << message;
  return message;
}

// ---- bad input: one case per field
// ----------------------------------------------------------------

TEST(TaskReader, MissingLengthNamesTheFieldAtTheRodLine) {
  const std::string message = error_of(band_with("  length: 0.29\n", ""));
  EXPECT_EQ(message, "task.yaml:1: rod.length is required");
}

TEST(TaskReader, MisspelledKeySuggestsTheAllowedOne) {
  const std::string message = error_of(band_with("length:", "lenght:"));
  EXPECT_EQ(message, "task.yaml:2: rod.lenght: unknown key; did you mean 'length'?");
}

TEST(TaskReader, UnknownKeyWithoutCloseMatchListsTheAllowedKeys) {
  const std::string message =
      error_of(band_with("  length: 0.29\n", "  length: 0.29\n  colour: 3\n"));
  EXPECT_TRUE(StartsWith(message, "task.yaml:3: rod.colour: unknown key; expected one of length,"));
}

TEST(TaskReader, MisspelledTopLevelSectionSuggestsIt) {
  const std::string message = error_of(kBandTask + "sovler: {tolerance: 1e-9}\n");
  EXPECT_EQ(message, "task.yaml:9: sovler: unknown key; did you mean 'solver'?");
}

TEST(TaskReader, GravityUnderRodSaysWhereItBelongs) {
  const std::string message =
      error_of(band_with("  length: 0.29\n", "  length: 0.29\n  gravity: [0, 0, -9.81]\n"));
  EXPECT_EQ(
      message,
      "task.yaml:3: rod.gravity: unknown key; gravity is a top-level section, not part of rod");
}

TEST(TaskReader, StiffnessDirectlyUnderRodSaysWhereItBelongs) {
  const std::string message =
      error_of(band_with("  length: 0.29\n", "  length: 0.29\n  EIx: 0.04\n"));
  EXPECT_EQ(message, "task.yaml:3: rod.EIx: unknown key; EIx belongs in rod.stiffness");
}

TEST(TaskReader, DuplicateKeyIsRejected) {
  const std::string message =
      error_of(band_with("  length: 0.29\n", "  length: 0.29\n  length: 0.3\n"));
  EXPECT_EQ(message, "task.yaml:3: rod.length: duplicate key (first given on line 2)");
}

TEST(TaskReader, NegativeLengthIsOutOfRange) {
  const std::string message = error_of(band_with("length: 0.29", "length: -0.3"));
  EXPECT_TRUE(StartsWith(message, "task.yaml:2: rod.length = -0.3"));
  EXPECT_TRUE(Contains(message, "must be > 0"));
}

TEST(TaskReader, ZeroStiffnessIsOutOfRange) {
  const std::string message = error_of(band_with("EIx: 0.04", "EIx: 0"));
  EXPECT_EQ(message, "task.yaml:5: rod.stiffness.EIx = 0 must be > 0");
}

TEST(TaskReader, NegativeSectionWidthIsNamed) {
  const std::string message = error_of(band_with("width: 0.02", "width: -0.02"));
  EXPECT_TRUE(StartsWith(message, "task.yaml:3: rod.section.width = -0.02"));
}

TEST(TaskReader, PoissonRatioOutOfRangeIsNamed) {
  const std::string message = error_of(band_with("poisson_ratio: 0.5", "poisson_ratio: 0.7"));
  EXPECT_TRUE(StartsWith(message, "task.yaml:4: rod.material.poisson_ratio = 0.7"));
}

TEST(TaskReader, NanIsNotAFiniteNumber) {
  const std::string message = error_of(band_with("length: 0.29", "length: .nan"));
  EXPECT_EQ(message, "task.yaml:2: rod.length = .nan is not a finite number");
}

TEST(TaskReader, InfinityInAVectorNamesTheElement) {
  const std::string message = error_of(band_with("[0.12, 0.0, 0.22]", "[0.12, -.inf, 0.22]"));
  EXPECT_EQ(message, "task.yaml:7: tip.position[1] = -.inf is not a finite number");
}

TEST(TaskReader, TextWhereANumberBelongsIsRejected) {
  EXPECT_EQ(error_of(band_with("length: 0.29", "length: long")),
            "task.yaml:2: rod.length = long is not a number");
  EXPECT_EQ(error_of(band_with("length: 0.29", "length: \"0.29\"")),
            "task.yaml:2: rod.length = \"0.29\" is a quoted string; expected a number");
}

TEST(TaskReader, NonOrthonormalRotationMatrixIsRejected) {
  const std::string message =
      error_of(band_with("rotation: [0.7071067811865476, 0, 0.7071067811865476, 0]",
                         "rotation: [[1, 0, 0], [0, 1, 0.001], [0, 0, 1]]"));
  EXPECT_TRUE(StartsWith(message, "task.yaml:8: tip.rotation: the matrix is not a rotation"));
}

TEST(TaskReader, ReflectionMatrixIsRejected) {
  const std::string message =
      error_of(band_with("rotation: [0.7071067811865476, 0, 0.7071067811865476, 0]",
                         "rotation: [[1, 0, 0], [0, 1, 0], [0, 0, -1]]"));
  EXPECT_TRUE(StartsWith(message, "task.yaml:8: tip.rotation: the matrix has determinant -1"));
}

TEST(TaskReader, NonUnitQuaternionIsRejected) {
  const std::string message =
      error_of(band_with("[0.7071067811865476, 0, 0.7071067811865476, 0]", "[1, 0, 0.5, 0]"));
  EXPECT_TRUE(
      StartsWith(message, "task.yaml:8: tip.rotation: quaternion [w, x, y, z] has norm 1.11"));
}

TEST(TaskReader, RotationOfTheWrongShapeIsRejected) {
  const std::string message =
      error_of(band_with("[0.7071067811865476, 0, 0.7071067811865476, 0]", "[0, 1, 0]"));
  EXPECT_TRUE(StartsWith(message, "task.yaml:8: tip.rotation: expected a quaternion [w, x, y, z]"));
}

TEST(TaskReader, TooFewNodesIsRejected) {
  const std::string message =
      error_of(band_with("  length: 0.29\n", "  length: 0.29\n  nodes: 1\n"));
  EXPECT_EQ(message, "task.yaml:3: rod.nodes = 1 must be >= 2 (both ends are nodes)");
}

TEST(TaskReader, TooManyNodesIsRejected) {
  const std::string message =
      error_of(band_with("  length: 0.29\n", "  length: 0.29\n  nodes: 100002\n"));
  EXPECT_EQ(message, "task.yaml:3: rod.nodes = 100002 must be <= 100001");
}

TEST(TaskReader, NodesTimesIterationsAndSubstepsBeyondTheirBoundIsRejectedWithTheEstimate) {
  EXPECT_EQ(error_of(band_with("  length: 0.29\n", "  length: 0.29\n  nodes: 100001\n") +
                     "solver: {max_iterations: 1000, max_substeps: 128}\n"),
            "task.yaml:10: solver.max_iterations = 1000 with 100001 rod nodes: a solve could take "
            "about 720 s (464 s to fail in solver.max_iterations = 1000, 256 s for "
            "solver.max_substeps = 128); at most 300 s (docs/limits.md): lower one of them");
  // Either alone is fine.
  EXPECT_EQ(error_of(band_with("  length: 0.29\n", "  length: 0.29\n  nodes: 100001\n")), "");
  EXPECT_EQ(error_of(kBandTask + "solver: {max_iterations: 10000}\n"), "");
}

TEST(TaskReader, SolverCountsBeyondTheirBoundsAreRejected) {
  EXPECT_EQ(error_of(kBandTask + "solver: {max_iterations: 1e9}\n"),
            "task.yaml:9: solver.max_iterations = 1e9 must be <= 10000");
  EXPECT_EQ(error_of(kBandTask + "solver: {max_continuation_steps: 4097}\n"),
            "task.yaml:9: solver.max_continuation_steps = 4097 must be <= 4096");
}

TEST(TaskReader, FractionalNodesIsRejected) {
  const std::string message =
      error_of(band_with("  length: 0.29\n", "  length: 0.29\n  nodes: 10.5\n"));
  EXPECT_EQ(message, "task.yaml:3: rod.nodes = 10.5 must be a whole number");
}

TEST(TaskReader, UnknownModelSuggestsOne) {
  const std::string message =
      error_of(band_with("  length: 0.29\n", "  length: 0.29\n  model: kirchoff\n"));
  EXPECT_EQ(message, "task.yaml:3: rod.model = kirchoff is not allowed; did you mean 'kirchhoff'?");
}

TEST(TaskReader, UnknownSectionShapeIsRejected) {
  const std::string message = error_of(band_with("shape: rectangle", "shape: hexagon"));
  EXPECT_EQ(message, "task.yaml:3: rod.section.shape = hexagon is not one of rectangle, circle");
}

TEST(TaskReader, UnknownTipFormIsRejected) {
  EXPECT_EQ(error_of(band_with("  position: [0.12, 0.0, 0.22]", "  velocity: [0.12, 0.0, 0.22]")),
            "task.yaml:7: tip.velocity: unknown key; expected one of position, rotation, released, "
            "wrench");
  EXPECT_TRUE(StartsWith(error_of(band_with("tip:\n", "tip:\n  wrench: {force: [0, 0, 1]}\n")),
                         "task.yaml:6: tip: give either a pose"));
  const std::string scalar_tip = kBandTask.substr(0, kBandTask.find("tip:")) + "tip: clamped\n";
  EXPECT_EQ(error_of(scalar_tip),
            "task.yaml:6: tip: expected a mapping with keys position, rotation, released, wrench, "
            "got 'clamped'");
}

TEST(TaskReader, TipWithoutPositionOrWrenchIsRejected) {
  const std::string text =
      kBandTask.substr(0, kBandTask.find("  position:")) + "  rotation: [1, 0, 0, 0]\n";
  EXPECT_EQ(error_of(text), "task.yaml:6: tip.position is required");
}

TEST(TaskReader, UnknownReleasedAxisSuggestsOne) {
  const std::string message = error_of(kBandTask + "  released: [mq]\n");
  EXPECT_EQ(message, "task.yaml:9: tip.released[0] = mq is not allowed; did you mean 'mx'?");
}

TEST(TaskReader, ReleasedAxisListedTwiceIsRejected) {
  const std::string message = error_of(kBandTask + "  released: [mx, fy, mx]\n");
  EXPECT_EQ(message, "task.yaml:9: tip.released[2] = mx is listed twice");
}

TEST(TaskReader, MissingTipIsNamedWithoutALine) {
  const std::string text = kBandTask.substr(0, kBandTask.find("tip:"));
  EXPECT_EQ(error_of(text), "task.yaml: tip is required");
}

TEST(TaskReader, RodWithoutSectionOrStiffnessNamesWhatIsMissing) {
  const std::string message = error_of("rod:\n  length: 0.29\ntip:\n  wrench: {}\n");
  EXPECT_TRUE(StartsWith(message, "task.yaml:1: rod.stiffness."));
  EXPECT_TRUE(Contains(message, "rod.section"));
}

TEST(TaskReader, YoungModulusWithoutPoissonRatioIsRejected) {
  const std::string message = error_of(band_with("poisson_ratio: 0.5, ", ""));
  EXPECT_EQ(message,
            "task.yaml:4: rod.material.poisson_ratio is required with rod.material.young_modulus");
}

TEST(TaskReader, GravityWithoutDensityNamesTheDensity) {
  const std::string message =
      error_of(band_with(", density: 1392", "") + "gravity: [0, 0, -9.81]\n");
  EXPECT_TRUE(StartsWith(message, "task.yaml:9: gravity"));
  EXPECT_TRUE(Contains(message, "rod.material.density"));
}

TEST(TaskReader, GravityWithoutSectionNamesTheSection) {
  const std::string text =
      "rod:\n  length: 0.29\n  material: {density: 1392}\n"
      "  stiffness: {EA: 1, GA: 1, EIx: 1, EIy: 1, GJ: 1}\n"
      "gravity: [0, 0, -9.81]\ntip:\n  wrench: {}\n";
  const std::string message = error_of(text);
  EXPECT_TRUE(StartsWith(message, "task.yaml:5: gravity"));
  EXPECT_TRUE(Contains(message, "rod.section"));
}

TEST(TaskReader, BadSolverOptionsAreNamed) {
  EXPECT_EQ(error_of(kBandTask + "solver: {max_iterations: 0}\n"),
            "task.yaml:9: solver.max_iterations = 0 must be >= 1");
  EXPECT_EQ(error_of(kBandTask + "solver: {tolerance: -1e-9}\n"),
            "task.yaml:9: solver.tolerance = -1e-9 must be > 0");
  EXPECT_EQ(error_of(kBandTask + "solver: {continuation: maybe}\n"),
            "task.yaml:9: solver.continuation = maybe must be true or false");
}

// Issue 43: a grasp that releases all six axes holds nothing (it was solved as a free tip).
TEST(TaskReader, ATipThatReleasesAllSixAxesIsRefusedNamingTheField) {
  EXPECT_EQ(error_of(kBandTask + "  released: [fx, fy, fz, mx, my, mz]\n"),
            "task.yaml:9: tip.released releases all six axes: the grasp would hold nothing; a tip "
            "held by nothing is a free tip (tip: {wrench: {}})");
  EXPECT_EQ(error_of(kBandTask + "  released: [fx, fy, fz, mx, my]\n"), "");
}

// Issue 43: solver.integration_tolerance: .inf was documented to turn the accuracy check off; a
// tolerance beyond 1 (a tip a metre off, an error of the rod's length) would pass anything.
TEST(TaskReader, ToleranceOfInfinityOrBeyondOneIsOutOfRange) {
  EXPECT_EQ(error_of(kBandTask + "solver: {integration_tolerance: .inf}\n"),
            "task.yaml:9: solver.integration_tolerance = .inf must be <= 1");
  EXPECT_EQ(error_of(kBandTask + "solver: {integration_tolerance: 2}\n"),
            "task.yaml:9: solver.integration_tolerance = 2 must be <= 1");
  EXPECT_EQ(error_of(kBandTask + "solver: {integration_tolerance: .nan}\n"),
            "task.yaml:9: solver.integration_tolerance = .nan is not a finite number");
  EXPECT_EQ(error_of(kBandTask + "solver: {integration_tolerance: -.inf}\n"),
            "task.yaml:9: solver.integration_tolerance = -.inf is not a finite number");
  EXPECT_EQ(error_of(kBandTask + "solver: {tolerance: 1e300}\n"),
            "task.yaml:9: solver.tolerance = 1e300 must be <= 1");
  EXPECT_EQ(error_of(kBandTask + "solver: {tolerance: .inf}\n"),
            "task.yaml:9: solver.tolerance = .inf must be <= 1");
  EXPECT_EQ(error_of(kBandTask + "solver: {tolerance: 1, integration_tolerance: 1}\n"), "");
}

// Issue 43: a position's bound, |p| <= 1e4 m (docs/limits.md), for every pose of a task file.
TEST(TaskReader, APositionBeyondTenKilometresIsRefusedNamingTheField) {
  EXPECT_EQ(error_of(band_with("[0.12, 0.0, 0.22]", "[1e300, 0.0, 0.22]")),
            "task.yaml:7: tip.position has magnitude 1e+300 m; at most 10000 m (docs/limits.md)");
  EXPECT_EQ(error_of(kBandTask + "base: {position: [0, -2e4, 0]}\n"),
            "task.yaml:9: base.position has magnitude 20000 m; at most 10000 m (docs/limits.md)");
}

// Issue 43: the guess of an equilibrium's base wrench, bounded as a wrench and named as written.
TEST(TaskReader, AnInitialWrenchBeyondItsBoundNamesTheField) {
  EXPECT_EQ(error_of(kBandTask + "solver: {initial_wrench: {force: [0, 1e300, 0]}}\n"),
            "task.yaml:9: solver.initial_wrench.force has magnitude 1e+300 N; at most 1e+20 N "
            "(docs/limits.md)");
  EXPECT_EQ(error_of(kBandTask + "solver:\n  initial_wrench:\n    moment: [0, 0, -3e20]\n"),
            "task.yaml:11: solver.initial_wrench.moment has magnitude 3e+20 N*m; at most 1e+20 "
            "N*m (docs/limits.md)");
  EXPECT_EQ(error_of(kBandTask + "solver: {initial_wrench: {moment: [0, .nan, 0]}}\n"),
            "task.yaml:9: solver.initial_wrench.moment[1] = .nan is not a finite number");
  EXPECT_EQ(error_of(kBandTask + "solver: {initial_wrench: {force: [0, 0, 1e20]}}\n"), "");
}

TEST(TaskReader, MalformedYamlGivesTheLine) {
  const std::string message = error_of(band_with("height: 0.02}", "height: 0.02"));
  EXPECT_TRUE(StartsWith(message, "task.yaml:"));
  EXPECT_TRUE(Contains(message, ": malformed YAML: "));
  EXPECT_NE(message, "task.yaml: malformed YAML: ") << "the line is missing";
}

TEST(TaskReader, EmptyFileIsRejected) {
  EXPECT_TRUE(StartsWith(error_of(""), "task.yaml: the task file: expected a mapping"));
}

TEST(TaskReader, UnreadableFileNamesThePath) {
  EXPECT_EQ(
      testing::input_error_message([] { read_equilibrium_task("/nonexistent/dir/task.yaml"); }),
      "/nonexistent/dir/task.yaml: cannot read: No such file or directory");
}

// ---- good input
// -----------------------------------------------------------------------------------

TEST(TaskReader, RubberBandExampleReadsThePapersRod) {
  const EquilibriumTask task =
      read_equilibrium_task(std::string(RODSHAPE_SOURCE_DIR) + "/examples/rubber_band.yaml");
  const RodProperties& p = task.rod.properties;
  EXPECT_DOUBLE_EQ(p.length, 0.29);
  EXPECT_EQ(p.model, ConstitutiveModel::Cosserat);
  EXPECT_EQ(task.rod.nodes(), 101);
  EXPECT_TRUE(CompareMatrices(p.K_rot, Eigen::Vector3d(0.04, 0.04, 0.028), 1e-15));
  // K_tra from the section: G = E / (2 (1 + ν)) = 3.2e6 / 3, A = 4e-4 m².
  const double GA = 3.2e6 / 3.0 * 4e-4;
  const double EA = 3.2e6 * 4e-4;
  EXPECT_NEAR(EA, 1.28e3, 1e-9);
  EXPECT_TRUE(CompareMatrices(p.K_tra, Eigen::Vector3d(GA, GA, EA), 1e-12,
                              testing::MatrixCompareType::relative));
  EXPECT_NEAR(p.mass_per_length, 1392 * 4e-4, 1e-15);
  // The paper neglects gravity: no load.
  EXPECT_TRUE(CompareMatrices(task.rod.load.force, Eigen::Vector3d::Zero(), 0.0));
  EXPECT_TRUE(CompareMatrices(task.rod.clamp.rotation, Eigen::Matrix3d::Identity(), 0.0));

  ASSERT_TRUE(std::holds_alternative<ClampedTip>(task.tip));
  const Pose& tip = std::get<ClampedTip>(task.tip).pose;
  EXPECT_TRUE(CompareMatrices(tip.position, Eigen::Vector3d(0.12, 0.0, 0.22), 0.0));
  // +90° about y: the tip's tangent (local z) points along world +x.
  EXPECT_TRUE(CompareMatrices(tip.rotation.col(2), Eigen::Vector3d::UnitX(), 1e-15));
}

TEST(TaskReader, CantileverExampleCarriesItsWeight) {
  const EquilibriumTask task =
      read_equilibrium_task(std::string(RODSHAPE_SOURCE_DIR) + "/examples/cantilever_gravity.yaml");
  const double weight_per_length = 7850 * std::numbers::pi * 1e-6 * 9.81;  // ρ A g
  EXPECT_TRUE(
      CompareMatrices(task.rod.load.force, Eigen::Vector3d(0, 0, -weight_per_length), 1e-15));
  ASSERT_TRUE(std::holds_alternative<FreeTip>(task.tip));
  EXPECT_TRUE(CompareMatrices(task.rod.clamp.rotation.col(2), Eigen::Vector3d::UnitX(), 0.0));
}

TEST(TaskReader, GraspedExampleReleasesMomentX) {
  const EquilibriumTask task =
      read_equilibrium_task(std::string(RODSHAPE_SOURCE_DIR) + "/examples/grasped_band.yaml");
  ASSERT_TRUE(std::holds_alternative<GraspedTip>(task.tip));
  const std::array<bool, 6> expected{false, false, false, true, false, false};
  EXPECT_EQ(std::get<GraspedTip>(task.tip).released, expected);
}

TEST(TaskReader, QuaternionAndMatrixGiveTheSamePose) {
  const EquilibriumTask by_quaternion = parse_equilibrium_task(kBandTask, "q.yaml");
  const EquilibriumTask by_matrix =
      parse_equilibrium_task(band_with("rotation: [0.7071067811865476, 0, 0.7071067811865476, 0]",
                                       "rotation: [[0, 0, 1], [0, 1, 0], [-1, 0, 0]]"),
                             "m.yaml");
  const Pose& a = std::get<ClampedTip>(by_quaternion.tip).pose;
  const Pose& b = std::get<ClampedTip>(by_matrix.tip).pose;
  EXPECT_TRUE(CompareMatrices(a.position, b.position, 0.0));
  EXPECT_TRUE(CompareMatrices(a.rotation, b.rotation, 1e-15));
}

TEST(TaskReader, NearlyUnitQuaternionIsNormalised) {
  const EquilibriumTask task = parse_equilibrium_task(
      band_with("[0.7071067811865476, 0, 0.7071067811865476, 0]", "[1.0000005, 0, 0, 0]"), "t");
  const Eigen::Matrix3d& R = std::get<ClampedTip>(task.tip).pose.rotation;
  EXPECT_TRUE(CompareMatrices(R, Eigen::Matrix3d::Identity(), 1e-15));
}

TEST(TaskReader, DefaultsApplyWhenLeftOut) {
  const EquilibriumTask task = parse_equilibrium_task(kBandTask, "task.yaml");
  const ShootingOptions defaults;
  EXPECT_EQ(task.source, "task.yaml");
  EXPECT_EQ(task.rod.intervals, 100);
  EXPECT_TRUE(CompareMatrices(task.rod.clamp.position, Eigen::Vector3d::Zero(), 0.0));
  EXPECT_TRUE(CompareMatrices(task.initial_wrench.to_vector(), Vector6d::Zero(), 0.0));
  EXPECT_EQ(task.options.max_iterations, defaults.max_iterations);
  EXPECT_EQ(task.options.residual_tolerance, defaults.residual_tolerance);
  EXPECT_EQ(task.options.continuation, defaults.continuation);
}

TEST(TaskReader, SolverSectionAndLoadsAreRead) {
  const std::string text = band_with("  length: 0.29\n",
                                     "  length: 0.29\n  nodes: 21\n  model: kirchhoff\n"
                                     "  rest_curvature: [0, 1.5, 0]\n") +
                           "distributed_load: {force: [0, 1, 0], moment: [0, 0, 2]}\n"
                           "solver:\n  max_iterations: 7\n  tolerance: 1e-9\n"
                           "  continuation: false\n  max_continuation_steps: 8\n"
                           "  initial_wrench: {force: [1, 2, 3], moment: [4, 5, 6]}\n";
  const EquilibriumTask task = parse_equilibrium_task(text, "task.yaml");
  EXPECT_EQ(task.rod.intervals, 20);
  EXPECT_EQ(task.rod.properties.model, ConstitutiveModel::Kirchhoff);
  EXPECT_TRUE(CompareMatrices(task.rod.properties.u_rest, Eigen::Vector3d(0, 1.5, 0), 0.0));
  EXPECT_TRUE(CompareMatrices(task.rod.load.force, Eigen::Vector3d(0, 1, 0), 0.0));
  EXPECT_TRUE(CompareMatrices(task.rod.load.moment, Eigen::Vector3d(0, 0, 2), 0.0));
  EXPECT_EQ(task.options.max_iterations, 7);
  EXPECT_EQ(task.options.residual_tolerance, 1e-9);
  EXPECT_FALSE(task.options.continuation);
  EXPECT_EQ(task.options.max_continuation_steps, 8);
  Vector6d guess;
  guess << 1, 2, 3, 4, 5, 6;
  EXPECT_TRUE(CompareMatrices(task.initial_wrench.to_vector(), guess, 0.0));
}

TEST(TaskReader, RodGivenByStiffnessNeedsOnlyDensityAndSectionForItsWeight) {
  const std::string text =
      "rod:\n  length: 1\n  section: {shape: circle, radius: 0.01}\n  material: {density: 1000}\n"
      "  stiffness: {EA: 1e4, GA: 1e4, EIx: 1, EIy: 2, GJ: 3}\n"
      "gravity: [0, 0, -10]\ntip:\n  wrench: {force: [0, 0, 1]}\n";
  const EquilibriumTask task = parse_equilibrium_task(text, "task.yaml");
  EXPECT_TRUE(CompareMatrices(task.rod.properties.K_rot, Eigen::Vector3d(1, 2, 3), 0.0));
  const double weight = 1000 * std::numbers::pi * 1e-4 * 10;
  EXPECT_TRUE(CompareMatrices(task.rod.load.force, Eigen::Vector3d(0, 0, -weight), 1e-12));
  ASSERT_TRUE(std::holds_alternative<FreeTip>(task.tip));
  EXPECT_TRUE(
      CompareMatrices(std::get<FreeTip>(task.tip).wrench.force, Eigen::Vector3d::UnitZ(), 0.0));
}

TEST(TaskReader, RodGivenWhollyByStiffnessNeedsNoSectionOrMaterial) {
  const std::string text =
      "rod:\n  length: 1\n  stiffness: {EA: 1e4, GA: 1e4, EIx: 1, EIy: 1, GJ: 1}\n"
      "gravity: [0, 0, 0]\ntip:\n  wrench: {}\n";
  const EquilibriumTask task = parse_equilibrium_task(text, "task.yaml");
  EXPECT_TRUE(CompareMatrices(task.rod.properties.K_tra, Eigen::Vector3d(1e4, 1e4, 1e4), 0.0));
  EXPECT_EQ(task.rod.properties.mass_per_length, 0.0);
}

}  // namespace
}  // namespace test_task_reader
}  // namespace rodshape
