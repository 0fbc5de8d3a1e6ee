// command.hpp: one subcommand of the rodshape tool. Each lives in cli/<name>_command.cpp and is
// listed in main.cpp. A command is thin: parse its arguments, call io and the library, write.
#pragma once

#include <CLI/CLI.hpp>
#include <iostream>
#include <string>

#include "rodshape/io/plan_output.hpp"

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

/// Unless `no_html`: a warning on standard error when the 3D pages cannot be written (three.js
/// missing: html_unavailable()); the SVG figures are written as ever.
inline void warn_without_html(bool no_html) {
  if (no_html) return;
  const std::string why = html_unavailable();
  if (!why.empty())
    std::cerr << "warning: the 3D pages (plan.html, validation.html) are not written: " << why
              << "; the SVG figures are\n";
}

}  // namespace rodshape::cli
