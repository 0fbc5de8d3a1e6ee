// hand_made_plan.hpp: a plan made by hand for the writers' tests (tests/io, tests/figures):
// configurations integrated from chosen base wrenches, no optimiser.
#pragma once

#include <string>
#include <vector>

#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/io/plan_task.hpp"
#include "rodshape/trajectory/end_effector_path.hpp"
#include "rodshape/trajectory/plan_result.hpp"

namespace rodshape::testing {

inline const std::string kHandMadeTask = R"(rod:
  length: 0.29
  nodes: 21
  stiffness: {EA: 1280, GA: 427, EIx: 0.04, EIy: 0.04, GJ: 0.028}
target:
  points: [[0.01, 0, 0.1], [0.05, 0, 0.2], [0.1, 0, 0.25]]
grasp:
  tip_to_end_effector: {position: [0, 0, 0.03]}
trajectory:
  steps: 3
)";

/// Three steps bending the band about y by a growing end moment, as if optimised.
inline PlanResult make_plan(const PlanTask& task, int steps) {
  const ClampedRod& rod = task.problem.rod;
  PlanResult plan;
  plan.status = steps == 3 ? PlanStatus::Complete : PlanStatus::Partial;
  plan.message = steps == 3 ? "complete: 3 steps" : "step 3 of 3 failed: <because>";
  plan.failed_step = steps == 3 ? -1 : steps;
  plan.initial_configuration = integrate(rod, BaseWrench{}, Derivatives::None);
  plan.initial_points = {{0, 0, 0.1}, {0, 0, 0.2}, {0, 0, 0.25}};
  std::vector<Pose> waypoints{plan.initial_configuration.tip()};
  for (int k = 1; k <= steps; ++k) {
    PlanStep step;
    for (const Eigen::Vector3d& p : task.problem.target.points)
      step.objective_points.push_back(plan.initial_points[step.objective_points.size()] +
                                      k / 3.0 *
                                          (p - plan.initial_points[step.objective_points.size()]));
    ShapeResult& solution = step.solution;
    solution.status = SolveStatus::Converged;
    solution.message = "IPOPT Solve_Succeeded";
    solution.base_wrench = {Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0.05 * k, 0)};
    solution.configuration = integrate(rod, solution.base_wrench, Derivatives::None);
    solution.cost.energy = solution.configuration.energy;
    solution.cost.distances = {0.001 * k, 0.002, 0.0005};
    solution.cost.max_distance = 0.002;
    solution.ipopt.iterations = 10 + k;
    solution.ipopt.application_status_name = "Solve_Succeeded";
    solution.stability = StabilityResult{};
    solution.stability->stable = true;
    step.end_effector = solution.configuration.tip();
    step.end_effector.position += step.end_effector.rotation * Eigen::Vector3d(0, 0, 0.03);
    waypoints.push_back(step.end_effector);
    plan.steps.push_back(step);
  }
  plan.end_effector_path = time_parameterize(waypoints, task.options.end_effector);
  return plan;
}

}  // namespace rodshape::testing
