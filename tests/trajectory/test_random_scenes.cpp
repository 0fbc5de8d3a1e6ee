// test_random_scenes.cpp: plans through random scenes (seeded). Each case takes a bundled plan
// (the C arc, the S curve, the tip bend), plans it without a scene, then adds obstacles:
//  - beside the way (even cases): 1 to 4 balls, boxes and poles, each placed beside a node of a
//    step of that plan and pushed outwards until it is clear of the initial rod and of every step
//    by the clearance, its planning margin and 3 mm more: the plan made without the scene is a
//    way through it, so a plan must exist;
//  - across the way (odd cases): one ball or pole centred on a node of a middle step (the plan made
//    without the scene passes through it), clear of the initial rod and the target.
// Never garbage: a plan reported complete is re-solved independently (scene_replay.hpp) and its rod
// stays the clearance away from every obstacle at every sample of its path. The cases must
// complete (≥ 99 % of them, issue 20; the CI sample: all). RODSHAPE_SCENE_CASES sets the number of
// cases (default 8; scripts/scene_sweep.sh runs 200) and RODSHAPE_SCENE_FIRST the first case's
// seed index (default 0); each case, the counts and the times are printed.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "rodshape/io/task_reader.hpp"
#include "rodshape/trajectory/plan.hpp"
#include "support/scene_replay.hpp"

