// equilibrium_task.hpp: what an equilibrium task file describes: the clamped rod, the condition at
// its tip, the solver's starting guess and options. See docs/task-file.md for the file format.
#pragma once

#include <string>

#include "rodshape/core/clamped_rod.hpp"
#include "rodshape/core/scene.hpp"
#include "rodshape/core/wrench.hpp"
#include "rodshape/solvers/shooting_solver.hpp"
#include "rodshape/solvers/tip_condition.hpp"

namespace rodshape {

struct EquilibriumTask {
  ClampedRod rod;             // properties, distributed load (weight included), clamp pose, nodes
  TipCondition tip;           // free (tip wrench), clamped (tip pose) or grasped (pose + released)
  BaseWrench initial_wrench;  // the shooting solver's guess for n(0), m(0); zero by default
  ShootingOptions options;    // solver.max_iterations, solver.tolerance, solver.continuation, ...
  Scene scene;                // obstacles the rod rests on (contact: touch); empty by default
  std::string source;         // the file name that messages name
};

}  // namespace rodshape
