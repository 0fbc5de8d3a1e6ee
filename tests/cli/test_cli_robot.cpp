// test_cli_robot.cpp: `rodshape fk` and `rodshape ik` as a user runs them: JSON on stdout, exit 0;
// bad URDFs, links, joint vectors and quaternions give one line on stderr and exit 2; a pose out of
// reach gives exit 3 with the JSON still printed.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <nlohmann/json.hpp>

#include "support/cli_runner.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace test_cli_robot {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

const std::string kPanda = std::string(RODSHAPE_SOURCE_DIR) + "/data/robots/panda.urdf";
const std::string kReady =
    "0 -0.7853981633974483 0 -2.356194490192345 0 1.5707963267948966 0.7853981633974483";

using Outcome = rodshape::testing::CliOutcome;
using rodshape::testing::quoted;

class CliRobot : public rodshape::testing::CliTest {
 protected:
  /// Writes a file and returns its path quoted for the shell.
  std::string write(const std::string& name, const std::string& text) const {
    return quoted(write_task(name, text).string());
  }
};

TEST_F(CliRobot, FkPrintsTheFlangePoseAtTheReadyPose) {
  const Outcome outcome = run("fk " + quoted(kPanda) + " " + kReady);
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  EXPECT_TRUE(outcome.err.empty()) << outcome.err;
  const Json json = Json::parse(outcome.out);
  ASSERT_EQ(json["position"].size(), 3u);
  ASSERT_EQ(json["rotation"].size(), 4u);
  EXPECT_NEAR(json["position"][0].get<double>(), 0.306891, 1e-6);
  EXPECT_NEAR(json["position"][1].get<double>(), 0.0, 1e-12);
  EXPECT_NEAR(json["position"][2].get<double>(), 0.590282, 1e-6);
  // Pointing down, turned by -π/4 about z: [w, x, y, z] = [0, cos(π/8), -sin(π/8), 0].
  EXPECT_NEAR(json["rotation"][0].get<double>(), 0.0, 1e-12);
  EXPECT_NEAR(json["rotation"][1].get<double>(), 0.9238795325112867, 1e-12);
  EXPECT_NEAR(json["rotation"][2].get<double>(), -0.3826834323650898, 1e-12);
  EXPECT_NEAR(json["rotation"][3].get<double>(), 0.0, 1e-12);
}

TEST_F(CliRobot, FkTakesABundledArmsName) {
  const Outcome outcome = run("fk fr3 " + kReady);  // the FR3's chain is the Panda's
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  const Json json = Json::parse(outcome.out);
  EXPECT_NEAR(json["position"][0].get<double>(), 0.306891, 1e-6);
  EXPECT_NEAR(json["position"][2].get<double>(), 0.590282, 1e-6);
  const Outcome misspelt = run("fk fr4 " + kReady);
  EXPECT_EQ(misspelt.exit_code, 2);
  EXPECT_NE(misspelt.err.find("'fr4' is neither a bundled arm (fr3, panda) nor a URDF file"),
            std::string::npos)
      << misspelt.err;
}

TEST_F(CliRobot, FkBaseAndTipChooseASubChain) {
  const Outcome outcome =
      run("fk " + quoted(kPanda) + " --base panda_link0 --tip panda_link2 0.3 -0.5");
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  const Json json = Json::parse(outcome.out);
  EXPECT_NEAR(json["position"][2].get<double>(), 0.333, 1e-12);
}

TEST_F(CliRobot, IkRoundTripsThroughFk) {
  const std::string q = "0.4 -0.3 0.2 -2.0 0.3 1.9 -0.5";
  const Outcome fk = run("fk " + quoted(kPanda) + " " + q);
  ASSERT_EQ(fk.exit_code, 0) << fk.err;
  const Json pose = Json::parse(fk.out);
  std::ostringstream target;
  target.precision(17);
  for (const auto& value : pose["position"]) target << value.get<double>() << " ";
  for (const auto& value : pose["rotation"]) target << value.get<double>() << " ";

  const Outcome ik = run("ik " + quoted(kPanda) + " " + target.str() + "--seed " + q);
  ASSERT_EQ(ik.exit_code, 0) << ik.err;
  const Json solution = Json::parse(ik.out);
  EXPECT_EQ(solution["status"], "converged");
  EXPECT_EQ(solution["iterations"], 0);  // the seed is the answer
  ASSERT_EQ(solution["q"].size(), 7u);

  const Outcome from_ready = run("ik " + quoted(kPanda) + " " + target.str());
  ASSERT_EQ(from_ready.exit_code, 0) << from_ready.err;
  const Json answer = Json::parse(from_ready.out);
  EXPECT_EQ(answer["status"], "converged");
  std::ostringstream q_found;
  q_found.precision(17);
  for (const auto& value : answer["q"]) q_found << value.get<double>() << " ";
  const Json back = Json::parse(run("fk " + quoted(kPanda) + " " + q_found.str()).out);
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(back["position"][i].get<double>(), pose["position"][i].get<double>(), 1e-9);
}