namespace rodshape {
namespace test_random_scenes {
namespace {

int case_count() {
  const char* text = std::getenv("RODSHAPE_SCENE_CASES");
  return text ? std::max(1, std::atoi(text)) : 8;
}

struct Base {
  PlanTask task;
  PlanResult free_plan;
};

const Base& base(int which) {
  static const std::vector<std::string> names = {"plan_c_arc", "plan_s_curve", "plan_tip_bend"};
  static std::map<int, Base> cache;
  auto found = cache.find(which);
  if (found != cache.end()) return found->second;
  Base b{read_plan_task(std::string(RODSHAPE_SOURCE_DIR) + "/examples/" + names[which] + ".yaml"),
         {}};
  b.free_plan = rodshape::plan(b.task.problem, b.task.options);
  return cache.emplace(which, std::move(b)).first->second;
}

/// The least gap of `obstacle` to the initial rod and every step's rod of `plan`.
double gap_to_plan(const Scene& scene, const Obstacle& obstacle, const PlanResult& plan) {
  Scene one = scene;
  one.obstacles = {obstacle};
  double gap = one.least_gap(plan.initial_configuration.p, {0.0}).gap;
  for (const PlanStep& step : plan.steps)
    gap = std::min(gap, one.least_gap(step.solution.configuration.p, {0.0}).gap);
  return gap;
}

Obstacle random_obstacle(std::mt19937& rng, const Eigen::Vector3d& at, const Eigen::Matrix3d& R) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double size = 0.005 + 0.015 * unit(rng);
  switch (rng() % 3) {
    case 0:
      return {"ball", SphereObstacle{at, size}};
    case 1:
      return {"box", BoxObstacle{at, Eigen::Vector3d::Constant(2 * size), R}};
    default:
      return {"pole", CapsuleObstacle{at - 0.03 * R.col(1), at + 0.03 * R.col(1), 0.6 * size}};
  }
}

struct Outcome {
  bool beside = true;
  PlanStatus status = PlanStatus::Infeasible;
  double seconds = 0.0;
  bool detour = false;
  std::string message;  // a plan that did not complete: why
};

Outcome run_case(int k) {
  std::mt19937 rng(1000 + k);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const Base& b = base(k / 2 % 3);
  PlanTask task = b.task;
  Scene& scene = task.problem.scene;
  scene.rod_radius = 0.5 * std::hypot(0.02, 0.02);
  const PlanResult& free = b.free_plan;
  const int steps = static_cast<int>(free.steps.size());
  const bool beside = k % 2 == 0;
  const double keep = scene.clearance * (1.0 + task.options.scene_margin) + 0.003;
  const int count = beside ? 1 + static_cast<int>(rng() % 4) : 1;
  for (int tries = 0; static_cast<int>(scene.obstacles.size()) < count && tries < 100; ++tries) {
    const RodConfiguration& c =
        free.steps[beside ? rng() % steps : steps / 2 + rng() % 2].solution.configuration;
    const int node = 10 + static_cast<int>(rng() % (c.nodes() - 20));
    const double angle = 2 * 3.141592653589793 * unit(rng);
    const Eigen::Vector3d side =
        std::cos(angle) * c.R[node].col(0) + std::sin(angle) * c.R[node].col(1);
    Obstacle obstacle = random_obstacle(rng, c.p[node], c.R[node]);
    if (beside) {  // outwards until the plan without the scene is clear of it
      for (double away = 0.01; gap_to_plan(scene, obstacle, free) < keep; away += 0.002)
        obstacle = random_obstacle(rng, c.p[node] + away * side, c.R[node]);
    } else {  // across: clear of where the rod starts and of the target only
      Scene one = scene;
      one.obstacles = {obstacle};
      if (one.least_gap(free.initial_configuration.p, {0.0}).gap < keep) continue;
      bool blocks_target = false;
      for (const Eigen::Vector3d& p : task.problem.target.points)
        blocks_target |= obstacle.distance(p).distance < scene.rod_radius + keep;
      if (blocks_target) continue;
    }
    obstacle.name.append(" ").append(std::to_string(scene.obstacles.size()));
    scene.obstacles.push_back(obstacle);
  }
  Outcome outcome;
  outcome.beside = beside;
  const auto start = std::chrono::steady_clock::now();
  PlanResult plan;
  try {
    plan = rodshape::plan(task.problem, task.options);
  } catch (const std::exception& error) {  // a generated scene is never bad input: a finding
    ADD_FAILURE() << "case " << k << " threw: " << error.what();
    return outcome;
  }
  outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  outcome.status = plan.status;
  if (plan.status != PlanStatus::Complete) {
    outcome.message = plan.message;
    for (const std::string& detour : plan.scene->detours) outcome.message += " [" + detour + "]";
  }
  outcome.detour = std::any_of(plan.steps.begin(), plan.steps.end(),
                               [](const PlanStep& step) { return step.detour; });
  if (plan.status == PlanStatus::Complete) {
    EXPECT_GE(plan.scene->min_gap, scene.clearance - SceneResult::kTolerance) << "case " << k;
    const testing::SceneReplay check = testing::replay_scene(task.problem, plan);
    EXPECT_TRUE(check.followed.followed()) << "case " << k << ": " << check.followed.brief();
    // Done when (issue 20): the replay, at the path's samples rather than the planner's tracking
    // substeps, keeps the clearance itself (within the tracked rod's accuracy).
    EXPECT_GE(check.least.margin, -SceneResult::kTolerance)
        << "case " << k << ": gap " << check.least.gap << " m to obstacle " << check.least.obstacle;
  }
  return outcome;
}

TEST(RandomScenes, CompleteClearOrReportedNeverThroughAnObstacle) {
  const int cases = case_count();
  int beside = 0, beside_complete = 0, across = 0, across_complete = 0, detours = 0;
  std::vector<double> times;
  const char* first_text = std::getenv("RODSHAPE_SCENE_FIRST");
  const int first = first_text ? std::max(0, std::atoi(first_text)) : 0;
  for (int k = first; k < first + cases; ++k) {
    const Outcome outcome = run_case(k);
    std::printf("case %d: %s, %s, %.3f s%s%s%s\n", k, outcome.beside ? "beside" : "across",
                to_string(outcome.status).c_str(), outcome.seconds,
                outcome.detour ? ", detour" : "", outcome.message.empty() ? "" : ": ",
                outcome.message.c_str());
    std::fflush(stdout);
    times.push_back(outcome.seconds);
    detours += outcome.detour ? 1 : 0;
    const bool complete = outcome.status == PlanStatus::Complete;
    EXPECT_TRUE(complete || cases >= 100) << "case " << k << ": " << to_string(outcome.status);
    if (outcome.beside) {
      ++beside;
      beside_complete += complete ? 1 : 0;
    } else {
      ++across;
      across_complete += complete ? 1 : 0;
    }
  }
  std::sort(times.begin(), times.end());
  std::printf(
      "random scenes: %d cases; beside the way %d/%d complete; across the way %d/%d complete "
      "(the others reported); %d with a detour; time median %.3f s, worst %.3f s\n",
      cases, beside_complete, beside, across_complete, across, detours, times[times.size() / 2],
      times.back());
  EXPECT_GE(beside_complete + across_complete, 0.99 * cases);
}

}  // namespace
}  // namespace test_random_scenes
}  // namespace rodshape
