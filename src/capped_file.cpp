// capped_file.cpp: read(2) in chunks until end of file or the cap (POSIX).
#include "capped_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>

#include "rodshape/error.hpp"

namespace rodshape::detail {

namespace {

/// "1 MiB", or "1000 bytes" for a cap that is not whole mebibytes.
std::string format_size(std::size_t bytes) {
  if (bytes % kMiB == 0) return std::to_string(bytes / kMiB) + " MiB";
  return std::to_string(bytes) + " bytes";
}

class FileDescriptor {
 public:
  explicit FileDescriptor(int fd) : fd_(fd) {}
  FileDescriptor(const FileDescriptor&) = delete;
  FileDescriptor& operator=(const FileDescriptor&) = delete;
  ~FileDescriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  int get() const { return fd_; }

 private:
  int fd_;
};

}  // namespace

std::string read_capped_file(const std::string& path, const FileCap& cap) {
  const auto cannot_read = [&](const std::string& reason) {
    return InputError(path + ": " + std::string(cap.cannot_read) + ": " + reason);
  };
  const auto too_large = [&] {
    return InputError(path + ": file is larger than " + format_size(cap.bytes) + ", the cap for " +
                      std::string(cap.kind));
  };

  const FileDescriptor file(::open(path.c_str(), O_RDONLY | O_CLOEXEC));
  if (file.get() < 0) throw cannot_read(std::strerror(errno));
  struct stat status {};
  if (::fstat(file.get(), &status) != 0) throw cannot_read(std::strerror(errno));
  if (S_ISDIR(status.st_mode)) throw cannot_read("it is a directory");
  // A regular file says its size; devices and FIFOs are read up to the cap.
  if (S_ISREG(status.st_mode) && static_cast<std::size_t>(status.st_size) > cap.bytes)
    throw too_large();

  std::string text;
  std::array<char, 1 << 16> chunk{};
  for (;;) {
    const ssize_t count = ::read(file.get(), chunk.data(), chunk.size());
    if (count < 0) {
      if (errno == EINTR) continue;
      throw cannot_read(std::strerror(errno));
    }
    if (count == 0) return text;
    if (text.size() + static_cast<std::size_t>(count) > cap.bytes) throw too_large();
    text.append(chunk.data(), static_cast<std::size_t>(count));
  }
}

}  // namespace rodshape::detail
