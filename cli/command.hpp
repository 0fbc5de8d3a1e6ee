// command.hpp: one subcommand of the rodshape tool. Each lives in cli/<name>_command.cpp and is
// listed in main.cpp. A command is thin: parse its arguments, call io and the library, write.
#pragma once

#include <CLI/CLI.hpp>

namespace rodshape::cli {

class Command {
 public:
  virtual ~Command() = default;
  /// Adds the subcommand, its options and their help to `app`; returns the subcommand.
  virtual CLI::App* add_to(CLI::App& app) = 0;
  /// Runs after the command line was parsed; returns an ExitCode. Bad input is thrown as
  /// rodshape::InputError, which main() prints as one line and turns into kBadInput.
  virtual int run() = 0;
};

}  // namespace rodshape::cli
