// test_cli_io.cpp: where `rodshape equilibrium`, `plan` and `validate` write and what they read.
// Outputs are never written into a device, a FIFO or through a symbolic link: -o naming one is
// exit 2 before any work, the device, FIFO or link left as it was (issue 43); plan and validate
// write their files as a set, checked first, so that a path refused leaves every file of the set
// as it was; -o - and no -o write standard output (a full one is exit 2), -q prints nothing; a
// task or URDF path of /dev/zero ends at the size cap; a misspelled command gets "did you mean";
// a file that is not a URDF is said in words.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "support/cli_runner.hpp"
#include "support/device_nodes.hpp"

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace test_cli_io {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using rodshape::testing::quoted;
using rodshape::testing::read_file;

const std::string kExamples = std::string(RODSHAPE_SOURCE_DIR) + "/examples";
const std::string kBand = quoted(kExamples + "/rubber_band.yaml");

// ---- -o: devices, FIFOs, symbolic links (issue 43: never written into) ------------------------

/// The one line of a refused output: its path and what it is.
std::string refusal(const fs::path& path, const std::string& what) {
  return "error: " + path.string() + ": cannot write: it is " + what +
         "; outputs are never written into a device, a pipe or through a symbolic link "
         "(docs/limits.md): remove it or give another output\n";
}

class CliIo : public rodshape::testing::CliTest {
 protected:
  /// run() under `timeout`: a tool that blocks (on a FIFO without a reader) is killed after
  /// `seconds`, exit code 137, and the test goes on.
  rodshape::testing::CliOutcome run_guarded(const std::string& arguments, int seconds) const {
    return run_prefixed("timeout -s KILL " + std::to_string(seconds) + " ", arguments);
  }

 private:
  rodshape::testing::CliOutcome run_prefixed(const std::string& prefix,
                                             const std::string& arguments) const {
    const fs::path out = directory_ / "stdout.txt", err = directory_ / "stderr.txt";
    const std::string command = prefix + quoted(cli_) + " " + arguments + " >" +
                                quoted(out.string()) + " 2>" + quoted(err.string());
    const int status = std::system(command.c_str());
    rodshape::testing::CliOutcome result;
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    result.out = read_file(out);
    result.err = read_file(err);
    fs::remove(out);
    fs::remove(err);
    return result;
  }
};

TEST_F(CliIo, OutputToANullDeviceIsRefusedAndTheDeviceStays) {
  const auto null = rodshape::testing::memory_device(directory_ / "null", 3);
  if (!null) GTEST_SKIP() << "cannot make a device node here (needs root and CAP_MKNOD)";
  const auto result = run("equilibrium " + kBand + " -o " + quoted(null->string()) + " -q");
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.err, refusal(*null, "a character device"));
  EXPECT_TRUE(rodshape::testing::is_character_device(*null)) << "the device was replaced";
}

TEST_F(CliIo, OutputToAFullDeviceIsRefusedBeforeSolving) {
  const auto full = rodshape::testing::memory_device(directory_ / "full", 7);
  if (!full) GTEST_SKIP() << "cannot make a device node here (needs root and CAP_MKNOD)";
  const auto result = run("equilibrium " + kBand + " -o " + quoted(full->string()));
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.err, refusal(*full, "a character device"));
  EXPECT_EQ(result.out, "");
  EXPECT_TRUE(rodshape::testing::is_character_device(*full)) << "the device was replaced";
}

TEST_F(CliIo, OutputThatIsTheTaskFileIsBadInputAndTheTaskIsKept) {
  // Issue 24: `-o` naming the task file overwrote the task with its result.
  const std::string text = read_file(kExamples + "/rubber_band.yaml");
  const fs::path task = directory_ / "band.yaml";
  fs::copy_file(kExamples + "/rubber_band.yaml", task);
  fs::create_symlink(task, directory_ / "link.json");
  for (const fs::path& output : {task, directory_ / "." / "band.yaml", directory_ / "link.json"}) {
    SCOPED_TRACE(output.string());
    const auto result =
        run("equilibrium " + quoted(task.string()) + " -o " + quoted(output.string()));
    EXPECT_EQ(result.exit_code, 2);
    EXPECT_EQ(result.err, "error: " + output.string() + ": is " + task.string() +
                              ", an input of this run: it would be overwritten; give another "
                              "output\n");
    EXPECT_EQ(result.out, "");
    EXPECT_EQ(read_file(task), text);
  }
}

TEST_F(CliIo, OutputThroughASymbolicLinkIsRefusedDanglingOrNot) {
  fs::create_directory(directory_ / "results");
  const fs::path link = directory_ / "band.json";
  fs::create_symlink("results/band.json", link);  // dangling
  auto result = run("equilibrium " + kBand + " -o " + quoted(link.string()) + " -q");
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.err, refusal(link, "a symbolic link"));
  EXPECT_FALSE(fs::exists(directory_ / "results" / "band.json")) << "written through the link";
  std::ofstream(directory_ / "results" / "band.json") << "another run's\n";  // no longer dangling
  result = run("equilibrium " + kBand + " -o " + quoted(link.string()) + " -q");
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.err, refusal(link, "a symbolic link"));
  EXPECT_EQ(read_file(directory_ / "results" / "band.json"), "another run's\n");
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(link))) << "the link was replaced";
}

