// validate_command.cpp: plan a task, carry the plan out on the simulated plant seen by the
// simulated sensors, and write the errors.
//   task file -> PlanTask (io) -> plan (trajectory) -> validate_plan (sim) -> validation.* (io)
#include "validate_command.hpp"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <limits>
#include <string>
#include <thread>
#include <vector>

#include "exit_code.hpp"
#include "progress_line.hpp"
#include "rodshape/io/field_names.hpp"
#include "rodshape/io/output_files.hpp"
#include "rodshape/io/plan_output.hpp"
#include "rodshape/io/task_reader.hpp"
#include "rodshape/io/validation_output.hpp"
#include "rodshape/sim/plan_validation.hpp"
#include "rodshape/trajectory/plan.hpp"

namespace rodshape::cli {

namespace {

/// --seed as written: a whole number in [0, 2^64 - 1], without a sign (CLI11 would take -1 as
/// 2^64 - 1 and wrap a larger number).
std::uint64_t parse_seed(const std::string& text) {
  std::uint64_t seed = 0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, seed);
  if (text.empty() || error != std::errc() || stop != end)
    throw InputError("--seed = " + text + " must be a whole number in [0, " +
                     std::to_string(std::numeric_limits<std::uint64_t>::max()) + "]");
  return seed;
}

/// The cores, within [1, ValidationOptions::kMaxJobs].
int default_jobs() {
  const auto cores = static_cast<int>(std::thread::hardware_concurrency());
  return std::clamp(cores, 1, ValidationOptions::kMaxJobs);
}

class ValidateCommand final : public Command {
 public:
  CLI::App* add_to(CLI::App& app) override {
    CLI::App* command = app.add_subcommand(
        "validate",
        "Plan the task, then carry the plan out in simulation: the real rod (the task's plant "
        "section) driven along the commanded path and seen by the sensors (its sensor section). "
        "Writes OUTDIR/validation.json, OUTDIR/validation.csv (the errors over time) and "
        "OUTDIR/validation.svg and the 3D page OUTDIR/validation.html, besides the plan's files.");
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
    command
        ->add_option("--seed", seed_,
                     "Seed of the first run (run k: seed + k - 1), a whole number in [0, 2^64 - "
                     "runs]")
        ->type_name("S");
    options_.jobs = default_jobs();
    command
        ->add_option("--jobs", options_.jobs,
                     "Closed loop: runs carried out at once, 1 to 256 (default: the cores, here " +
                         std::to_string(default_jobs()) +
                         "); the results are the same for every value")
        ->check(CLI::Range(1, ValidationOptions::kMaxJobs))
        ->type_name("N");
    command->add_flag("--closed-loop", options_.closed_loop,
                      "Close the loop: at each waypoint, estimate the rod from the sensors and "
                      "re-plan the rest (the task's closed_loop section)");
    command->add_flag("-q,--quiet", quiet_,
                      "Do not print the one-line summary on standard output, nor the progress on "
                      "standard error (drawn only when it is a terminal)");
    command->add_flag("--no-html", no_html_,
                      "Do not write plan.html and validation.html (the 3D pages)");
    command->footer(
        "Exit codes: 0 the plant followed the whole path; 2 bad input (task file, command line, "
        "output path, an infeasible target): nothing written or removed; 3 the plant snapped, was "
        "lost or "
        "would touch an obstacle of the scene, or the plan has no path to carry out (the files are "
        "still written); 1 internal "
        "error.");
    return command;
  }

  int run() override {
    ValidationOptions options = options_;
    options.seed = parse_seed(seed_);
    try {
      options.validate();
    } catch (const InputError& error) {
      throw InputError(fields_in_task_names(error.what()));
    }
    const PlanTask task = read_plan_task(task_path_);
    // As for plan: bad input writes and removes nothing (plan_command.cpp).
    check_output_directory(output_directory_);
    std::vector<std::string> outputs = plan_file_names();
    for (const std::string& name : validation_file_names()) outputs.push_back(name);
    check_output_files(output_directory_, outputs, task.input_files);
    PlanResult plan;
    ValidationResult result;
    try {
      plan = rodshape::plan(task.problem, task.options);
    } catch (const InputError& error) {
      throw InputError(task.locate(error));
    }
    if (plan.status == PlanStatus::Infeasible) throw task.infeasible_target(plan);
    if (plan.end_effector_path.empty()) {
      std::cerr << "error: " << task_path_
                << ": nothing to validate: " << fields_in_task_names(plan.brief(task.options.steps))
                << "\n";
      write_plan(output_directory_, plan, task, {.html = !no_html_});
      remove_earlier_outputs(output_directory_, validation_file_names());
      return kPartialPlan;
    }
    options.loop = task.closed_loop;
    options.planning = task.options;
    {
      ProgressLine progress("validate", options.closed_loop ? "runs" : "frames", !quiet_);
      if (progress.active())
        options.progress = [&progress](int done, int total) { progress.update(done, total); };
      try {
        result = validate_plan(task.problem, plan, task.plant, task.sensor_model(), options);
      } catch (const InputError& error) {
        throw InputError(task.locate(error));
      }
    }
    warn_without_html(no_html_);
    std::vector<std::string> written =
        write_plan(output_directory_, plan, task, {.html = !no_html_});
    for (const std::string& name :
         write_validation(output_directory_, result, plan, task, {.html = !no_html_}))
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
  std::string seed_ = "1";
  bool quiet_ = false;
  bool no_html_ = false;
};

}  // namespace

std::unique_ptr<Command> make_validate_command() { return std::make_unique<ValidateCommand>(); }

}  // namespace rodshape::cli
