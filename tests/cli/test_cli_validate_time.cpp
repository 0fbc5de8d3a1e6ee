// test_cli_validate_time.cpp: issue 43, part 6. `rodshape validate` estimates its time before any
// work and refuses beyond 300 s (--max-seconds raises it): a thousand closed-loop runs are refused
// within a second with the estimate and the option, and the estimate of a small validation is
// not under a third of its real time nor over 5 times it (docs/limits.md, "Sizes of a
// validation": the estimate is fitted on one machine and high on faster ones).
#include <gtest/gtest.h>

#include "support/cli_runner.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <string>

namespace test_cli_validate_time {
namespace {

namespace fs = std::filesystem;
using Outcome = rodshape::testing::CliOutcome;
using rodshape::testing::quoted;

const std::string kArc = quoted(std::string(RODSHAPE_SOURCE_DIR) + "/examples/plan_c_arc.yaml");

class CliValidateTime : public rodshape::testing::CliTest {
 protected:
  Outcome validate(const std::string& arguments) const {
    return run("validate " + kArc + " -o " + quoted((directory_ / "out").string()) + " -q" +
               arguments);
  }
  /// The seconds in "... validate would take <words> <S> s, ..." (-1 if not there).
  static double seconds_in(const std::string& message, const std::string& words) {
    const std::string before = "validate would take " + words + " ";
    const std::size_t at = message.find(before);
    return at == std::string::npos ? -1.0 : std::stod(message.substr(at + before.size()));
  }
  static double estimate_in(const std::string& message) { return seconds_in(message, "about"); }
};

TEST_F(CliValidateTime, AThousandClosedLoopRunsAreRefusedUpFrontWithTheEstimate) {
  // About 9 minutes of work (0.3 s of CPU a run): it ran, with no estimate.
  const auto start = std::chrono::steady_clock::now();
  const Outcome refused = validate(" --runs 1000 --closed-loop");
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(1));
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_EQ(std::count(refused.err.begin(), refused.err.end(), '\n'), 1) << refused.err;
  EXPECT_GT(estimate_in(refused.err), 300.0) << refused.err;
  EXPECT_NE(refused.err.find("1000 runs, closed loop"), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("at most 300 s"), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("--max-seconds"), std::string::npos) << refused.err;
  EXPECT_FALSE(fs::exists(directory_ / "out")) << "written or created before the refusal";
}

TEST_F(CliValidateTime, TheEstimateOfASmallValidationIsNeitherUnderNorFarOverItsTime) {
  // The estimate is fitted to CPU seconds (times a margin of 1.5); on 2 shared cores the wall time
  // was 0.9-1.9 times the CPU time (docs/limits.md): estimate / time within [1/3, 3].
  // Before planning the estimate is a lower bound (the path's frames unknown): refused below it,
  // then a little above it, after planning, with the estimate.
  const std::string arguments = " --runs 8 --closed-loop --jobs 1";
  const Outcome early = validate(arguments + " --max-seconds 0.001");
  const double least = seconds_in(early.err, "at least about");
  ASSERT_GT(least, 0.0) << early.err;
  const Outcome refused = validate(arguments + " --max-seconds " + std::to_string(1.1 * least));
  ASSERT_EQ(refused.exit_code, 2) << refused.err;
  const double estimate = estimate_in(refused.err);
  ASSERT_GT(estimate, least) << refused.err;
#if !defined(NDEBUG) || defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
  // The estimate is fitted to the Release build's CPU time; a Debug or sanitizer build runs the
  // same validation 10-20 times slower (CI: 94.5 s against 5.6 s estimated), so its time says
  // nothing.
  GTEST_SKIP() << "the estimate is of the Release build";
#endif
  const auto start = std::chrono::steady_clock::now();
  const Outcome done = validate(arguments + " --no-html");
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_EQ(done.exit_code, 0) << done.err;
  // Not under: the refusal relies on it (a machine up to 2 × slower than the fitted one within
  // the margin's 1.5 and the wall time's 1.9). Over by at most 5: the margin's 1.5 on a machine up
  // to 3.3 × faster than the fitted one (this case took 2.5 s of CPU there, 1.6 s of wall time on
  // an AMD family 26 machine in 2026-12: 3.5 × under the estimate, where 3 was asserted before).
  EXPECT_GT(estimate, seconds / 3.0) << "estimated " << estimate << " s, took " << seconds << " s";
  EXPECT_LT(estimate, seconds * 5.0) << "estimated " << estimate << " s, took " << seconds << " s";
}

}  // namespace
}  // namespace test_cli_validate_time
