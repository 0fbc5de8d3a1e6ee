// field_names.hpp: the library names its own fields in its messages ("PlanOptions.steps = 0 must
// be >= 1", InputError::field()); a task file names them its way ("trajectory.steps"). This is the
// table between the two, in one place.
#pragma once

#include <string>

#include "rodshape/error.hpp"

namespace rodshape {

/// The task file's name of a library field: the longest leading part of `library_field` (whole
/// dotted segments) that the table knows, renamed, and the rest as it is ("Workspace.box.lower" →
/// "workspace.box.lower"). A field the table does not know is returned as it is.
std::string task_field_name(const std::string& library_field);

/// `text` with every library field in it ("Grasp.released") said as the task file says it.
std::string fields_in_task_names(const std::string& text);

/// The message of `error` with its field, and the fields its problem names, said as the task file
/// says them.
std::string in_task_names(const InputError& error);

}  // namespace rodshape
