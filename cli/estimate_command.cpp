// estimate_command.cpp: estimate the rod's state from one depth camera cloud and write it as JSON.
//   task file -> EstimateTask (io), cloud file -> points (io) -> estimate_from_cloud (io,
//   feedback) -> JSON (io)
#include "estimate_command.hpp"

#include <iostream>
#include <string>

#include "exit_code.hpp"
#include "rodshape/io/atomic_file.hpp"
#include "rodshape/io/cloud_reader.hpp"
#include "rodshape/io/field_names.hpp"
#include "rodshape/io/output_files.hpp"
#include "rodshape/io/result_json.hpp"
#include "rodshape/io/task_reader.hpp"

namespace rodshape::cli {

namespace {

class EstimateCommand final : public Command {
 public:
  CLI::App* add_to(CLI::App& app) override {
    CLI::App* command = app.add_subcommand(
        "estimate",
        "Estimate the rod's equilibrium from one depth camera cloud (PLY, PCD or CSV, in the frame "
        "of the task's sensor.camera) and print it as JSON: the equilibrium result's keys plus "
        "'fit' (residual, chi2, covariance, points used and rejected). Exit 0: the model explains "
        "the cloud; 3: it does not (the result says why); 2: bad input, nothing written.");
    command->add_option("task", task_path_, "Task file (YAML); format in docs/estimate.md")
        ->required()
        ->type_name("TASK.yaml");
    command
        ->add_option("--cloud", cloud_path_,
                     "The cloud (.ply, .pcd or .csv; at most 10^6 points and 64 MiB)")
        ->required()
        ->type_name("FILE");
    command
        ->add_option("-o,--output", output_path_,
                     "Write the JSON result to this file (whole or not at all; never into a "
                     "device, a FIFO or through a symbolic link) instead of standard output; '-' "
                     "is standard output")
        ->type_name("OUT.json");
    return command;
  }

  int run() override {
    const EstimateTask task = read_estimate_task(task_path_);
    const bool to_file = !output_path_.empty() && output_path_ != "-";
    if (to_file) {  // before reading the cloud: nothing written
      check_not_an_input(output_path_, {task_path_, cloud_path_});
      check_output_path(output_path_);
    }
    const std::vector<Eigen::Vector3d> points = read_cloud(cloud_path_);
    CloudEstimate result;
    try {
      result = estimate_from_cloud(task, points);
    } catch (const InputError& error) {
      throw InputError(task_path_ + ": " + in_task_names(error));
    }
    const std::string json = estimate_result_json(task, result);
    if (!to_file) {
      write_to_standard_output(json);
    } else {
      write_file_atomically(output_path_, json);
      std::cout << task_path_ << ": " << to_string(result.estimate.status) << ", "
                << result.estimate.points << " points (" << result.estimate.outliers
                << " rejected), residual " << result.estimate.residual << "; wrote " << output_path_
                << "\n";
    }
    if (!result.explained()) {
      std::cerr << "error: " << task_path_ << ": " << result.unexplained << "\n";
      return kNotExplained;
    }
    return kSuccess;
  }

 private:
  std::string task_path_, cloud_path_, output_path_;
};

}  // namespace

std::unique_ptr<Command> make_estimate_command() { return std::make_unique<EstimateCommand>(); }

}  // namespace rodshape::cli
