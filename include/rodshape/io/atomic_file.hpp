// atomic_file.hpp: output files are written whole or not at all, a set of them together, and
// never into a device, a FIFO or through a symbolic link (issue 43: an output is a regular file
// rodshape makes; docs/limits.md, "Files written").
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace rodshape {

/// InputError "<path>: cannot write: it is a symbolic link; outputs are never written into a
/// device, a pipe or through a symbolic link (docs/limits.md): remove it or give another output"
/// (or "a FIFO", "a character device", "a block device", "a socket"; a directory: "<path>: cannot
/// write: Is a directory") when something other than a regular file is at `path`. A link is
/// refused whether or not it dangles. Never opens `path` (a FIFO cannot block it).
void check_output_path(const std::string& path);

/// Writes each (path, content) of `files` as one set: every path is checked first
/// (check_output_path), then every content goes to a new temporary file beside its path, flushed
/// to disk, and only when all are written are they renamed over their paths, in order (atomic per
/// file on POSIX file systems; an existing file keeps its permissions). On any failure before the
/// renames nothing is changed and the temporaries are removed. Throws InputError "<path>: cannot
/// write: <reason>" (e.g. "out.json: cannot write: No space left on device").
void write_files_atomically(const std::vector<std::pair<std::string, std::string>>& files);

/// write_files_atomically() of one file.
void write_file_atomically(const std::string& path, const std::string& content);

/// Writes `content` to standard output (file descriptor 1, unbuffered), all of it or
/// InputError "standard output: cannot write: <reason>" (e.g. when it is /dev/full).
void write_to_standard_output(const std::string& content);

}  // namespace rodshape
