// test_atomic_file.cpp: output files are written whole or not at all, and no temporary is left; a
// device, a FIFO or a symbolic link (dangling or not) at an output is refused and stays what it is,
// what a link names untouched (issue 43).
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "rodshape/error.hpp"
#include "rodshape/io/atomic_file.hpp"
#include "support/device_nodes.hpp"
#include "support/input_error.hpp"

namespace rodshape {
namespace test_atomic_file {
namespace {

namespace fs = std::filesystem;

class AtomicFile : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string pattern = (fs::temp_directory_path() / "rodshape_atomic_XXXXXX").string();
    ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
    directory_ = pattern;
  }
  void TearDown() override { fs::remove_all(directory_); }

  static std::string contents(const fs::path& path) {
    std::ifstream file(path);
    std::ostringstream text;
    text << file.rdbuf();
    return text.str();
  }
  int entries() const {
    return static_cast<int>(std::distance(fs::directory_iterator(directory_), {}));
  }

  fs::path directory_;
};

TEST_F(AtomicFile, WritesAndReplacesTheWholeFile) {
  const fs::path path = directory_ / "out.json";
  write_file_atomically(path.string(), "first\n");
  EXPECT_EQ(contents(path), "first\n");
  write_file_atomically(path.string(), "second, longer\n");
  EXPECT_EQ(contents(path), "second, longer\n");
  EXPECT_EQ(entries(), 1) << "a temporary file was left behind";
}

TEST_F(AtomicFile, MissingDirectoryFailsNamingThePathAndLeavesNothing) {
  const std::string path = (directory_ / "no" / "out.json").string();
  try {
    write_file_atomically(path, "x");
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()), path + ": cannot write: No such file or directory");
  }
  EXPECT_EQ(entries(), 0);
}

TEST_F(AtomicFile, DirectoryAsTargetFailsAndIsLeftAlone) {
  const fs::path target = directory_ / "taken";
  fs::create_directory(target);
  EXPECT_EQ(testing::input_error_message([&] { write_file_atomically(target.string(), "x"); }),
            target.string() + ": cannot write: Is a directory");
  EXPECT_TRUE(fs::is_directory(target));
  EXPECT_EQ(entries(), 1);
}

// ---- devices, FIFOs and symbolic links: never written into (issue 43) --------------------------

/// The message of a refused output: its path and what it is.
std::string refusal(const fs::path& path, const std::string& what) {
  return path.string() + ": cannot write: it is " + what +
         "; outputs are never written into a device, a pipe or through a symbolic link "
         "(docs/limits.md): remove it or give another output";
}

TEST_F(AtomicFile, NullDeviceIsRefusedAndStaysADevice) {
  const auto null = testing::memory_device(directory_ / "null", testing::kNullMinor);
  if (!null) GTEST_SKIP() << "cannot make a device node here (needs root and CAP_MKNOD)";
  EXPECT_EQ(testing::input_error_message([&] { write_file_atomically(null->string(), "{}\n"); }),
            refusal(*null, "a character device"));
  EXPECT_TRUE(testing::is_character_device(*null)) << "the device was replaced";
  EXPECT_EQ(entries(), 1) << "a temporary file was left behind";
}

TEST_F(AtomicFile, FullDeviceIsRefusedAndStaysADevice) {
  const auto full = testing::memory_device(directory_ / "full", testing::kFullMinor);
  if (!full) GTEST_SKIP() << "cannot make a device node here (needs root and CAP_MKNOD)";
  EXPECT_EQ(testing::input_error_message([&] { write_file_atomically(full->string(), "{}\n"); }),
            refusal(*full, "a character device"));
  EXPECT_TRUE(testing::is_character_device(*full)) << "the device was replaced";
  EXPECT_EQ(entries(), 1);
}

TEST_F(AtomicFile, FifoIsRefusedAndNothingGoesThrough) {
  const fs::path fifo = directory_ / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // A reader is there (non-blocking), so that a writer that opened the FIFO could not hang the
  // test: what it wrote would show in the pipe.
  const int reader = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
  ASSERT_GE(reader, 0);
  const std::string message = testing::input_error_message(
      [&] { write_file_atomically(fifo.string(), "into the pipe\n"); });
  std::array<char, 64> buffer{};
  const ssize_t count = ::read(reader, buffer.data(), buffer.size());
  ::close(reader);
  EXPECT_EQ(message, refusal(fifo, "a FIFO"));
  EXPECT_LE(count, 0) << "written into the FIFO";
  EXPECT_TRUE(fs::is_fifo(fs::symlink_status(fifo))) << "the FIFO was replaced";
  EXPECT_EQ(entries(), 1);
}

TEST_F(AtomicFile, SymbolicLinkIsRefusedAndWhatItNamesIsUntouched) {
  const fs::path real = directory_ / "real.json";
  const fs::path link = directory_ / "link.json";
  std::ofstream(real) << "another run's\n";
  fs::create_symlink("real.json", link);  // relative, as ln -s makes them
  EXPECT_EQ(testing::input_error_message([&] { write_file_atomically(link.string(), "new\n"); }),
            refusal(link, "a symbolic link"));
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(link))) << "the link was replaced";
  EXPECT_EQ(contents(real), "another run's\n");
  EXPECT_EQ(entries(), 2) << "a temporary file was left behind";
}

TEST_F(AtomicFile, DanglingSymbolicLinkIsRefusedAndCreatesNothing) {
  const fs::path link = directory_ / "link.json";
  fs::create_symlink(directory_ / "later.json", link);
  EXPECT_EQ(testing::input_error_message([&] { write_file_atomically(link.string(), "made\n"); }),
            refusal(link, "a symbolic link"));
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(link)));
  EXPECT_FALSE(fs::exists(directory_ / "later.json"));
}

TEST_F(AtomicFile, SymbolicLinkToADeviceIsRefused) {
  const auto null = testing::memory_device(directory_ / "null", testing::kNullMinor);
  if (!null) GTEST_SKIP() << "cannot make a device node here (needs root and CAP_MKNOD)";
  const fs::path link = directory_ / "out.json";
  fs::create_symlink(*null, link);
  EXPECT_EQ(testing::input_error_message([&] { write_file_atomically(link.string(), "{}\n"); }),
            refusal(link, "a symbolic link"));
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(link)));
  EXPECT_TRUE(testing::is_character_device(*null));
}

TEST_F(AtomicFile, LoopOfSymbolicLinksIsRefusedAsALink) {
  const fs::path a = directory_ / "a", b = directory_ / "b";
  fs::create_symlink(b, a);
  fs::create_symlink(a, b);
  EXPECT_EQ(testing::input_error_message([&] { write_file_atomically(a.string(), "x"); }),
            refusal(a, "a symbolic link"));
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(a)));
}

TEST_F(AtomicFile, ReplacedFileKeepsItsPermissions) {
  const fs::path path = directory_ / "private.json";
  std::ofstream(path) << "old\n";
  fs::permissions(path, fs::perms::owner_read | fs::perms::owner_write);
  write_file_atomically(path.string(), "new\n");
  EXPECT_EQ(contents(path), "new\n");
  EXPECT_EQ(fs::status(path).permissions() & fs::perms::all,
            fs::perms::owner_read | fs::perms::owner_write);
}

}  // namespace
}  // namespace test_atomic_file
}  // namespace rodshape
