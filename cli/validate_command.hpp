// validate_command.hpp: `rodshape validate TASK.yaml -o OUTDIR [--runs N] [--seed S]`.
#pragma once

#include <memory>

#include "command.hpp"

namespace rodshape::cli {

std::unique_ptr<Command> make_validate_command();

}  // namespace rodshape::cli
