// atomic_file.hpp: output files are written whole or not at all.
#pragma once

#include <string>

namespace rodshape {

/// Writes `content` to a new temporary file in the directory of `path`, flushes it to disk and
/// renames it over `path` (atomic on POSIX file systems). On any failure the temporary file is
/// removed, `path` is left as it was, and InputError "<path>: cannot write: <reason>" is thrown.
void write_file_atomically(const std::string& path, const std::string& content);

}  // namespace rodshape
