// test_plan_mcap.cpp: plan.mcap of a hand-made plan (plan_mcap.hpp): the topics a plan without an
// arm has (/tf at every path sample, /rodshape/rod for the initial shape and each step), the rod's
// messages at the times their waypoints are reached (the last at the path's end), and plan.mcap
// as one of the plan's files: written with --mcap's option, removed as stale without it, a foreign
// file or a link in its place refused, none for a plan without a path.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "rodshape/error.hpp"
#include "rodshape/io/output_files.hpp"
#include "rodshape/io/plan_mcap.hpp"
#include "rodshape/io/plan_output.hpp"
#include "rodshape/io/ros_messages.hpp"
#include "rodshape/io/task_reader.hpp"
#include "support/hand_made_plan.hpp"

namespace rodshape {
namespace test_plan_mcap {
namespace {

namespace fs = std::filesystem;

template <typename T>
T field(std::string_view data, std::size_t& at) {
  T value{};
  std::memcpy(&value, data.data() + at, sizeof(T));
  at += sizeof(T);
  return value;
}

std::string text(std::string_view data, std::size_t& at) {
  const auto size = field<std::uint32_t>(data, at);
  std::string s(data.substr(at, size));
  at += size;
  return s;
}

/// Each topic's messages' log times, read from an uncompressed file's data section.
std::map<std::string, std::vector<std::uint64_t>> message_times(std::string_view file) {
  std::size_t footer = file.size() - 8 - 20;
  const auto summary_start = field<std::uint64_t>(file, footer);
  std::map<std::uint16_t, std::string> topics;
  std::map<std::string, std::vector<std::uint64_t>> times;
  const auto walk = [&](std::string_view data, std::size_t at, std::size_t end,
                        auto& self) -> void {
    while (at < end) {
      const auto opcode = field<std::uint8_t>(data, at);
      const auto length = field<std::uint64_t>(data, at);
      std::size_t c = at;
      if (opcode == static_cast<std::uint8_t>(McapOpcode::Channel)) {
        const auto id = field<std::uint16_t>(data, c);
        field<std::uint16_t>(data, c);
        topics[id] = text(data, c);
      } else if (opcode == static_cast<std::uint8_t>(McapOpcode::Message)) {
        const auto id = field<std::uint16_t>(data, c);
        field<std::uint32_t>(data, c);
        times[topics.at(id)].push_back(field<std::uint64_t>(data, c));
      } else if (opcode == static_cast<std::uint8_t>(McapOpcode::Chunk)) {
        c += 8 + 8 + 8 + 4;
        EXPECT_EQ(text(data, c), "");  // uncompressed
        const auto size = field<std::uint64_t>(data, c);
        self(data.substr(c, size), 0, size, self);
      }
      at += length;
    }
  };
  walk(file, 8, summary_start, walk);
  return times;
}

fs::path fresh_directory(const std::string& name) {
  const fs::path directory =
      fs::temp_directory_path() / ("rodshape_plan_mcap_" + std::to_string(::getpid())) / name;
  fs::remove_all(directory);
  return directory;
}

TEST(PlanMcap, APlanWithoutAnArmHasTfAtEverySampleAndTheRodAtEveryWaypoint) {
  const PlanTask task = parse_plan_task(testing::kHandMadeTask, "hand_made.yaml");
  const PlanResult plan = testing::make_plan(task, 3);
  const std::string file = plan_mcap(plan, task.problem, {.compression = McapCompression::None});
  const auto times = message_times(file);
  ASSERT_EQ(times.size(), 2U) << "a plan without an arm: /tf and /rodshape/rod";
  const std::vector<std::uint64_t>& tf = times.at("/tf");
  ASSERT_EQ(tf.size(), plan.end_effector_path.size());
  for (std::size_t i = 0; i < tf.size(); ++i)
    EXPECT_EQ(tf[i], RosTime::from_seconds(plan.end_effector_path[i].t).nanoseconds());
  const std::vector<std::uint64_t>& rod = times.at("/rodshape/rod");
  ASSERT_EQ(rod.size(), plan.steps.size() + 1);
  EXPECT_EQ(rod.front(), 0U);  // the initial shape at the start
  for (std::size_t k = 1; k < rod.size(); ++k) EXPECT_GT(rod[k], rod[k - 1]) << "step " << k;
  EXPECT_EQ(rod.back(), tf.back())
      << "the last step's shape when its waypoint, the end, is reached";
}

TEST(PlanMcap, IsOneOfThePlansFilesWrittenAsASet) {
  const PlanTask task = parse_plan_task(testing::kHandMadeTask, "hand_made.yaml");
  const PlanResult plan = testing::make_plan(task, 3);
  const fs::path dir = fresh_directory("set");
  const FigureFiles with_mcap{.html = false, .mcap = McapOptions{}};
  const std::vector<std::string> written = write_plan(dir.string(), plan, task, with_mcap);
  EXPECT_EQ(written.back(), "plan.mcap");
  EXPECT_TRUE(is_rodshape_output((dir / "plan.mcap").string()));
  // Without --mcap an earlier run's plan.mcap is stale: removed.
  write_plan(dir.string(), plan, task, {.html = false});
  EXPECT_FALSE(fs::exists(dir / "plan.mcap"));
  // A file that is not rodshape's in its place is refused by the check before planning.
  std::ofstream(dir / "plan.mcap") << "someone's recording\n";
  EXPECT_THROW(check_output_files(dir.string(), plan_file_names(), {}), InputError);
  EXPECT_TRUE(fs::exists(dir / "plan.mcap"));  // (the CLI checks before it plans, then writes)
  fs::remove(dir / "plan.mcap");
  // Nor written through a link.
  std::ofstream(dir / "elsewhere") << "kept\n";
  fs::create_symlink(dir / "elsewhere", dir / "plan.mcap");
  EXPECT_THROW(write_plan(dir.string(), plan, task, with_mcap), InputError);
  EXPECT_TRUE(fs::is_symlink(dir / "plan.mcap"));
  std::ifstream in(dir / "elsewhere");
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "kept");
  fs::remove_all(dir.parent_path());
}

TEST(PlanMcap, APlanWithoutAPathHasNone) {
  const PlanTask task = parse_plan_task(testing::kHandMadeTask, "hand_made.yaml");
  PlanResult plan = testing::make_plan(task, 3);
  plan.end_effector_path.clear();
  EXPECT_THROW(plan_mcap(plan, task.problem), InputError);
  const OutputSet set = plan_outputs(plan, task, {.html = false, .mcap = McapOptions{}});
  for (const auto& [name, content] : set.files) EXPECT_NE(name, "plan.mcap");
}

}  // namespace
}  // namespace test_plan_mcap
}  // namespace rodshape
