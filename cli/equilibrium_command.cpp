// equilibrium_command.cpp: solve the rod a task file describes and write the result as JSON.
//   task file -> EquilibriumTask (io) -> solve_equilibrium, assess_stability (solvers) -> JSON (io)
#include "equilibrium_command.hpp"

#include <iostream>
#include <optional>
#include <string>
#include <variant>

#include "exit_code.hpp"
#include "rodshape/io/atomic_file.hpp"
#include "rodshape/io/field_names.hpp"
#include "rodshape/io/result_json.hpp"
#include "rodshape/io/task_reader.hpp"
#include "rodshape/solvers/model_validity.hpp"
#include "rodshape/solvers/shooting_solver.hpp"
#include "rodshape/solvers/stability.hpp"

namespace rodshape::cli {

namespace {

class EquilibriumCommand final : public Command {
 public:
  CLI::App* add_to(CLI::App& app) override {
    CLI::App* command = app.add_subcommand(
        "equilibrium",
        "Solve the static equilibrium of the rod described by a task file and print the result "
        "as JSON (status, residual, energy, stability, base and tip wrench, tip pose, nodes).");
    command->add_option("task", task_path_, "Task file (YAML); format in docs/task-file.md")
        ->required()
        ->type_name("TASK.yaml");
    command
        ->add_option("-o,--output", output_path_,
                     "Write the JSON result to this file (whole or not at all; a device or a "
                     "FIFO is written in place, a symbolic link is followed) instead of standard "
                     "output; '-' is standard output")
        ->type_name("OUT.json");
    command->add_flag("-q,--quiet", quiet_,
                      "Print nothing on standard output: with -o, no one-line summary; without "
                      "(or with -o -), no result. The exit code says the status; errors still "
                      "go to standard error");
    return command;
  }

  int run() override {
    const EquilibriumTask task = read_equilibrium_task(task_path_);

    // The stability test needs the derivatives at every node.
    ShootingOptions options = task.options;
    options.output_derivatives = Derivatives::AllNodes;

    const ShootingResult solution =
        solve_equilibrium(task.rod, task.tip, task.initial_wrench, options);
    const ShootingSummary& summary = solution.summary;
    ClampedRod solved_rod = task.rod;  // with the sub-steps the solver needed
    solved_rod.substeps = summary.substeps;

    std::optional<StabilityResult> stability;
    if (summary.converged()) {
      // A pose the user holds the tip at must not ask the model for more than it can say.
      if (!std::holds_alternative<FreeTip>(task.tip)) {
        try {
          check_model_validity(solved_rod.properties, solution.configuration, options.strain_limits,
                               "ClampedTip.pose", "ShootingOptions.strain_limits");
        } catch (const InputError& error) {
          throw InputError(task_path_ + ": " + in_task_names(error));
        }
      }
      stability = assess_stability(solved_rod, solution.configuration, task.tip);
    }

    const std::string json = equilibrium_result_json(solution, stability, solved_rod);
    if (output_path_.empty() || output_path_ == "-") {
      if (!quiet_) write_to_standard_output(json);
    } else {
      write_file_atomically(output_path_, json);
      if (!quiet_) {
        std::cout << task_path_ << ": " << summary.brief();
        if (stability) std::cout << (stability->stable ? ", stable" : ", unstable");
        std::cout << "; wrote " << output_path_ << "\n";
      }
    }

    if (!summary.converged()) {
      std::cerr << "error: " << task_path_ << ": the solver did not converge: " << summary.brief();
      if (!summary.message.empty())
        std::cerr << " (" << fields_in_task_names(summary.message) << ")";
      std::cerr << "\n";
      return kNotConverged;
    }
    return kSuccess;
  }

 private:
  std::string task_path_;
  std::string output_path_;
  bool quiet_ = false;
};

}  // namespace

std::unique_ptr<Command> make_equilibrium_command() {
  return std::make_unique<EquilibriumCommand>();
}

}  // namespace rodshape::cli
