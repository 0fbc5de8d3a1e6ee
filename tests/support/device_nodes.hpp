// device_nodes.hpp: character devices made in a test's own directory (mknod, as root), so that the
// tests of writing to a device never touch /dev: a bug that replaced the device replaces only the
// test's copy.
#pragma once

#include <sys/stat.h>
#include <sys/sysmacros.h>

#include <filesystem>
#include <optional>

namespace rodshape::testing {

/// Linux's memory devices (drivers/char/mem.c): 1:3 takes everything, 1:7 fails with ENOSPC.
inline constexpr unsigned kNullMinor = 3;
inline constexpr unsigned kFullMinor = 7;

/// A character device 1:`minor` at `path`, or nullopt when it cannot be made (not root, or a
/// container without CAP_MKNOD): callers skip the test then.
inline std::optional<std::filesystem::path> memory_device(const std::filesystem::path& path,
                                                          unsigned minor) {
  if (::mknod(path.c_str(), S_IFCHR | 0666, makedev(1, minor)) != 0) return std::nullopt;
  return path;
}

inline bool is_character_device(const std::filesystem::path& path) {
  struct stat status {};
  return ::lstat(path.c_str(), &status) == 0 && S_ISCHR(status.st_mode);
}

}  // namespace rodshape::testing