TEST_F(CliIo, OutputToAFifoIsRefusedPromptly) {
  const fs::path fifo = directory_ / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // No reader: a tool that opened the FIFO would block (killed by the guard after 20 s).
  const auto start = std::chrono::steady_clock::now();
  const auto result = run_guarded("equilibrium " + kBand + " -o " + quoted(fifo.string()), 20);
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(10));
  EXPECT_EQ(result.exit_code, 2) << "137: blocked on the FIFO and killed";
  EXPECT_EQ(result.err, refusal(fifo, "a FIFO"));
  EXPECT_EQ(result.out, "");
  EXPECT_TRUE(fs::is_fifo(fs::symlink_status(fifo))) << "the FIFO was replaced";
}

// ---- plan and validate: the outputs as a set (issue 43) -----------------------------------------

// A gentle bend of the band (test_cli_plan.cpp), 51 nodes: fast. band_task(3) differs in its steps,
// so its plan.json differs from band_task(2)'s.
std::string band_task(int steps) {
  return R"(rod:
  length: 0.29
  nodes: 51
  section: {shape: rectangle, width: 0.02, height: 0.02}
  material: {young_modulus: 3.2e6, poisson_ratio: 0.5, density: 1392}
  stiffness: {EIx: 0.04, EIy: 0.04, GJ: 0.028}
target:
  points:
    - [0.003, 0.000, 0.057]
    - [0.013, 0.000, 0.114]
    - [0.030, 0.000, 0.169]
    - [0.052, 0.000, 0.223]
    - [0.081, 0.000, 0.273]
trajectory:
  steps: )" +
         std::to_string(steps) + "\n";
}

TEST_F(CliIo, PlanWithADanglingLinkAtTrajectoryCsvWritesNothingOfTheSet) {
  // The link names a file in a missing directory: following it failed, after plan.json was
  // written, so plan.json no longer matched the other files.
  const fs::path first = write_task("first.yaml", band_task(2));
  const fs::path second = write_task("second.yaml", band_task(3));
  const fs::path out = directory_ / "out";
  ASSERT_EQ(run("plan " + quoted(first.string()) + " -o " + quoted(out.string()) + " -q").exit_code,
            0);
  const std::string plan_json = read_file(out / "plan.json");
  fs::remove(out / "trajectory.csv");
  fs::create_symlink("nowhere/trajectory.csv", out / "trajectory.csv");
  const auto result = run("plan " + quoted(second.string()) + " -o " + quoted(out.string()));
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.err, refusal(out / "trajectory.csv", "a symbolic link"));
  EXPECT_TRUE(read_file(out / "plan.json") == plan_json) << "plan.json of the second run written";
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(out / "trajectory.csv")));
  EXPECT_FALSE(fs::exists(out / "nowhere"));
  // In a fresh directory: no plan.json at all.
  const fs::path fresh = directory_ / "fresh";
  fs::create_directory(fresh);
  fs::create_symlink("nowhere/trajectory.csv", fresh / "trajectory.csv");
  EXPECT_EQ(run("plan " + quoted(second.string()) + " -o " + quoted(fresh.string())).exit_code, 2);
  EXPECT_FALSE(fs::exists(fresh / "plan.json"));
  EXPECT_FALSE(fs::exists(fresh / "plan.svg"));
}

TEST_F(CliIo, PlanJsonLinkedIntoAnotherRunsDirectoryIsRefusedAndThatRunIsUntouched) {
  const fs::path first = write_task("first.yaml", band_task(2));
  const fs::path second = write_task("second.yaml", band_task(3));
  const fs::path other = directory_ / "other", out = directory_ / "out";
  ASSERT_EQ(
      run("plan " + quoted(first.string()) + " -o " + quoted(other.string()) + " -q").exit_code, 0);
  const std::string other_plan = read_file(other / "plan.json");
  fs::create_directory(out);
  fs::create_symlink(other / "plan.json", out / "plan.json");
  const auto result = run("plan " + quoted(second.string()) + " -o " + quoted(out.string()));
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.err, refusal(out / "plan.json", "a symbolic link"));
  EXPECT_TRUE(read_file(other / "plan.json") == other_plan)
      << "the other run's plan.json was written";
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(out / "plan.json")));
  EXPECT_EQ(std::distance(fs::directory_iterator(out), {}), 1) << "something else was written";
}

