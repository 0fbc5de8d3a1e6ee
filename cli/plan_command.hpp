// plan_command.hpp: `rodshape plan TASK.yaml -o OUTDIR`.
#pragma once

#include <memory>

#include "command.hpp"

namespace rodshape::cli {

std::unique_ptr<Command> make_plan_command();

}  // namespace rodshape::cli
