// test_moving_base_plan.cpp: plan() with the base end held by a moving gripper (issue 21), no arms:
// the band's target made from an equilibrium whose clamp was moved and turned, planned in steps
// that move both ends. Each step re-integrated from its base pose and base wrench puts its tip
// (and, through the grasps, both end effectors) where the plan says to 1e-9 m; both ends' paths
// share one clock; the base path starts at the initial base and ends at the last step's.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <numbers>

#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/core/so3.hpp"
#include "rodshape/samples/rubber_band.hpp"
#include "rodshape/trajectory/plan.hpp"
#include "support/input_error.hpp"
#include "trajectory/moving_base_plan.hpp"

namespace rodshape {
namespace test_moving_base_plan {
namespace {

Eigen::Matrix3d along_x() {
  return Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitY()).toRotationMatrix();
}

/// The band along +x at z = 0.35 m, its base held by a gripper 1 cm in from the end; the target:
/// six points of the equilibrium of a bending wrench with the base moved by (3, 2, 1) cm and
/// turned by 0.3 rad about z.
PlanProblem moved_band(bool gravity) {
  PlanProblem problem;
  problem.rod = samples::rubber_band(ConstitutiveModel::Cosserat, 50);
  problem.rod.load =
      gravity ? DistributedLoad::gravity(0.02, Eigen::Vector3d(0, 0, -9.81)) : DistributedLoad{};
  problem.rod.clamp = {Eigen::Vector3d(-0.145, 0, 0.35), along_x()};
  ClampedRod moved = problem.rod;
  moved.clamp.position += Eigen::Vector3d(0.03, 0.02, 0.01);
  moved.clamp.rotation = exp_so3(Eigen::Vector3d(0, 0, 0.3)) * moved.clamp.rotation;
  const double EI = problem.rod.properties.K_rot.y();
  const double L = problem.rod.properties.length;
  const BaseWrench w{Eigen::Vector3d::Zero(),
                     moved.clamp.rotation * Eigen::Vector3d(0.0, 1.5 * EI / L, 0.0)};
  const RodConfiguration truth = integrate(moved, w);
  for (int i : {5, 15, 25, 35, 45, 50}) problem.target.points.push_back(truth.p[i]);
  MovingBase base;
  base.grasp.tip_to_end_effector.position = Eigen::Vector3d(0, 0, 0.01);
  problem.moving_base = base;
  problem.target.energy_weight = 1e-3;  // the points decide (the S-curve example's W1)
  problem.grasp.tip_to_end_effector.position = Eigen::Vector3d(0, 0, -0.01);
  return problem;
}

TEST(MovingBasePlan, EveryStepReintegratedFromItsBasePoseAndWrenchIsWhereThePlanSays) {
  for (bool gravity : {false, true}) {
    const PlanProblem problem = moved_band(gravity);
    PlanOptions options;
    options.steps = 5;
    const PlanResult result = plan(problem, options);
    ASSERT_EQ(result.status, PlanStatus::Complete) << result.message;
    EXPECT_LT(result.steps.back().solution.cost.max_distance, 1e-3) << result.brief();
    const Pose& base_ee = problem.moving_base->grasp.tip_to_end_effector;
    for (const PlanStep& step : result.steps) {
      const RodConfiguration& c = step.solution.configuration;
      ClampedRod rod = problem.rod;
      rod.clamp = {c.p[0], c.R[0]};
      const RodConfiguration again = integrate(rod, step.solution.base_wrench);
      EXPECT_LT((again.p.back() - c.p.back()).norm(), 1e-9);
      const Pose tip_ee = compose(again.tip(), problem.grasp.tip_to_end_effector);
      EXPECT_LT((tip_ee.position - step.end_effector.position).norm(), 1e-9);
      const Pose b = compose(rod.clamp, base_ee);
      EXPECT_LT((b.position - step.base_end_effector.position).norm(), 1e-12);
    }
    // The base moved towards the target's base.
    const Eigen::Vector3d moved_by =
        result.steps.back().solution.configuration.p[0] - problem.rod.clamp.position;
    EXPECT_GT(moved_by.norm(), 0.01) << moved_by.transpose();
    // One clock for both ends.
    ASSERT_EQ(result.base_end_effector_path.size(), result.end_effector_path.size());
    for (std::size_t k = 0; k < result.end_effector_path.size(); ++k)
      EXPECT_EQ(result.base_end_effector_path[k].t, result.end_effector_path[k].t);
    EXPECT_LT((result.base_end_effector_path.front().pose.position -
               compose(problem.rod.clamp, base_ee).position)
                  .norm(),
              1e-12);
    EXPECT_LT((result.base_end_effector_path.back().pose.position -
               result.steps.back().base_end_effector.position)
                  .norm(),
              1e-12);
    EXPECT_TRUE(result.tracking.performed);
  }
}

TEST(MovingBasePlan, FixedClampGivesTheClampAsEveryStepsBaseEndEffector) {
  PlanProblem problem = moved_band(false);
  problem.moving_base.reset();
  problem.target.points = {{-0.05, 0.0, 0.37}, {0.05, 0.0, 0.38}};
  PlanOptions options;
  options.steps = 2;
  const PlanResult result = plan(problem, options);
  ASSERT_FALSE(result.steps.empty()) << result.message;
  for (const PlanStep& step : result.steps)
    EXPECT_EQ(step.base_end_effector.position, problem.rod.clamp.position);
  EXPECT_TRUE(result.base_end_effector_path.empty());
}

TEST(MovingBasePlan, PoseAndSearchAreRefusedWithAMovingBase) {
  const PlanProblem problem = moved_band(false);
  PlanOptions options;
  options.interpolation = ObjectiveInterpolation::Pose;
  EXPECT_NE(testing::input_error_message([&] {
              plan(problem, options);
            }).find("PlanOptions.interpolation"),
            std::string::npos);
}

}  // namespace
}  // namespace test_moving_base_plan
}  // namespace rodshape

namespace rodshape {
namespace test_moving_base_plan {
namespace {

TEST(MovingBasePlan, AFreeBasesChainMayExceedTheCosseratRodByItsStretchSlackOnly) {
  // Points on a line whose chain is L (1 + e): a Cosserat rod's own equilibria are stretched by
  // their tension, so 5e-4 is feasible (slack 1e-3), 2e-3 not; an inextensible rod allows none.
  const auto chain_of = [](double e, ConstitutiveModel model) {
    PlanProblem problem = moved_band(false);
    problem.rod.properties.model = model;
    const double L = problem.rod.properties.length;
    problem.target.points.clear();
    for (int i = 0; i <= 4; ++i)
      problem.target.points.push_back(Eigen::Vector3d(-0.1 + 0.25 * i * L * (1.0 + e), 0.0, 0.4));
    return detail::free_base_feasibility(problem).feasible;
  };
  EXPECT_TRUE(chain_of(5e-4, ConstitutiveModel::Cosserat));
  EXPECT_FALSE(chain_of(2e-3, ConstitutiveModel::Cosserat));
  EXPECT_FALSE(chain_of(5e-4, ConstitutiveModel::Kirchhoff));
}

}  // namespace
}  // namespace test_moving_base_plan
}  // namespace rodshape
