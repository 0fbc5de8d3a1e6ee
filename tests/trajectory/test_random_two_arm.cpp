// test_random_two_arm.cpp: plans of random reachable targets for two arms (seeded), issue 21's goal
// "on 1000 seeded random reachable targets (points of equilibria whose two ends lie in both arms'
// workspaces), IK succeeds at every sample of ≥ 99.5 % of plans; the rest are reported".
//
// The cell is examples/plan_two_pandas.yaml's: the rubber band held from above at both ends by two
// bundled Pandas facing each other 0.8 m apart, its problem and options as the file gives them
// (7 steps, `interpolation: auto`, both arms' IK, reach shells and link clearance). Case k draws,
// with std::mt19937(21000 + k), an equilibrium of that band:
//   - a base pose near the initial one: moved up to 5 cm (uniform in the ball) and turned up to
//     0.3 rad about a random axis;
//   - a base wrench, in the base's frame: a bending moment θ EI / L about a random axis ⊥ d3
//     (θ 30–150°) and a force of up to 0.5 EI / L² per component, which bends the band out of
//     its plane (a 3D centreline, with torsion); no moment about d3: the band's section is
//     isotropic (EIx = EIy), so m·d3 is its twist all along, and the optimum through a set of
//     points is the least twisted equilibrium through them, which is not one drawn with a twist
//     (measured: with a twisting moment ψ GJ / L, ψ within ±90°, the plans ended within 0.03 mm
//     of the drawn ends but their tip grippers turned 27–70° about the band from the drawn ones,
//     so the drawn ends' IK said nothing of the plan's); the equilibrium is integrated from it
//     and kept when its bend (the angle between the tangents d3 at the two ends) is 30–150°, it is
//     stable (assess_stability) and both end-effector poses (base pose · base_T_ee for the base
//     arm, tip · tip_T_ee for the tip arm) have an IK solution (solve_ik from the arm's default
//     seed, its default restarts) at which each arm's links keep the scene's clearance (5 mm) from
//     the rod and from the other arm's links (a target the two arms can only hold by colliding is
//     not reachable); otherwise the draw is repeated (counted).
// Its objective points are 6–10 points of the equilibrium at equal arc lengths, both ends among
// them. Each plan is counted: IK at every sample (the goal's count: both arms' status reachable,
// an IK solution at every step and every sample of the timed path, or collision, which says the
// same but that links came nearer than the clearance: the two arms' hands, counted apart);
// complete (PlanStatus::Complete); complete with both arms reachable. The rest are printed with
// their seed, plan status and message, both arms' status and message, and how far the last
// step's grippers are from the drawn ones, and counted by cause. Each line also gives the angle
// of best_rigid_alignment (intermediate_targets.hpp) of the initial rod's points at the same arc
// lengths onto the target's: the Shape steps of a moving base turn the shape by a fraction of it
// on the way. The initial rod is straight, its points collinear, so that rotation's turn about
// the rod's axis is arbitrary (Kabsch on a rank-1 covariance): 160–179° in most cases, where the
// base moved by ≤ 0.3 rad.
//
// What a sample can show: the cases are seeded, so a run is deterministic, but a sample of n
// cases only bounds the rate statistically. The test asserts that the failures (plans without
// IK at every sample) do not reject the goal at the 5 % level: their count f must satisfy
// P(X ≥ f | X ~ Binomial(n, 0.005)) > 0.05, i.e. f ≤ 1 for n = 16 (the CI default: one failure
// in 16 happens with probability 7.7 % at exactly 99.5 %), f ≤ 9 for n = 1000. It prints f / n
// and the Clopper–Pearson 95 % upper bound on the failure rate (which is below 0.5 % only from
// n ≈ 600 cases with no failure: the full sweep, scripts/two_arm_sweep.sh, is what can show it).
// RODSHAPE_TWO_ARM_CASES sets the number of cases (default 16), RODSHAPE_TWO_ARM_FIRST the
// first case.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/core/so3.hpp"
#include "rodshape/enum_names.hpp"
#include "rodshape/io/task_reader.hpp"
#include "rodshape/optimisation/curve_distance.hpp"
#include "rodshape/robot/arm_clearance.hpp"
#include "rodshape/robot/arm_placement.hpp"
#include "rodshape/robot/inverse_kinematics.hpp"
#include "rodshape/solvers/stability.hpp"
#include "rodshape/trajectory/intermediate_targets.hpp"
#include "rodshape/trajectory/plan.hpp"

