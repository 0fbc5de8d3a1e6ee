// test_cli_mcap.cpp: `--mcap` and `--mcap-compression` of `rodshape plan` and `rodshape validate`
// (issue 49, docs/ros.md): plan.mcap written only when asked, named among the files written,
// rodshape's by its header, smaller with zstd, removed as stale by a run without --mcap; an
// unknown compression is bad input writing nothing; a validation writes validation.mcap (with
// the plan's topics) and no plan.mcap. What the files hold is io.mcap_decoders' and
// tests/io/test_plan_mcap.cpp's.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "rodshape/io/mcap_writer.hpp"
#include "rodshape/io/output_files.hpp"
#include "support/cli_runner.hpp"

namespace rodshape {
namespace test_cli_mcap {
namespace {

namespace fs = std::filesystem;
using rodshape::testing::quoted;
using rodshape::testing::read_file;

const fs::path kExamples = fs::path(RODSHAPE_SOURCE_DIR) / "examples";

class CliMcap : public rodshape::testing::CliTest {
 protected:
  rodshape::testing::CliOutcome plan(const fs::path& outdir, const std::string& options) const {
    return run("plan " + quoted((kExamples / "plan_c_arc.yaml").string()) + " -o " +
               quoted(outdir.string()) + " --no-html " + options);
  }
};

TEST_F(CliMcap, PlanWritesPlanMcapWhenAskedAndRemovesItWhenNot) {
  const fs::path out = directory_ / "plan";
  auto result = plan(out, "");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_FALSE(fs::exists(out / "plan.mcap"));

  result = plan(out, "--mcap");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find((out / "plan.mcap").string()), std::string::npos) << result.out;
  EXPECT_TRUE(is_rodshape_output((out / "plan.mcap").string()));
  const std::string zstd = read_file(out / "plan.mcap");
  EXPECT_EQ(zstd.substr(0, 8), kMcapMagic);
  EXPECT_NE(zstd.find("zstd"), std::string::npos);  // the chunks' compression field

  result = plan(out, "--mcap --mcap-compression none");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const std::string none = read_file(out / "plan.mcap");
  EXPECT_EQ(none.find("zstd"), std::string::npos);
  EXPECT_GT(none.size(), 2 * zstd.size());

  result = plan(out, "");  // an earlier run's plan.mcap would not match plan.json
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_FALSE(fs::exists(out / "plan.mcap"));
}

TEST_F(CliMcap, AnUnknownCompressionIsBadInputAndWritesNothing) {
  const fs::path out = directory_ / "lz4";
  const auto result = plan(out, "--mcap --mcap-compression lz4");
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("--mcap-compression"), std::string::npos) << result.err;
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(CliMcap, AValidationWritesValidationMcapAndNoPlanMcap) {
  const fs::path out = directory_ / "validate";
  const auto result = run("validate " + quoted((kExamples / "plan_c_arc.yaml").string()) + " -o " +
                          quoted(out.string()) + " --runs 1 --no-html -q --mcap");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_TRUE(is_rodshape_output((out / "validation.mcap").string()));
  EXPECT_FALSE(fs::exists(out / "plan.mcap"));
  const std::string file = read_file(out / "validation.mcap");
  for (const char* topic : {"/tf", "/rodshape/rod", "/rodshape/markers_measured"})
    EXPECT_NE(file.find(topic), std::string::npos) << topic;  // channels: never compressed
}

}  // namespace
}  // namespace test_cli_mcap
}  // namespace rodshape
