// plan_output.hpp: what `rodshape plan` writes: the plan as JSON (plan.json), the timed
// end-effector path as CSV (trajectory.csv) and a picture of the steps as SVG (plan.svg). Each
// function returns the whole text; write it with write_file_atomically(). Schemas are in
// docs/task-file.md.
#pragma once

#include <string>
#include <vector>

#include "rodshape/io/plan_task.hpp"
#include "rodshape/trajectory/end_effector_path.hpp"
#include "rodshape/trajectory/shape_plan.hpp"

namespace rodshape {

/// The plan document: status, message, reason, the target and its feasibility, the initial
/// configuration and points, one entry per step that succeeded (objective points, configuration as
/// `equilibrium` writes it, end-effector pose, energy, distances, stability, the optimiser's
/// account), the end-effector path's summary and the tracking report. Ends with a newline.
std::string plan_result_json(const ShapePlan& plan, const PlanTask& task);

/// "t,x,y,z,qw,qx,qy,qz" and one line per sample of `path` (s, m, unit quaternion). Consecutive
/// quaternions lie in the same hemisphere (q and -q are one rotation; the first has qw ≥ 0), so
/// that a consumer may interpolate them componentwise.
std::string trajectory_csv(const std::vector<TimedPose>& path);

/// A self-contained SVG picture of the plan: three projections (x–z, y–z, x–y) at one common
/// scale, with grids labelled in metres; the initial rod (grey), each step's rod (a colour ramp
/// from the first step to the last, the last drawn thick), each step's objective points (small dots
/// of the step's colour), the target points (red ×) and a legend.
std::string plan_svg(const ShapePlan& plan, const PlanTask& task);

}  // namespace rodshape
