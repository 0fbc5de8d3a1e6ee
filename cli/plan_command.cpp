// plan_command.cpp: plan the shape a task file asks for and write plan.json, trajectory.csv and
// plan.svg into the output directory; with a robot section, the plan respects the arm's reach, its
// poses are checked by inverse kinematics, and the joint trajectory that follows the end-effector
// path is written too (joint_trajectory.csv and .json).
//   task file -> PlanTask (io) -> plan_shape (trajectory), or with a robot plan_with_arm (robot:
//             reach, IK checks, re-plans, joint trajectory) -> JSON, CSV, SVG (io)
#include "plan_command.hpp"

#include <filesystem>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "exit_code.hpp"
#include "rodshape/error.hpp"
#include "rodshape/io/atomic_file.hpp"
#include "rodshape/io/plan_output.hpp"
#include "rodshape/io/task_reader.hpp"
#include "rodshape/robot/arm_plan.hpp"
#include "rodshape/trajectory/shape_plan.hpp"

namespace rodshape::cli {

namespace {

namespace fs = std::filesystem;

/// InputError when `directory` exists but is not a directory (checked before planning, which may
/// take a while, and again by make_directory()).
void check_directory(const std::string& directory) {
  std::error_code error;
  if (fs::exists(directory, error) && !fs::is_directory(directory, error))
    throw InputError(directory + ": cannot create the output directory: it is not a directory");
}

/// Creates `directory` (and its parents) if missing; InputError when that fails or it is a file.
void make_directory(const std::string& directory) {
  std::error_code error;
  fs::create_directories(directory, error);
  if (error)
    throw InputError(directory + ": cannot create the output directory: " + error.message());
  if (!fs::is_directory(directory, error))
    throw InputError(directory + ": cannot create the output directory: it is not a directory");
}

std::string millimetres(double metres) {
  std::ostringstream out;
  out << std::setprecision(3) << metres * 1e3 << " mm";
  return out.str();
}

class PlanCommand final : public Command {
 public:
  CLI::App* add_to(CLI::App& app) override {
    CLI::App* command = app.add_subcommand(
        "plan",
        "Plan the rod's deformation towards a target shape (objective points): n_inter optimal "
        "shapes, each warm-started from the last, and the timed end-effector path through their "
        "tip poses. Writes OUTDIR/plan.json, OUTDIR/trajectory.csv and OUTDIR/plan.svg; with a "
        "robot section, also the joint trajectory OUTDIR/joint_trajectory.csv and "
        "OUTDIR/joint_trajectory.json.");
    command->add_option("task", task_path_, "Task file (YAML); format in docs/task-file.md")
        ->required()
        ->type_name("TASK.yaml");
    command
        ->add_option("-o,--output", output_directory_,
                     "Directory for plan.json, trajectory.csv and plan.svg (created if missing; "
                     "each file is written whole or not at all)")
        ->required()
        ->type_name("OUTDIR");
    command->add_flag("-q,--quiet", quiet_, "Do not print the one-line summary on standard output");
    return command;
  }

  int run() override {
    const PlanTask task = read_plan_task(task_path_);
    check_directory(output_directory_);
    ShapePlan shape_plan;
    std::optional<ArmPlan> arm;
    try {
      if (task.robot) {
        arm = plan_with_arm(task.request, task.options, task.robot->arm, task.robot->placement,
                            task.robot->options);
      } else {
        shape_plan = plan_shape(task.request, task.options);
      }
    } catch (const InputError& error) {
      // The library names the field; say which file it is about.
      throw InputError(task_path_ + ": " + error.what());
    }
    const ShapePlan& plan = arm ? arm->plan : shape_plan;
    const JointTrajectory* joints = arm ? &arm->joints : nullptr;

    make_directory(output_directory_);
    const fs::path directory(output_directory_);
    std::vector<std::string> written;
    const auto write = [&](const char* name, const std::string& content) {
      write_file_atomically((directory / name).string(), content);
      written.push_back(name);
    };
    write("plan.json", plan_result_json(plan, task, arm ? &*arm : nullptr));
    if (plan.status != PlanStatus::Infeasible) {
      write("trajectory.csv", trajectory_csv(plan.end_effector_path));
      write("plan.svg", plan_svg(plan, task));
    } else {
      // No path and no picture: remove those of an earlier run, which would not match plan.json.
      std::error_code ignored;
      fs::remove(directory / "trajectory.csv", ignored);
      fs::remove(directory / "plan.svg", ignored);
    }
    if (joints && joints->complete()) {
      write("joint_trajectory.csv", joint_trajectory_csv(*joints));
      write("joint_trajectory.json", joint_trajectory_json(*joints));
    } else {
      // No joint trajectory: remove that of an earlier run, which would not match plan.json.
      std::error_code ignored;
      fs::remove(directory / "joint_trajectory.csv", ignored);
      fs::remove(directory / "joint_trajectory.json", ignored);
    }

    const int completed = static_cast<int>(plan.steps.size());
    if (!quiet_) {
      std::cout << task_path_ << ": " << to_string(plan.status) << " plan, " << completed
                << " steps (" << task.options.steps << " requested";
      if (plan.tracking.refinements > 0)
        std::cout << ", " << plan.tracking.refinements << " inserted where the rod would jump";
      std::cout << ")";
      if (completed > 0) {
        const ShapeCostBreakdown& cost = plan.steps.back().solution.cost;
        std::cout << ", final max distance " << millimetres(cost.max_distance) << ", energy "
                  << std::setprecision(3) << cost.energy << " J";
      }
      if (plan.tracking.performed && plan.tracking.jump)
        std::cout << "; tracking: " << plan.tracking.note;
      if (arm && arm->shell) {
        std::cout << "; reach shell " << std::setprecision(3) << arm->shell->inner_radius << "–"
                  << arm->shell->outer_radius << " m";
        if (!arm->replans.empty()) std::cout << " (" << arm->replans.size() << " re-plans)";
      }
      if (joints && joints->complete()) {
        std::cout << "; joint trajectory: " << joints->t.size() << " samples, "
                  << std::setprecision(4) << joints->duration() << " s";
        if (joints->slowed) std::cout << " (slowed ×" << joints->slowdown << ")";
      }
      std::cout << "; wrote";
      for (const std::string& name : written) std::cout << " " << (directory / name).string();
      std::cout << "\n" << std::flush;
    }

    switch (plan.status) {
      case PlanStatus::Complete:
        if (arm && !arm->reachable()) {
          std::cerr << "error: " << task_path_ << ": robot: " << arm->message << "\n";
          return kNotConverged;
        }
        return kSuccess;
      case PlanStatus::Infeasible:
        std::cerr << "error: " << task_path_ << ": infeasible target: " << plan.message << "\n";
        return kBadInput;
      case PlanStatus::Partial:
        std::cerr << "error: " << task_path_ << ": partial plan: " << plan.message << "; wrote the "
                  << completed << " step" << (completed == 1 ? "" : "s") << " that succeeded\n";
        return kPartialPlan;
    }
    return kInternalError;
  }

 private:
  std::string task_path_;
  std::string output_directory_;
  bool quiet_ = false;
};

}  // namespace

std::unique_ptr<Command> make_plan_command() { return std::make_unique<PlanCommand>(); }

}  // namespace rodshape::cli
