// test_plan_threads.cpp: plan() from several threads equals plan() in series, bit for bit, for a
// task with an arm (whose model the threads share: the copies of one PlanTask), with an arm in a
// scene (its links kept clear) and without an arm.
// Named "Threads" so that the ThreadSanitizer job of CI runs it (ctest -R Threads).
#include <gtest/gtest.h>

#include <string>
#include <thread>
#include <vector>

#include "rodshape/io/task_reader.hpp"
#include "rodshape/trajectory/plan.hpp"

namespace test_plan_threads {
namespace {

using rodshape::PlanResult;
using rodshape::PlanTask;

const std::string kExamples = std::string(RODSHAPE_SOURCE_DIR) + "/examples/";

void expect_identical(const PlanResult& a, const PlanResult& b) {
  ASSERT_EQ(a.status, b.status) << a.message << " / " << b.message;
  ASSERT_EQ(a.steps.size(), b.steps.size());
  for (std::size_t k = 0; k < a.steps.size(); ++k) {
    EXPECT_EQ(a.steps[k].solution.base_wrench.to_vector(),
              b.steps[k].solution.base_wrench.to_vector())
        << k;
    EXPECT_EQ(a.steps[k].end_effector.position, b.steps[k].end_effector.position) << k;
  }
  ASSERT_EQ(a.arm.has_value(), b.arm.has_value());
  if (!a.arm) return;
  EXPECT_EQ(a.arm->status, b.arm->status);
  ASSERT_TRUE(a.arm->shell && b.arm->shell);
  EXPECT_EQ(a.arm->shell->inner_radius, b.arm->shell->inner_radius);
  EXPECT_EQ(a.arm->shell->outer_radius, b.arm->shell->outer_radius);
  ASSERT_EQ(a.arm->joints.q.size(), b.arm->joints.q.size());
  for (std::size_t i = 0; i < a.arm->joints.q.size(); ++i)
    EXPECT_EQ(a.arm->joints.q[i], b.arm->joints.q[i]) << "sample " << i;
}

/// `task` planned in series, then by `threads` threads at once, each with its own copy of the task
/// (the copies share the arm's model).
void expect_threads_equal_series(const PlanTask& task, int threads) {
  const PlanResult serial = rodshape::plan(task.problem, task.options);
  std::vector<PlanResult> parallel(threads);
  std::vector<std::thread> workers;
  for (PlanResult& result : parallel)
    workers.emplace_back([task, &result] { result = rodshape::plan(task.problem, task.options); });
  for (std::thread& worker : workers) worker.join();
  for (const PlanResult& result : parallel) expect_identical(result, serial);
}

TEST(PlanThreads, ThePandaTaskFromThreeThreadsEqualsTheSerialPlan) {
  expect_threads_equal_series(rodshape::read_plan_task(kExamples + "plan_panda_s_curve.yaml"), 3);
}

// The arm in a scene: the links' null-space IK and gaps (ArmClearance, thread-local frames) too.
TEST(PlanThreads, ThePandaShelfTaskFromTwoThreadsEqualsTheSerialPlan) {
  expect_threads_equal_series(rodshape::read_plan_task(kExamples + "plan_panda_shelf.yaml"), 2);
}

TEST(PlanThreads, ATaskWithoutArmFromTwoThreadsEqualsTheSerialPlan) {
  expect_threads_equal_series(rodshape::read_plan_task(kExamples + "plan_c_arc.yaml"), 2);
}

}  // namespace
}  // namespace test_plan_threads
