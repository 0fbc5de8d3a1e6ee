// test_arm_check_bounds.cpp: what makes the arms' checks of a plan faster gives the same answers.
// The reach from the process-wide cache (two Pandas read separately, the second served by the
// first's entry) equals compute_arm_reach() bit for bit; least_gap(), which skips the rod's and
// the other arm's pairs that cannot beat the least margin so far and runs of rod segments whose
// bounding ball lies too far, finds the same least pair as measuring every pair, at every joint
// sample of both arms of examples/plan_two_pandas.yaml and at random joint positions (many of
// them through the rod or the other arm).
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "robot/arm_reach_cache.hpp"
#include "robot/random_joint_positions.hpp"
#include "rodshape/io/task_reader.hpp"
#include "rodshape/robot/arm_clearance.hpp"
#include "rodshape/robot/arm_reach.hpp"
#include "rodshape/samples/panda.hpp"
#include "rodshape/trajectory/plan.hpp"

namespace rodshape {
namespace test_arm_check_bounds {
namespace {

void expect_same_reach(const ArmReach& a, const ArmReach& b) {
  EXPECT_EQ(a.shoulder, b.shoulder);
  EXPECT_EQ(a.wrist_in_tip_link, b.wrist_in_tip_link);
  EXPECT_EQ(a.min_distance, b.min_distance);
  EXPECT_EQ(a.max_distance, b.max_distance);
  EXPECT_EQ(a.q_min_distance, b.q_min_distance);
  EXPECT_EQ(a.q_max_distance, b.q_max_distance);
}

TEST(CachedArmReach, EqualsTheComputedReachForEveryModelOfTheChain) {
  const ArmModel first = samples::panda(), second = samples::panda();
  ArmReachOptions options;
  options.samples = 300;  // options of this test alone: the first call computes
  options.random_seed = 1234;
  const ArmReach computed = compute_arm_reach(second, options);
  expect_same_reach(detail::cached_arm_reach(first, options), computed);
  expect_same_reach(detail::cached_arm_reach(second, options), computed);  // from the cache
  ArmReachOptions other = options;
  other.random_seed = 99;  // another key: computed, not the first entry
  expect_same_reach(detail::cached_arm_reach(first, other), compute_arm_reach(first, other));
  EXPECT_NE(detail::cached_arm_reach(first, other).q_max_distance, computed.q_max_distance);
}

/// Every pair measured (link capsules that the rod check covers against every rod segment, and
/// against every capsule of the other arm), the least margin first met in least_gap's order.
LinkGap exhaustive_least_gap(const ArmModel& arm,
                             const Pose& world_T_base,
                             const Scene& scene,
                             const Eigen::VectorXd& q,
                             const std::vector<const RodNodes*>& rods,
                             const std::vector<Obstacle>* others) {
  LinkGap least;
  const std::vector<Obstacle> ours = world_capsules(arm, world_T_base, q);
  for (std::size_t c = 0; c < ours.size(); ++c) {
    const auto& capsule = std::get<CapsuleObstacle>(ours[c].shape);
    const auto consider = [&](double distance, int obstacle, int index) {
      const double gap = distance - capsule.radius;
      if (gap - scene.clearance < least.margin) {
        least = {};
        least.gap = gap;
        least.margin = gap - scene.clearance;
        least.capsule = static_cast<int>(c);
        least.obstacle = obstacle;
        (obstacle == kOtherArm ? least.other_capsule : least.rod_segment) = index;
      }
    };
    for (std::size_t j = 0; others != nullptr && j < others->size(); ++j)
      consider((*others)[j].distance(capsule.from, capsule.to).distance, kOtherArm,
               static_cast<int>(j));
    const int frame = arm.link_capsules()[c].frame;
    if (arm.joints_moving_frame(frame) >= arm.joints()) continue;  // not checked against the rod
    for (const RodNodes* rod : rods) {
      double best = std::numeric_limits<double>::infinity();
      int nearest = -1;
      for (std::size_t i = 0; i + 1 < rod->size(); ++i) {
        const Obstacle segment{"", CapsuleObstacle{(*rod)[i], (*rod)[i + 1], scene.rod_radius}};
        const double d = segment.distance(capsule.from, capsule.to).distance;
        if (d <= best) {
          best = d;
          nearest = static_cast<int>(i);
        }
      }
      if (nearest >= 0) consider(best, -1, nearest);
    }
  }
  return least;
}

TEST(LeastGap, SkippingPairsFindsTheLeastPairOfEveryPairOnTheTwoArmPlan) {
  const PlanTask task =
      read_plan_task(std::string(RODSHAPE_SOURCE_DIR) + "/examples/plan_two_pandas.yaml");
  const PlanResult plan = rodshape::plan(task.problem, task.options);
  ASSERT_TRUE(plan.arm && plan.base_arm);
  ASSERT_TRUE(plan.arm->reachable() && plan.base_arm->reachable()) << plan.message;
  std::vector<RodNodes> shapes{plan.initial_configuration.p};
  for (const PlanStep& step : plan.steps) shapes.push_back(step.solution.configuration.p);
  std::vector<const RodNodes*> rods;
  for (const RodNodes& shape : shapes) rods.push_back(&shape);
  const Scene& scene = task.problem.scene;
  struct Side {
    const PlanArm* arm;
    const std::vector<Eigen::VectorXd>* q;
  };
  const Side tip{&*task.problem.arm, &plan.arm->joints.q};
  const Side base{&*task.problem.base_arm, &plan.base_arm->joints.q};
  std::mt19937 random(7);
  int compared = 0, negative = 0;
  for (const auto& [side, other] : {std::pair{tip, base}, std::pair{base, tip}}) {
    const ArmModel& model = side.arm->model;
    const Pose& world_T_base = side.arm->placement.world_T_base;
    const ArmClearance clearance(model, world_T_base, scene, side.q->front());
    std::vector<Eigen::VectorXd> qs = *side.q;  // the plan's samples, then random positions
    std::vector<Eigen::VectorXd> other_qs = *other.q;
    for (int k = 0; k < 300; ++k) {
      qs.push_back(detail::random_joint_positions(model, random));
      other_qs.push_back((*other.q)[static_cast<std::size_t>(k) % other.q->size()]);
    }
    for (std::size_t i = 0; i < qs.size(); ++i) {
      const std::vector<Obstacle> others =
          world_capsules(other.arm->model, other.arm->placement.world_T_base, other_qs[i]);
      for (const std::vector<const RodNodes*>& used :
           {rods, std::vector<const RodNodes*>{rods[i % rods.size()]}}) {
        const LinkGap fast = clearance.least_gap(qs[i], used, &others);
        const LinkGap every =
            exhaustive_least_gap(model, world_T_base, scene, qs[i], used, &others);
        ASSERT_GE(fast.capsule, 0);
        EXPECT_NEAR(fast.margin, every.margin, 1e-12) << "sample " << i;
        EXPECT_EQ(fast.capsule, every.capsule) << "sample " << i;
        EXPECT_EQ(fast.obstacle, every.obstacle) << "sample " << i;
        if (fast.obstacle == kOtherArm)
          EXPECT_EQ(fast.other_capsule, every.other_capsule) << "sample " << i;
        else
          EXPECT_EQ(fast.rod_segment, every.rod_segment) << "sample " << i;
        ++compared;
        if (every.margin < 0.0) ++negative;
      }
    }
  }
  EXPECT_GT(compared, 1000);
  EXPECT_GT(negative, 50);  // links through the rod or the other arm among the random positions
}

}  // namespace
}  // namespace test_arm_check_bounds
}  // namespace rodshape
