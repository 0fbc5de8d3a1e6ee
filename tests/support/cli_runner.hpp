// cli_runner.hpp: runs the rodshape tool as a user does, for the tests under tests/cli/: a
// temporary directory per test, `rodshape <arguments>` through the shell with stdout and stderr
// captured, and the exit code; checks of the shapes of the values in the JSON it writes.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace rodshape::testing {

struct CliOutcome {
  int exit_code = -1;
  std::string out;
  std::string err;
};

inline std::string read_file(const std::filesystem::path& path) {
  std::ifstream file(path);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

/// Single-quoted for the shell (the test paths hold no quote).
inline std::string quoted(const std::string& text) { return "'" + text + "'"; }

class CliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_FALSE(cli_.empty()) << "the rodshape tool was not built";
    std::string pattern = (std::filesystem::temp_directory_path() / "rodshape_cli_XXXXXX").string();
    ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
    directory_ = pattern;
  }
  void TearDown() override { std::filesystem::remove_all(directory_); }

  /// Runs `rodshape <arguments>` (already quoted for the shell).
  CliOutcome run(const std::string& arguments) const {
    const std::filesystem::path out = directory_ / "stdout.txt";
    const std::filesystem::path err = directory_ / "stderr.txt";
    const std::string command =
        quoted(cli_) + " " + arguments + " >" + quoted(out.string()) + " 2>" + quoted(err.string());
    const int status = std::system(command.c_str());
    CliOutcome result;
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    result.out = read_file(out);
    result.err = read_file(err);
    std::filesystem::remove(out);
    std::filesystem::remove(err);
    return result;
  }

  /// Runs `rodshape <arguments>` with the test's directory as the working directory, and with
  /// standard output sent to `stdout_path` (a device such as /dev/full) when it is not empty (out
  /// is "" then).
  CliOutcome run_in_directory(const std::string& arguments,
                              const std::string& stdout_path = "") const {
    const std::filesystem::path out = directory_ / "stdout.txt";
    const std::filesystem::path err = directory_ / "stderr.txt";
    const std::string command =
        "cd " + quoted(directory_.string()) + " && " + quoted(cli_) + " " + arguments + " >" +
        quoted(stdout_path.empty() ? out.string() : stdout_path) + " 2>" + quoted(err.string());
    const int status = std::system(command.c_str());
    CliOutcome result;
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    if (stdout_path.empty()) result.out = read_file(out);
    result.err = read_file(err);
    std::filesystem::remove(out);
    std::filesystem::remove(err);
    return result;
  }

  /// Writes `text` to `name` in the test's directory.
  std::filesystem::path write_task(const std::string& name, const std::string& text) const {
    const std::filesystem::path path = directory_ / name;
    std::ofstream(path) << text;
    return path;
  }

  const std::string cli_ = RODSHAPE_CLI_PATH;
  std::filesystem::path directory_;
};

/// An array of three numbers.
inline void expect_vector3(const nlohmann::json& v) {
  ASSERT_TRUE(v.is_array());
  ASSERT_EQ(v.size(), 3u);
  for (const nlohmann::json& c : v) EXPECT_TRUE(c.is_number());
}

/// A unit quaternion [w, x, y, z] with w ≥ 0, as the JSON writers give every rotation
/// (src/io/json_format.hpp, json_quaternion).
inline void expect_unit_quaternion(const nlohmann::json& q) {
  ASSERT_TRUE(q.is_array());
  ASSERT_EQ(q.size(), 4u);
  double norm2 = 0.0;
  for (const nlohmann::json& c : q) norm2 += c.get<double>() * c.get<double>();
  EXPECT_NEAR(std::sqrt(norm2), 1.0, 1e-12);
  EXPECT_GE(q[0].get<double>(), 0.0);
}

}  // namespace rodshape::testing
