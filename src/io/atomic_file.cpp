// atomic_file.cpp: write to temporary files beside the targets, fsync, then rename them all
// (POSIX); devices, FIFOs and symbolic links at a target are refused, never opened (issue 43).
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
    if (written == 0) return EIO;
    data += written;
    left -= static_cast<std::size_t>(written);
  }
  return 0;
}

/// A checked target: its existing permissions (nullopt when nothing is there).
std::optional<mode_t> checked_target(const std::string& path) {
  if (path.empty()) fail(path, ENOENT);
  if (!fs::path(path).has_filename()) fail(path, EISDIR);  // "dir/"
  struct stat status {};
  if (::lstat(path.c_str(), &status) != 0) {
    if (errno == ENOENT) return std::nullopt;
    fail(path, errno);
  }
  const char* what = nullptr;
  switch (status.st_mode & S_IFMT) {
    case S_IFREG:
      return status.st_mode & 07777;
    case S_IFDIR:
      fail(path, EISDIR);
    case S_IFLNK:
      what = "a symbolic link";
      break;
    case S_IFIFO:
      what = "a FIFO";
      break;
    case S_IFCHR:
      what = "a character device";
      break;
    case S_IFBLK:
      what = "a block device";
      break;
    default:
      what = "a socket";
  }
  throw InputError(path + ": cannot write: it is " + what +
                   "; outputs are never written into a device, a pipe or through a symbolic "
                   "link (docs/limits.md): remove it or give another output");
}

/// A temporary file written and flushed beside its target, removed unless renamed.
class Temporary {
 public:
  Temporary(const std::string& path, const std::string& content, std::optional<mode_t> mode)
      : path_(path) {
    int fd = -1;
    for (int attempt = 0; attempt < 100 && fd < 0; ++attempt) {
      name_ = temporary_name(path);
      // 0666 before the umask, as for any new file.
      fd = ::open(name_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
      if (fd < 0 && errno != EEXIST) fail(path, errno);
    }
    if (fd < 0) fail(path, EEXIST);
    int error = 0;
    if (mode && ::fchmod(fd, *mode) != 0) error = errno;
    if (error == 0) error = write_all(fd, content);
    if (error == 0 && ::fsync(fd) != 0) error = errno;
    if (::close(fd) != 0 && error == 0) error = errno;
    if (error != 0) {
      ::unlink(name_.c_str());
      fail(path, error);
    }
  }
  Temporary(const Temporary&) = delete;
  Temporary& operator=(const Temporary&) = delete;
  Temporary(Temporary&& other) noexcept
      : path_(std::move(other.path_)), name_(std::exchange(other.name_, {})) {}
  Temporary& operator=(Temporary&&) = delete;
  ~Temporary() {
    if (!name_.empty()) ::unlink(name_.c_str());
  }

  /// Renames the temporary over its target (which rename() replaces, never follows).
  void commit() {
    if (std::rename(name_.c_str(), path_.c_str()) != 0) fail(path_, errno);
    name_.clear();
  }

 private:
  std::string path_, name_;
};

}  // namespace

void check_output_path(const std::string& path) { checked_target(path); }

void write_files_atomically(const std::vector<std::pair<std::string, std::string>>& files) {
  std::vector<std::optional<mode_t>> modes;
  for (const auto& [path, content] : files) modes.push_back(checked_target(path));
  std::vector<Temporary> temporaries;
  temporaries.reserve(files.size());
  for (std::size_t k = 0; k < files.size(); ++k)
    temporaries.emplace_back(files[k].first, files[k].second, modes[k]);
  for (Temporary& temporary : temporaries) temporary.commit();
}

void write_file_atomically(const std::string& path, const std::string& content) {
  write_files_atomically({{path, content}});
}

void write_to_standard_output(const std::string& content) {
  if (const int error = write_all(STDOUT_FILENO, content); error != 0) {
    throw InputError(std::string("standard output: cannot write: ") + std::strerror(error));
  }
}

}  // namespace rodshape
