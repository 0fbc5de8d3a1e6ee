// Tests of the simulated experiment with a moving base (issue 21, item 6): a plan whose waypoints
// move both ends validated by the plant driven by both ends, open and closed loop. Until plan()
// moves the base, the plan is the band's (fixed clamp) with every waypoint moved rigidly, its two
// paths timed on one clock by hand: each waypoint is then an equilibrium with both ends moved,
// which the plant must reach.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/core/so3.hpp"
#include "rodshape/io/task_reader.hpp"
#include "rodshape/robot/arm_placement.hpp"
#include "rodshape/sim/commanded_path.hpp"
#include "rodshape/sim/plan_validation.hpp"
#include "rodshape/trajectory/plan.hpp"
#include "sim/two_end_path.hpp"
#include "support/band_problem.hpp"

namespace rodshape {
namespace test_two_end_validation {
namespace {

using testing::band_problem;

const PlanResult& band_plan() {
  static const PlanResult plan = [] {
    PlanOptions options;
    options.steps = 3;
    return rodshape::plan(band_problem(), options);
  }();
  return plan;
}

/// The rigid motion of waypoint k of n: a translation on a line and a turn about a fixed axis.
Pose motion_at(int k, int n) {
  const double sigma = static_cast<double>(k) / n;
  return {sigma * Eigen::Vector3d(0.02, -0.01, 0.01),
          exp_so3(sigma * Eigen::Vector3d(0.1, -0.05, 0.15))};
}

Eigen::Vector3d moved_point(const Pose& motion, const Eigen::Vector3d& p) {
  return motion.position + motion.rotation * p;
}

BaseWrench turned(const Pose& motion, const BaseWrench& w) {
  return {motion.rotation * w.force, motion.rotation * w.moment};
}

/// The rod's equilibrium of `w` with its clamp moved by `motion` and the wrench turned with it.
RodConfiguration moved(const ClampedRod& rod, const Pose& motion, const BaseWrench& w) {
  ClampedRod at = rod;
  at.clamp = compose(motion, rod.clamp);
  return integrate(at, turned(motion, w));
}

struct MovingBasePlan {
  PlanProblem problem;
  PlanResult plan;
  Pose final_motion;
};

/// band_plan() with waypoint k moved by motion_at(k, n) and the base held by a gripper at
/// base_T_ee from the clamp: the target moved with the last.
MovingBasePlan moving_base_plan() {
  const PlanProblem fixed = band_problem();
  const PlanResult& original = band_plan();
  MovingBasePlan out;
  out.problem = fixed;
  MovingBase base;
  base.grasp.tip_to_end_effector = {Eigen::Vector3d(0.0, 0.0, -0.02), exp_so3({0.0, 0.0, 0.3})};
  out.problem.moving_base = base;
  const int n = static_cast<int>(original.steps.size());
  out.final_motion = motion_at(n, n);
  for (Eigen::Vector3d& p : out.problem.target.points) p = moved_point(out.final_motion, p);
  PlanResult& plan = out.plan;
  plan = original;
  std::vector<Pose> tip{original.end_effector_path.front().pose};
  std::vector<Pose> base_poses{compose(fixed.rod.clamp, base.grasp.tip_to_end_effector)};
  for (int k = 1; k <= n; ++k) {
    const Pose motion = motion_at(k, n);
    PlanStep& step = plan.steps[static_cast<std::size_t>(k - 1)];
    step.solution.configuration = moved(fixed.rod, motion, step.solution.base_wrench);
    step.solution.base_wrench = turned(motion, step.solution.base_wrench);
    step.end_effector = compose(motion, step.end_effector);
    step.base_end_effector =
        compose(compose(motion, fixed.rod.clamp), base.grasp.tip_to_end_effector);
    for (Eigen::Vector3d& p : step.objective_points) p = moved_point(motion, p);
    tip.push_back(step.end_effector);
    base_poses.push_back(step.base_end_effector);
  }
  const PlanOptions options;
  const sim_detail::TwoEndPath both =
      sim_detail::time_two_ends(tip, base_poses, options.end_effector, options.base_end_effector);
  plan.end_effector_path = both.tip;
  plan.base_end_effector_path = both.base;
  return out;
}

MarkerSensorModel noiseless() {
  MarkerSensorModel sensor;
  sensor.in_plane_noise = 0.0;
  sensor.depth_noise = 0.0;
  return sensor;
}

TEST(TwoEndValidation, TheCommandedBaseIsTheBasePathWithoutABaseArm) {
  const MovingBasePlan moving = moving_base_plan();
  EXPECT_FALSE(drives_base_joints(moving.problem, moving.plan));
  const BaseGripperPath base = commanded_base(moving.problem, moving.plan);
  ASSERT_EQ(base.path.size(), moving.plan.base_end_effector_path.size());
  EXPECT_EQ(base.path.back().pose.position,
            moving.plan.base_end_effector_path.back().pose.position);
  // A fixed clamp has no base path, whatever the plan holds.
  EXPECT_FALSE(commanded_base(band_problem(), moving.plan).moves());
}

TEST(TwoEndValidation, OpenLoopDrivesThePlantByBothEnds) {
  const MovingBasePlan moving = moving_base_plan();
  const ValidationResult fixed = validate_plan(band_problem(), band_plan(), {}, noiseless());
  const ValidationResult result = validate_plan(moving.problem, moving.plan, {}, noiseless());
  ASSERT_EQ(result.status, ValidationStatus::Complete) << result.brief();
  EXPECT_TRUE(result.plant.events.empty());
  const ValidationRun& run = result.runs.front();
  EXPECT_TRUE(run.base_moved);
  EXPECT_FALSE(run.base_driven_by_joints);
  EXPECT_FALSE(fixed.runs.front().base_moved);
  // The plant ends on the plan's last shape moved with both ends, so its true error to the moved
  // target is the fixed plan's.
  const RodConfiguration& last = moving.plan.steps.back().solution.configuration;
  double distance = 0.0;
  for (int i = 0; i < last.nodes(); ++i)
    distance = std::max(distance, (result.plant.last.configuration.p[i] - last.p[i]).norm());
  EXPECT_LT(distance, 1e-8);
  EXPECT_NEAR(run.final.true_error, fixed.runs.front().final.true_error, 1e-8);
  EXPECT_LT((result.plant.last.clamp.position - moving.final_motion.position).norm(), 1e-15);
  EXPECT_LT((result.plant.last.base_end_effector.position -
             moving.plan.base_end_effector_path.back().pose.position)
                .norm(),
            1e-15);
}

TEST(TwoEndValidation, ClosedLoopEstimatesWhereTheBaseIs) {
  // The plant is the planner's model and the markers noise-free: at every checkpoint the estimate,
  // made with the clamp where the base gripper is, explains the markers and finds the plan's
  // (moved) wrench. Re-plans are off: a re-plan with a moving base is plan()'s (issue 21, item 2).
  const MovingBasePlan moving = moving_base_plan();
  ValidationOptions options;
  options.closed_loop = true;
  options.planning.steps = 3;
  options.loop.replan = false;
  const ValidationResult result =
      validate_plan(moving.problem, moving.plan, {}, noiseless(), options);
  ASSERT_EQ(result.status, ValidationStatus::Complete) << result.brief();
  const ValidationRun& run = result.runs.front();
  EXPECT_TRUE(run.base_moved);
  ASSERT_EQ(run.checkpoints.size(), 2u);
  for (std::size_t k = 0; k < run.checkpoints.size(); ++k) {
    const Checkpoint& c = run.checkpoints[k];
    EXPECT_TRUE(c.consistent) << c.message;
    const BaseWrench& planned = moving.plan.steps[k].solution.base_wrench;
    EXPECT_LT((c.estimate.base_wrench.force - planned.force).norm(), 1e-6) << c.message;
    EXPECT_LT((c.estimate.base_wrench.moment - planned.moment).norm(), 1e-6) << c.message;
    EXPECT_LT(c.shape_rms, 1e-6);
  }
  const ValidationResult open = validate_plan(moving.problem, moving.plan, {}, noiseless());
  EXPECT_NEAR(run.final.true_error, open.runs.front().final.true_error, 1e-8);
  EXPECT_LT((result.plant.last.clamp.position - moving.final_motion.position).norm(), 1e-15);
}

TEST(TwoEndValidation, AMovingBaseWithoutABasePathIsHeldAtTheClamp) {
  // A plan made before plan() moved the base has no base path: open and closed loop, the base is
  // the fixed clamp (rod.clamp), bit for bit as without a moving base.
  PlanProblem problem = band_problem();
  problem.moving_base = MovingBase{};
  problem.moving_base->grasp.tip_to_end_effector.position = {0.0, 0.0, -0.02};
  ValidationOptions options;
  options.closed_loop = true;
  options.planning.steps = 3;
  options.loop.replan = false;
  for (const bool closed : {false, true}) {
    options.closed_loop = closed;
    const ValidationResult fixed =
        validate_plan(band_problem(), band_plan(), {}, noiseless(), options);
    const ValidationResult held = validate_plan(problem, band_plan(), {}, noiseless(), options);
    EXPECT_FALSE(held.runs.front().base_moved);
    EXPECT_EQ(held.runs.front().final.true_error, fixed.runs.front().final.true_error);
    EXPECT_EQ(held.runs.front().true_error, fixed.runs.front().true_error);
  }
}

TEST(TwoEndValidation, ClosedLoopRePlansFromWhereTheBaseIs) {
  // The paper's mismatch (15 % softer, the weight the planner neglects, the tip held 2 mm off):
  // open loop the plant misses the moved target; closed, each estimate is made and each re-plan
  // starts with the rod's clamp where the base is, and the re-plans move the base (issue 21).
  const MovingBasePlan moving = moving_base_plan();
  PlantModel plant;
  plant.stiffness_scale = 0.85;
  plant.gravity = Eigen::Vector3d(0.0, 0.0, -9.81);
  plant.grasp_offset.position = {0.002, 0.0, 0.0};
  const ValidationResult open = validate_plan(moving.problem, moving.plan, plant, noiseless());
  ValidationOptions options;
  options.closed_loop = true;
  options.planning.steps = 3;
  options.loop.estimation.gravity = Eigen::Vector3d(0.0, 0.0, -9.81);
  const ValidationResult closed =
      validate_plan(moving.problem, moving.plan, plant, noiseless(), options);
  ASSERT_EQ(closed.status, ValidationStatus::Complete) << closed.brief();
  const ValidationRun& run = closed.runs.front();
  ASSERT_EQ(run.checkpoints.size(), 2u);
  for (const Checkpoint& c : run.checkpoints) {
    EXPECT_TRUE(c.consistent) << c.message;
    EXPECT_TRUE(c.replanned) << c.message;
  }
  RecordProperty("open_true_mm", std::to_string(1e3 * open.runs.front().final.true_error));
  RecordProperty("closed_true_mm", std::to_string(1e3 * run.final.true_error));
  EXPECT_LT(run.final.true_error, 0.5 * open.runs.front().final.true_error)
      << "closed " << run.final.true_error << " m, open " << open.runs.front().final.true_error;
}

/// The largest distance between the nodes of two configurations of the same rod.
double max_node_distance(const RodConfiguration& a, const RodConfiguration& b) {
  double distance = 0.0;
  for (int i = 0; i < a.nodes(); ++i) distance = std::max(distance, (a.p[i] - b.p[i]).norm());
  return distance;
}

TEST(TwoEndValidation, TheBaseArmsJointsDriveTheBaseThroughItsForwardKinematics) {
  // A Panda (the bundled example's) holds the base, standing where its default seed puts its hand
  // on the base gripper's first pose; its joints along the base path by IK (re-timed where its
  // velocity limits ask: the plant then takes each end at its own time).
  MovingBasePlan moving = moving_base_plan();
  const PlanTask task =
      read_plan_task(std::string(RODSHAPE_SOURCE_DIR) + "/examples/plan_panda_s_curve.yaml");
  ASSERT_TRUE(task.problem.arm.has_value());
  PlanArm arm{task.problem.arm->model, {}};
  arm.placement.flange_T_ee = task.problem.arm->placement.flange_T_ee;
  JointTrajectoryOptions joint_options;
  const Eigen::VectorXd q0 = joint_options.first_seed(arm.model);
  const Pose hand = end_effector_pose(arm.model, arm.placement, q0);
  arm.placement.world_T_base =
      compose(moving.plan.base_end_effector_path.front().pose, inverse(hand));
  joint_options.seed = q0;
  ArmPlanResult base_arm;
  base_arm.status = ArmPlanStatus::Reachable;
  base_arm.joints =
      joint_trajectory(arm.model, moving.plan.base_end_effector_path, arm.placement, joint_options);
  ASSERT_TRUE(base_arm.joints.complete()) << base_arm.joints.message;
  moving.problem.base_arm = arm;
  moving.plan.base_arm = base_arm;
  ASSERT_TRUE(drives_base_joints(moving.problem, moving.plan));
  const BaseGripperPath base = commanded_base(moving.problem, moving.plan);
  EXPECT_LT(
      (base.path.back().pose.position - moving.plan.base_end_effector_path.back().pose.position)
          .norm(),
      1e-9);

  PlanResult by_poses = moving.plan;
  by_poses.base_arm.reset();
  const ValidationResult poses = validate_plan(moving.problem, by_poses, {}, noiseless());
  const ValidationResult joints = validate_plan(moving.problem, moving.plan, {}, noiseless());
  ASSERT_EQ(joints.status, ValidationStatus::Complete) << joints.brief();
  EXPECT_TRUE(joints.runs.front().base_driven_by_joints);
  EXPECT_FALSE(poses.runs.front().base_driven_by_joints);
  // The same ends at the last sample (the IK's 1e-10): the same last equilibrium.
  EXPECT_LT(max_node_distance(joints.plant.last.configuration, poses.plant.last.configuration),
            1e-8);
  // Closed loop: each segment's base joints by IK from the base arm's, as for the tip's arm.
  ValidationOptions closed;
  closed.closed_loop = true;
  closed.planning.steps = 3;
  closed.loop.replan = false;
  const ValidationResult loop = validate_plan(moving.problem, moving.plan, {}, noiseless(), closed);
  ASSERT_EQ(loop.status, ValidationStatus::Complete) << loop.brief();
  EXPECT_TRUE(loop.runs.front().base_driven_by_joints);
  EXPECT_LT(max_node_distance(loop.plant.last.configuration, poses.plant.last.configuration), 1e-8);
}

}  // namespace
}  // namespace test_two_end_validation
}  // namespace rodshape