namespace rodshape {
namespace test_random_two_arm {
namespace {

constexpr double kPi = std::numbers::pi;
/// The goal: IK at every sample of ≥ 99.5 % of plans.
constexpr double kGoalFailureRate = 0.005;
/// The level at which a sample's failures must not reject the goal.
constexpr double kLevel = 0.05;

int env_int(const char* name, int fallback) {
  const char* text = std::getenv(name);
  return text ? std::max(0, std::atoi(text)) : fallback;
}

const PlanTask& two_pandas() {
  static const PlanTask task =
      read_plan_task(std::string(RODSHAPE_SOURCE_DIR) + "/examples/plan_two_pandas.yaml");
  return task;
}

/// P(X ≥ f) for X ~ Binomial(n, p).
double binomial_tail(int n, double p, int f) {
  double below = 0.0;  // P(X < f)
  double term = std::pow(1.0 - p, n);
  for (int i = 0; i < f; ++i) {
    below += term;
    term *= static_cast<double>(n - i) / (i + 1) * p / (1.0 - p);
  }
  return std::max(0.0, 1.0 - below);
}

/// The largest number of failures among n that does not reject the goal at kLevel.
int allowed_failures(int n) {
  int f = 0;
  while (f < n && binomial_tail(n, kGoalFailureRate, f + 1) > kLevel) ++f;
  return f;
}

/// The Clopper–Pearson upper bound (one-sided 95 %) on a rate with f events among n: the p at
/// which P(X ≤ f | n, p) = 0.05 (bisection).
double upper_bound(int n, int f) {
  double lo = static_cast<double>(f) / n, hi = 1.0;
  for (int i = 0; i < 100; ++i) {
    const double p = 0.5 * (lo + hi);
    (1.0 - binomial_tail(n, p, f + 1) > kLevel ? lo : hi) = p;
  }
  return hi;
}

Eigen::Vector3d random_direction(std::mt19937& rng) {
  std::normal_distribution<double> normal;
  Eigen::Vector3d v(normal(rng), normal(rng), normal(rng));
  while (v.norm() < 1e-9) v = Eigen::Vector3d(normal(rng), normal(rng), normal(rng));
  return v.normalized();
}

/// An IK solution for the arm's end effector at `world_T_ee`, from its default seed.
std::optional<Eigen::VectorXd> ik_solution(const PlanArm& arm, const Pose& world_T_ee) {
  const IkResult ik =
      solve_ik(arm.model, flange_target(arm.placement, world_T_ee), default_seed(arm.model));
  if (!ik.converged()) return std::nullopt;
  return ik.q;
}

/// Whether `arm` at `q` keeps the scene's clearance from the rod and from the other arm's links.
bool clear(const PlanArm& arm,
           const Eigen::VectorXd& q,
           const Scene& scene,
           const RodNodes& rod,
           const std::vector<Obstacle>& other) {
  const ArmClearance clearance(arm.model, arm.placement.world_T_base, scene, q);
  return clearance.least_gap(q, {&rod}, &other).clear();
}

struct TwoArmCase {
  PlanTask task;
  double bend = 0.0;       // the angle between the end tangents, rad
  double alignment = 0.0;  // the angle of the best rigid alignment of the initial points on them
  int draws = 0;           // draws until one was accepted
  Pose base_ee, tip_ee;    // the drawn equilibrium's end-effector poses
  bool drawn = false;
};

TwoArmCase draw_case(int k) {
  std::mt19937 rng(21000 + k);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  TwoArmCase drawn{two_pandas(), 0.0, 0.0, 0, {}, {}, false};
  PlanProblem& problem = drawn.task.problem;
  const Pose initial_base = two_pandas().problem.rod.clamp;
  const RodProperties& properties = problem.rod.properties;
  const double length = properties.length;
  const double EI = 0.5 * (properties.K_rot.x() + properties.K_rot.y());
  for (drawn.draws = 1; drawn.draws <= 200; ++drawn.draws) {
    ClampedRod rod = two_pandas().problem.rod;
    rod.clamp.position =
        initial_base.position + 0.05 * std::cbrt(unit(rng)) * random_direction(rng);
    rod.clamp.rotation = exp_so3(0.3 * unit(rng) * random_direction(rng)) * initial_base.rotation;
    const double theta = (30.0 + 120.0 * unit(rng)) * kPi / 180.0;
    const double beta = 2 * kPi * unit(rng);
    const Eigen::Vector3d moment(theta * EI / length * std::cos(beta),
                                 theta * EI / length * std::sin(beta), 0.0);
    const Eigen::Vector3d force =
        0.5 * EI / (length * length) *
        Eigen::Vector3d(2 * unit(rng) - 1, 2 * unit(rng) - 1, 2 * unit(rng) - 1);
    const BaseWrench wrench{rod.clamp.rotation * force, rod.clamp.rotation * moment};
    const RodConfiguration equilibrium = integrate(rod, wrench, Derivatives::AllNodes);
    const double bend = std::acos(
        std::clamp(equilibrium.R.front().col(2).dot(equilibrium.R.back().col(2)), -1.0, 1.0));
    if (!equilibrium.p.back().allFinite() || bend < kPi / 6 || bend > 5 * kPi / 6) continue;
    if (!assess_stability(rod, equilibrium).stable) continue;
    const Pose base_ee = compose(rod.clamp, problem.moving_base->grasp.tip_to_end_effector);
    const Pose tip_ee = compose(equilibrium.tip(), problem.grasp.tip_to_end_effector);
    const std::optional<Eigen::VectorXd> q_base = ik_solution(*problem.base_arm, base_ee);
    const std::optional<Eigen::VectorXd> q_tip = ik_solution(*problem.arm, tip_ee);
    if (!q_base || !q_tip) continue;
    const RodNodes nodes(equilibrium.p.begin(), equilibrium.p.end());
    const PlanArm& base_arm = *problem.base_arm;
    const PlanArm& tip_arm = *problem.arm;
    if (!clear(tip_arm, *q_tip, problem.scene, nodes,
               world_capsules(base_arm.model, base_arm.placement.world_T_base, *q_base)) ||
        !clear(base_arm, *q_base, problem.scene, nodes,
               world_capsules(tip_arm.model, tip_arm.placement.world_T_base, *q_tip)))
      continue;
    const int count = 6 + static_cast<int>(rng() % 5);
    PointSet points;
    for (int i = 0; i < count; ++i)
      points.push_back(curve_point(equilibrium, length * i / (count - 1)));
    problem.target.points = points;
    drawn.bend = bend;
    PointSet initial_points;
    const RodConfiguration initial = integrate(two_pandas().problem.rod, BaseWrench{});
    for (int i = 0; i < count; ++i)
      initial_points.push_back(curve_point(initial, length * i / (count - 1)));
    drawn.alignment =
        Eigen::AngleAxisd(best_rigid_alignment(initial_points, points).rotation).angle();
    drawn.base_ee = base_ee;
    drawn.tip_ee = tip_ee;
    drawn.drawn = true;
    return drawn;
  }
  ADD_FAILURE() << "case " << k << ": no reachable stable target in 200 draws";
  return drawn;
}

struct Outcome {
  bool complete = false;
  bool reachable = false;  // both arms reachable: IK at every sample, the links clear
  bool ik = false;         // both arms reachable or collision: IK at every sample
  std::string cause;       // why not complete and reachable (empty: it is)
  std::string line;
  double seconds = 0.0;
};

std::string arm_brief(const std::optional<ArmPlanResult>& arm) {
  return arm ? arm->brief() : std::string("absent");
}

Outcome run_case(int k) {
  const TwoArmCase c = draw_case(k);
  Outcome outcome;
  if (!c.drawn) {
    outcome.line = "case " + std::to_string(k) + ": no target drawn";
    return outcome;
  }
  const auto start = std::chrono::steady_clock::now();
  PlanResult plan;
  char text[512];
  try {
    plan = rodshape::plan(c.task.problem, c.task.options);
  } catch (const std::exception& error) {  // a drawn target is never bad input: a finding
    outcome.line = "case " + std::to_string(k) + " threw: " + error.what();
    ADD_FAILURE() << outcome.line;
    return outcome;
  }
  outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  outcome.complete = plan.complete();
  outcome.reachable =
      plan.arm && plan.arm->reachable() && plan.base_arm && plan.base_arm->reachable();
  const auto has_ik = [](const std::optional<ArmPlanResult>& arm) {
    return arm &&
           (arm->status == ArmPlanStatus::Reachable || arm->status == ArmPlanStatus::Collision);
  };
  outcome.ik = has_ik(plan.arm) && has_ik(plan.base_arm);
  if (!outcome.reachable) {
    const auto status_of = [](const std::optional<ArmPlanResult>& arm) {
      return arm ? to_string(arm->status) : std::string("absent");
    };
    outcome.cause = "tip arm " + status_of(plan.arm) + ", base arm " + status_of(plan.base_arm);
  } else if (!outcome.complete) {
    outcome.cause = "both arms reachable, plan " + to_string(plan.status);
  }
  const double reach =
      plan.steps.empty() ? std::nan("") : plan.steps.back().solution.cost.max_distance;
  std::snprintf(text, sizeof text,
                "case %d (seed %d, %zu points, bend %.0f deg, aligned by %.0f deg, %d draws): %s, "
                "arms %s/%s, %zu samples, reach %.2f mm, %.2f s",
                k, 21000 + k, c.task.problem.target.points.size(), c.bend * 180 / kPi,
                c.alignment * 180 / kPi, c.draws, to_string(plan.status).c_str(),
                plan.arm ? to_string(plan.arm->status).c_str() : "-",
                plan.base_arm ? to_string(plan.base_arm->status).c_str() : "-",
                plan.end_effector_path.size(), reach * 1e3, outcome.seconds);
  outcome.line = text;
  if (!plan.steps.empty() && !(outcome.complete && outcome.reachable)) {
    const auto off = [](const Pose& a, const Pose& b) {
      return std::to_string((a.position - b.position).norm() * 1e3) + " mm " +
             std::to_string(Eigen::AngleAxisd(a.rotation.transpose() * b.rotation).angle() * 180 /
                            kPi) +
             " deg";
    };
    outcome.line += "\n    the last step's grippers from the drawn ones: tip " +
                    off(plan.steps.back().end_effector, c.tip_ee) + ", base " +
                    off(plan.steps.back().base_end_effector, c.base_ee);
    const std::size_t samples =
        std::min(plan.end_effector_path.size(), plan.base_end_effector_path.size());
    double least = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < samples; ++i)
      least = std::min(least, (plan.end_effector_path[i].pose.position -
                               plan.base_end_effector_path[i].pose.position)
                                  .norm());
    outcome.line +=
        "; the grippers " + std::to_string(least * 1e3) + " mm apart at least on the path, " +
        std::to_string(
            (plan.steps.back().end_effector.position - plan.steps.back().base_end_effector.position)
                .norm() *
            1e3) +
        " mm at the end";
    for (const InterpolationTrial& trial : plan.interpolation.tried)
      outcome.line += "\n    tried " + to_string(trial.scheme) + ": " + to_string(trial.status) +
                      " " + trial.note;
  }
  if (!outcome.complete) outcome.line += "\n    plan: " + plan.message;
  if (!outcome.reachable) {
    outcome.line += "\n    tip arm: " + arm_brief(plan.arm);
    outcome.line += "\n    base arm: " + arm_brief(plan.base_arm);
  }
  return outcome;
}

TEST(RandomTwoArmTargets, BinomialBoundsOfTheGoal) {
  EXPECT_EQ(allowed_failures(16), 1);  // P(X ≥ 1) = 7.7 %, P(X ≥ 2) = 0.27 %
  EXPECT_EQ(allowed_failures(1000), 9);
  EXPECT_NEAR(upper_bound(599, 0), 0.005, 1e-4);  // 0.995^599 = 0.05
}

TEST(RandomTwoArmTargets, BothArmsHaveIkAtEverySampleOrAreReported) {
  const int cases = std::max(1, env_int("RODSHAPE_TWO_ARM_CASES", 16));
  const int first = env_int("RODSHAPE_TWO_ARM_FIRST", 0);
  int complete = 0, reachable = 0, ik = 0, both = 0;
  std::map<std::string, int> causes;
  std::vector<double> times;
  std::vector<std::string> failures;
  for (int k = first; k < first + cases; ++k) {
    const Outcome outcome = run_case(k);
    std::printf("%s%s\n", outcome.line.c_str(),
                !outcome.ik          ? "  <- NO IK AT EVERY SAMPLE"
                : !outcome.reachable ? "  <- LINKS TOO NEAR"
                : !outcome.complete  ? "  <- NOT COMPLETE"
                                     : "");
    std::fflush(stdout);
    complete += outcome.complete ? 1 : 0;
    reachable += outcome.reachable ? 1 : 0;
    ik += outcome.ik ? 1 : 0;
    if (!outcome.cause.empty()) ++causes[outcome.cause];
    both += outcome.complete && outcome.reachable ? 1 : 0;
    if (!outcome.reachable || !outcome.complete) failures.push_back(outcome.line);
    times.push_back(outcome.seconds);
  }
  std::sort(times.begin(), times.end());
  const int failed = cases - ik;
  std::printf(
      "random two-arm targets, cases %d-%d:\n"
      "  IK at every sample (both arms reachable or collision): %d/%d (%.2f %%); failures %d, "
      "allowed %d (binomial, goal %.1f %%, level %.0f %%); 95 %% upper bound on the failure "
      "rate %.2f %%\n"
      "  both arms reachable (IK at every sample, links clear): %d/%d\n"
      "  complete: %d/%d (%.2f %%); complete and reachable: %d/%d\n"
      "  time per plan: median %.3f s, worst %.3f s\n",
      first, first + cases - 1, ik, cases, 100.0 * ik / cases, failed, allowed_failures(cases),
      100 * (1 - kGoalFailureRate), 100 * kLevel, 100 * upper_bound(cases, failed), reachable,
      cases, complete, cases, 100.0 * complete / cases, both, cases, times[times.size() / 2],
      times.back());
  for (const auto& [cause, count] : causes)
    std::printf("  not complete and reachable: %s: %d\n", cause.c_str(), count);
  if (!failures.empty()) {
    std::printf("the plans not complete or without both arms reachable:\n");
    for (const std::string& line : failures) std::printf("  %s\n", line.c_str());
  }
  EXPECT_LE(failed, allowed_failures(cases))
      << "more plans without IK at every sample than the goal allows on " << cases << " cases";
}

}  // namespace
}  // namespace test_random_two_arm
}  // namespace rodshape

