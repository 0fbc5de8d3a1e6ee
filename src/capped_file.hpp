// capped_file.hpp (private): reading a whole input file with a cap on its size, so that a path such
// as /dev/zero, a FIFO or a huge file ends with a message instead of reading until memory runs out.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace rodshape::detail {

/// One mebibyte, the unit the caps are given in (docs/limits.md).
inline constexpr std::size_t kMiB = std::size_t{1} << 20;

/// What is read and how much of it: messages say "<path>: <cannot_read>: <reason>" and
/// "<path>: file is larger than <cap>, the cap for <kind>".
struct FileCap {
  std::size_t bytes;             // the largest accepted size
  std::string_view kind;         // "a task file"
  std::string_view cannot_read;  // "cannot read"
};

/// The whole content of the file at `path` (a regular file, a FIFO or a device), read in chunks
/// and never more than cap.bytes + one chunk. Throws InputError when the file cannot be opened or
/// read, is a directory, or holds more than cap.bytes.
std::string read_capped_file(const std::string& path, const FileCap& cap);

}  // namespace rodshape::detail
