// Benchmarks of the robot area on the bundled Panda: a warm inverse kinematics solve (the step of a
// joint trajectory: the target 1 mm from the seed's pose) and the joint trajectory of the S-curve
// plan (examples/plan_panda_s_curve.yaml: IK at every sample of its end-effector path, velocities,
// velocity-limit check). The plan itself is made once, outside the timing. Then the arm's reach
// (shoulder, wrist, range of their distance: 4096 FK samples and refinement) and the whole plan
// with the arm (reach shell in the workspace, IK of every step's pose, joint trajectory), for the
// S-curve and for the reach-limit example, where the shell is active in the last step. And one
// closed-loop segment's joints (IK along the next waypoint's path, from the arm's joints).
#include <benchmark/benchmark.h>

#include <numbers>
#include <stdexcept>
#include <string>

#include "rodshape/io/task_reader.hpp"
#include "rodshape/robot/arm_model.hpp"
#include "rodshape/robot/arm_reach.hpp"
#include "rodshape/robot/inverse_kinematics.hpp"
#include "rodshape/samples/panda.hpp"
#include "rodshape/trajectory/joint_trajectory.hpp"
#include "rodshape/trajectory/plan.hpp"

namespace {

using namespace rodshape;

const std::string kSource = RODSHAPE_SOURCE_DIR;

void BM_IkWarm(benchmark::State& state) {
  const ArmModel arm = samples::panda();
  const Eigen::VectorXd seed = default_seed(arm);
  Pose target = arm.forward_kinematics(seed);
  target.position += Eigen::Vector3d(0.0006, -0.0005, 0.0006);  // 1.0 mm away
  IkResult result;
  for (auto _ : state) {
    result = solve_ik(arm, target, seed);
    benchmark::DoNotOptimize(result.q.data());
  }
  if (!result.converged()) state.SkipWithError(result.message.c_str());
  state.counters["iterations"] = result.iterations;
}

void BM_JointTrajectoryPaperExperiment(benchmark::State& state) {
  const PlanTask task = read_plan_task(kSource + "/examples/plan_panda_s_curve.yaml");
  if (!task.problem.arm) {
    state.SkipWithError("the S-curve task has no robot");
    return;
  }
  const PlanArm& arm = *task.problem.arm;
  PlanProblem rod_only = task.problem;  // the path as planned without the arm's reach
  rod_only.arm.reset();
  const PlanResult plan = rodshape::plan(rod_only, task.options);
  if (plan.status != PlanStatus::Complete) {
    state.SkipWithError("the S-curve plan did not complete");
    return;
  }
  JointTrajectoryResult joints;
  for (auto _ : state) {
    joints =
        joint_trajectory(arm.model, plan.end_effector_path, arm.placement, task.options.arm.joints);
    benchmark::DoNotOptimize(joints.q.data());
  }
  if (!joints.complete()) state.SkipWithError(joints.message.c_str());
  state.counters["samples"] = static_cast<double>(joints.t.size());
  state.counters["slowdown"] = joints.slowdown;
}

/// One closed-loop segment of the S-curve plan with the arm: the next waypoint's path (sampled as
/// the plan's) solved by IK from the joints at the waypoint before it, as at every checkpoint.
void BM_JointSegmentCheckpoint(benchmark::State& state) {
  const PlanTask task = read_plan_task(kSource + "/examples/plan_panda_s_curve.yaml");
  const PlanResult plan = rodshape::plan(task.problem, task.options);
  if (!task.problem.arm || !plan.arm || plan.arm->waypoint_q.size() < 4) {
    state.SkipWithError("the S-curve plan has no arm's waypoints");
    return;
  }
  const std::size_t k = plan.arm->waypoint_q.size() / 2;  // a segment in the middle
  const std::vector<TimedPose> segment = time_parameterize(
      {plan.steps[k - 2].end_effector, plan.steps[k - 1].end_effector}, task.options.end_effector);
  JointTrajectoryOptions options = task.options.arm.joints;
  options.seed = plan.arm->waypoint_q[k - 1];
  const PlanArm& arm = *task.problem.arm;
  JointTrajectoryResult joints;
  for (auto _ : state) {
    joints = joint_trajectory(arm.model, segment, arm.placement, options);
    benchmark::DoNotOptimize(joints.q.data());
  }
  if (!joints.complete()) state.SkipWithError(joints.message.c_str());
  state.counters["samples"] = static_cast<double>(joints.t.size());
}

void BM_ArmReachPanda(benchmark::State& state) {
  const ArmModel arm = samples::panda();
  ArmReach reach;
  for (auto _ : state) {
    reach = compute_arm_reach(arm);
    benchmark::DoNotOptimize(reach.max_distance);
  }
  state.counters["r_max"] = reach.max_distance;
}

void BM_PlanWithArm(benchmark::State& state, const char* example) {
  const PlanTask task = read_plan_task(kSource + "/examples/" + example);
  if (!task.problem.arm) {
    state.SkipWithError("the task has no robot");
    return;
  }
  PlanResult result;
  for (auto _ : state) {
    result = plan(task.problem, task.options);
    benchmark::DoNotOptimize(result.arm->joints.q.data());
  }
  const ArmPlanResult& arm = *result.arm;
  if (!arm.reachable()) state.SkipWithError(arm.message.c_str());
  state.counters["replans"] = static_cast<double>(arm.replans.size());
  state.counters["samples"] = static_cast<double>(arm.joints.t.size());
}

}  // namespace

BENCHMARK(BM_ArmReachPanda)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_PlanWithArm, SCurve, "plan_panda_s_curve.yaml")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_PlanWithArm, ReachLimit, "plan_panda_reach_limit.yaml")
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_IkWarm)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_JointTrajectoryPaperExperiment)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_JointSegmentCheckpoint)->Unit(benchmark::kMillisecond);
