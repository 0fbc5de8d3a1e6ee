// plan_task.hpp: what a plan task file describes: the rod and its clamp (as for `equilibrium`), the
// target shape, the weights of the cost, what the shapes must respect (workspace, grasp, strain
// limits), the initial tip pose, and the options of the optimiser and of the trajectory. See
// docs/task-file.md for the file format.
#pragma once

#include <string>

#include "rodshape/trajectory/shape_plan.hpp"

namespace rodshape {

struct PlanTask {
  PlanRequest request;  // rod, target (points, weights), workspace, grasp, limits, initial tip
  PlanOptions options;  // trajectory.steps (n_inter), optimizer, end-effector limits, tracking
  std::string source;   // the file name that messages name
};

}  // namespace rodshape
