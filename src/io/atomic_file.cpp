// atomic_file.cpp: write to a temporary file beside the target, fsync, rename (POSIX).
#include "rodshape/io/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "rodshape/error.hpp"

namespace rodshape {

namespace {

[[noreturn]] void fail(const std::string& path, int error) {
  throw InputError(path + ": cannot write: " + std::strerror(error));
}

/// ".<name>.tmp-<pid>-<n>" in the target's directory: same file system, so rename() is atomic.
std::string temporary_name(const std::filesystem::path& target) {
  static std::atomic<unsigned> counter{0};
  const std::filesystem::path directory = target.parent_path();
  // (Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "." + std::string&&.)
  std::string name = ".";
  name += target.filename().string();
  name += ".tmp-";
  name += std::to_string(::getpid());
  name += "-";
  name += std::to_string(counter++);
  return (directory / name).string();
}

/// Writes all of `content`, retrying short writes and interrupted calls. Returns 0 or an errno.
int write_all(int fd, const std::string& content) {
  const char* data = content.data();
  std::size_t left = content.size();
  while (left > 0) {
    const ssize_t written = ::write(fd, data, left);
    if (written < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    data += written;
    left -= static_cast<std::size_t>(written);
  }
  return 0;
}

}  // namespace

void write_file_atomically(const std::string& path, const std::string& content) {
  const std::filesystem::path target(path);
  if (path.empty() || !target.has_filename()) fail(path, EISDIR);
  std::error_code status_error;
  if (std::filesystem::is_directory(target, status_error)) fail(path, EISDIR);

  std::string temporary;
  int fd = -1;
  for (int attempt = 0; attempt < 100 && fd < 0; ++attempt) {
    temporary = temporary_name(target);
    // 0666 before the umask, as for any new file.
    fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0 && errno != EEXIST) fail(path, errno);
  }
  if (fd < 0) fail(path, EEXIST);

  int error = write_all(fd, content);
  if (error == 0 && ::fsync(fd) != 0) error = errno;
  if (::close(fd) != 0 && error == 0) error = errno;
  if (error == 0 && std::rename(temporary.c_str(), path.c_str()) != 0) error = errno;
  if (error != 0) {
    ::unlink(temporary.c_str());
    fail(path, error);
  }
}

}  // namespace rodshape
