// scene_replay.hpp: a plan's rod re-solved independently of the planner: the held equilibrium
// followed along every sample of the plan's timed end-effector path (the rate's step, one direct
// solve each, not the planner's tracking substeps), with its least gap to the scene over every
// sample.
#pragma once

#include <algorithm>
#include <vector>

#include "rodshape/solvers/follow_equilibrium.hpp"
#include "rodshape/trajectory/plan.hpp"

namespace rodshape::testing {

struct SceneReplay {
  FollowResult followed;
  SceneGap least;
  double peak_energy = 0.0;  // the largest elastic energy over the start and every sample, J
};

inline SceneReplay replay_scene(const PlanProblem& problem, const PlanResult& plan) {
  std::vector<TipCondition> samples;
  const Pose ee_T_tip = inverse(problem.grasp.tip_to_end_effector);
  for (const TimedPose& sample : plan.end_effector_path)
    samples.push_back(ClampedTip{compose(sample.pose, ee_T_tip)});
  const std::vector<double> required = problem.scene.required_gaps(problem.rod.clamp.position);
  SceneReplay result;
  result.peak_energy = plan.initial_configuration.energy;
  FollowOptions options;
  options.observer = [&](double, const RodConfiguration& c) {
    const SceneGap gap = problem.scene.least_gap(c.p, required);
    if (gap.margin < result.least.margin) result.least = gap;
    result.peak_energy = std::max(result.peak_energy, c.energy);
    return true;
  };
  // In pieces of at most FollowOptions::kMaxSubsteps samples, each from where the last ended;
  // the last piece arrives on the plan's final shape.
  BaseWrench w = plan.initial_wrench;
  for (std::size_t first = 0; first + 1 < samples.size();) {
    const std::size_t last =
        std::min(samples.size() - 1, first + static_cast<std::size_t>(FollowOptions::kMaxSubsteps));
    const std::vector<TipCondition> piece(samples.begin() + first, samples.begin() + last + 1);
    options.substeps = static_cast<int>(piece.size()) - 1;
    const bool final = last == samples.size() - 1;
    result.followed =
        follow_equilibrium(problem.rod, sampled_tip_path(piece), w, options,
                           final ? &plan.steps.back().solution.configuration : nullptr);
    if (!result.followed.followed()) break;
    w = result.followed.base_wrench;
    first = last;
  }
  return result;
}

}  // namespace rodshape::testing
