// test_random_gentle.cpp: plans of random stable targets (seeded), issue 25. Each case draws a rod
// (the paper's rubber band or a nylon cable), gravity on or off, a random clamp orientation, and a
// tip pose: a 3D bend of 90–170° with twist, or the end of a helix of 0.5–1.2 turns. The target is
// the equilibrium a straight tip-pose continuation from the rod's rest reaches, when every substep
// on the way is stable and within 1.05 × its final energy (a gentle path exists); otherwise the
// draw is repeated (counted), as it is when the continuation followed 16 × finer arrives elsewhere
// (the path passes near a point where the branch divides). Its objective points are 4–10 points of
// that equilibrium at equal arc lengths, the tip's among them. The default plan
// (trajectory.interpolation: auto) must be complete, reach the points, and be followed gently: its
// tracked peak, and the peak of an independent replay of its timed path (one solve per sample, not
// the planner's substeps), ≤ PlanOptions::kGentleRatio × the larger of its initial and final
// energies. ≥ 99 % of the cases (the CI sample: all); the others are printed with their ratios.
// RODSHAPE_GENTLE_CASES sets the number of cases (default 8, one of each rod, gravity and shape;
// scripts/gentle_sweep.sh runs 512) and RODSHAPE_GENTLE_FIRST the first seed.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <numbers>
#include <optional>
#include <random>
#include <string>

#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/core/so3.hpp"
#include "rodshape/enum_names.hpp"
#include "rodshape/io/task_reader.hpp"
#include "rodshape/optimisation/curve_distance.hpp"
#include "rodshape/solvers/follow_equilibrium.hpp"
#include "rodshape/trajectory/plan.hpp"
#include "support/scene_replay.hpp"

