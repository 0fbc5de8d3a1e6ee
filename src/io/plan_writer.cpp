// plan_writer.cpp: which files a plan writes into its output directory (see plan_output.hpp).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "rodshape/error.hpp"
#include "rodshape/io/atomic_file.hpp"
#include "rodshape/io/output_files.hpp"
#include "rodshape/io/plan_output.hpp"

namespace rodshape {

namespace {

namespace fs = std::filesystem;

/// Creates `directory` (and its parents) if missing; InputError when that fails or it is a file.
void make_directory(const std::string& directory) {
  std::error_code error;
  fs::create_directories(directory, error);
  if (error)
    throw InputError(directory + ": cannot create the output directory: " + error.message());
  if (!fs::is_directory(directory, error))
    throw InputError(directory + ": cannot create the output directory: it is not a directory");
}

}  // namespace

const std::vector<std::string>& plan_file_names() {
  static const std::vector<std::string> names = {"plan.json",
                                                 "trajectory.csv",
                                                 "plan.svg",
                                                 "plan.html",
                                                 "joint_trajectory.csv",
                                                 "joint_trajectory.json",
                                                 "base_joint_trajectory.csv",
                                                 "base_joint_trajectory.json"};
  return names;
}

void remove_plan_files(const std::string& directory) {
  remove_earlier_outputs(directory, plan_file_names());
}

void check_output_directory(const std::string& directory) {
  std::error_code error;
  if (fs::exists(directory, error) && !fs::is_directory(directory, error))
    throw InputError(directory + ": cannot create the output directory: it is not a directory");
}

FigureCaption figure_caption(const PlanTask& task) { return {task.source, task.options.steps}; }

std::string plan_svg(const PlanResult& plan, const PlanTask& task) {
  return plan_svg(plan, task.problem, figure_caption(task));
}

std::string html_unavailable() {
  std::string why;
  return load_page_library(&why) ? std::string() : why;
}

std::vector<std::string> write_plan(const std::string& directory,
                                    const PlanResult& plan,
                                    const PlanTask& task,
                                    const FigureFiles& figures) {
  make_directory(directory);
  const fs::path dir(directory);
  std::vector<std::string> written;
  const auto write = [&](const char* name, const std::string& content) {
    write_file_atomically((dir / name).string(), content);
    written.push_back(name);
  };
  const auto remove = [&](const char* name) {  // a file of an earlier run, only if rodshape's
    remove_earlier_outputs(directory, {name});
  };
  write("plan.json", plan_result_json(plan, task));
  if (plan.status != PlanStatus::Infeasible) {
    write("trajectory.csv", trajectory_csv(plan.end_effector_path, plan.base_end_effector_path));
    write("plan.svg", plan_svg(plan, task));
  } else {
    remove("trajectory.csv");
    remove("plan.svg");
  }
  const std::optional<PageLibrary> library =
      figures.html && plan.status != PlanStatus::Infeasible ? load_page_library() : std::nullopt;
  if (library)
    write("plan.html", plan_html(plan, task.problem, figure_caption(task), *library));
  else
    remove("plan.html");
  if (plan.arm && plan.arm->joints.complete()) {
    write("joint_trajectory.csv", joint_trajectory_csv(plan.arm->joints));
    write("joint_trajectory.json", joint_trajectory_json(plan.arm->joints));
  } else {
    remove("joint_trajectory.csv");
    remove("joint_trajectory.json");
  }
  if (plan.base_arm && plan.base_arm->joints.complete()) {
    write("base_joint_trajectory.csv", joint_trajectory_csv(plan.base_arm->joints));
    write("base_joint_trajectory.json", joint_trajectory_json(plan.base_arm->joints));
  } else {
    remove("base_joint_trajectory.csv");
    remove("base_joint_trajectory.json");
  }
  return written;
}

}  // namespace rodshape
