// test_atomic_file.cpp: output files are written whole or not at all, and no temporary is left.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "rodshape/error.hpp"
#include "rodshape/io/atomic_file.hpp"

namespace rodshape {
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
  EXPECT_THROW(write_file_atomically(target.string(), "x"), InputError);
  EXPECT_TRUE(fs::is_directory(target));
  EXPECT_EQ(entries(), 1);
}

}  // namespace
}  // namespace rodshape
