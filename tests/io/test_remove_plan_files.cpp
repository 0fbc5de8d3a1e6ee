// test_remove_plan_files.cpp: remove_plan_files() takes an earlier run's plan files out of the
// output directory, recognised by their signature (issue 24: any other file is left alone, as is
// a missing directory), and lists the same files write_plan() writes.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "rodshape/io/output_files.hpp"
#include "rodshape/io/plan_output.hpp"

namespace rodshape {
namespace test_remove_plan_files {
namespace {

namespace fs = std::filesystem;

fs::path fresh_directory(const std::string& name) {
  const fs::path directory = fs::temp_directory_path() /
                             ("rodshape_remove_plan_files_" + std::to_string(::getpid())) / name;
  fs::remove_all(directory);
  fs::create_directories(directory);
  return directory;
}

TEST(RemovePlanFiles, RemovesAnEarlierRunsPlanFilesOnly) {
  const fs::path directory = fresh_directory("earlier");
  const std::string json =
      "{\"" + std::string(kGeneratorKey) + "\": \"" + generator_signature() + "\"}\n";
  std::ofstream(directory / "plan.json") << json;
  std::ofstream(directory / "joint_trajectory.json") << json;
  std::ofstream(directory / "trajectory.csv") << "t,x,y,z,qw,qx,qy,qz\n";
  std::ofstream(directory / "joint_trajectory.csv") << "t,joint_1\n";
  std::ofstream(directory / "plan.svg") << "<?xml version=\"1.0\"?>\n"
                                        << svg_signature_comment() << "\n<svg/>\n";
  std::ofstream(directory / "notes.txt") << "mine\n";
  remove_plan_files(directory.string());
  for (const std::string& name : plan_file_names())
    EXPECT_FALSE(fs::exists(directory / name)) << name;
  EXPECT_TRUE(fs::exists(directory / "notes.txt"));
  // A file named like a plan file that is not rodshape's (no signature) is left alone.
  std::ofstream(directory / "plan.json") << "old\n";
  remove_plan_files(directory.string());
  EXPECT_TRUE(fs::exists(directory / "plan.json"));
  fs::remove_all(directory.parent_path());
}

TEST(RemovePlanFiles, ADanglingLinkNamedPlanJsonIsLeftAloneNotFollowed) {
  const fs::path directory = fresh_directory("link");
  fs::create_symlink(directory / "nowhere", directory / "plan.json");
  remove_plan_files(directory.string());
  EXPECT_TRUE(fs::is_symlink(directory / "plan.json"));  // not recognisably rodshape's
  EXPECT_FALSE(fs::exists(directory / "nowhere"));
  fs::remove_all(directory.parent_path());
}

TEST(RemovePlanFiles, AMissingDirectoryIsLeftMissing) {
  const fs::path directory = fresh_directory("missing") / "not_yet";
  EXPECT_NO_THROW(remove_plan_files(directory.string()));
  EXPECT_FALSE(fs::exists(directory));
  fs::remove_all(directory.parent_path().parent_path());
}

TEST(RemovePlanFiles, NamesTheFilesWritePlanWrites) {
  EXPECT_EQ(plan_file_names(),
            (std::vector<std::string>{"plan.json", "trajectory.csv", "plan.svg", "plan.html",
                                      "joint_trajectory.csv", "joint_trajectory.json",
                                      "base_joint_trajectory.csv", "base_joint_trajectory.json",
                                      "plan.mcap"}));
}

}  // namespace
}  // namespace test_remove_plan_files
}  // namespace rodshape
