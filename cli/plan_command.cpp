// plan_command.cpp: plan the shape a task file asks for and write plan.json, trajectory.csv and
// plan.svg (and, with a robot section, the joint trajectory) into the output directory.
//   task file -> PlanTask (io) -> plan() (trajectory) -> write_plan() (io) -> exit code
#include "plan_command.hpp"

#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "exit_code.hpp"
#include "mcap_option.hpp"
#include "rodshape/error.hpp"
#include "rodshape/io/field_names.hpp"
#include "rodshape/io/output_files.hpp"
#include "rodshape/io/plan_output.hpp"
#include "rodshape/io/task_reader.hpp"
#include "rodshape/trajectory/plan.hpp"

namespace rodshape::cli {

namespace {

/// The exit code of a plan, with a line on standard error when it is not a success.
int report_status(const std::string& task_path, const PlanResult& result) {
  const int completed = static_cast<int>(result.steps.size());
  switch (result.status) {
    case PlanStatus::Complete:
      if (result.arm && !result.arm->reachable()) {
        std::cerr << "error: " << task_path
                  << ": robot: " << fields_in_task_names(result.arm->message) << "\n";
        return kNotConverged;
      }
      return kSuccess;
    case PlanStatus::Infeasible:  // thrown as bad input before anything is written
      return kBadInput;
    case PlanStatus::SnapThrough:
      std::cerr << "error: " << task_path
                << ": snap-through: " << fields_in_task_names(result.message) << "\n";
      return kPartialPlan;
    case PlanStatus::Collision:
      std::cerr << "error: " << task_path << ": collision: " << fields_in_task_names(result.message)
                << "\n";
      return kPartialPlan;
    case PlanStatus::Partial:
      std::cerr << "error: " << task_path
                << ": partial plan: " << fields_in_task_names(result.message) << "; wrote the "
                << completed << " step" << (completed == 1 ? "" : "s") << " that succeeded\n";
      return kPartialPlan;
  }
  return kInternalError;
}

class PlanCommand final : public Command {
 public:
  CLI::App* add_to(CLI::App& app) override {
    CLI::App* command = app.add_subcommand(
        "plan",
        "Plan the rod's deformation towards a target shape (objective points): n_inter optimal "
        "shapes, each warm-started from the last, and the timed end-effector path through their "
        "tip poses. Writes OUTDIR/plan.json, OUTDIR/trajectory.csv, OUTDIR/plan.svg and the 3D "
        "page "
        "OUTDIR/plan.html (docs/figures.md); with a "
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
    command->add_flag("--no-html", no_html_,
                      "Do not write plan.html (the 3D page, which inlines Debian's libjs-three)");
    mcap_.add_to(command, "plan.mcap");
    return command;
  }

  int run() override {
    const PlanTask task = read_plan_task(task_path_);
    // Bad input writes and removes nothing: the outputs' places are checked first (no input among
    // them, no file that is not an earlier run's), and the earlier run's files are replaced only
    // by write_plan(), once the plan is made.
    check_output_directory(output_directory_);
    check_output_files(output_directory_, plan_file_names(), task.input_files);
    PlanResult result;
    try {
      result = plan(task.problem, task.options);
    } catch (const InputError& error) {
      // The library names its own fields: say them as the task file does, and where.
      throw InputError(task.locate(error));
    }
    if (result.status == PlanStatus::Infeasible) throw task.infeasible_target(result);
    warn_without_html(no_html_);
    const std::vector<std::string> written =
        write_plan(output_directory_, result, task, {.html = !no_html_, .mcap = mcap_.options()});
    if (!quiet_) {
      std::cout << task_path_ << ": " << fields_in_task_names(result.brief()) << "; wrote";
      for (const std::string& name : written)
        std::cout << " " << (std::filesystem::path(output_directory_) / name).string();
      std::cout << "\n" << std::flush;
    }
    return report_status(task_path_, result);
  }

 private:
  std::string task_path_;
  std::string output_directory_;
  bool quiet_ = false;
  bool no_html_ = false;
  McapOption mcap_;
};

}  // namespace

std::unique_ptr<Command> make_plan_command() { return std::make_unique<PlanCommand>(); }

}  // namespace rodshape::cli
