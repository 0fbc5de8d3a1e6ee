// atomic_file.cpp: write to a temporary file beside the target, fsync, rename (POSIX); devices and
// FIFOs are written in place; symbolic links are followed.
#include "rodshape/io/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <optional>

#include "rodshape/error.hpp"

namespace rodshape {

namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const std::string& path, int error) {
  throw InputError(path + ": cannot write: " + std::strerror(error));
}

/// ".<name>.tmp-<pid>-<n>" in the target's directory: same file system, so rename() is atomic.
std::string temporary_name(const fs::path& target) {
  static std::atomic<unsigned> counter{0};
  const fs::path directory = target.parent_path();
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
    if (written == 0) return EIO;  // a device that takes nothing more
    data += written;
    left -= static_cast<std::size_t>(written);
  }
  return 0;
}

/// What `path` names after following symbolic links in its last component (at most 40, as the
/// kernel does; more fail with ELOOP). A dangling link gives the path it points to.
std::string follow_links(const std::string& path) {
  fs::path current(path);
  for (int hops = 0; hops <= 40; ++hops) {
    std::error_code error;
    if (!fs::is_symlink(fs::symlink_status(current, error))) return current.string();
    const fs::path target = fs::read_symlink(current, error);
    if (error) fail(path, error.value());
    current = target.is_absolute() ? target : current.parent_path() / target;
  }
  fail(path, ELOOP);
}

/// Opens an existing device or FIFO for writing, without O_CREAT or O_TRUNC, and writes it.
void write_in_place(const std::string& path,
                    const std::string& target,
                    const std::string& content) {
  const int fd = ::open(target.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) fail(path, errno);
  int error = write_all(fd, content);
  if (::close(fd) != 0 && error == 0) error = errno;
  if (error != 0) fail(path, error);
}

/// Writes a temporary file beside `target` with the given permissions, then renames it over
/// `target`.
void replace_atomically(const std::string& path,
                        const std::string& target,
                        const std::string& content,
                        std::optional<mode_t> permissions) {
  std::string temporary;
  int fd = -1;
  for (int attempt = 0; attempt < 100 && fd < 0; ++attempt) {
    temporary = temporary_name(target);
    // 0666 before the umask, as for any new file.
    fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0 && errno != EEXIST) fail(path, errno);
  }
  if (fd < 0) fail(path, EEXIST);

  int error = 0;
  if (permissions && ::fchmod(fd, *permissions) != 0) error = errno;
  if (error == 0) error = write_all(fd, content);
  if (error == 0 && ::fsync(fd) != 0) error = errno;
  if (::close(fd) != 0 && error == 0) error = errno;
  if (error == 0 && std::rename(temporary.c_str(), target.c_str()) != 0) error = errno;
  if (error != 0) {
    ::unlink(temporary.c_str());
    fail(path, error);
  }
}

}  // namespace

void write_file_atomically(const std::string& path, const std::string& content) {
  if (path.empty()) fail(path, ENOENT);
  const std::string target = follow_links(path);
  if (!fs::path(target).has_filename()) fail(path, EISDIR);  // "dir/"

  struct stat status {};
  std::optional<mode_t> permissions;
  if (::stat(target.c_str(), &status) == 0) {
    if (S_ISDIR(status.st_mode)) fail(path, EISDIR);
    if (S_ISCHR(status.st_mode) || S_ISBLK(status.st_mode) || S_ISFIFO(status.st_mode)) {
      write_in_place(path, target, content);
      return;
    }
    if (!S_ISREG(status.st_mode)) throw InputError(path + ": cannot write: it is a socket");
    permissions = status.st_mode & 07777;
  }
  replace_atomically(path, target, content, permissions);
}

void write_to_standard_output(const std::string& content) {
  if (const int error = write_all(STDOUT_FILENO, content); error != 0) {
    throw InputError(std::string("standard output: cannot write: ") + std::strerror(error));
  }
}

}  // namespace rodshape
