// output_files.cpp: an earlier run's outputs told from other files, outputs that are inputs, and
// a run's files written as a set (output_files.hpp; docs/limits.md, "Files written").
#include "rodshape/io/output_files.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string_view>

#include "rodshape/error.hpp"
#include "rodshape/io/atomic_file.hpp"
#include "rodshape/io/mcap_writer.hpp"
#include "rodshape/io/plan_output.hpp"
#include "rodshape/version.hpp"

namespace rodshape {

namespace {

namespace fs = std::filesystem;

/// The first bytes of a file (enough for any signature), or "" when it cannot be read.
std::string head_of(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::string head(512, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(std::max<std::streamsize>(in.gcount(), 0)));
  return head;
}

std::string_view skip_space(std::string_view text) {
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front())))
    text.remove_prefix(1);
  return text;
}

/// `text` without `prefix` (and the white space before it), or false when it does not begin so.
bool consume(std::string_view& text, std::string_view prefix) {
  text = skip_space(text);
  if (!text.starts_with(prefix)) return false;
  text.remove_prefix(prefix.size());
  return true;
}

/// {"generator": "rodshape ...", ...}
bool has_json_signature(std::string_view text) {
  return consume(text, "{") && consume(text, std::string("\"") + kGeneratorKey + "\"") &&
         consume(text, ":") && consume(text, "\"rodshape");
}

/// An MCAP file (mcap_writer.hpp) whose Header record's library is "rodshape ...": magic, opcode
/// 0x01, uint64 length, the profile and the library as uint32-length strings.
bool has_mcap_signature(std::string_view text) {
  if (!text.starts_with(kMcapMagic)) return false;
  text.remove_prefix(kMcapMagic.size());
  if (text.size() < 13 || text[0] != '\x01') return false;
  text.remove_prefix(9);
  for (int field = 0; field < 2; ++field) {
    if (text.size() < 4) return false;
    std::uint32_t size = 0;
    for (int k = 3; k >= 0; --k) size = size << 8 | static_cast<unsigned char>(text[k]);
    text.remove_prefix(4);
    if (text.size() < size) return false;
    if (field == 1) return text.substr(0, size).starts_with("rodshape ");
    text.remove_prefix(size);
  }
  return false;
}

std::string_view first_line(std::string_view text) { return text.substr(0, text.find('\n')); }

/// "t,<name>,<name>...": joint names of letters, digits, '_', '-', '/' and '.'.
bool is_joint_header(std::string_view line) {
  if (!line.starts_with("t,") || line.size() < 3) return false;
  for (char c : line.substr(2))
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '/' ||
          c == '.' || c == ','))
      return false;
  return line.back() != ',';
}

}  // namespace

std::string generator_signature() { return "rodshape " + version(); }

bool is_rodshape_output(const std::string& path) {
  std::error_code error;
  if (!fs::is_regular_file(fs::symlink_status(path, error))) return false;
  const std::string head = head_of(path);
  const std::string name = fs::path(path).filename().string();
  const std::string extension = fs::path(path).extension().string();
  if (extension == ".json") return has_json_signature(head);
  if (extension == ".mcap") return has_mcap_signature(head);
  if (extension == ".svg" || extension == ".html")
    return head.find("<!-- generator: rodshape") != std::string::npos;
  const std::string_view header = first_line(head);
  if (name == "trajectory.csv")
    return header == kTrajectoryCsvHeader || header == kTrajectoryCsvHeaderWithBase;
  if (name == "validation.csv")
    return header == "run,seed,t,error_3d,error_2d,true_error,visible_markers";
  if (name == "joint_trajectory.csv" || name == "base_joint_trajectory.csv")
    return is_joint_header(header);
  return false;
}

void check_not_an_input(const std::string& output, const std::vector<std::string>& inputs) {
  for (const std::string& input : inputs) {
    std::error_code error;
    if (!input.empty() && fs::equivalent(output, input, error) && !error)
      throw InputError(output + ": is " + input +
                       ", an input of this run: it would be overwritten; give another output");
  }
}

void check_output_files(const std::string& directory,
                        const std::vector<std::string>& names,
                        const std::vector<std::string>& inputs) {
  for (const std::string& name : names) {
    const std::string path = (fs::path(directory) / name).string();
    check_not_an_input(path, inputs);
    std::error_code error;
    const fs::file_status status = fs::symlink_status(path, error);
    if (error || !fs::exists(status)) continue;
    // A link, a device or a FIFO: refused, never opened (a FIFO would block).
    if (!fs::is_directory(status)) check_output_path(path);
    if (is_rodshape_output(path)) continue;
    throw InputError(path +
                     ": is in the way of an output and is not one rodshape wrote (no rodshape "
                     "signature); move it away or choose another output directory");
  }
}

void remove_earlier_outputs(const std::string& directory, const std::vector<std::string>& names) {
  for (const std::string& name : names) {
    const fs::path path = fs::path(directory) / name;
    if (!is_rodshape_output(path.string())) continue;
    std::error_code error;
    if (!fs::remove(path, error) && error)
      throw InputError(path.string() +
                       ": cannot remove the file of an earlier run: " + error.message());
  }
}

void OutputSet::append(OutputSet other) {
  for (auto& file : other.files) files.push_back(std::move(file));
  for (auto& name : other.stale) stale.push_back(std::move(name));
}

std::vector<std::string> write_output_set(const std::string& directory, OutputSet set) {
  check_output_directory(directory);
  std::error_code error;
  fs::create_directories(directory, error);
  if (error)
    throw InputError(directory + ": cannot create the output directory: " + error.message());
  if (!fs::is_directory(directory, error))
    throw InputError(directory + ": cannot create the output directory: it is not a directory");
  std::vector<std::string> written;
  for (auto& file : set.files) {  // names become paths; the contents are not copied
    written.push_back(file.first);
    file.first = (fs::path(directory) / file.first).string();
  }
  write_files_atomically(set.files);
  remove_earlier_outputs(directory, set.stale);
  return written;
}

}  // namespace rodshape
