// test_arm_threads.cpp: one ArmModel shared by threads. Copies of an ArmModel share its immutable
// description; before each evaluation worked on its own KDL chain, KDL's pose caches (mutable
// members of its joints) were shared too, and concurrent forward kinematics returned other
// configurations' poses. Every thread's results must equal the serial ones bit for bit. Named
// "Threads" so that the ThreadSanitizer job of CI runs it (ctest -R Threads).
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <thread>
#include <vector>

#include "rodshape/robot/arm_model.hpp"
#include "rodshape/robot/inverse_kinematics.hpp"
#include "rodshape/samples/panda.hpp"

namespace test_arm_threads {
namespace {

using rodshape::ArmModel;

struct ArmSample {
  rodshape::Pose pose;
  Eigen::Matrix<double, 6, Eigen::Dynamic> jacobian;
  Eigen::VectorXd ik;
};

/// Configuration k of a fixed sequence that sweeps every joint (all within the Panda's limits).
Eigen::VectorXd configuration(const ArmModel& arm, int k) {
  Eigen::VectorXd q = rodshape::samples::panda_ready_pose();
  for (int j = 0; j < arm.joints(); ++j) q(j) += 0.3 * std::sin(0.7 * k + 1.3 * j);
  return arm.clamp_to_limits(q);
}

/// FK, Jacobian and an IK solve (seeded at the ready pose) of configurations 0..count-1.
std::vector<ArmSample> evaluate(const ArmModel& arm, int count) {
  std::vector<ArmSample> samples(count);
  for (int k = 0; k < count; ++k) {
    const Eigen::VectorXd q = configuration(arm, k);
    arm.forward_kinematics(q, samples[k].pose, samples[k].jacobian);
    samples[k].ik =
        rodshape::solve_ik(arm, samples[k].pose, rodshape::samples::panda_ready_pose()).q;
  }
  return samples;
}

void expect_identical(const std::vector<ArmSample>& a, const std::vector<ArmSample>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].pose.position, b[k].pose.position) << "sample " << k;
    EXPECT_EQ(a[k].pose.rotation, b[k].pose.rotation) << "sample " << k;
    EXPECT_EQ(a[k].jacobian, b[k].jacobian) << "sample " << k;
    EXPECT_EQ(a[k].ik, b[k].ik) << "sample " << k;
  }
}

/// Each arm of `arms` evaluated by its own thread, all at once.
std::vector<std::vector<ArmSample>> evaluate_in_threads(const std::vector<const ArmModel*>& arms,
                                                        int count) {
  std::vector<std::vector<ArmSample>> results(arms.size());
  std::vector<std::thread> threads;
  for (std::size_t k = 0; k < arms.size(); ++k)
    threads.emplace_back([&, k] { results[k] = evaluate(*arms[k], count); });
  for (std::thread& thread : threads) thread.join();
  return results;
}

constexpr int kCount = 60;

TEST(ArmModelThreads, OneModelSharedByFourThreadsGivesTheSerialResults) {
  const ArmModel arm = rodshape::samples::panda();
  const std::vector<ArmSample> serial = evaluate(arm, kCount);
  for (const auto& result : evaluate_in_threads({&arm, &arm, &arm, &arm}, kCount))
    expect_identical(result, serial);
}

TEST(ArmModelThreads, CopiesOfOneModelInThreadsGiveTheSerialResults) {
  const ArmModel arm = rodshape::samples::panda();
  const std::vector<ArmSample> serial = evaluate(arm, kCount);
  const std::vector<ArmModel> copies(4, arm);  // they share the model's description
  for (const auto& result :
       evaluate_in_threads({&copies[0], &copies[1], &copies[2], &copies[3]}, kCount))
    expect_identical(result, serial);
}

}  // namespace
}  // namespace test_arm_threads
