// task_reader.hpp: task files (YAML) in. Every error is an InputError whose one-line message names
// the file, the line and the field path, e.g. "task.yaml:4: rod.length = -0.3 must be > 0".
// Unknown keys are rejected ("rod.lenght: unknown key; did you mean 'length'?"). The format is
// documented in docs/task-file.md.
#pragma once

#include <string>

#include "rodshape/io/equilibrium_task.hpp"
#include "rodshape/io/estimate_task.hpp"
#include "rodshape/io/plan_task.hpp"

namespace rodshape {

/// Reads and checks the task file at `path` (messages name the path as given). Throws InputError
/// when the file cannot be read, is not valid YAML, or describes an invalid task.
EquilibriumTask read_equilibrium_task(const std::string& path);

/// The same for a task already in memory; `source_name` stands for the file in messages.
EquilibriumTask parse_equilibrium_task(const std::string& yaml_text,
                                       const std::string& source_name);

/// Reads and checks a plan task file (`rodshape plan`): the rod sections of an equilibrium task
/// without `tip` and `solver`, plus target, weights, workspace, grasp, initial, limits, trajectory
/// and optimizer. Throws InputError as read_equilibrium_task does, also for a workspace that
/// excludes the initial tip.
PlanTask read_plan_task(const std::string& path);

/// The same for a plan task already in memory; `source_name` stands for the file in messages.
PlanTask parse_plan_task(const std::string& yaml_text, const std::string& source_name);

/// Reads and checks an estimate task file (`rodshape estimate`, docs/estimate.md): an equilibrium
/// task whose tip is held (the fit's prior), whose rod has a section, with a `sensor` section of
/// kind depth (its camera: the frame of the cloud). Throws InputError as read_equilibrium_task
/// does.
EstimateTask read_estimate_task(const std::string& path);

/// The same for an estimate task already in memory; `source_name` stands for the file in messages.
EstimateTask parse_estimate_task(const std::string& yaml_text, const std::string& source_name);

}  // namespace rodshape
