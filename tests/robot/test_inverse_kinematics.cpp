// test_inverse_kinematics.cpp: round trips q -> FK -> IK -> FK on the Panda at random joint
// positions within the limits (to the solver's tolerances, 1e-10 m and 1e-10 rad), a
// trajectory that stays on one branch, limit avoidance, targets out of reach and bad input.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <random>
#include <string>

#include "rodshape/error.hpp"
#include "rodshape/robot/arm_model.hpp"
#include "rodshape/robot/inverse_kinematics.hpp"
#include "support/eigen_compare.hpp"
#include "support/input_error.hpp"
#include "support/panda_dh.hpp"

namespace test_inverse_kinematics {
namespace {

using namespace rodshape;
using rodshape::testing::rotation_angle;

const ArmModel& panda() {
  static const ArmModel arm = samples::panda();
  return arm;
}

Eigen::VectorXd ready_pose() { return rodshape::testing::panda_ready_pose(); }

Eigen::VectorXd random_within_limits(std::mt19937& rng) {
  Eigen::VectorXd q(7);
  for (int i = 0; i < 7; ++i)
    q(i) = std::uniform_real_distribution<double>(panda().lower_limits()(i),
                                                  panda().upper_limits()(i))(rng);
  return q;
}

/// The solution's pose, recomputed by forward kinematics, is the target's to the solver's
/// tolerances (plus 1e-14 for the round-off of recomputing it), and the solution is within the
/// limits.
void expect_round_trip(const IkResult& result, const Pose& target) {
  ASSERT_TRUE(result.converged()) << to_string(result.status) << ": " << result.message;
  const Pose reached = panda().forward_kinematics(result.q);
  EXPECT_LE((reached.position - target.position).norm(), IkOptions{}.position_tolerance + 1e-14);
  EXPECT_LE(rotation_angle(reached.rotation, target.rotation),
            IkOptions{}.rotation_tolerance + 1e-14);
  EXPECT_NO_THROW(panda().check_joint_positions(result.q, "q", 0.0));
}

// Seed count from the environment (RODSHAPE_IK_TRIALS) for longer sweeps; 200 by default.
int trials() {
  const char* text = std::getenv("RODSHAPE_IK_TRIALS");
  return text != nullptr ? std::max(1, std::atoi(text)) : 200;
}

TEST(InverseKinematics, RoundTripsFromTheReadyPoseAtRandomReachablePoses) {
  std::mt19937 rng(2024);
  int most_iterations = 0, total_iterations = 0, restarted = 0;
  for (int trial = 0; trial < trials(); ++trial) {
    const Pose target = panda().forward_kinematics(random_within_limits(rng));
    const IkResult result = solve_ik(panda(), target, ready_pose());
    SCOPED_TRACE("trial " + std::to_string(trial));
    expect_round_trip(result, target);
    most_iterations = std::max(most_iterations, result.iterations);
    total_iterations += result.iterations;
    restarted += result.restarts > 0 ? 1 : 0;
  }
  std::cout << "[ stats    ] " << trials() << " targets from the ready pose: mean "
            << total_iterations / trials() << " iterations, most " << most_iterations << ", "
            << restarted << " needed a restart\n";
}

// Seeded near the answer (as from the previous waypoint): few iterations, no restart, and the
// solution stays near the seed (the same branch).
TEST(InverseKinematics, NearbySeedsConvergeQuicklyOnTheSameBranch) {
  std::mt19937 rng(11);
  std::normal_distribution<double> noise(0.0, 0.02);
  int most_iterations = 0;
  for (int trial = 0; trial < trials(); ++trial) {
    const Eigen::VectorXd q = random_within_limits(rng);
    const Pose target = panda().forward_kinematics(q);
    Eigen::VectorXd seed = q;
    for (int i = 0; i < 7; ++i) seed(i) += noise(rng);
    seed = panda().clamp_to_limits(seed);
    const IkResult result = solve_ik(panda(), target, seed);
    SCOPED_TRACE("trial " + std::to_string(trial));
    expect_round_trip(result, target);
    EXPECT_EQ(result.restarts, 0);
    EXPECT_LE((result.q - q).cwiseAbs().maxCoeff(), 0.3);
    most_iterations = std::max(most_iterations, result.iterations);
  }
  std::cout << "[ stats    ] nearby seeds: most " << most_iterations << " iterations\n";
}

// A straight 20 cm line in 1 cm steps, each solve seeded by the previous solution: the joints
// move by little at each step (no jump to another branch).
TEST(InverseKinematics, AWaypointPathSeededFromThePreviousWaypointStaysOnOneBranch) {
  Pose target = panda().forward_kinematics(ready_pose());
  Eigen::VectorXd q = ready_pose();
  for (int step = 0; step < 20; ++step) {
    target.position += Eigen::Vector3d(0.005, 0.01, -0.005);
    const IkResult result = solve_ik(panda(), target, q);
    expect_round_trip(result, target);
    EXPECT_EQ(result.restarts, 0);
    EXPECT_LE((result.q - q).cwiseAbs().maxCoeff(), 0.1) << "step " << step;
    q = result.q;
  }
}

// Joint 7 starts 0.05 rad from its upper limit; the null-space motion pulls it inward while the
// tip still reaches the target. Without it (gain 0) joint 7 stays near the limit.
TEST(InverseKinematics, RedundancyMovesJointsAwayFromTheirLimits) {
  Eigen::VectorXd q = ready_pose();
  q(6) = 2.8473;
  const Pose start = panda().forward_kinematics(q);
  Pose target = start;
  target.position += Eigen::Vector3d(0.05, 0.0, 0.0);
  IkOptions without;
  without.limit_avoidance_gain = 0.0;
  const IkResult plain = solve_ik(panda(), target, q, without);
  const IkResult avoiding = solve_ik(panda(), target, q);
  expect_round_trip(plain, target);
  expect_round_trip(avoiding, target);
  EXPECT_LT(std::abs(avoiding.q(6)), std::abs(plain.q(6)));
}

TEST(InverseKinematics, TargetsOutOfReachAreAStatusNotAnException) {
  Pose far;
  far.position = Eigen::Vector3d(2.0, 0.0, 0.5);
  const IkResult beyond = solve_ik(panda(), far, ready_pose());
  EXPECT_EQ(beyond.status, SolveStatus::OutOfReach);
  EXPECT_EQ(beyond.message.rfind("out of reach: the target is", 0), 0u) << beyond.message;
  EXPECT_EQ(beyond.q, ready_pose());

  // Inside the crude reach bound (1.32 m) but beyond what the joints can do.
  Pose hard = panda().forward_kinematics(ready_pose());
  hard.position = Eigen::Vector3d(0.9, 0.0, 0.9);
  const IkResult stalled = solve_ik(panda(), hard, ready_pose());
  EXPECT_EQ(stalled.status, SolveStatus::OutOfReach);
  EXPECT_EQ(stalled.message.rfind("out of reach: no joint positions", 0), 0u) << stalled.message;
  EXPECT_GT(stalled.position_error, 0.1);
  EXPECT_NO_THROW(panda().check_joint_positions(stalled.q, "q", 0.0));
}

TEST(InverseKinematics, BadSeedsTargetsAndOptionsAreInputErrors) {
  const Pose target = panda().forward_kinematics(ready_pose());
  EXPECT_THROW(solve_ik(panda(), target, Eigen::VectorXd::Zero(6)), InputError);
  Eigen::VectorXd outside = ready_pose();
  outside(3) = 0.0;  // joint 4's upper limit is -0.0698
  const std::string seed =
      rodshape::testing::input_error_message([&] { solve_ik(panda(), target, outside); });
  EXPECT_NE(seed.find("seed[3] = 0 is outside the limits"), std::string::npos) << seed;
  Pose bad = target;
  bad.position.x() = std::nan("");
  EXPECT_THROW(solve_ik(panda(), bad, ready_pose()), InputError);
  bad = target;
  bad.rotation *= 2.0;
  EXPECT_THROW(solve_ik(panda(), bad, ready_pose()), InputError);
  IkOptions options;
  options.position_tolerance = 0.0;
  EXPECT_THROW(solve_ik(panda(), target, ready_pose(), options), InputError);
  options = IkOptions{};
  options.max_restarts = -1;
  EXPECT_THROW(solve_ik(panda(), target, ready_pose(), options), InputError);
}

}  // namespace
}  // namespace test_inverse_kinematics