namespace rodshape {
namespace test_random_gentle {
namespace {

constexpr double kPi = std::numbers::pi;
/// The continuation that defines a target peaks within this factor of its final energy.
constexpr double kContinuationRatio = 1.05;
/// The plan's last step passes within this fraction of the rod's length of every point: the
/// points lie on an equilibrium, so an optimum that misses them by more went elsewhere.
constexpr double kReachFraction = 0.01;

int env_int(const char* name, int fallback) {
  const char* text = std::getenv(name);
  return text ? std::max(0, std::atoi(text)) : fallback;
}

/// The two rods: the paper's band (plan_c_arc.yaml) and the nylon cable (plan_cable_helix.yaml).
const PlanTask& rod_template(bool cable) {
  static const PlanTask band =
      read_plan_task(std::string(RODSHAPE_SOURCE_DIR) + "/examples/plan_c_arc.yaml");
  static const PlanTask nylon =
      read_plan_task(std::string(RODSHAPE_SOURCE_DIR) + "/examples/plan_cable_helix.yaml");
  return cable ? nylon : band;
}

Eigen::Matrix3d about(const Eigen::Vector3d& axis, double angle) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

/// A bend of θ (90–170°) about an axis a ⊥ e3 with twist ψ (±90°), in the clamp's frame, as a
/// path from the straight rod: at σ the tip where a circular arc of the rod's length turned by σθ
/// would put it (σ = 0: `rest`, the tip at rest in the clamp's frame), pulled towards the clamp by
/// σ of the slack (≤ 20 %) and out of the plane by σ of the lift (±10 % L), turned by σθ and
/// twisted by σψ. A straight path to the same pose would compress the rod on the way (its chord
/// shortens faster than the arc's): for a planar 90° arc the straight continuation peaks at 1.6 ×
/// the final energy, so bends are defined along this one.
std::function<Pose(double)> bend_path(std::mt19937& rng, double length, const Pose& rest) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double theta = (90.0 + 80.0 * unit(rng)) * kPi / 180.0;
  const double beta = 2 * kPi * unit(rng);
  const double psi = (unit(rng) - 0.5) * kPi;
  const double slack = 0.2 * unit(rng);
  const double lift = (unit(rng) - 0.5) * 0.2 * length;
  const Eigen::Vector3d a(std::cos(beta), std::sin(beta), 0.0);
  const Eigen::Vector3d b = a.cross(Eigen::Vector3d::UnitZ());
  return [=](double sigma) {
    const double turn = std::max(sigma * theta, 1e-12);
    const double radius = length / turn;  // the arc of length L turned by σθ
    const Eigen::Vector3d arc =
        radius * std::sin(turn) * Eigen::Vector3d::UnitZ() + radius * (1.0 - std::cos(turn)) * b;
    const Pose bent{(1.0 - sigma * slack) * arc + sigma * lift * a,
                    about(a, sigma * theta) * about(Eigen::Vector3d::UnitZ(), sigma * psi)};
    // from where the rod rests (under its weight: not the straight rod's tip), the difference
    // fading out by σ = 1
    const Eigen::Vector3d sag = rest.position - length * Eigen::Vector3d::UnitZ();
    return Pose{bent.position + (1.0 - sigma) * sag,
                bent.rotation * exp_so3((1.0 - sigma) * log_so3(rest.rotation))};
  };
}

/// The end of a helix of the rod's length (0.5–1.2 turns, pitch angle 10–40°) that starts along
/// e3 at the clamp, turned about e3 at random, a little slack and twist, in the clamp's frame; the
/// path to it from `rest` (the tip at rest in the clamp's frame) is straight (issue 25's
/// definition).
std::function<Pose(double)> helix_path(std::mt19937& rng, double length, const Pose& rest) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double turns = 0.5 + 0.7 * unit(rng);
  const double pitch = (10.0 + 30.0 * unit(rng)) * kPi / 180.0;
  const double ell = length / (2 * kPi * turns);  // |c'(φ)|: s = ℓ φ
  const double r = ell * std::cos(pitch), h = ell * std::sin(pitch);
  const auto c = [&](double phi) {
    return Eigen::Vector3d(r * std::cos(phi), r * std::sin(phi), h * phi);
  };
  const auto frame = [&](double phi) {  // the columns N, B, T: the rod's d1, d2, d3
    const Eigen::Vector3d T = Eigen::Vector3d(-r * std::sin(phi), r * std::cos(phi), h) / ell;
    const Eigen::Vector3d N(-std::cos(phi), -std::sin(phi), 0.0);
    Eigen::Matrix3d F;
    F << N, T.cross(N), T;
    return F;
  };
  const double end = 2 * kPi * turns;
  const Eigen::Matrix3d roll = about(Eigen::Vector3d::UnitZ(), 2 * kPi * unit(rng));
  const Eigen::Matrix3d to_clamp = roll * frame(0.0).transpose();
  const double slack = 0.90 + 0.10 * unit(rng);
  const double twist = (unit(rng) - 0.5) * 0.6;
  const Pose tip{slack * to_clamp * (c(end) - c(0.0)),
                 to_clamp * frame(end) * about(Eigen::Vector3d::UnitZ(), twist)};
  return [=](double sigma) { return interpolate(rest, tip, sigma); };  // straight: issue 25
}

Eigen::Matrix3d random_rotation(std::mt19937& rng) {
  std::normal_distribution<double> normal;
  Eigen::Quaterniond q(normal(rng), normal(rng), normal(rng), normal(rng));
  return q.normalized().toRotationMatrix();
}

struct GentleCase {
  PlanTask task;
  std::string kind;
  double continuation_ratio = 0.0;  // the defining continuation's peak over its final energy
  int draws = 0;                    // draws until one was accepted
};

constexpr int kContinuationSubsteps = 64;

/// The defining continuation: from rest along `path` (in the clamp's frame, σ = 0 the rod at
/// rest), every substep stable; its peak energy over the final one, or nullopt when it is lost,
/// unstable or not gentle.
std::optional<double> continuation_ratio(const ClampedRod& rod,
                                         const RodConfiguration& rest,
                                         const std::function<Pose(double)>& path,
                                         RodConfiguration& arrival) {
  std::vector<TipCondition> samples;
  for (int k = 0; k <= kContinuationSubsteps; ++k)
    samples.push_back(
        ClampedTip{compose(rod.clamp, path(static_cast<double>(k) / kContinuationSubsteps))});
  FollowOptions options;
  options.substeps = kContinuationSubsteps;  // an unstable substep ends the path
  options.stability_every_substep = true;
  const FollowResult followed =
      follow_equilibrium(rod, sampled_tip_path(samples), BaseWrench{}, options);
  if (!followed.followed() || followed.states.empty()) return std::nullopt;
  double peak = rest.energy;
  for (const FollowedState& state : followed.states) peak = std::max(peak, state.energy);
  const double ratio = peak / followed.states.back().energy;
  if (!(ratio <= kContinuationRatio)) return std::nullopt;
  // Robustly: followed 16 × finer it arrives on the same equilibrium (a path passing near a point
  // where the branch divides goes one way or the other with the resolution; no plan can rely on
  // such a target being reached).
  std::vector<TipCondition> fine;
  const int finer = 16 * kContinuationSubsteps;
  for (int k = 0; k <= finer; ++k)
    fine.push_back(ClampedTip{compose(rod.clamp, path(static_cast<double>(k) / finer))});
  FollowOptions again;
  again.substeps = finer;
  again.final_derivatives = Derivatives::None;
  if (!follow_equilibrium(rod, sampled_tip_path(fine), BaseWrench{}, again, &followed.configuration)
           .followed())
    return std::nullopt;
  arrival = followed.configuration;
  return ratio;
}

GentleCase draw_case(int k) {
  std::mt19937 rng(5000 + k);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const bool cable = k % 2 == 1, gravity = k / 2 % 2 == 1, helix = k / 4 % 2 == 1;
  GentleCase drawn{rod_template(cable), "", 0.0, 0};
  drawn.kind = std::string(cable ? "cable" : "band") + (gravity ? ", gravity" : "") +
               (helix ? ", helix" : ", bend");
  ClampedRod& rod = drawn.task.problem.rod;
  rod.load =
      DistributedLoad::gravity(rod.properties.mass_per_length,
                               gravity ? Eigen::Vector3d(0, 0, -9.81) : Eigen::Vector3d::Zero());
  for (drawn.draws = 1; drawn.draws <= 50; ++drawn.draws) {
    rod.clamp.rotation = random_rotation(rng);
    const double length = rod.properties.length;
    const RodConfiguration rest = integrate(rod, BaseWrench{}, Derivatives::AllNodes);
    const Pose rest_tip = compose(inverse(rod.clamp), rest.tip());  // in the clamp's frame
    const std::function<Pose(double)> path =
        helix ? helix_path(rng, length, rest_tip) : bend_path(rng, length, rest_tip);
    RodConfiguration arrival;
    const std::optional<double> ratio = continuation_ratio(rod, rest, path, arrival);
    if (!ratio) continue;
    const int count = 4 + static_cast<int>(rng() % 7);
    PointSet points;
    for (int i = 1; i <= count; ++i)
      points.push_back(curve_point(arrival, rod.properties.length * i / count));
    drawn.task.problem.target.points = points;
    drawn.continuation_ratio = *ratio;
    return drawn;
  }
  ADD_FAILURE() << "case " << k << ": no gentle target in 50 draws (" << drawn.kind << ")";
  return drawn;
}

struct Outcome {
  bool gentle = false;
  std::string line;
  double seconds = 0.0;
};

Outcome run_case(int k) {
  const GentleCase c = draw_case(k);
  const auto start = std::chrono::steady_clock::now();
  PlanResult plan;
  try {
    plan = rodshape::plan(c.task.problem, c.task.options);
  } catch (const std::exception& error) {  // a drawn target is never bad input: a finding
    ADD_FAILURE() << "case " << k << " threw: " << error.what();
    return {};
  }
  Outcome outcome;
  outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  char text[512];
  std::snprintf(text, sizeof text, "case %d (%s, %zu points, continuation %.3f, %d draws): %s", k,
                c.kind.c_str(), c.task.problem.target.points.size(), c.continuation_ratio, c.draws,
                to_string(plan.status).c_str());
  outcome.line = text;
  const auto add_tried = [&] {
    for (const InterpolationTrial& trial : plan.interpolation.tried)
      outcome.line += "; tried " + to_string(trial.scheme) + ": " + to_string(trial.status) + " " +
                      std::to_string(trial.peak_ratio) + " " + trial.note;
  };
  if (!plan.complete() || plan.steps.empty()) {
    outcome.line += ": " + plan.message;
    add_tried();
    return outcome;
  }
  const double larger =
      std::max(plan.initial_configuration.energy, plan.steps.back().solution.configuration.energy);
  const double tracked = plan.tracking.peak_energy / larger;
  const testing::SceneReplay replay = testing::replay_scene(c.task.problem, plan);
  const double replayed = replay.peak_energy / larger;
  const double reach = plan.steps.back().solution.cost.max_distance;
  std::snprintf(text, sizeof text,
                " by %s, peak %.3f tracked, %.3f replayed (%s), reach %.2f mm, %.2f s",
                to_string(plan.interpolation.used).c_str(), tracked, replayed,
                replay.followed.followed() ? "followed" : replay.followed.brief().c_str(),
                reach * 1e3, outcome.seconds);
  outcome.line += text;
  add_tried();
  outcome.gentle = replay.followed.followed() && tracked <= PlanOptions::kGentleRatio &&
                   replayed <= PlanOptions::kGentleRatio &&
                   reach <= kReachFraction * c.task.problem.rod.properties.length;
  return outcome;
}

/// `plan` of the case `c` complete, followed gently (tracked and replayed) and reaching the points.
void expect_gentle(const GentleCase& c, const PlanResult& plan) {
  ASSERT_TRUE(plan.complete()) << plan.message;
  const double larger =
      std::max(plan.initial_configuration.energy, plan.steps.back().solution.configuration.energy);
  EXPECT_LE(plan.tracking.peak_energy / larger, PlanOptions::kGentleRatio);
  const testing::SceneReplay replay = testing::replay_scene(c.task.problem, plan);
  EXPECT_TRUE(replay.followed.followed()) << replay.followed.brief();
  EXPECT_LE(replay.peak_energy / larger, PlanOptions::kGentleRatio);
  EXPECT_LE(plan.steps.back().solution.cost.max_distance,
            kReachFraction * c.task.problem.rod.properties.length);
}

/// Case k planned by Pose alone: gentle, along the wrench line.
void expect_gentle_by_wrench_line(int k) {
  GentleCase c = draw_case(k);
  c.task.options.interpolation = ObjectiveInterpolation::Pose;
  const PlanResult plan = rodshape::plan(c.task.problem, c.task.options);
  EXPECT_NE(plan.message.find("base wrenches lie on the straight line"), std::string::npos)
      << plan.message;
  expect_gentle(c, plan);
}

// Case 247 (the cable with its weight wound into a helix): every scheme's straight way snapped or
// arrived elsewhere (the target's optimum is the least twisted equilibrium through its points,
// turned from the one they were taken from; the straight path winds the rod onto another
// equilibrium at the optimum's pose). Pose turning the tip about the rod's tangent on the way was
// gentle (1.00 ×); the wrench line, tried before the twists, is too.
TEST(RandomGentleTargets, PoseLeavesTheStraightPathWhereItWindsTheRodElsewhere) {
  expect_gentle_by_wrench_line(247);
}

// Case 490 (the band with its weight, a bend of 7 points): the Shape sets' optima bend the rod to
// 1.42 x its final energy on the way and the straight path to the optimum's pose (twisted or not)
// compresses it; the equilibria whose base wrenches lie on the straight line from the initial
// rod's to the optimum's grow steadily to the goal's energy.
TEST(RandomGentleTargets, PoseTakesTheWrenchLineWhereTheStraightPathsAreNotGentle) {
  expect_gentle_by_wrench_line(490);
}

// Case 492 (the band wound into a helix through 5 points): the first Shape set's optimum lies
// beyond the rod's scale, so the Shape plan is partial; Pose takes the target's optimum from finer
// sets and reaches it gently.
TEST(RandomGentleTargets, PoseFindsTheOptimumWhereTheShapeSetsFail) {
  GentleCase c = draw_case(492);
  c.task.options.interpolation = ObjectiveInterpolation::Pose;
  expect_gentle(c, rodshape::plan(c.task.problem, c.task.options));
}

TEST(RandomGentleTargets, ArePlannedGentlyOrReportedWithTheirRatio) {
  const int cases = std::max(1, env_int("RODSHAPE_GENTLE_CASES", 8));
  const int first = env_int("RODSHAPE_GENTLE_FIRST", 0);
  int gentle = 0;
  std::vector<double> times;
  for (int k = first; k < first + cases; ++k) {
    const Outcome outcome = run_case(k);
    std::printf("%s%s\n", outcome.line.c_str(), outcome.gentle ? "" : "  <- NOT GENTLE");
    std::fflush(stdout);
    gentle += outcome.gentle ? 1 : 0;
    times.push_back(outcome.seconds);
    EXPECT_TRUE(outcome.gentle || cases >= 100) << outcome.line;
  }
  std::sort(times.begin(), times.end());
  std::printf("random gentle targets: %d/%d planned gently; time median %.3f s, worst %.3f s\n",
              gentle, cases, times[times.size() / 2], times.back());
  EXPECT_GE(gentle, 0.99 * cases);
}

}  // namespace
}  // namespace test_random_gentle
}  // namespace rodshape