TEST_F(CliIo, ValidateWithAFifoAtValidationCsvIsRefusedPromptly) {
  const fs::path task = write_task("task.yaml", band_task(2));
  const fs::path out = directory_ / "out";
  fs::create_directory(out);
  ASSERT_EQ(::mkfifo((out / "validation.csv").c_str(), 0600), 0);
  // No reader: writing the FIFO blocked for ever (the guard kills the tool after 30 s).
  const auto start = std::chrono::steady_clock::now();
  const auto result =
      run_guarded("validate " + quoted(task.string()) + " -o " + quoted(out.string()), 30);
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(10));
  EXPECT_EQ(result.exit_code, 2) << "137: blocked on the FIFO and killed";
  EXPECT_EQ(result.err, refusal(out / "validation.csv", "a FIFO"));
  EXPECT_TRUE(fs::is_fifo(fs::symlink_status(out / "validation.csv")));
  for (const char* name : {"plan.json", "trajectory.csv", "validation.json"})
    EXPECT_FALSE(fs::exists(out / name)) << name;
}

// ---- standard output and -q ---------------------------------------------------------------------

TEST_F(CliIo, DashIsStandardOutput) {
  const auto result = run_in_directory("equilibrium " + kBand + " -o -");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(Json::parse(result.out)["status"], "converged");
  EXPECT_FALSE(fs::exists(directory_ / "-")) << "wrote a file named '-'";
}

TEST_F(CliIo, FullStandardOutputIsBadInput) {
  const auto result = run_in_directory("equilibrium " + kBand, "/dev/full");
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.err, "error: standard output: cannot write: No space left on device\n");
}

TEST_F(CliIo, QuietWithoutOutputPrintsNothingAndTheExitCodeSaysTheStatus) {
  const auto quiet = run_in_directory("equilibrium " + kBand + " -q");
  EXPECT_EQ(quiet.exit_code, 0) << quiet.err;
  EXPECT_EQ(quiet.out, "");
  EXPECT_EQ(quiet.err, "");
  const auto dash = run_in_directory("equilibrium " + kBand + " -q -o -");
  EXPECT_EQ(dash.exit_code, 0);
  EXPECT_EQ(dash.out, "");
  EXPECT_FALSE(fs::exists(directory_ / "-"));
}

// ---- reading: size caps, URDF messages ----------------------------------------------------------

TEST_F(CliIo, TaskPathDevZeroEndsAtTheCap) {
  const auto start = std::chrono::steady_clock::now();
  const auto result = run("equilibrium /dev/zero");
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.err, "error: /dev/zero: file is larger than 1 MiB, the cap for a task file\n");
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(10));
}

TEST_F(CliIo, UrdfPathDevZeroEndsAtTheCap) {
  const auto result = run("fk /dev/zero 0");
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.err, "error: /dev/zero: file is larger than 4 MiB, the cap for a URDF file\n");
}

TEST_F(CliIo, FileThatIsNotXmlIsSaidInWords) {
  const fs::path text = write_task("notes.urdf", "these are my notes, not a robot\n");
  EXPECT_EQ(run("fk " + quoted(text.string()) + " 0").err,
            "error: " + text.string() +
                ": the URDF does not parse: it is not XML (no XML element found; a URDF is an XML "
                "file with a <robot> element)\n");
  const fs::path empty = write_task("empty.urdf", "\n");
  EXPECT_EQ(run("fk " + quoted(empty.string()) + " 0").err,
            "error: " + empty.string() + ": the URDF does not parse: the file is empty\n");
  const fs::path html = write_task("page.urdf", "<html><body/></html>\n");
  EXPECT_EQ(run("fk " + quoted(html.string()) + " 0").err,
            "error: " + html.string() +
                ": the URDF does not parse: no <robot> element (a URDF is an XML file with a "
                "<robot> element)\n");
  const fs::path broken =
      write_task("broken.urdf", "<robot name=\"r\">\n<link name=\"a\">\n</robot>\n");
  EXPECT_EQ(run("fk " + quoted(broken.string()) + " 0").err,
            "error: " + broken.string() +
                ": the URDF does not parse: malformed XML (error reading end tag)\n");
}

TEST_F(CliIo, DeeplyNestedUrdfIsRejectedWithTheLine) {
  // TinyXML takes quadratic time in the depth and overflows the stack near 100,000 levels.
  std::string xml = "<robot name=\"r\">\n<link name=\"a\"/>\n";
  for (int k = 0; k < 100; ++k) xml += "<x>";
  const fs::path deep = write_task("deep.urdf", xml);
  EXPECT_EQ(run("fk " + quoted(deep.string()) + " 0").err,
            "error: " + deep.string() +
                ":3: the URDF does not parse: XML elements nested deeper than 64 levels\n");
}

// ---- the command line ---------------------------------------------------------------------------

TEST_F(CliIo, MisspelledCommandGetsDidYouMean) {
  const auto result = run("equilibrim " + kBand);
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.err,
            "error: unknown command 'equilibrim'; did you mean 'equilibrium'? (run 'rodshape "
            "--help')\n");
  EXPECT_EQ(run("paln x.yaml").err,
            "error: unknown command 'paln'; did you mean 'plan'? (run 'rodshape --help')\n");
  EXPECT_EQ(run("frobnicate x.yaml").err,
            "error: unknown command 'frobnicate'; the commands are equilibrium, estimate, plan, "
            "validate, fk, ik (run 'rodshape --help')\n");
}

}  // namespace
}  // namespace test_cli_io
