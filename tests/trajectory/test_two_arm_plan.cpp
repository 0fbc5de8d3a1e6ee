// test_two_arm_plan.cpp: the rod held by two arms (issue 21), checked on plans made by hand (the
// rod's base moved and its shape integrated from chosen base wrenches, as if optimised): two
// bundled Pandas facing each other 0.8 m apart, one holding each end. Every step's and every path
// sample's pose has IK for both arms, the two joint trajectories share their times, and the
// forward kinematics of both arms' joints puts each gripper on its path; a base pose outside the
// base arm's reach shell is bad input naming PlanProblem.rod.clamp, and one IK cannot reach is
// reported by the base arm; a planner standing in for the optimisation shows the re-plan with the
// base arm's shell tightened by the tip's rule, and the two arms' re-plans sharing one budget; two
// hands brought together give a negative arm–arm margin and the status collision; two bases
// that overlap are bad input before any plan.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <string>

#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/robot/arm_clearance.hpp"
#include "rodshape/robot/arm_placement.hpp"
#include "rodshape/robot/inverse_kinematics.hpp"
#include "rodshape/samples/panda.hpp"
#include "rodshape/samples/rubber_band.hpp"
#include "support/eigen_compare.hpp"
#include "support/input_error.hpp"
#include "trajectory/arm_replanning.hpp"

