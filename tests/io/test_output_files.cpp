// test_output_files.cpp: issue 24, item 4. An earlier run's outputs are told from other files by
// their signature (the JSON's first member, the CSV's header, the SVG's comment); an output that
// is an input of the run is bad input; a file in the way that is not rodshape's is named and left
// alone; only rodshape's files are removed; a link (dangling or not) or a FIFO at an output is
// refused, and so is an output directory that is a link (issue 43).
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "rodshape/error.hpp"
#include "rodshape/io/output_files.hpp"
#include "rodshape/io/plan_output.hpp"
#include "rodshape/io/validation_output.hpp"
#include "support/input_error.hpp"

namespace rodshape {
namespace test_output_files {
namespace {

namespace fs = std::filesystem;

fs::path fresh_directory(const std::string& name) {
  const fs::path directory =
      fs::temp_directory_path() / ("rodshape_output_files_" + std::to_string(::getpid())) / name;
  fs::remove_all(directory);
  fs::create_directories(directory);
  return directory;
}

fs::path written(const fs::path& path, const std::string& content) {
  std::ofstream(path) << content;
  return path;
}

TEST(OutputFiles, RodshapesOutputsAreRecognisedByTheirSignature) {
  const fs::path d = fresh_directory("signatures");
  const std::string json = "{\n  \"" + std::string(kGeneratorKey) + "\": \"" +
                           generator_signature() + "\",\n  \"status\": \"complete\"\n}\n";
  EXPECT_TRUE(is_rodshape_output(written(d / "plan.json", json).string()));
  EXPECT_TRUE(is_rodshape_output(written(d / "validation.json", json).string()));
  EXPECT_TRUE(is_rodshape_output(
      written(d / "plan.svg", "<?xml version=\"1.0\"?>\n" + svg_signature_comment() + "\n<svg/>\n")
          .string()));
  EXPECT_TRUE(is_rodshape_output(
      written(d / "trajectory.csv", "t,x,y,z,qw,qx,qy,qz\n0,0,0,0,1,0,0,0\n").string()));
  EXPECT_TRUE(is_rodshape_output(
      written(d / "validation.csv", "run,seed,t,error_3d,error_2d,true_error,visible_markers\n")
          .string()));
  EXPECT_TRUE(is_rodshape_output(
      written(d / "joint_trajectory.csv", "t,panda_joint1,panda_joint2\n0,0,0\n").string()));

  // Anything else is not rodshape's: a task file, a JSON without the signature, other headers.
  EXPECT_FALSE(is_rodshape_output(written(d / "plan.json", "rod:\n  length: 0.29\n").string()));
  EXPECT_FALSE(is_rodshape_output(written(d / "plan.json", "{\"status\": \"x\"}\n").string()));
  EXPECT_FALSE(is_rodshape_output(written(d / "plan.svg", "<svg/>\n").string()));
  EXPECT_FALSE(is_rodshape_output(written(d / "trajectory.csv", "t,x\n").string()));
  EXPECT_FALSE(is_rodshape_output(written(d / "joint_trajectory.csv", "time;q\n").string()));
  EXPECT_FALSE(is_rodshape_output((d / "missing.json").string()));
  EXPECT_FALSE(is_rodshape_output(d.string()));  // a directory
  fs::remove_all(d.parent_path());
}

TEST(OutputFiles, AnOutputThatIsAnInputOfTheRunIsBadInput) {
  const fs::path d = fresh_directory("inputs");
  const fs::path task = written(d / "task.yaml", "rod: {}\n");
  fs::create_symlink(task, d / "link.json");
  const std::vector<std::string> inputs = {task.string()};
  EXPECT_THROW(check_not_an_input((d / "." / "task.yaml").string(), inputs), InputError);
  EXPECT_THROW(check_not_an_input((d / "link.json").string(), inputs), InputError);
  const std::string message =
      testing::input_error_message([&] { check_not_an_input((d / "link.json").string(), inputs); });
  EXPECT_NE(message.find(task.string() + ", an input of this run"), std::string::npos) << message;
  EXPECT_NO_THROW(check_not_an_input((d / "out.json").string(), inputs));  // not there yet
  EXPECT_NO_THROW(check_not_an_input(written(d / "other.json", "{}").string(), inputs));
  fs::remove_all(d.parent_path());
}

TEST(OutputFiles, AFileInTheWayThatIsNotRodshapesIsNamedAndLeftAlone) {
  const fs::path d = fresh_directory("in_the_way");
  written(d / "trajectory.csv", "t,x,y,z,qw,qx,qy,qz\n");  // an earlier run's: may be replaced
  written(d / "plan.json", "my own notes\n");
  const std::string message =
      testing::input_error_message([&] { check_output_files(d.string(), plan_file_names(), {}); });
  EXPECT_EQ(message.rfind((d / "plan.json").string() + ": is in the way of an output", 0), 0u)
      << message;
  EXPECT_EQ(message.find('\n'), std::string::npos);
  remove_earlier_outputs(d.string(), plan_file_names());
  EXPECT_TRUE(fs::exists(d / "plan.json"));        // not rodshape's: left alone
  EXPECT_FALSE(fs::exists(d / "trajectory.csv"));  // rodshape's: removed
  // A task file named like an output, in the output directory, is an input: bad input.
  const fs::path task = written(d / "plan.svg", "rod: {}\n");
  fs::remove(d / "plan.json");
  const std::string named = testing::input_error_message(
      [&] { check_output_files(d.string(), plan_file_names(), {task.string()}); });
  EXPECT_NE(named.find("an input of this run"), std::string::npos) << named;
  EXPECT_TRUE(fs::exists(task));
  fs::remove_all(d.parent_path());
}

TEST(OutputFiles, ALinkOrAFifoAtAnOutputIsRefusedNamedAndLeftAlone) {
  // Issue 43: outputs are never written into a device, a pipe or through a symbolic link.
  const fs::path d = fresh_directory("links"), other = fresh_directory("other_run");
  const auto refusal = [](const fs::path& path, const std::string& what) {
    return path.string() + ": cannot write: it is " + what +
           "; outputs are never written into a device, a pipe or through a symbolic link "
           "(docs/limits.md): remove it or give another output";
  };
  const auto message = [&](const std::vector<std::string>& names) {
    return testing::input_error_message([&] { check_output_files(d.string(), names, {}); });
  };
  // Dangling: it created what it named (or failed after the set's first files were written).
  fs::create_symlink("nowhere/trajectory.csv", d / "trajectory.csv");
  EXPECT_EQ(message(plan_file_names()), refusal(d / "trajectory.csv", "a symbolic link"));
  fs::remove(d / "trajectory.csv");
  // Into another run's directory, at a file that is rodshape's: that run's file was written.
  const std::string json =
      "{\"" + std::string(kGeneratorKey) + "\": \"" + generator_signature() + "\"}\n";
  fs::create_symlink(written(other / "plan.json", json), d / "plan.json");
  EXPECT_EQ(message(plan_file_names()), refusal(d / "plan.json", "a symbolic link"));
  remove_earlier_outputs(d.string(), plan_file_names());
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(d / "plan.json"))) << "the link was removed";
  EXPECT_EQ(std::ifstream(other / "plan.json").peek(), '{');
  fs::remove(d / "plan.json");
  // A FIFO: writing it blocked until a reader came.
  ASSERT_EQ(::mkfifo((d / "validation.csv").c_str(), 0600), 0);
  EXPECT_EQ(message(validation_file_names()), refusal(d / "validation.csv", "a FIFO"));
  EXPECT_TRUE(fs::is_fifo(fs::symlink_status(d / "validation.csv")));
  fs::remove_all(d.parent_path());
}

TEST(OutputFiles, AnOutputDirectoryThatIsALinkIsRefusedAndNothingWritten) {
  // Issue 43: `-o LINK` wrote through the link into the directory it names (another run's).
  const fs::path d = fresh_directory("directory_link"), other = fresh_directory("linked_run");
  const fs::path link = d / "out";
  fs::create_symlink(other, link);
  const std::string refusal =
      link.string() +
      ": cannot write into it: the output directory is a symbolic link; outputs are never written "
      "through a symbolic link (docs/limits.md): give the directory it names or another output "
      "directory";
  for (const std::string& given : {link.string(), link.string() + "/"}) {
    EXPECT_EQ(testing::input_error_message([&] { check_output_directory(given); }), refusal);
    OutputSet set;
    set.files.emplace_back("plan.json", "{}\n");
    EXPECT_EQ(testing::input_error_message([&] { write_output_set(given, set); }), refusal);
  }
  EXPECT_TRUE(fs::is_empty(other)) << "written through the link";
  // Dangling: the directory it names was created and written.
  fs::remove(link);
  fs::create_symlink(d / "nowhere", link);
  OutputSet set;
  set.files.emplace_back("plan.json", "{}\n");
  EXPECT_EQ(testing::input_error_message([&] { write_output_set(link.string(), set); }), refusal);
  EXPECT_FALSE(fs::exists(d / "nowhere"));
  // A link above the directory is followed.
  fs::create_symlink(other, d / "above");
  EXPECT_EQ(write_output_set((d / "above" / "run").string(), set),
            std::vector<std::string>{"plan.json"});
  EXPECT_TRUE(fs::is_regular_file(other / "run" / "plan.json"));
  fs::remove_all(d.parent_path());
}

TEST(OutputFiles, ValidationNamesItsFiles) {
  EXPECT_EQ(validation_file_names(),
            (std::vector<std::string>{"validation.json", "validation.csv", "validation.svg",
                                      "validation.html", "validation.mcap"}));
}

}  // namespace
}  // namespace test_output_files
}  // namespace rodshape
