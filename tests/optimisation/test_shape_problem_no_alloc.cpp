// test_shape_problem_no_alloc.cpp: ShapeProblem::evaluate() allocates nothing after construction
// (the first call included), with every kind of constraint row and cost term active.
//
// The counting machinery is tests/support/allocation_counter.hpp (program-wide replacements: this
// executable, rodshape_tests_optimisation, must hold no other).
#include <gtest/gtest.h>
#include <Eigen/Core>

#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <new>
#include <string>
#include <vector>

#include "rodshape/core/so3.hpp"
#include "rodshape/optimisation/base_motion.hpp"
#include "rodshape/optimisation/shape_problem.hpp"
#include "support/allocation_counter.hpp"
#include "support/solver_fixtures.hpp"

namespace rodshape {
namespace test_shape_problem_no_alloc {
namespace {

ShapeProblem make_problem(ConstitutiveModel model, bool squared) {
  ClampedRod rod;
  rod.properties.length = 0.29;
  rod.properties.model = model;
  rod.properties.K_rot = Eigen::Vector3d(0.04, 0.04, 0.028);
  rod.properties.K_tra = Eigen::Vector3d(426.67, 426.67, 1280.0);
  rod.properties.u_rest = Eigen::Vector3d(0.5, -0.3, 1.0);
  rod.load =
      DistributedLoad::gravity(testing::kBandMassPerLength, Eigen::Vector3d(0.0, 0.0, -9.81));
  rod.clamp.rotation = exp_so3(Eigen::Vector3d(0.1, 0.2, 0.3));
  rod.intervals = 32;
  rod.validate();
  ShapeTarget target;
  target.points = {{0.02, 0.05, 0.1}, {0.0, 0.1, 0.2}, {-0.03, 0.12, 0.22}};
  target.squared_distances = squared;
  Workspace ws;
  ws.box = Workspace::Box{Eigen::Vector3d::Constant(-1.0), Eigen::Vector3d::Constant(1.0)};
  ws.inside.push_back({Eigen::Vector3d::Zero(), 0.5});
  ws.outside.push_back({Eigen::Vector3d(0.3, 0.0, 0.0), 0.05});
  ws.half_spaces.push_back({Eigen::Vector3d(0.0, 0.0, 1.0), 0.4});
  ws.reach = Workspace::ReachShell{{-0.4, 0.0, 0.3}, 0.1, 0.8, {0.0, 0.0, 0.2}};
  Grasp grasp;
  grasp.released = {true, false, true, true, false, false};
  StrainLimits limits;
  limits.max_curvature = 20.0;
  limits.max_axial_strain = 0.05;
  // One obstacle of each kind: the clearance rows (a box's golden-section search included).
  Clearance clearance;
  clearance.scene.rod_radius = 0.002;
  clearance.scene.obstacles = {
      {"ball", SphereObstacle{{0.1, 0.0, 0.1}, 0.02}},
      {"crate", BoxObstacle{{-0.1, 0.05, 0.1}, {0.02, 0.03, 0.04}, Eigen::Matrix3d::Identity()}},
      {"rail", CapsuleObstacle{{0.0, -0.1, 0.1}, {0.0, -0.1, 0.2}, 0.01}},
      {"floor", HalfSpaceObstacle{{0.0, 0.0, -1.0}, 0.05}}};
  clearance.required.assign(4, 0.005);
  return ShapeProblem(rod, target, ws, grasp, limits, WrenchBounds{}, clearance);
}

using testing::count_allocations;

TEST(ShapeProblemNoAlloc, CountersSeeAnAllocation) {
  std::vector<double> grows;
  const auto [news, mallocs] = count_allocations([&] { grows.resize(1000); });
  EXPECT_GE(news, 1);
#ifdef RODSHAPE_COUNT_MALLOC
  EXPECT_GE(mallocs, 1);
  Eigen::VectorXd dynamic;
  const auto [news_eigen, mallocs_eigen] = count_allocations([&] { dynamic.resize(1000); });
  EXPECT_EQ(news_eigen, 0);
  EXPECT_GE(mallocs_eigen, 1);
#else
  (void)mallocs;
#endif
}

TEST(ShapeProblemNoAlloc, EvaluateAllocatesNothingAfterConstruction) {
  for (ConstitutiveModel model : {ConstitutiveModel::Cosserat, ConstitutiveModel::Kirchhoff}) {
    for (bool squared : {false, true}) {
      ShapeProblem problem = make_problem(model, squared);
      Vector6d w1, w2;
      w1 << 0.1, -0.2, 0.3, 0.05, -0.02, 0.01;
      w2 << -0.2, 0.1, 0.4, -0.03, 0.04, 0.02;
      const std::string label = to_string(model) + (squared ? ", squared" : ", plain");
      // The first call after construction, a new w, the cached w.
      for (const Vector6d* w : {&w1, &w2, &w2}) {
        const auto [news, mallocs] = count_allocations([&] { problem.evaluate(*w); });
        EXPECT_EQ(news, 0) << "operator new calls, " << label;
        EXPECT_EQ(mallocs, 0) << "malloc calls, " << label;
      }
      EXPECT_EQ(problem.configuration().n.front(), w2.head<3>());  // the calls did run
      EXPECT_EQ(problem.row_blocks().clearance, 4 * 32);
      EXPECT_GE(problem.constraint_count(), 6 + 3 + 33);  // workspace, grasp, curvature
      EXPECT_GT(problem.cost(), 0.0);
    }
  }
}

// The moving base with its pose eliminated (issue 21, the dense Newton's problem): after a first
// call has sized the base-frame shape and the alignment's scratch, evaluate(w̃) (an integration in
// the base's frame, align_base's Newton steps, the evaluation at (w_b, ξ*)) allocates nothing.
TEST(ShapeProblemNoAlloc, EliminatedBasePoseEvaluateAllocatesNothingAfterTheFirstCall) {
  ClampedRod rod;  // no distributed load: the shape in the base's frame depends on w_b alone
  rod.properties.length = 0.29;
  rod.properties.K_rot = Eigen::Vector3d(0.04, 0.04, 0.028);
  rod.properties.K_tra = Eigen::Vector3d(426.67, 426.67, 1280.0);
  rod.clamp.rotation = exp_so3(Eigen::Vector3d(0.1, 0.2, 0.3));
  rod.intervals = 32;
  rod.validate();
  ShapeTarget target;
  target.points = {{0.02, 0.05, 0.1}, {0.0, 0.1, 0.2}, {-0.03, 0.12, 0.22}};
  ShapeProblem problem(rod, target);
  BaseMotion motion;
  motion.reference = rod.clamp;
  problem.move_base(motion);
  ASSERT_TRUE(problem.rigid_alignment_applies());
  problem.eliminate_base_pose(true);
  Vector6d w1, w2, w3;  // in bending units
  w1 << 0.1, -0.2, 0.3, 0.05, -0.02, 0.01;
  w2 << -0.2, 0.1, 0.4, -0.03, 0.04, 0.02;
  w3 << -0.1, 0.2, 0.3, -0.04, 0.03, 0.02;
  problem.evaluate(w1);  // sizes the shape, its balls and the scratch
  ASSERT_TRUE(std::isfinite(problem.cost()));
  for (const Vector6d* w : {&w2, &w3, &w3}) {
    const auto [news, mallocs] = count_allocations([&] { problem.evaluate(*w); });
    EXPECT_EQ(news, 0) << "operator new calls";
    EXPECT_EQ(mallocs, 0) << "malloc calls";
    EXPECT_TRUE(std::isfinite(problem.cost()));
  }
  // The clamp is the evaluated base pose (ξ* about the reference), not the base frame's identity
  // the alignment integrates in.
  const Pose base = problem.base_pose(problem.evaluated_variables());
  EXPECT_EQ(problem.rod().clamp.position, base.position);
  EXPECT_EQ(problem.rod().clamp.rotation, base.rotation);
}

}  // namespace
}  // namespace test_shape_problem_no_alloc
}  // namespace rodshape