namespace rodshape {
namespace test_two_arm_plan {
namespace {

using testing::input_error_message;
using testing::rotation_angle;

/// Rotation about `axis` by `angle`.
Eigen::Matrix3d turn(double angle, const Eigen::Vector3d& axis) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

/// The rod's base frame when the band lies along +x (its tangent d3 = +x, d1 pointing down).
Eigen::Matrix3d along_x() { return turn(std::numbers::pi / 2, Eigen::Vector3d::UnitY()); }

/// The grippers hold the band from above: the end effector's z axis (the approach, the flange's
/// z) along the band's d1 (down when the band lies along +x), its x along the tangent d3; it holds
/// the band `inset` metres from the end, along the tangent into the band.
Pose grasp_from_above(double inset) {
  Eigen::Matrix3d R;
  R.col(0) = Eigen::Vector3d::UnitZ();   // ee x = d3
  R.col(1) = -Eigen::Vector3d::UnitY();  // ee y = -d2
  R.col(2) = Eigen::Vector3d::UnitX();   // ee z = d1
  return {Eigen::Vector3d(0, 0, inset), R};
}

/// Two Pandas on the floor facing each other, their bases 0.8 m apart on the x axis: the base
/// arm at x = -0.4 facing +x, the tip arm at x = +0.4 facing -x; the band 0.35 m above the floor,
/// from x = -0.145 to 0.145 at rest. Each hand's fingertips 0.1034 m out along the flange's z.
PlanProblem two_pandas(const BaseWrench& initial_wrench = {}) {
  PlanProblem problem;
  problem.rod = samples::rubber_band(ConstitutiveModel::Cosserat, 50);
  problem.rod.clamp = {Eigen::Vector3d(-0.145, 0, 0.35), along_x()};
  problem.target.points = {{-0.1, 0, 0.35}, {0.0, 0, 0.35}, {0.1, 0, 0.35}};
  problem.grasp.tip_to_end_effector = grasp_from_above(-0.01);
  problem.initial = InitialState::equilibrium(initial_wrench);
  MovingBase base;
  base.grasp.tip_to_end_effector = grasp_from_above(0.01);
  problem.moving_base = base;
  ArmPlacement tip_placement, base_placement;
  tip_placement.world_T_base = {Eigen::Vector3d(0.4, 0, 0),
                                turn(std::numbers::pi, Eigen::Vector3d::UnitZ())};
  base_placement.world_T_base = {Eigen::Vector3d(-0.4, 0, 0), Eigen::Matrix3d::Identity()};
  tip_placement.flange_T_ee.position = Eigen::Vector3d(0, 0, 0.1034);
  base_placement.flange_T_ee.position = Eigen::Vector3d(0, 0, 0.1034);
  problem.arm = PlanArm{samples::panda(), tip_placement};
  problem.base_arm = PlanArm{samples::panda(), base_placement};
  return problem;
}

/// One step of a hand-made plan: the base moved to `base`, the shape integrated from `wrench`.
PlanStep hand_made_step(const PlanProblem& problem, const Pose& base, const BaseWrench& wrench) {
  ClampedRod rod = problem.rod;
  rod.clamp = base;
  PlanStep step;
  step.solution.status = SolveStatus::Converged;
  step.solution.base_wrench = wrench;
  step.solution.configuration = integrate(rod, wrench, Derivatives::None);
  step.end_effector = compose(step.solution.configuration.tip(), problem.grasp.tip_to_end_effector);
  step.base_end_effector = compose(base, problem.moving_base->grasp.tip_to_end_effector);
  return step;
}

/// A plan made by hand: `steps` steps moving the base by (0, 0.03, 0.02) m and turning it by 0.25
/// rad about z in all, while a growing base moment bends the band; both paths timed together.
PlanResult hand_made_plan(const PlanProblem& problem,
                          const PlanOptions& options,
                          int steps = 4,
                          const Eigen::Vector3d& base_shift = {0.0, 0.03, 0.02}) {
  PlanResult plan;
  plan.status = PlanStatus::Complete;
  plan.initial_configuration = integrate(problem.rod, problem.initial.base_wrench);
  plan.initial_wrench = problem.initial.base_wrench;
  std::vector<Pose> tips{
      compose(plan.initial_configuration.tip(), problem.grasp.tip_to_end_effector)};
  std::vector<Pose> bases{
      compose(problem.rod.clamp, problem.moving_base->grasp.tip_to_end_effector)};
  for (int k = 1; k <= steps; ++k) {
    const double f = static_cast<double>(k) / steps;
    const Pose base{problem.rod.clamp.position + f * base_shift,
                    turn(0.25 * f, Eigen::Vector3d::UnitZ()) * problem.rod.clamp.rotation};
    const BaseWrench wrench{Eigen::Vector3d::Zero(), Eigen::Vector3d(0.0, 0.0, 0.03 * f)};
    plan.steps.push_back(hand_made_step(problem, base, wrench));
    tips.push_back(plan.steps.back().end_effector);
    bases.push_back(plan.steps.back().base_end_effector);
  }
  const TwoEndPath path =
      time_parameterize_together(tips, bases, options.end_effector, options.base_end_effector);
  plan.end_effector_path = path.tip;
  plan.base_end_effector_path = path.base;
  return plan;
}

/// Both arms' FK at every joint sample on their grippers' path samples; returns the largest
/// position error, m (and the rotation's in `angle`).
double fk_error(const PlanArm& arm,
                const JointTrajectoryResult& joints,
                const std::vector<TimedPose>& path,
                double& angle) {
  double worst = 0.0;
  angle = 0.0;
  for (std::size_t i = 0; i < joints.q.size(); ++i) {
    const Pose reached = end_effector_pose(arm.model, arm.placement, joints.q[i]);
    worst = std::max(worst, (reached.position - path[i].pose.position).norm());
    angle = std::max(angle, rotation_angle(reached.rotation, path[i].pose.rotation));
  }
  return worst;
}

TEST(TwoArmPlan, TwoPandasFollowBothEndsSampleBySample) {
  const PlanProblem problem = two_pandas();
  const PlanOptions options;
  PlanResult plan = hand_made_plan(problem, options);
  const std::size_t samples = plan.end_effector_path.size();
  ASSERT_GT(samples, 100u);
  detail::check_arms(problem, options, plan);
  ASSERT_TRUE(plan.arm && plan.base_arm);
  const ArmPlanResult& tip = *plan.arm;
  const ArmPlanResult& base = *plan.base_arm;
  ASSERT_EQ(tip.status, ArmPlanStatus::Reachable) << tip.message;
  ASSERT_EQ(base.status, ArmPlanStatus::Reachable) << base.message;
  EXPECT_EQ(plan.status, PlanStatus::Complete) << plan.message;
  // The shells: the base arm's for its wrist point in the rod's base frame.
  ASSERT_TRUE(base.shell && base.reach);
  EXPECT_LE(base.shell->distance(problem.rod.clamp), base.shell->outer_radius);
  EXPECT_GE(base.shell->distance(problem.rod.clamp), base.shell->inner_radius);
  for (const PlanStep& step : plan.steps) {
    const Pose rod_base = step.solution.configuration.node_pose(0);
    EXPECT_LE(base.shell->distance(rod_base), base.shell->outer_radius);
  }
  // IK at every step (and the initial pose) for both arms.
  ASSERT_EQ(tip.waypoint_q.size(), plan.steps.size() + 1);
  ASSERT_EQ(base.waypoint_q.size(), plan.steps.size() + 1);
  for (std::size_t k = 1; k <= plan.steps.size(); ++k) {
    const Pose reached =
        end_effector_pose(problem.base_arm->model, problem.base_arm->placement, base.waypoint_q[k]);
    EXPECT_LE((reached.position - plan.steps[k - 1].base_end_effector.position).norm(), 1e-9);
  }
  // IK at every path sample, on one clock.
  ASSERT_TRUE(tip.joints.complete()) << tip.joints.message;
  ASSERT_TRUE(base.joints.complete()) << base.joints.message;
  ASSERT_EQ(tip.joints.q.size(), samples);
  ASSERT_EQ(base.joints.q.size(), samples);
  EXPECT_EQ(tip.joints.t, base.joints.t);
  double angle = 0.0;
  EXPECT_LE(fk_error(*problem.arm, tip.joints, plan.end_effector_path, angle), 1e-6);
  EXPECT_LE(angle, 1e-6);
  EXPECT_LE(fk_error(*problem.base_arm, base.joints, plan.base_end_effector_path, angle), 1e-6);
  EXPECT_LE(angle, 1e-6);
  // The last joint samples put both grippers on their last poses.
  const Pose tip_last =
      end_effector_pose(problem.arm->model, problem.arm->placement, tip.joints.q.back());
  const Pose base_last =
      end_effector_pose(problem.base_arm->model, problem.base_arm->placement, base.joints.q.back());
  EXPECT_LE((tip_last.position - plan.steps.back().end_effector.position).norm(), 1e-6);
  EXPECT_LE((base_last.position - plan.steps.back().base_end_effector.position).norm(), 1e-6);
  // Within the joints' position and velocity limits.
  for (const auto* arm : {&*problem.arm, &*problem.base_arm}) {
    const JointTrajectoryResult& joints = arm == &*problem.arm ? tip.joints : base.joints;
    const Eigen::VectorXd v = arm->model.velocity_limits();
    for (std::size_t i = 0; i < joints.q.size(); ++i) {
      EXPECT_NO_THROW(arm->model.check_joint_positions(joints.q[i], "q"));
      EXPECT_TRUE((joints.qdot[i].cwiseAbs().array() <= v.array() * (1 + 1e-9)).all())
          << "sample " << i;
    }
  }
  // Each arm's links measured against the rod at every sample (the hand holding it excepted: it
  // grips the band, and would be "too near" it), and the two arms' links against each other:
  // all clear, the least named in the scene result.
  for (const ArmPlanResult* arm : {&tip, &base}) {
    EXPECT_GE(arm->joints.link_gap.capsule, 0);
    EXPECT_EQ(arm->joints.link_gap.obstacle, -1);  // no scene: the rod
    EXPECT_TRUE(arm->joints.link_gap.clear());
  }
  ASSERT_TRUE(plan.scene && plan.scene->robot);
  EXPECT_TRUE(plan.scene->robot->clear()) << plan.scene->robot->note;
  const LinkGap arms =
      arm_arm_gap(problem.arm->model, problem.arm->placement.world_T_base, tip.joints.q.front(),
                  problem.base_arm->model, problem.base_arm->placement.world_T_base,
                  base.joints.q.front(), problem.scene.clearance);
  // The least over every sample is at most the arms' gap at the first.
  EXPECT_LE(plan.scene->robot->margin, arms.margin + 1e-12);
}

TEST(TwoArmPlan, ABaseOutsideTheBaseArmsShellIsBadInputNamingTheClamp) {
  PlanProblem problem = two_pandas();
  problem.rod.clamp.position = Eigen::Vector3d(0.6, 0, 0.35);  // 1 m from the base arm
  PlanResult plan = hand_made_plan(problem, PlanOptions{}, 1);
  const std::string message =
      input_error_message([&] { detail::check_arms(problem, PlanOptions{}, plan); });
  EXPECT_NE(message.find("PlanProblem.rod.clamp"), std::string::npos) << message;
  EXPECT_NE(message.find("the base arm"), std::string::npos) << message;

  // A base workspace that has its own reach shell while the base arm's is asked for.
  PlanProblem doubled = two_pandas();
  doubled.moving_base->workspace.reach =
      Workspace::ReachShell{Eigen::Vector3d::Zero(), 0.0, 1.0, Eigen::Vector3d::Zero()};
  PlanResult at_rest = hand_made_plan(doubled, PlanOptions{}, 1);
  const std::string twice =
      input_error_message([&] { detail::check_arms(doubled, PlanOptions{}, at_rest); });
  EXPECT_EQ(twice.find("PlanProblem.moving_base.workspace.reach"), 0u) << twice;
}

TEST(TwoArmPlan, ABasePoseWithoutIkIsReportedByTheBaseArm) {
  // A base arm and no tip arm; no reach shell, so that a step moving the base 0.9 m sideways,
  // out of the base arm's reach, is found by IK: the base arm reports that step by name.
  PlanProblem problem = two_pandas();
  problem.arm.reset();
  PlanOptions options;
  options.arm.use_reach = false;
  PlanResult plan = hand_made_plan(problem, options, 1, {0.0, 0.9, 0.0});
  detail::check_arms(problem, options, plan);
  EXPECT_FALSE(plan.arm);
  ASSERT_TRUE(plan.base_arm);
  EXPECT_EQ(plan.base_arm->status, ArmPlanStatus::Unreachable) << plan.base_arm->message;
  EXPECT_NE(plan.base_arm->message.find("step 1's base end-effector pose has no inverse "
                                        "kinematics solution"),
            std::string::npos)
      << plan.base_arm->message;
  EXPECT_EQ(plan.base_arm->waypoint_q.size(), 1u);  // the initial pose's only
  EXPECT_FALSE(plan.base_arm->shell);
}

/// hand_made_plan() with the grippers' poses of its steps after the first moved by `tip_shift`
/// and `base_shift` (out of reach when large), as a planner that ignored the arms' reach would
/// have them; both paths timed anew.
PlanResult shifted_plan(const PlanProblem& problem,
                        const PlanOptions& options,
                        const Eigen::Vector3d& tip_shift,
                        const Eigen::Vector3d& base_shift) {
  PlanResult plan = hand_made_plan(problem, options, 3, {0.0, 0.01, 0.0});
  std::vector<Pose> tips{plan.end_effector_path.front().pose};
  std::vector<Pose> bases{plan.base_end_effector_path.front().pose};
  for (std::size_t k = 0; k < plan.steps.size(); ++k) {
    if (k > 0) {
      plan.steps[k].end_effector.position += tip_shift;
      plan.steps[k].base_end_effector.position += base_shift;
    }
    tips.push_back(plan.steps[k].end_effector);
    bases.push_back(plan.steps[k].base_end_effector);
  }
  const TwoEndPath path =
      time_parameterize_together(tips, bases, options.end_effector, options.base_end_effector);
  plan.end_effector_path = path.tip;
  plan.base_end_effector_path = path.base;
  return plan;
}

/// The shells a planner was given, call by call.
struct ShellsSeen {
  std::vector<Workspace::ReachShell> tip, base;
};

TEST(TwoArmPlan, ABaseStepWithoutIkIsReplannedWithTheBaseArmsShellTightened) {
  // A planner (standing in for the rod's optimisation) that puts the base's later steps 0.9 m
  // sideways until the base arm's shell is tightened: the base arm's IK fails at step 2, the plan
  // is made again with the base shell pulled in past that pose's wrist distance, and then both
  // arms reach every pose. (No link clearance: the moved grippers do not hold the rod.)
  const PlanProblem problem = two_pandas();
  PlanOptions options;
  options.arm.link_clearance = false;
  ShellsSeen seen;
  const auto planner = [&](const PlanProblem& planned) {
    seen.tip.push_back(*planned.workspace.reach);
    seen.base.push_back(*planned.moving_base->workspace.reach);
    const bool tightened = seen.base.back().outer_radius < seen.base.front().outer_radius;
    return shifted_plan(problem, options, Eigen::Vector3d::Zero(),
                        tightened ? Eigen::Vector3d::Zero() : Eigen::Vector3d(0, 0.9, 0));
  };
  const Pose initial_tip = integrate(problem.rod, BaseWrench{}).tip();
  const PlanResult plan = detail::plan_with_arms(problem, options, initial_tip, planner);
  ASSERT_EQ(seen.base.size(), 2u);
  ASSERT_TRUE(plan.arm && plan.base_arm);
  const ArmPlanResult& base = *plan.base_arm;
  EXPECT_EQ(plan.arm->status, ArmPlanStatus::Reachable) << plan.arm->message;
  EXPECT_EQ(base.status, ArmPlanStatus::Reachable) << base.message;
  EXPECT_TRUE(plan.arm->replans.empty());
  ASSERT_EQ(base.replans.size(), 1u);
  const Replan& replan = base.replans.front();
  EXPECT_EQ(replan.reason.find("step 2's base end-effector pose has no inverse kinematics"), 0u)
      << replan.reason;
  // The rule: a pose in the shell's outer half pulls the outer radius in below its wrist distance.
  EXPECT_GT(replan.wrist_distance, seen.base[0].outer_radius);
  EXPECT_DOUBLE_EQ(replan.shell.outer_radius,
                   seen.base[0].outer_radius - options.arm.replan_tightening);
  EXPECT_DOUBLE_EQ(replan.shell.inner_radius, seen.base[0].inner_radius);
  EXPECT_DOUBLE_EQ(seen.base[1].outer_radius, replan.shell.outer_radius);
  EXPECT_DOUBLE_EQ(base.shell->outer_radius, replan.shell.outer_radius);
  // The base arm's shell went to the base's workspace, the tip arm's (unchanged) to the tip's.
  EXPECT_DOUBLE_EQ(seen.tip[1].outer_radius, seen.tip[0].outer_radius);
  EXPECT_EQ(seen.base[0].tip_point, base.shell->tip_point);
  EXPECT_NE(base.message.find("after 1 re-plan"), std::string::npos) << base.message;
  EXPECT_EQ(plan.arm->joints.t, base.joints.t);
}

TEST(TwoArmPlan, BothArmsReplansShareTheBudget) {
  // The tip's steps out of reach until its shell is tightened, the base's always: with one re-plan
  // allowed, the tip's arm takes it and the base arm, failing next, has none left.
  const PlanProblem problem = two_pandas();
  PlanOptions options;
  options.arm.link_clearance = false;
  options.arm.max_replans = 1;
  ShellsSeen seen;
  const auto planner = [&](const PlanProblem& planned) {
    seen.tip.push_back(*planned.workspace.reach);
    const bool tightened = seen.tip.back().outer_radius < seen.tip.front().outer_radius;
    return shifted_plan(problem, options,
                        tightened ? Eigen::Vector3d::Zero() : Eigen::Vector3d(0, -0.9, 0),
                        Eigen::Vector3d(0, 0.9, 0));
  };
  const Pose initial_tip = integrate(problem.rod, BaseWrench{}).tip();
  const PlanResult plan = detail::plan_with_arms(problem, options, initial_tip, planner);
  EXPECT_EQ(seen.tip.size(), 2u);
  ASSERT_TRUE(plan.arm && plan.base_arm);
  EXPECT_EQ(plan.arm->status, ArmPlanStatus::Reachable) << plan.arm->message;
  EXPECT_EQ(plan.arm->replans.size(), 1u);
  EXPECT_EQ(plan.base_arm->status, ArmPlanStatus::Unreachable);
  EXPECT_TRUE(plan.base_arm->replans.empty());
  EXPECT_NE(plan.base_arm->message.find("(after 1 re-plans with a tighter reach shell"),
            std::string::npos)
      << plan.base_arm->message;
}

TEST(TwoArmPlan, TwoHandsThatMeetHaveANegativeMargin) {
  // Both Pandas' hands on the same point between them: their capsules overlap.
  const PlanProblem problem = two_pandas();
  const Pose meet{Eigen::Vector3d(0, 0, 0.35), along_x() * grasp_from_above(0).rotation};
  const IkResult a = solve_ik(problem.arm->model, flange_target(problem.arm->placement, meet),
                              samples::panda_ready_pose());
  const Pose other{meet.position, turn(std::numbers::pi, Eigen::Vector3d::UnitZ()) * meet.rotation};
  const IkResult b =
      solve_ik(problem.base_arm->model, flange_target(problem.base_arm->placement, other),
               samples::panda_ready_pose());
  ASSERT_TRUE(a.converged() && b.converged()) << a.message << " / " << b.message;
  const LinkGap gap =
      arm_arm_gap(problem.arm->model, problem.arm->placement.world_T_base, a.q,
                  problem.base_arm->model, problem.base_arm->placement.world_T_base, b.q, 0.005);
  ASSERT_GE(gap.capsule, 0);
  EXPECT_EQ(gap.obstacle, kOtherArm);
  EXPECT_LT(gap.margin, 0.0);
  EXPECT_LT(gap.gap, 0.0);
  EXPECT_NEAR(gap.gap - gap.margin, 0.005, 1e-15);
  // Symmetric: the same pair seen from the other arm.
  const LinkGap back =
      arm_arm_gap(problem.base_arm->model, problem.base_arm->placement.world_T_base, b.q,
                  problem.arm->model, problem.arm->placement.world_T_base, a.q, 0.005);
  EXPECT_NEAR(back.gap, gap.gap, 1e-12);
  // Apart, at the ready pose, 0.8 m apart: clear.
  const LinkGap ready =
      arm_arm_gap(problem.arm->model, problem.arm->placement.world_T_base,
                  samples::panda_ready_pose(), problem.base_arm->model,
                  problem.base_arm->placement.world_T_base, samples::panda_ready_pose(), 0.005);
  EXPECT_GT(ready.margin, 0.0);
}

TEST(TwoArmPlan, HandsTooNearEachOtherMakeThePlanACollision) {
  // A short band (8 cm) held by both: the two hands 6 cm apart, their capsules overlap.
  PlanProblem problem = two_pandas();
  problem.rod.properties.length = 0.08;
  problem.rod.clamp.position.x() = -0.04;
  const PlanOptions options;
  PlanResult plan = hand_made_plan(problem, options, 2, {0.0, 0.01, 0.0});
  detail::check_arms(problem, options, plan);
  ASSERT_TRUE(plan.arm && plan.base_arm);
  EXPECT_EQ(plan.status, PlanStatus::Collision) << plan.message;
  EXPECT_EQ(plan.arm->status, ArmPlanStatus::Collision) << plan.arm->message;
  EXPECT_EQ(plan.base_arm->status, ArmPlanStatus::Collision);
  EXPECT_EQ(plan.message.find("the two arms come too near each other at step "), 0u)
      << plan.message;
  EXPECT_NE(plan.message.find("(hand) of the base arm, gap -"), std::string::npos) << plan.message;
  ASSERT_TRUE(plan.scene && plan.scene->robot);
  const RobotGapResult& robot = *plan.scene->robot;
  EXPECT_EQ(robot.obstacle, kOtherArm);
  EXPECT_FALSE(robot.other_link.empty());
  EXPECT_LT(robot.margin, 0.0);
  // Measured anew at that sample.
  const LinkGap replay = arm_arm_gap(
      problem.arm->model, problem.arm->placement.world_T_base,
      plan.arm->joints.q[static_cast<std::size_t>(robot.sample)], problem.base_arm->model,
      problem.base_arm->placement.world_T_base,
      plan.base_arm->joints.q[static_cast<std::size_t>(robot.sample)], problem.scene.clearance);
  EXPECT_NEAR(replay.margin, robot.margin, 1e-12);
}

// Issue 43, item 7: two bases standing in each other were found only after planning (a collision);
// they are bad input before the rod is planned, naming both base links.
TEST(TwoArmPlan, OverlappingBasesAreBadInputBeforeAnyPlan) {
  PlanProblem problem = two_pandas();
  // The tip arm beside the base arm, 0.1 m to its side, both facing +x: their base links' capsules
  // (radius 6 cm each, at the same x) overlap by 2 cm.
  problem.arm->placement.world_T_base = {Eigen::Vector3d(-0.4, 0.1, 0),
                                         Eigen::Matrix3d::Identity()};
  PlanOptions options;
  int planned = 0;
  const auto planner = [&](const PlanProblem&) {
    ++planned;
    return hand_made_plan(problem, options, 1);
  };
  const Pose initial_tip = integrate(problem.rod, BaseWrench{}).tip();
  const std::string message = input_error_message(
      [&] { (void)detail::plan_with_arms(problem, options, initial_tip, planner); });
  EXPECT_EQ(message.find("PlanArm.placement.world_T_base: the arm's base link panda_link0 "
                         "overlaps the base arm's base link panda_link0"),
            0u)
      << message;
  EXPECT_NE(message.find("PlanProblem.base_arm.placement.world_T_base"), std::string::npos)
      << message;
  EXPECT_NE(message.find("by 20 mm"), std::string::npos) << message;
  EXPECT_EQ(planned, 0);
}

}  // namespace
}  // namespace test_two_arm_plan
}  // namespace rodshape
