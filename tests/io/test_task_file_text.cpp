// test_task_file_text.cpp: what the task reader says about files that are not a task's YAML text:
// too large (a cap, checked while reading: /dev/zero ends at once), not UTF-8 text, tab
// indentation, nesting beyond the YAML reader's limit, a second document. Each message names the
// file and the line in words.
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "rodshape/io/task_reader.hpp"
#include "support/input_error.hpp"
#include "support/task_text.hpp"

namespace rodshape {
namespace test_task_file_text {
namespace {

using testing::kBandTask;

std::string error_of(const std::string& text) {
  const std::string message =
      testing::input_error_message([&] { parse_equilibrium_task(text, "task.yaml"); });
  EXPECT_EQ(message.find('\n'), std::string::npos) << "not one line: " << message;
  return message;
}

// ---- the size cap -------------------------------------------------------------------------------

TEST(TaskFileText, DevZeroEndsAtTheCapAtOnce) {
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(testing::input_error_message([] { read_equilibrium_task("/dev/zero"); }),
            "/dev/zero: file is larger than 1 MiB, the cap for a task file");
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
}

TEST(TaskFileText, RegularFileOverTheCapIsRejectedWithoutParsing) {
  std::string pattern =
      (std::filesystem::temp_directory_path() / "rodshape_task_XXXXXX.yaml").string();
  const int fd = ::mkstemps(pattern.data(), 5);
  ASSERT_GE(fd, 0);
  ::close(fd);
  {
    std::ofstream file(pattern);
    file << kBandTask;
    file << "# " << std::string((1 << 20) - kBandTask.size(), 'x') << "\n";  // 1 MiB + 3 bytes
  }
  EXPECT_EQ(testing::input_error_message([&] { read_equilibrium_task(pattern); }),
            pattern + ": file is larger than 1 MiB, the cap for a task file");
  std::filesystem::remove(pattern);
}

TEST(TaskFileText, DirectoryIsNamed) {
  EXPECT_EQ(testing::input_error_message([] { read_equilibrium_task("/"); }),
            "/: cannot read: it is a directory");
}

// ---- not YAML text ------------------------------------------------------------------------------

TEST(TaskFileText, BinaryGarbageIsNotATextFile) {
  // A PNG signature where the task should be.
  EXPECT_EQ(error_of(std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16)),
            "task.yaml:1: not a text file: invalid byte 0x89 (a task file is YAML, in UTF-8)");
}

TEST(TaskFileText, InvalidBytesAreNamedWithTheirLine) {
  // Latin-1 é in a comment, a NUL byte, a stray continuation byte, a C1 control in UTF-8.
  EXPECT_EQ(error_of(kBandTask + "# caf\xE9\n"),
            "task.yaml:9: not a text file: invalid byte 0xE9 (a task file is YAML, in UTF-8)");
  EXPECT_EQ(error_of(kBandTask + std::string("# \0\n", 4)),
            "task.yaml:9: not a text file: invalid byte 0x00 (a task file is YAML, in UTF-8)");
  EXPECT_EQ(error_of("rod:\n  length: 0.29 \x80\n"),
            "task.yaml:2: not a text file: invalid byte 0x80 (a task file is YAML, in UTF-8)");
  EXPECT_EQ(error_of("# \xC2\x9B\n" + kBandTask),
            "task.yaml:1: not a text file: invalid byte 0xC2 (a task file is YAML, in UTF-8)");
}

TEST(TaskFileText, Utf8TextAndAByteOrderMarkAreAccepted) {
  EXPECT_EQ(error_of("\xEF\xBB\xBF# Gummiband, 29 cm, \xC3\xA9\xE2\x82\xAC\xF0\x9F\x99\x82\n" +
                     kBandTask),
            "");
}

TEST(TaskFileText, TabIndentationIsSaidInWords) {
  EXPECT_EQ(error_of("rod:\n\tlength: 0.29\n"),
            "task.yaml:2: malformed YAML: tab characters are not allowed for indentation in YAML; "
            "indent with spaces");
  EXPECT_EQ(error_of(testing::replaced_first(kBandTask, "  rotation:", "\trotation:")),
            "task.yaml:8: malformed YAML: tab characters are not allowed for indentation in YAML; "
            "indent with spaces");
}

TEST(TaskFileText, DeepNestingIsSaidInWords) {
  const std::string deep = "rod: " + std::string(1000, '[') + std::string(1000, ']') + "\n";
  EXPECT_EQ(error_of(deep),
            "task.yaml:1: lists and mappings nested too deeply (the YAML reader stops at about "
            "500 levels)");
}

TEST(TaskFileText, SecondDocumentIsAnErrorAtItsLine) {
  EXPECT_EQ(error_of(kBandTask + "---\nrod: {length: 1}\n"),
            "task.yaml:9: a second YAML document starts here (after '---'); a task file is a "
            "single document");
  EXPECT_EQ(error_of(kBandTask + "---\n"),
            "task.yaml:9: a second YAML document starts here (after '---'); a task file is a "
            "single document");
  // A leading "---" and a closing "..." belong to the one document.
  EXPECT_EQ(error_of("---\n" + kBandTask + "...\n"), "");
}

TEST(TaskFileText, TextAfterTheEndOfTheDocumentIsAnError) {
  // yaml-cpp's Load() reads "[1, 2]" and silently drops the rest.
  EXPECT_EQ(error_of("[1, 2]\nrod: {length: 0.29}\n"),
            "task.yaml:2: malformed YAML: text after the end of the document (check the "
            "indentation)");
}

// Found by fuzz_task_reader: inputs on which YAML::LoadAll (yaml-cpp 0.7) never returns. Each must
// end, with an error, at once; SIGALRM ends the test binary if one loops.
TEST(TaskFileText, FuzzRegressionsEndWithAnError) {
  const std::filesystem::path directory =
      std::filesystem::path(RODSHAPE_SOURCE_DIR) / "fuzz" / "regressions";
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(directory)) {
    std::ifstream file(entry.path(), std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(file)),
                           std::istreambuf_iterator<char>());
    ::alarm(20);
    EXPECT_NE(error_of(text), "") << entry.path();
    ::alarm(0);
    ++files;
  }
  EXPECT_GE(files, 2);
}

}  // namespace
}  // namespace test_task_file_text
}  // namespace rodshape
