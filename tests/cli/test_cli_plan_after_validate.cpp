// test_cli_plan_after_validate.cpp: `rodshape plan` into a directory where `rodshape validate`
// wrote before takes the validation's files out with the earlier plan's (found by this session's
// trial re-run: a C-arc plan.json stood beside a validation.json of another plan).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "support/cli_runner.hpp"

namespace test_cli_plan_after_validate {
namespace {

namespace fs = std::filesystem;
using rodshape::testing::quoted;

class CliPlanAfterValidate : public rodshape::testing::CliTest {};

TEST_F(CliPlanAfterValidate, AnEarlierValidationsFilesAreTakenOut) {
  const std::string examples = std::string(RODSHAPE_SOURCE_DIR) + "/examples/";
  const fs::path out = directory_ / "out";
  const auto validated = run("validate " + quoted(examples + "plan_c_arc.yaml") + " -o " +
                             quoted(out.string()) + " -q --runs 1 --no-html");
  ASSERT_EQ(validated.exit_code, 0) << validated.err;
  ASSERT_TRUE(fs::exists(out / "validation.json"));
  std::ofstream(out / "notes.txt") << "mine\n";
  const auto planned = run("plan " + quoted(examples + "plan_s_curve.yaml") + " -o " +
                           quoted(out.string()) + " -q --no-html");
  ASSERT_EQ(planned.exit_code, 0) << planned.err;
  for (const char* name : {"validation.json", "validation.csv", "validation.svg"})
    EXPECT_FALSE(fs::exists(out / name)) << name;
  EXPECT_TRUE(fs::exists(out / "plan.json"));
  EXPECT_TRUE(fs::exists(out / "notes.txt"));  // not rodshape's: left alone
}

}  // namespace
}  // namespace test_cli_plan_after_validate
