// test_cli_io.cpp: where `rodshape equilibrium` writes and what it reads. -o to a device or a FIFO
// writes it in place (a full device is exit 2 with the reason), -o through a symbolic link writes
// its target, -o - and no -o write standard output (a full one is exit 2), -q prints nothing; a
// task or URDF path of /dev/zero ends at the size cap; a misspelled command gets "did you mean";
// a file that is not a URDF is said in words.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "support/cli_runner.hpp"
#include "support/device_nodes.hpp"

#include <array>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <string>
#include <thread>

namespace test_cli_io {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using rodshape::testing::quoted;
using rodshape::testing::read_file;

const std::string kExamples = std::string(RODSHAPE_SOURCE_DIR) + "/examples";
const std::string kBand = quoted(kExamples + "/rubber_band.yaml");

class CliIo : public rodshape::testing::CliTest {};

// ---- -o: devices, FIFOs, symbolic links ---------------------------------------------------------

TEST_F(CliIo, OutputToANullDeviceLeavesTheDevice) {
  const auto null = rodshape::testing::memory_device(directory_ / "null", 3);
  if (!null) GTEST_SKIP() << "cannot make a device node here (needs root and CAP_MKNOD)";
  const auto result = run("equilibrium " + kBand + " -o " + quoted(null->string()) + " -q");
  EXPECT_EQ(result.exit_code, 0) << result.err;
  EXPECT_TRUE(rodshape::testing::is_character_device(*null)) << "the device was replaced";
}

TEST_F(CliIo, OutputToAFullDeviceIsBadInputWithTheReason) {
  const auto full = rodshape::testing::memory_device(directory_ / "full", 7);
  if (!full) GTEST_SKIP() << "cannot make a device node here (needs root and CAP_MKNOD)";
  const auto result = run("equilibrium " + kBand + " -o " + quoted(full->string()));
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.err, "error: " + full->string() + ": cannot write: No space left on device\n");
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

TEST_F(CliIo, OutputThroughASymbolicLinkWritesItsTarget) {
  fs::create_directory(directory_ / "results");
  const fs::path link = directory_ / "band.json";
  fs::create_symlink("results/band.json", link);  // dangling until the first write
  ASSERT_EQ(run("equilibrium " + kBand + " -o " + quoted(link.string()) + " -q").exit_code, 0);
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(link))) << "the link was replaced";
  EXPECT_EQ(Json::parse(read_file(directory_ / "results" / "band.json"))["status"], "converged");
}

TEST_F(CliIo, OutputToAFifoReachesItsReader) {
  const fs::path fifo = directory_ / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // Read end first, non-blocking: a reader thread drains it while the tool writes (the result is
  // larger than a pipe's buffer), and nothing can hang if the tool never opens the FIFO.
  const int reader = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
  ASSERT_GE(reader, 0);
  std::atomic<bool> done{false};
  std::string received;
  std::thread drain([&] {
    std::array<char, 4096> buffer{};
    for (bool last = false; !last;) {
      last = done.load();
      for (ssize_t count; (count = ::read(reader, buffer.data(), buffer.size())) > 0;)
        received.append(buffer.data(), static_cast<std::size_t>(count));
      if (!last) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
  });
  const auto result = run("equilibrium " + kBand + " -o " + quoted(fifo.string()) + " -q");
  done = true;
  drain.join();
  ::close(reader);
  EXPECT_EQ(result.exit_code, 0) << result.err;
  EXPECT_TRUE(fs::is_fifo(fs::symlink_status(fifo))) << "the FIFO was replaced";
  ASSERT_FALSE(received.empty()) << "nothing came through the FIFO";
  EXPECT_EQ(Json::parse(received)["status"], "converged");
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
