// equilibrium_command.cpp: solve the rod a task file describes and write the result as JSON.
//   task file -> EquilibriumTask (io) -> answer_equilibrium_task (io: free or resting) -> JSON (io)
#include "equilibrium_command.hpp"

#include <iostream>
#include <string>

#include "exit_code.hpp"
#include "rodshape/io/atomic_file.hpp"
#include "rodshape/io/equilibrium_answer.hpp"
#include "rodshape/io/field_names.hpp"
#include "rodshape/io/output_files.hpp"
#include "rodshape/io/task_reader.hpp"

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
                     "Write the JSON result to this file (whole or not at all; never into a "
                     "device, a FIFO or through a symbolic link) instead of standard output; '-' "
                     "is standard output")
        ->type_name("OUT.json");
    command->add_flag("-q,--quiet", quiet_,
                      "Print nothing on standard output: with -o, no one-line summary; without "
                      "(or with -o -), no result. The exit code says the status; errors still "
                      "go to standard error");
    return command;
  }

  int run() override {
    const EquilibriumTask task = read_equilibrium_task(task_path_);
    const bool to_file = !output_path_.empty() && output_path_ != "-";
    if (to_file) {  // before solving: nothing written
      check_not_an_input(output_path_, {task_path_});
      check_output_path(output_path_);
    }

    const EquilibriumAnswer answer = answer_equilibrium_task(task);
    const ShootingSummary& summary = answer.solution().summary;
    const std::string json = equilibrium_answer_json(answer, task);
    if (!to_file) {
      if (!quiet_) write_to_standard_output(json);
    } else {
      write_file_atomically(output_path_, json);
      if (!quiet_) {
        std::cout << task_path_ << ": " << answer.brief() << "; wrote " << output_path_ << "\n";
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
