// scene_replay.hpp: a plan's rod re-solved independently of the planner: the held equilibrium
// followed along every sample of the plan's timed end-effector path (the rate's step, one direct
// solve each, not the planner's tracking substeps), with its least gap to the scene over every
// sample.
#pragma once

#include <vector>

#include "rodshape/solvers/follow_equilibrium.hpp"
#include "rodshape/trajectory/plan.hpp"

namespace rodshape::testing {

struct SceneReplay {
  FollowResult followed;
  SceneGap least;
};

inline SceneReplay replay_scene(const PlanProblem& problem, const PlanResult& plan) {
  std::vector<TipCondition> samples;
  const Pose ee_T_tip = inverse(problem.grasp.tip_to_end_effector);
  for (const TimedPose& sample : plan.end_effector_path)
    samples.push_back(ClampedTip{compose(sample.pose, ee_T_tip)});
  const std::vector<double> required = problem.scene.required_gaps(problem.rod.clamp.position);
  SceneReplay result;
  FollowOptions options;
  options.substeps = static_cast<int>(samples.size()) - 1;
  options.observer = [&](double, const RodConfiguration& c) {
    const SceneGap gap = problem.scene.least_gap(c.p, required);
    if (gap.margin < result.least.margin) result.least = gap;
    return true;
  };
  result.followed = follow_equilibrium(problem.rod, sampled_tip_path(samples), plan.initial_wrench,
                                       options, &plan.steps.back().solution.configuration);
  return result;
}

}  // namespace rodshape::testing
