// main.cpp: the rodshape tool. Lists the subcommands, parses the command line with CLI11 and turns
// exceptions into one-line messages and exit codes (exit_code.hpp).
#include <CLI/CLI.hpp>

#include <algorithm>
#include <exception>
#include <iostream>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "command.hpp"
#include "equilibrium_command.hpp"
#include "estimate_command.hpp"
#include "exit_code.hpp"
#include "fk_command.hpp"
#include "ik_command.hpp"
#include "plan_command.hpp"
#include "rodshape/error.hpp"
#include "rodshape/version.hpp"
#include "validate_command.hpp"

namespace {

/// Messages are one line: newlines inside one (from a dependency) become spaces.
std::string one_line(std::string message) {
  for (char& c : message) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  return message;
}

/// Optimal-string-alignment distance: insertions, deletions, substitutions and transpositions of
/// two neighbours ("paln" is 1 from "plan").
std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    for (std::size_t j = 1; j <= b.size(); ++j) {
      d[i][j] = std::min(
          {d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  }
  return d[a.size()][b.size()];
}

/// For a first argument that is no subcommand: "unknown command 'equilibrim'; did you mean
/// 'equilibrium'?", or the list of commands when none is close (at most a third of the letters
/// wrong). Empty when `word` is a subcommand or an option.
std::string unknown_command_message(const CLI::App& app, const std::string& word) {
  if (word.empty() || word.front() == '-') return "";
  std::string names, closest;
  std::size_t best = word.size() / 3 + 1;
  for (const CLI::App* command : app.get_subcommands({})) {
    if (command->check_name(word)) return "";
    const std::string& name = command->get_name();
    names += (names.empty() ? "" : ", ") + name;
    if (const std::size_t distance = edit_distance(word, name); distance < best) {
      best = distance;
      closest = name;
    }
  }
  if (!closest.empty()) return "unknown command '" + word + "'; did you mean '" + closest + "'?";
  return "unknown command '" + word + "'; the commands are " + names;
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
      "Exit codes: 0 success, 2 bad input (task file, command line, output path, an infeasible "
      "target; nothing is written or removed), 3 solver did not converge, plan stopped at a "
      "failed step, validate's plant snapped or was lost, ik found no solution, or estimate's "
      "model does not explain the cloud (the result is still written), 1 internal error.");
  app.failure_message([](const CLI::App*, const CLI::Error& error) {
    return "error: " + one_line(error.what()) + " (run 'rodshape --help')\n";
  });

  std::vector<std::pair<CLI::App*, std::unique_ptr<Command>>> commands;
  const auto add = [&](std::unique_ptr<Command> command) {
    CLI::App* subcommand = command->add_to(app);
    commands.emplace_back(subcommand, std::move(command));
  };
  add(make_equilibrium_command());
  add(make_estimate_command());
  add(make_plan_command());
  add(make_validate_command());
  add(make_fk_command());
  add(make_ik_command());

  if (argc > 1) {
    if (const std::string unknown = unknown_command_message(app, argv[1]); !unknown.empty()) {
      std::cerr << "error: " << unknown << " (run 'rodshape --help')\n";
      return kBadInput;
    }
  }
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
