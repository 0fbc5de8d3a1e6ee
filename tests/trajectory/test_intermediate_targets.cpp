#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "rodshape/error.hpp"
#include "rodshape/trajectory/intermediate_targets.hpp"

namespace rodshape {
namespace test_intermediate_targets {
namespace {

TEST(IntermediateTargets, LastStepIsTheObjectiveAndStepsAreEvenlySpaced) {
  const PointSet initial = {{0, 0, 0.1}, {0, 0, 0.2}};
  const PointSet objective = {{0.07, 0, 0.1}, {0.1, 0.03, 0.15}};
  const auto steps = intermediate_targets(initial, objective, 7);
  ASSERT_EQ(steps.size(), 7u);
  for (std::size_t k = 0; k < objective.size(); ++k) {
    EXPECT_EQ(steps.back()[k], objective[k]);  // exactly, not one step short
    for (int i = 1; i <= 7; ++i)
      EXPECT_TRUE(
          steps[i - 1][k].isApprox(initial[k] + i / 7.0 * (objective[k] - initial[k]), 1e-15));
  }
}

TEST(IntermediateTargets, OneStepGoesStraightToTheObjective) {
  const PointSet initial = {{0, 0, 0.1}};
  const PointSet objective = {{0.05, 0, 0.1}};
  const auto steps = intermediate_targets(initial, objective, 1);
  ASSERT_EQ(steps.size(), 1u);
  EXPECT_EQ(steps[0][0], objective[0]);
}

TEST(IntermediateTargets, FewerThanOneStepNamesTheField) {
  try {
    intermediate_targets({}, {}, 0);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("n_inter"), std::string::npos);
  }
}

}  // namespace
}  // namespace test_intermediate_targets
}  // namespace rodshape

// ---- a moving base's sets (issue 21) ------------------------------------------------------------

namespace test_intermediate_targets {
namespace {

/// The angle of a rotation matrix, rad.
double angle_of(const Eigen::Matrix3d& R) {
  return std::acos(std::clamp(0.5 * (R.trace() - 1.0), -1.0, 1.0));
}

TEST(AlignedObjectiveSet, PointsOnALineAreTurnedByTheLeastRotationOntoTheTargetsDirection) {
  // The straight rod along x, its target a line along y shifted: Kabsch leaves the turn about the
  // line free; the least rotation is the 90° one about z (any larger one rolls the rod).
  rodshape::PointSet line, target;
  for (int i = 0; i < 5; ++i) {
    line.push_back(Eigen::Vector3d(0.05 * i, 0.0, 0.0));
    target.push_back(Eigen::Vector3d(0.3, 0.1 + 0.05 * i, 0.2));
  }
  const rodshape::RigidAlignment a = rodshape::best_rigid_alignment(line, target);
  EXPECT_NEAR(angle_of(a.rotation), std::acos(-1.0) / 2.0, 1e-12);
  EXPECT_LT((a.rotation * Eigen::Vector3d::UnitX() - Eigen::Vector3d::UnitY()).norm(), 1e-12);
}

TEST(AlignedObjectiveSet, EndsOnTheObjectiveStartsOnTheInitialAndMovesRigidlyOnTheWay) {
  rodshape::PointSet initial, objective;
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized()).matrix();
  for (int i = 0; i < 6; ++i) {
    initial.push_back(Eigen::Vector3d(0.05 * i, 0.01 * i * i, 0.002 * i * i * i));
    objective.push_back(R * initial.back() + Eigen::Vector3d(0.1, -0.2, 0.05));
  }
  const Eigen::Vector3d base(-0.05, 0.0, 0.0);
  const rodshape::PointSet end = rodshape::aligned_objective_set(base, initial, objective, 1.0);
  const rodshape::PointSet start = rodshape::aligned_objective_set(base, initial, objective, 0.0);
  for (std::size_t i = 0; i < initial.size(); ++i) {
    EXPECT_EQ(end[i], objective[i]);
    EXPECT_LT((start[i] - initial[i]).norm(), 1e-15);
  }
  // A target that is the initial set moved rigidly is reached by rigid motions only: every
  // intermediate set keeps the initial set's distances (to round-off).
  const rodshape::PointSet half = rodshape::aligned_objective_set(base, initial, objective, 0.5);
  for (std::size_t i = 1; i < initial.size(); ++i)
    EXPECT_NEAR((half[i] - half[0]).norm(), (initial[i] - initial[0]).norm(), 1e-12);
}

}  // namespace
}  // namespace test_intermediate_targets
