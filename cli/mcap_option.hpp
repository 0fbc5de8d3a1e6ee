// mcap_option.hpp: `--mcap` and `--mcap-compression none|zstd` of `rodshape plan` and `rodshape
// validate` (plan.mcap, validation.mcap: docs/ros.md).
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "rodshape/io/mcap_writer.hpp"

namespace rodshape::cli {

class McapOption {
 public:
  /// Adds the two options to `command`; `file` names the file in their help ("plan.mcap").
  void add_to(CLI::App* command, const std::string& file);
  /// What FigureFiles::mcap takes: the options when --mcap was given, else nullopt.
  std::optional<McapOptions> options() const;

 private:
  bool mcap_ = false;
  std::string compression_ = "zstd";
};

}  // namespace rodshape::cli
