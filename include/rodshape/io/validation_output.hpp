// validation_output.hpp: what `rodshape validate` writes: validation.json (the plant, the sensor,
// each run's errors over time, final errors, events and the plant's last equilibrium),
// validation.csv (the errors over time, one line per run and frame) validation.svg (the errors over
// time, as the paper's figure) and validation.html (the 3D page).  Schemas in docs/task-file.md.
#pragma once

#include <string>
#include <vector>

#include "rodshape/figures/figures.hpp"
#include "rodshape/io/plan_output.hpp"
#include "rodshape/io/plan_task.hpp"
#include "rodshape/sim/plan_validation.hpp"
#include "rodshape/trajectory/plan_result.hpp"

namespace rodshape {

/// What drove a moving base's end in every run (validation.json's `base_driven_by`, written only
/// when the task's base moves): "base_joint_trajectory" (every run along the base arm's joint
/// trajectory through its forward kinematics), "base_end_effector_path" (a run drove it along the
/// plan's base path), or "clamp" (no run moved it: the plan had no base path).
std::string base_driven_by(const ValidationResult& result);

/// The validation document, ending with a newline.
std::string validation_json(const ValidationResult& result,
                            const PlanResult& plan,
                            const PlanTask& task);
/// "run,seed,t,error_3d,error_2d,true_error,visible_markers" and one line per run and frame
/// (s, m).
std::string validation_csv(const ValidationResult& result);
// validation_svg() and validation_html(): rodshape/figures/figures.hpp.
/// The files write_validation() may write: validation.json, validation.csv, validation.svg,
/// validation.html, validation.mcap.
const std::vector<std::string>& validation_file_names();
/// validation.json, validation.csv, validation.svg and (figures.html, three.js found:
/// html_unavailable()) validation.html, and with figures.mcap validation.mcap
/// (validation_mcap(), plan_mcap.hpp), for write_output_set(); those not written are stale.
OutputSet validation_outputs(const ValidationResult& result,
                             const PlanResult& plan,
                             const PlanTask& task,
                             const FigureFiles& figures = {});
/// Writes validation_outputs() into `directory` (created with its parents if missing) as one set,
/// as write_plan() does. `rodshape validate` writes the plan's and these as one set. Returns the
/// names written.
std::vector<std::string> write_validation(const std::string& directory,
                                          const ValidationResult& result,
                                          const PlanResult& plan,
                                          const PlanTask& task,
                                          const FigureFiles& figures = {});

}  // namespace rodshape
