// ik_command.hpp: `rodshape ik URDF x y z qw qx qy qz [--seed q1 … qn] [--base LINK] [--tip LINK]`.
#pragma once

#include <memory>

#include "command.hpp"

namespace rodshape::cli {

std::unique_ptr<Command> make_ik_command();

}  // namespace rodshape::cli