namespace rodshape {
namespace test_random_two_arm {
namespace {

/// The least gap between the two arms' links over the plan's joint samples.
LinkGap least_arm_arm_gap(const PlanProblem& problem, const PlanResult& plan) {
  LinkGap least;
  const std::vector<Eigen::VectorXd>& q_tip = plan.arm->joints.q;
  const std::vector<Eigen::VectorXd>& q_base = plan.base_arm->joints.q;
  for (std::size_t i = 0; i < q_tip.size() && i < q_base.size(); ++i) {
    const LinkGap gap = arm_arm_gap(
        problem.arm->model, problem.arm->placement.world_T_base, q_tip[i], problem.base_arm->model,
        problem.base_arm->placement.world_T_base, q_base[i], problem.scene.clearance);
    if (gap.margin < least.margin) least = gap;
  }
  return least;
}

/// |flange pose of q - the flange pose that puts the end effector at world_T_ee|, m.
double flange_off(const PlanArm& arm, const Eigen::VectorXd& q, const Pose& world_T_ee) {
  return (arm.model.forward_kinematics(q).position -
          flange_target(arm.placement, world_T_ee).position)
      .norm();
}

// Issue 21 item 4 on the full sweep's arm–arm collisions (scripts/two_arm_sweep.sh on 34b8a9d:
// 23 plans ended with status collision at step 7). Case 583 ended with the tip arm's forearm
// (panda_link5) 0.05 mm into the base arm's hand: the tip arm's IK, kept off the base arm's
// links at each sample, swings its elbow away and the plan completes with every pair of links
// the clearance apart and both hands on their poses.
TEST(TwoArmSweepCollisions, TheTipArmsForearmKeepsOffTheBaseArmsHand) {
  const TwoArmCase c = draw_case(583);
  ASSERT_TRUE(c.drawn);
  const PlanProblem& problem = c.task.problem;
  const PlanResult plan = rodshape::plan(problem, c.task.options);
  ASSERT_EQ(plan.status, PlanStatus::Complete) << plan.message;
  ASSERT_TRUE(plan.arm && plan.arm->reachable()) << arm_brief(plan.arm);
  ASSERT_TRUE(plan.base_arm && plan.base_arm->reachable()) << arm_brief(plan.base_arm);
  const LinkGap least = least_arm_arm_gap(problem, plan);
  EXPECT_GE(least.gap, problem.scene.clearance);
  // IK's tolerance is 1e-10 m; the flange is where the gripper's pose puts it.
  EXPECT_LE(flange_off(*problem.arm, plan.arm->joints.q.back(), plan.steps.back().end_effector),
            1e-9);
  EXPECT_LE(flange_off(*problem.base_arm, plan.base_arm->joints.q.back(),
                       plan.steps.back().base_end_effector),
            1e-9);
}

// The band of plan_two_pandas.yaml bent into a loop of radius 8 cm in its horizontal plane (ten
// objective points on an arc of 208°): the two hands come so near each other that their
// link 7s overlap (-80 mm against the 5 mm asked), where no joint positions help, as both links
// are fixed to the hands whose poses the plan sets. A made target, not a drawn one: the margin
// holds whatever the compiler's rounding does to the plan.
TEST(TwoArmSweepCollisions, LinksFixedToBothHandsAreReportedWithTheReason) {
  PlanTask task = two_pandas();
  constexpr double kRadius = 0.08;
  const double length = task.problem.rod.properties.length;
  PointSet loop;
  for (int i = 0; i < 10; ++i) {
    const double angle = (i + 0.5) * length / 10.0 / kRadius;
    loop.push_back(Eigen::Vector3d(-0.05 + kRadius * std::sin(angle),
                                   -0.05 + kRadius * (1.0 - std::cos(angle)), 0.38));
  }
  task.problem.target.points = loop;
  const PlanResult plan = rodshape::plan(task.problem, task.options);
  EXPECT_EQ(plan.status, PlanStatus::Collision) << plan.message;
  ASSERT_TRUE(plan.arm && plan.base_arm);
  EXPECT_EQ(plan.arm->status, ArmPlanStatus::Collision);
  EXPECT_EQ(plan.base_arm->status, ArmPlanStatus::Collision);
  EXPECT_TRUE(plan.arm->joints.complete() && plan.base_arm->joints.complete());
  EXPECT_NE(plan.message.find("link panda_link7 of the arm and link panda_link7 of the base arm"),
            std::string::npos)
      << plan.message;
  EXPECT_NE(plan.message.find("both links are fixed to their hands"), std::string::npos)
      << plan.message;
  const LinkGap least = least_arm_arm_gap(task.problem, plan);
  EXPECT_LT(least.gap, task.problem.scene.clearance);
}

}  // namespace
}  // namespace test_random_two_arm
}  // namespace rodshape
