// equilibrium_command.hpp: `rodshape equilibrium TASK.yaml [-o OUT.json]`.
#pragma once

#include <memory>

#include "command.hpp"

namespace rodshape::cli {

std::unique_ptr<Command> make_equilibrium_command();

}  // namespace rodshape::cli
