// validate_command.cpp: plan a task, carry the plan out on the simulated plant seen by the
// simulated sensors, and write the errors.
//   task file -> PlanTask (io) -> plan (trajectory) -> validate_plan (sim) -> validation.* (io)
#include "validate_command.hpp"

#include <cstdint>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "exit_code.hpp"
#include "rodshape/io/field_names.hpp"
#include "rodshape/io/plan_output.hpp"
#include "rodshape/io/task_reader.hpp"
#include "rodshape/io/validation_output.hpp"
#include "rodshape/sim/plan_validation.hpp"
#include "rodshape/trajectory/plan.hpp"

namespace rodshape::cli {

namespace {

class ValidateCommand final : public Command {
 public:
  CLI::App* add_to(CLI::App& app) override {
    CLI::App* command = app.add_subcommand(
        "validate",
        "Plan the task, then carry the plan out in simulation: the real rod (the task's plant "
        "section) driven along the commanded path and seen by the sensors (its sensor section). "
        "Writes OUTDIR/validation.json, OUTDIR/validation.csv (the errors over time) and "
        "OUTDIR/validation.svg, besides the plan's files.");
    command->add_option("task", task_path_, "Task file (YAML); format in docs/task-file.md")
        ->required()
        ->type_name("TASK.yaml");
    command
        ->add_option("-o,--output", output_directory_,
                     "Directory for the plan's files and validation.* (created if missing)")
        ->required()
        ->type_name("OUTDIR");
    command
        ->add_option(
            "--runs", options_.runs,
            "Repeats with the sensor's noise drawn anew (1 to 1000; the plant is the same)")
        ->check(CLI::Range(1, ValidationOptions::kMaxRuns));
    command->add_option("--seed", options_.seed, "Seed of the first run (run k: seed + k - 1)");
    command->add_flag("--closed-loop", options_.closed_loop,
                      "Close the loop: at each waypoint, estimate the rod from the sensors and "
                      "re-plan the rest (the task's closed_loop section)");
    command->add_flag("-q,--quiet", quiet_, "Do not print the one-line summary on standard output");
    return command;
  }

  int run() override {
    const PlanTask task = read_plan_task(task_path_);
    check_output_directory(output_directory_);
    PlanResult plan;
    ValidationResult result;
    try {
      plan = rodshape::plan(task.problem, task.options);
      if (plan.end_effector_path.empty()) {
        std::cerr << "error: " << task_path_ << ": nothing to validate: "
                  << fields_in_task_names(plan.brief(task.options.steps)) << "\n";
        write_plan(output_directory_, plan, task);
        return kPartialPlan;
      }
      ValidationOptions options = options_;
      options.loop = task.closed_loop;
      options.planning = task.options;
      result = validate_plan(task.problem, plan, task.plant, task.sensor, options);
    } catch (const InputError& error) {
      throw InputError(task.locate(error));
    }
    std::vector<std::string> written = write_plan(output_directory_, plan, task);
    for (const std::string& name : write_validation(output_directory_, result, plan, task))
      written.push_back(name);
    if (!quiet_) {
      std::cout << task_path_ << ": " << fields_in_task_names(result.brief()) << "; wrote";
      for (const std::string& name : written)
        std::cout << " " << (std::filesystem::path(output_directory_) / name).string();
      std::cout << "\n" << std::flush;
    }
    if (result.status == ValidationStatus::Complete) return kSuccess;
    std::cerr << "error: " << task_path_ << ": " << to_string(result.status) << ": "
              << result.message << "\n";
    return kNotConverged;
  }

 private:
  std::string task_path_;
  std::string output_directory_;
  ValidationOptions options_;
  bool quiet_ = false;
};

}  // namespace

std::unique_ptr<Command> make_validate_command() { return std::make_unique<ValidateCommand>(); }

}  // namespace rodshape::cli
