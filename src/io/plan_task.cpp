// plan_task.cpp: PlanTask::locate, a library error said in the task file's terms and place.
#include "rodshape/io/plan_task.hpp"

#include "rodshape/io/field_names.hpp"

namespace rodshape {

namespace {

/// "workspace.inside[0].radius" → "workspace.inside.radius": the keys only.
std::string keys_of(const std::string& field) {
  std::string keys;
  bool in_index = false;
  for (const char c : field) {
    if (c == '[') in_index = true;
    if (!in_index) keys += c;
    if (c == ']') in_index = false;
  }
  return keys;
}

}  // namespace

std::string PlanTask::locate(const InputError& error) const {
  const std::string message = in_task_names(error);
  if (error.field().empty()) return source + ": " + message;
  for (std::string keys = keys_of(task_field_name(error.field()));;) {
    if (const auto found = lines.find(keys); found != lines.end() && found->second > 0)
      return source + ":" + std::to_string(found->second) + ": " + message;
    const std::size_t dot = keys.rfind('.');
    if (dot == std::string::npos) return source + ": " + message;
    keys.resize(dot);
  }
}

InputError PlanTask::infeasible_target(const PlanResult& plan) const {
  const std::string& reason = plan.feasibility.reason;
  const int i = plan.feasibility.offending_point;
  if (i < 0) return InputError(source + ": infeasible target: " + fields_in_task_names(reason));
  // Located at the offending point: "<source>:<line>: target.points[i] <why>".
  const std::string field = "ShapeTarget.points";
  // Appended, not `"[" + std::to_string(i)`: GCC 12 warns (-Wrestrict, a false positive) on
  // that inlined concatenation of a temporary.
  std::string index = "[";
  index += std::to_string(i);
  index += "]";
  const std::string why = reason.starts_with(field + index)
                              ? reason.substr(field.size() + index.size())
                              : ": " + reason;
  return InputError(locate(InputError(field, index + why + ": the target is infeasible")));
}

}  // namespace rodshape
