// atomic_file.hpp: output files are written whole or not at all, and never replace a device, a
// FIFO or a symbolic link.
#pragma once

#include <string>

namespace rodshape {

/// Writes `content` to `path`. On failure throws InputError "<path>: cannot write: <reason>"
/// (e.g. "out.json: cannot write: No space left on device").
///   - A regular file, or a path where nothing is: `content` goes to a new temporary file in the
///     same directory, which is flushed to disk and renamed over `path` (atomic on POSIX file
///     systems; an existing file keeps its permissions). On failure the temporary file is removed
///     and `path` is left as it was.
///   - A symbolic link is followed (through up to 40 links) and what it names is written as
///     above; the link stays. A dangling link creates the file it names.
///   - A character or block device or a FIFO (/dev/null, /dev/stdout, a named pipe) is opened
///     and written in place, without truncating or replacing it; a FIFO waits for its reader. A
///     device that takes less than the whole content (/dev/full) is an error.
///   - A directory or a socket is an error.
void write_file_atomically(const std::string& path, const std::string& content);

/// Writes `content` to standard output (file descriptor 1, unbuffered), all of it or
/// InputError "standard output: cannot write: <reason>" (e.g. when it is /dev/full).
void write_to_standard_output(const std::string& content);

}  // namespace rodshape
