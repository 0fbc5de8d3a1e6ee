// task_reader.cpp: the equilibrium task file: which top-level sections it has, in which order they
// are read, and the final whole-task checks.
#include "rodshape/io/task_reader.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string_view>
#include <vector>

#include "io/task_sections.hpp"
#include "io/yaml_field.hpp"
#include "rodshape/error.hpp"

namespace rodshape {

namespace {

using io_detail::YamlField;

/// The top-level sections of an equilibrium task. Another command's reader lists its own (`plan`
/// adds target, weights, workspace, ...) and reuses the section readers.
const std::vector<std::string_view>& equilibrium_sections() {
  static const std::vector<std::string_view> sections = {"rod",  "gravity", "distributed_load",
                                                         "base", "tip",     "solver"};
  return sections;
}

std::string read_text_file(const std::string& path) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) {
    throw InputError(path + ": cannot read: it is a directory");
  }
  std::ifstream file(path, std::ios::binary);
  if (!file) throw InputError(path + ": cannot read: " + std::strerror(errno));
  std::ostringstream text;
  text << file.rdbuf();
  if (file.bad()) throw InputError(path + ": cannot read: " + std::strerror(errno));
  return text.str();
}

/// ShootingOptions::validate() names its own fields ("residual_tolerance = ..."); say them as the
/// task file does.
std::string solver_field_message(std::string message) {
  const std::string_view residual_tolerance = "residual_tolerance";
  if (message.rfind(residual_tolerance, 0) == 0) {
    return "solver.tolerance" + message.substr(residual_tolerance.size());
  }
  if (message.rfind("solver.", 0) == 0) return message;
  return "solver." + message;
}

}  // namespace

EquilibriumTask parse_equilibrium_task(const std::string& yaml_text,
                                       const std::string& source_name) {
  const YamlField root = io_detail::parse_yaml(yaml_text, source_name);
  root.expect_mapping(equilibrium_sections());

  EquilibriumTask task;
  task.source = source_name;

  const YamlField rod_field = root.require("rod");
  const io_detail::RodSection rod = io_detail::read_rod_section(rod_field);
  task.rod.properties = io_detail::build_rod_properties(rod, rod_field);
  task.rod.intervals = rod.nodes - 1;
  task.rod.load = io_detail::read_distributed_load(root, rod);
  if (const YamlField base = root.get("base"); base.present()) {
    task.rod.clamp = io_detail::read_pose(base);
  }
  task.tip = io_detail::read_tip_condition(root.require("tip"));
  if (const YamlField solver = root.get("solver"); solver.present()) {
    io_detail::read_solver_section(solver, task.options, task.initial_wrench);
  }

  // Whole-task checks by the library; their messages name the field, we add file and line.
  rod_field.located([&] { task.rod.validate(); });
  try {
    task.options.validate();
  } catch (const InputError& error) {
    root.fail_located(solver_field_message(error.what()));
  }
  return task;
}

EquilibriumTask read_equilibrium_task(const std::string& path) {
  return parse_equilibrium_task(read_text_file(path), path);
}

}  // namespace rodshape
