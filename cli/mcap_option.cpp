// mcap_option.cpp: the MCAP options (mcap_option.hpp).
#include "mcap_option.hpp"

#include <vector>

namespace rodshape::cli {

void McapOption::add_to(CLI::App* command, const std::string& file) {
  command->add_flag("--mcap", mcap_,
                    "Also write OUTDIR/" + file +
                        ": ROS 2 messages (joint trajectory, joint states, tf, the rod as markers) "
                        "for Foxglove, Rerun or ros2 bag (docs/ros.md)");
  std::vector<std::string> names;
  for (const std::string_view name : names_of(kMcapCompressionNames)) names.emplace_back(name);
  command
      ->add_option("--mcap-compression", compression_,
                   "Compression of " + file + "'s chunks (default zstd)")
      ->check(CLI::IsMember(names))
      ->type_name("none|zstd");
}

std::optional<McapOptions> McapOption::options() const {
  if (!mcap_) return std::nullopt;
  McapOptions options;
  options.compression =
      value_of(kMcapCompressionNames, compression_).value_or(McapCompression::Zstd);
  return options;
}

}  // namespace rodshape::cli
