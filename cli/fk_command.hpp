// fk_command.hpp: `rodshape fk URDF q1 … qn [--base LINK] [--tip LINK]`, and what fk and ik share:
// the arm's arguments.
#pragma once

#include <memory>
#include <string>

#include "command.hpp"
#include "rodshape/robot/arm_model.hpp"

namespace rodshape::cli {

std::unique_ptr<Command> make_fk_command();

/// The arm a command works on: the URDF (a positional argument) and the chain's --base/--tip.
struct ArmArguments {
  std::string urdf_path;
  std::string base_link;
  std::string tip_link;
  /// Adds the positional URDF argument (call before the command's other positionals) and the
  /// --base and --tip options.
  void add_to(CLI::App& command);
  /// Reads the chain (InputError naming the URDF when it cannot): a bundled arm's name ("fr3",
  /// "panda"), else the file.
  ArmModel load() const;
};

}  // namespace rodshape::cli
