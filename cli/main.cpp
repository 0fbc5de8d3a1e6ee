// main.cpp: the rodshape tool. Lists the subcommands, parses the command line with CLI11 and turns
// exceptions into one-line messages and exit codes (exit_code.hpp).
#include <CLI/CLI.hpp>

#include <exception>
#include <iostream>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "command.hpp"
#include "equilibrium_command.hpp"
#include "exit_code.hpp"
#include "fk_command.hpp"
#include "ik_command.hpp"
#include "plan_command.hpp"
#include "rodshape/error.hpp"
#include "rodshape/version.hpp"

namespace {

/// Messages are one line: newlines inside one (from a dependency) become spaces.
std::string one_line(std::string message) {
  for (char& c : message) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  return message;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace rodshape::cli;

  CLI::App app{
      "rodshape: static Cosserat rods, solved by shooting, and optimal shape control.\n"
      "Units are SI; quaternions are [w, x, y, z]. Task file format: docs/task-file.md."};
  app.name("rodshape");
  app.set_version_flag("--version", "rodshape " + rodshape::version());
  app.require_subcommand(1);
  app.footer(
      "Exit codes: 0 success, 2 bad input (task file, command line, output path; for plan also "
      "an infeasible target), 3 solver did not converge, plan stopped at a failed step or ik found "
      "no solution (the "
      "result is still written), 1 internal error.");
  app.failure_message([](const CLI::App*, const CLI::Error& error) {
    return "error: " + one_line(error.what()) + " (run 'rodshape --help')\n";
  });

  std::vector<std::pair<CLI::App*, std::unique_ptr<Command>>> commands;
  const auto add = [&](std::unique_ptr<Command> command) {
    CLI::App* subcommand = command->add_to(app);
    commands.emplace_back(subcommand, std::move(command));
  };
  add(make_equilibrium_command());
  add(make_plan_command());
  add(make_fk_command());
  add(make_ik_command());

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    const int code = app.exit(error);  // prints help, the version or the error
    return code == 0 ? kSuccess : kBadInput;
  }

  try {
    for (auto& [subcommand, command] : commands) {
      if (subcommand->parsed()) return command->run();
    }
    return kBadInput;  // unreachable: require_subcommand(1)
  } catch (const rodshape::InputError& error) {
    std::cerr << "error: " << one_line(error.what()) << "\n";
    return kBadInput;
  } catch (const std::exception& error) {
    std::cerr << "error: internal error: " << one_line(error.what()) << "\n";
    return kInternalError;
  }
}