TEST_F(CliRobot, IkOutOfReachExitsThreeWithTheJsonStillPrinted) {
  const Outcome outcome = run("ik " + quoted(kPanda) + " 2 0 0.5 0 1 0 0");
  EXPECT_EQ(outcome.exit_code, 3);
  const Json json = Json::parse(outcome.out);
  EXPECT_EQ(json["status"], "out_of_reach");
  EXPECT_NE(json["message"].get<std::string>().find("out of reach"), std::string::npos);
  EXPECT_NE(outcome.err.find("out of reach"), std::string::npos) << outcome.err;
}

struct BadRun {
  const char* name;
  std::string arguments;
  const char* message;
};

TEST_F(CliRobot, BadInputGivesOneLineAndExitTwo) {
  const std::string panda = quoted(kPanda);
  const std::string garbage = write("garbage.urdf", "this is not a robot");
  const std::string floating = write(
      "floating.urdf",
      "<robot name=\"f\"><link name=\"a\"/><link name=\"b\"/><joint name=\"j\" type=\"floating\">"
      "<parent link=\"a\"/><child link=\"b\"/></joint></robot>");
  const std::string loop =
      write("loop.urdf",
            "<robot name=\"l\"><link name=\"a\"/><link name=\"b\"/>"
            "<joint name=\"j1\" type=\"continuous\"><parent link=\"a\"/><child link=\"b\"/></joint>"
            "<joint name=\"j2\" type=\"continuous\"><parent link=\"b\"/><child link=\"a\"/></joint>"
            "</robot>");
  const std::vector<BadRun> cases = {
      {"missing file", "fk /nonexistent/panda.urdf 0", "cannot read the URDF file"},
      {"not a urdf", "fk " + garbage + " 0", "the URDF does not parse"},
      {"floating joint", "fk " + floating + " 0", "joint 'j' is floating"},
      {"closed loop", "fk " + loop + " 0", "closed loop"},
      {"unknown tip", "fk " + panda + " --tip panda_hand " + kReady,
       "unknown tip link 'panda_hand'"},
      {"unknown base", "ik " + panda + " --base base 0.3 0 0.5 0 1 0 0",
       "unknown base link 'base'"},
      {"too few joints", "fk " + panda + " 0 0 0", "q has 3 values but the chain"},
      {"beyond a limit", "fk " + panda + " 0 0 0 0 0 0 0",
       "outside the limits of joint 'panda_joint4'"},
      {"seed size", "ik " + panda + " 0.3 0 0.5 0 1 0 0 --seed 0 0", "--seed has 2 values"},
      {"seed beyond a limit", "ik " + panda + " 0.3 0 0.5 0 1 0 0 --seed 3 0 0 -1 0 1 0",
       "--seed[0] = 3 is outside the limits of joint 'panda_joint1'"},
      {"not a unit quaternion", "ik " + panda + " 0.3 0 0.5 0 2 0 0",
       "has norm 2; it must be 1 within 1e-6"},
      {"short pose", "ik " + panda + " 0.3 0 0.5", "pose"},
  };
  for (const BadRun& bad : cases) {
    SCOPED_TRACE(bad.name);
    const Outcome outcome = run(bad.arguments);
    EXPECT_EQ(outcome.exit_code, 2) << outcome.err;
    EXPECT_NE(outcome.err.find(bad.message), std::string::npos) << outcome.err;
    EXPECT_EQ(std::count(outcome.err.begin(), outcome.err.end(), '\n'), 1) << outcome.err;
    EXPECT_TRUE(outcome.out.empty()) << outcome.out;
  }
}

}  // namespace
}  // namespace test_cli_robot
