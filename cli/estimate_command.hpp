// estimate_command.hpp: `rodshape estimate TASK.yaml --cloud FILE [-o OUT.json]`.
#pragma once

#include <memory>

#include "command.hpp"

namespace rodshape::cli {

std::unique_ptr<Command> make_estimate_command();

}  // namespace rodshape::cli
