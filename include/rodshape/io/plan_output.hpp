// plan_output.hpp: what `rodshape plan` writes: the plan as JSON (plan.json), the timed
// end-effector path as CSV (trajectory.csv), a picture of the steps as SVG (plan.svg), the 3D page
// (plan.html, made by the figures area) and, when the task has a robot, the joint trajectory
// (joint_trajectory.csv, joint_trajectory.json), and with a base robot the base arm's
// (base_joint_trajectory.csv, base_joint_trajectory.json). Each function returns the whole text;
// write it with write_file_atomically(). Schemas are in docs/task-file.md, the page in
// docs/figures.md.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "rodshape/figures/figures.hpp"
#include "rodshape/io/mcap_writer.hpp"
#include "rodshape/io/output_files.hpp"
#include "rodshape/io/plan_task.hpp"
#include "rodshape/trajectory/end_effector_path.hpp"
#include "rodshape/trajectory/joint_trajectory.hpp"
#include "rodshape/trajectory/plan_result.hpp"

namespace rodshape {

/// The plan document: status, message, reason, the target and its feasibility, the initial
/// configuration and points, one entry per step that succeeded (objective points, configuration as
/// `equilibrium` writes it, end-effector pose, energy, distances, stability, the optimiser's
/// account), the end-effector path's summary and the tracking report. Ends with a newline.
/// With an arm (plan.arm): `robot` is {status, message, reach
/// (the shell the plan was made with: center, inner_radius, outer_radius, tip_point, wrist_range,
/// margin, and wrist_distances |w - c| where the rod starts and at each step; null when not used),
/// replans (reason, wrist_distance and the shell that followed), waypoint_joint_positions} and
/// `joint_trajectory` the summary {status, message, file, samples, duration, path_duration, slowed,
/// slowdown, failed_sample, ik_restarts, max_position_error, max_rotation_error} of arm.joints;
/// both are null without an arm (a task without a robot).
/// Each step has `base_end_effector` next to `end_effector` (the base gripper's pose; the clamp's,
/// the same at every step, with a fixed clamp). With a base arm (plan.base_arm, issue 21) the
/// document ends with `base_robot` and `base_joint_trajectory`, of the same form as `robot` and
/// `joint_trajectory` (the reach's wrist distances at the rod's base pose p(0), R(0); the file
/// base_joint_trajectory.csv); without one they are left out.
std::string plan_result_json(const PlanResult& plan, const PlanTask& task);

/// trajectory.csv's header: the end effector's pose; with a moving base, the base gripper's too.
inline constexpr const char* kTrajectoryCsvHeader = "t,x,y,z,qw,qx,qy,qz";
inline constexpr const char* kTrajectoryCsvHeaderWithBase =
    "t,x,y,z,qw,qx,qy,qz,bx,by,bz,bqw,bqx,bqy,bqz";

/// "t,x,y,z,qw,qx,qy,qz" and one line per sample of `path` (s, m, unit quaternion). Consecutive
/// quaternions lie in the same hemisphere (q and -q are one rotation; the first has qw ≥ 0), so
/// that a consumer may interpolate them componentwise. With `base_path` (the base gripper's path,
/// PlanResult::base_end_effector_path, a moving base) the columns bx, by, bz, bqw, bqx, bqy, bqz
/// follow, its pose at the same sample (its quaternions kept in one hemisphere likewise);
/// InputError naming PlanResult.base_end_effector_path when it has not as many samples as `path`.
std::string trajectory_csv(const std::vector<TimedPose>& path,
                           const std::vector<TimedPose>& base_path = {});

/// "t,<joint names...>" and one line per sample: time (s) and joint positions (rad or m).
std::string joint_trajectory_csv(const JointTrajectoryResult& trajectory);

/// The joint trajectory shaped like ROS trajectory_msgs/JointTrajectory:
/// {"joint_names": [...], "points": [{"positions": [...], "velocities": [...],
///  "time_from_start": {"sec": int, "nanosec": int}}, ...]}. Ends with a newline.
std::string joint_trajectory_json(const JointTrajectoryResult& trajectory);

/// The figures' caption of a task: its source and the steps it asks for.
FigureCaption figure_caption(const PlanTask& task);
/// plan_svg() (rodshape/figures/figures.hpp) of the task's problem, captioned by the task.
std::string plan_svg(const PlanResult& plan, const PlanTask& task);

/// What write_plan() and write_validation() write besides the data: the HTML pages (plan.html,
/// validation.html; `rodshape plan --no-html` turns them off). When three.js cannot be read
/// (load_page_library()), no page is written and html_unavailable() says why, for the caller to
/// warn: the SVG figures are written as ever.
struct FigureFiles {
  bool html = true;
  /// plan.mcap, validation.mcap (`--mcap`; plan_mcap.hpp, docs/ros.md): written when set.
  std::optional<McapOptions> mcap = std::nullopt;  // (initialised: {.html = h} stays warning-free)
};

/// InputError when `directory` exists but is not a directory, or is a symbolic link, dangling or
/// not (issue 43: followed, a link into another run's directory rewrote that run's files; links
/// above it are followed). To check before planning, which may take a while; write_output_set()
/// checks it again.
void check_output_directory(const std::string& directory);

/// The files write_plan() may write, in its order: plan.json, trajectory.csv, plan.svg,
/// plan.html, joint_trajectory.csv, joint_trajectory.json, base_joint_trajectory.csv,
/// base_joint_trajectory.json, plan.mcap.
const std::vector<std::string>& plan_file_names();

/// Removes the plan files (plan_file_names()) of an earlier run from `directory`: those that are
/// recognisably rodshape's (is_rodshape_output(), output_files.hpp); other files are left alone.
/// The CLI does not call it before planning (bad input found while planning must remove nothing,
/// issue 24): write_plan() replaces an earlier run's files. Throws InputError when such a file
/// exists and cannot be removed.
void remove_plan_files(const std::string& directory);

/// The files of the plan, for write_output_set() (output_files.hpp): plan.json; unless the plan is
/// infeasible, trajectory.csv, plan.svg and (figures.html, three.js found) plan.html; with a
/// complete joint trajectory, joint_trajectory.csv and joint_trajectory.json; with a base arm's
/// complete joint trajectory, base_joint_trajectory.csv and base_joint_trajectory.json (same
/// forms); with figures.mcap and an end-effector path, plan.mcap. The others of plan_file_names()
/// are stale: an earlier run's would not match plan.json.
OutputSet plan_outputs(const PlanResult& plan,
                       const PlanTask& task,
                       const FigureFiles& figures = {});

/// Writes plan_outputs() into `directory` (created with its parents if missing) as one set: every
/// path is checked before any is written (a device, a FIFO or a symbolic link is refused), each
/// file is written whole, and none is replaced unless all are written; then the stale files of
/// an earlier run are removed when they are rodshape's (check_output_files() first, to refuse
/// others before planning). Returns the names written, in order. Throws InputError when the
/// directory cannot be made or a file cannot be written.
std::vector<std::string> write_plan(const std::string& directory,
                                    const PlanResult& plan,
                                    const PlanTask& task,
                                    const FigureFiles& figures = {});

/// Why the HTML pages cannot be written ("" when they can): three.js not found
/// (load_page_library()). The CLI prints it as a warning before writing.
std::string html_unavailable();

}  // namespace rodshape
