// plan_writer.cpp: which files a plan writes into its output directory (see plan_output.hpp).
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "rodshape/error.hpp"
#include "rodshape/io/output_files.hpp"
#include "rodshape/io/plan_mcap.hpp"
#include "rodshape/io/plan_output.hpp"
#include "rodshape/io/validation_output.hpp"

namespace rodshape {

const std::vector<std::string>& plan_file_names() {
  static const std::vector<std::string> names = {"plan.json",
                                                 "trajectory.csv",
                                                 "plan.svg",
                                                 "plan.html",
                                                 "joint_trajectory.csv",
                                                 "joint_trajectory.json",
                                                 "base_joint_trajectory.csv",
                                                 "base_joint_trajectory.json",
                                                 "plan.mcap"};
  return names;
}

void remove_plan_files(const std::string& directory) {
  remove_earlier_outputs(directory, plan_file_names());
}

void check_output_directory(const std::string& directory) {
  namespace fs = std::filesystem;
  std::string path = directory;  // "DIR/": lstat would follow a link named DIR
  while (path.size() > 1 && path.back() == '/') path.pop_back();
  std::error_code error;
  if (fs::is_symlink(fs::symlink_status(path, error)))
    throw InputError(path +
                     ": cannot write into it: the output directory is a symbolic link; outputs "
                     "are never written through a symbolic link (docs/limits.md): give the "
                     "directory it names or another output directory");
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

OutputSet plan_outputs(const PlanResult& plan, const PlanTask& task, const FigureFiles& figures) {
  OutputSet set;
  const auto add = [&](const char* name, std::string content) {
    set.files.emplace_back(name, std::move(content));
  };
  const auto stale = [&](const char* name) { set.stale.emplace_back(name); };
  add("plan.json", plan_result_json(plan, task));
  if (plan.status != PlanStatus::Infeasible) {
    add("trajectory.csv", trajectory_csv(plan.end_effector_path, plan.base_end_effector_path));
    add("plan.svg", plan_svg(plan, task));
  } else {
    stale("trajectory.csv");
    stale("plan.svg");
  }
  const std::optional<PageLibrary> library =
      figures.html && plan.status != PlanStatus::Infeasible ? load_page_library() : std::nullopt;
  if (library)
    add("plan.html", plan_html(plan, task.problem, figure_caption(task), *library));
  else
    stale("plan.html");
  if (plan.arm && plan.arm->joints.complete()) {
    add("joint_trajectory.csv", joint_trajectory_csv(plan.arm->joints));
    add("joint_trajectory.json", joint_trajectory_json(plan.arm->joints));
  } else {
    stale("joint_trajectory.csv");
    stale("joint_trajectory.json");
  }
  if (plan.base_arm && plan.base_arm->joints.complete()) {
    add("base_joint_trajectory.csv", joint_trajectory_csv(plan.base_arm->joints));
    add("base_joint_trajectory.json", joint_trajectory_json(plan.base_arm->joints));
  } else {
    stale("base_joint_trajectory.csv");
    stale("base_joint_trajectory.json");
  }
  if (figures.mcap && !plan.end_effector_path.empty())  // a plan without a path has nothing to play
    add("plan.mcap", plan_mcap(plan, task.problem, *figures.mcap));
  else
    stale("plan.mcap");
  return set;
}

std::vector<std::string> write_plan(const std::string& directory,
                                    const PlanResult& plan,
                                    const PlanTask& task,
                                    const FigureFiles& figures) {
  OutputSet set = plan_outputs(plan, task, figures);
  // An earlier validation's files in the directory answer another plan: taken out with the rest.
  for (const std::string& name : validation_file_names()) set.stale.push_back(name);
  return write_output_set(directory, std::move(set));
}

}  // namespace rodshape
