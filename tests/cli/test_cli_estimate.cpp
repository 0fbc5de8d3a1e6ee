// test_cli_estimate.cpp: `rodshape estimate TASK --cloud FILE [-o OUT.json]`: the bundled band's
// cloud is explained (exit 0, the equilibrium's keys plus fit); a cloud of something else is not
// (exit 3, the result written and saying why); a broken cloud, a task without a depth camera and
// an output that is an input are bad input (exit 2, nothing written).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "support/cli_runner.hpp"

namespace test_cli_estimate {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using rodshape::testing::quoted;
using rodshape::testing::read_file;

const std::string kExamples = std::string(RODSHAPE_SOURCE_DIR) + "/examples";
const std::string kTask = kExamples + "/estimate_band.yaml";
const std::string kCloud = kExamples + "/clouds/estimate_band.ply";

class CliEstimate : public rodshape::testing::CliTest {
 protected:
  fs::path write(const std::string& name, const std::string& text) const {
    const fs::path path = directory_ / name;
    std::ofstream(path) << text;
    return path;
  }
};

TEST_F(CliEstimate, TheBundledCloudIsExplained) {
  const fs::path out = directory_ / "est.json";
  const auto result = run("estimate " + quoted(kTask) + " --cloud " + quoted(kCloud) + " -o " +
                          quoted(out.string()));
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const Json j = Json::parse(read_file(out));
  EXPECT_EQ(j["status"], "converged");
  ASSERT_EQ(j["nodes"]["position"].size(), 51u);  // the equilibrium document's keys
  EXPECT_TRUE(j.contains("base_wrench") && j.contains("tip") && j.contains("energy"));
  const Json& fit = j["fit"];
  EXPECT_EQ(fit["explained"], true);
  EXPECT_EQ(fit["points"], 500);
  // 50 outliers were drawn in a box around the band; most lie far from its surface.
  EXPECT_GE(fit["rejected"].get<int>(), 30);
  EXPECT_LE(fit["rejected"].get<int>(), 60);
  EXPECT_EQ(fit["used"].get<int>() + fit["rejected"].get<int>(), 500);
  EXPECT_LT(fit["residual"].get<double>(), 1.5);
  EXPECT_EQ(fit["base_wrench_covariance"].size(), 6u);
  EXPECT_GT(fit["base_wrench_sigma"][0].get<double>(), 0.0);
  EXPECT_NE(result.out.find("500 points"), std::string::npos) << result.out;
}

TEST_F(CliEstimate, ACloudOfSomethingElseIsNotExplained) {
  // The band's cloud moved 5 cm along the camera's x: the clamped band cannot follow it.
  std::ifstream in(kCloud);
  std::string line, moved;
  bool body = false;
  while (std::getline(in, line)) {
    if (body) {
      double x, y, z;
      std::istringstream(line) >> x >> y >> z;
      moved += std::to_string(x + 0.05) + " " + std::to_string(y) + " " + std::to_string(z) + "\n";
    } else {
      moved += line + "\n";
      body = line == "end_header";
    }
  }
  const fs::path cloud = write("moved.ply", moved);
  const fs::path out = directory_ / "est.json";
  const auto result = run("estimate " + quoted(kTask) + " --cloud " + quoted(cloud.string()) +
                          " -o " + quoted(out.string()));
  ASSERT_EQ(result.exit_code, 3) << result.err;
  EXPECT_NE(result.err.find("does not explain the cloud"), std::string::npos) << result.err;
  const Json j = Json::parse(read_file(out));
  EXPECT_EQ(j["fit"]["explained"], false);
  EXPECT_NE(j["fit"]["message"].get<std::string>().find("does not explain"), std::string::npos);
}

TEST_F(CliEstimate, BadInputWritesNothing) {
  const fs::path out = directory_ / "est.json";
  const fs::path broken = write("broken.csv", "x,y,z\n0.1,0.2,1.0\n0.1,0.2\n");
  auto result = run("estimate " + quoted(kTask) + " --cloud " + quoted(broken.string()) + " -o " +
                    quoted(out.string()));
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("broken.csv: line 3: 2 fields, expected 3"), std::string::npos)
      << result.err;
  EXPECT_FALSE(fs::exists(out));
  // A task without a depth camera.
  const fs::path markers =
      write("band.yaml", read_file(kExamples + "/rubber_band.yaml") + "sensor: {markers: 10}\n");
  result = run("estimate " + quoted(markers.string()) + " --cloud " + quoted(kCloud) + " -o " +
               quoted(out.string()));
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("sensor.kind: depth"), std::string::npos) << result.err;
  EXPECT_FALSE(fs::exists(out));
  // The output is the cloud.
  result =
      run("estimate " + quoted(kTask) + " --cloud " + quoted(kCloud) + " -o " + quoted(kCloud));
  EXPECT_EQ(result.exit_code, 2);
  // No --cloud.
  EXPECT_EQ(run("estimate " + quoted(kTask)).exit_code, 2);
}

}  // namespace
}  // namespace test_cli_estimate
