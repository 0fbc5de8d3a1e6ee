// test_result_json.cpp: the result document on a hand-made solution: every documented key, arrays
// of the configuration's size, quaternions [w, x, y, z], null for what is unknown or not finite.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <limits>
#include <string>

#include "rodshape/core/so3.hpp"
#include "rodshape/io/result_json.hpp"

namespace rodshape {
namespace test_result_json {
namespace {

using Json = nlohmann::json;

/// A 3-node configuration bent about y, as if integrated.
ShootingResult make_solution() {
  ShootingResult solution;
  solution.summary.status = SolveStatus::Converged;
  solution.summary.message = "converged";
  solution.summary.iterations = 4;
  solution.summary.integrations = 5;
  solution.summary.continuation_steps = 0;
  solution.summary.residual_norm = 2.5e-13;
  solution.base_wrench = {Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(4, 5, 6)};
  RodConfiguration& c = solution.configuration;
  for (int i = 0; i < 3; ++i) {
    c.s.push_back(0.5 * i);
    c.p.emplace_back(0.1 * i, 0.0, 0.5 * i);
    c.R.push_back(exp_so3(Eigen::Vector3d(0, 0.3 * i, 0)));
    c.n.emplace_back(1, 2, 3);
    c.m.emplace_back(4, 5, 6 + i);
    c.u.emplace_back(0, 0.6, 0);
    c.v.emplace_back(0, 0, 1);
  }
  c.energy = 0.125;
  return solution;
}

ClampedRod make_rod() {
  ClampedRod rod;
  rod.properties.length = 1.0;
  rod.intervals = 2;
  return rod;
}

TEST(ResultJson, HasEveryDocumentedKeyWithConsistentSizes) {
  StabilityResult stability;
  stability.stable = true;
  stability.min_singular_value = 0.25;
  stability.tip_singular_value = 0.5;
  const Json j = Json::parse(equilibrium_result_json(make_solution(), stability, make_rod()));

  for (const char* key :
       {"status", "message", "residual", "iterations", "integrations", "continuation_steps",
        "model", "energy", "stable", "stability", "base_wrench", "tip_wrench", "tip", "nodes"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j["status"], "converged");
  EXPECT_EQ(j["model"], "cosserat");
  EXPECT_EQ(j["residual"].get<double>(), 2.5e-13);
  EXPECT_EQ(j["iterations"], 4);
  EXPECT_EQ(j["energy"].get<double>(), 0.125);
  EXPECT_EQ(j["stable"], true);
  EXPECT_EQ(j["stability"]["stable"], true);
  EXPECT_TRUE(j["stability"]["conjugate_point_s"].is_null());
  EXPECT_EQ(j["stability"]["min_singular_value"].get<double>(), 0.25);
  EXPECT_EQ(j["base_wrench"]["moment"], Json::array({4.0, 5.0, 6.0}));
  EXPECT_EQ(j["tip_wrench"]["moment"], Json::array({4.0, 5.0, 8.0}));
  EXPECT_EQ(j["tip"]["position"], Json::array({0.2, 0.0, 1.0}));

  // The tip's rotation, 0.6 rad about y, as [w, x, y, z].
  const Json& q = j["tip"]["rotation"];
  ASSERT_EQ(q.size(), 4u);
  EXPECT_NEAR(q[0].get<double>(), std::cos(0.3), 1e-15);
  EXPECT_NEAR(q[2].get<double>(), std::sin(0.3), 1e-15);

  const Json& nodes = j["nodes"];
  for (const char* key : {"s", "position", "rotation", "force", "moment", "u", "v"}) {
    ASSERT_TRUE(nodes.contains(key)) << key;
    EXPECT_EQ(nodes[key].size(), 3u) << key;
  }
  EXPECT_EQ(nodes["rotation"][1].size(), 4u);
  EXPECT_EQ(nodes["u"][2], Json::array({0.0, 0.6, 0.0}));
}

TEST(ResultJson, UnassessedStabilityAndNonFiniteNumbersAreNull) {
  ShootingResult solution = make_solution();
  solution.summary.status = SolveStatus::Diverged;
  solution.summary.residual_norm = std::numeric_limits<double>::quiet_NaN();
  solution.configuration.energy = std::numeric_limits<double>::infinity();
  const Json j = Json::parse(equilibrium_result_json(solution, std::nullopt, make_rod()));
  EXPECT_EQ(j["status"], "diverged");
  EXPECT_TRUE(j["residual"].is_null());
  EXPECT_TRUE(j["energy"].is_null());
  EXPECT_TRUE(j["stable"].is_null());
  EXPECT_TRUE(j["stability"].is_null());
}

TEST(ResultJson, NumbersRoundTripExactly) {
  ShootingResult solution = make_solution();
  solution.configuration.p[1] = Eigen::Vector3d(0.1 + 0.2, 1.0 / 3.0, -2.0e-300);
  const Json j = Json::parse(equilibrium_result_json(solution, std::nullopt, make_rod()));
  EXPECT_EQ(j["nodes"]["position"][1][0].get<double>(), 0.1 + 0.2);
  EXPECT_EQ(j["nodes"]["position"][1][1].get<double>(), 1.0 / 3.0);
  EXPECT_EQ(j["nodes"]["position"][1][2].get<double>(), -2.0e-300);
}

}  // namespace
}  // namespace test_result_json
}  // namespace rodshape

namespace rodshape {
namespace test_result_json {
namespace {

TEST(ResultJson, ReportsTheLargestStrainsAndTheAccuracyOfTheShape) {
  // make_solution(): u = (0, 0.6, 0), v = (0, 0, 1) at every node except the tip, which is
  // stretched by 0.2 and sheared by -0.05 here.
  ShootingResult solution = make_solution();
  solution.configuration.v.back() = Eigen::Vector3d(-0.05, 0.0, 1.2);
  solution.summary.integration_error = 3e-9;
  solution.summary.substeps = 4;
  const Json j = Json::parse(equilibrium_result_json(solution, std::nullopt, make_rod()));
  ASSERT_TRUE(j.contains("strain"));
  EXPECT_DOUBLE_EQ(j["strain"]["max_axial"].get<double>(), 0.2);
  EXPECT_DOUBLE_EQ(j["strain"]["max_shear"].get<double>(), 0.05);
  EXPECT_DOUBLE_EQ(j["strain"]["max_curvature"].get<double>(), 0.6);
  EXPECT_EQ(j["integration_error"].get<double>(), 3e-9);
  EXPECT_EQ(j["substeps"].get<int>(), 4);
}

TEST(ResultJson, FreeTipStabilityCarriesTheTipStiffnessEigenvalue) {
  StabilityResult stability;
  stability.stable = false;
  stability.tip_stiffness_eigenvalue = -0.25;
  const Json j = Json::parse(equilibrium_result_json(make_solution(), stability, make_rod()));
  EXPECT_EQ(j["stable"], false);
  EXPECT_EQ(j["stability"]["tip_stiffness_eigenvalue"].get<double>(), -0.25);
}

TEST(ResultJson, StrainsOfANonFiniteShapeAreNull) {
  ShootingResult solution = make_solution();
  solution.summary.status = SolveStatus::NonFinite;
  solution.configuration.p[1].x() = std::numeric_limits<double>::quiet_NaN();
  const Json j = Json::parse(equilibrium_result_json(solution, std::nullopt, make_rod()));
  EXPECT_EQ(j["status"], "non_finite");
  EXPECT_TRUE(j["strain"]["max_axial"].is_null());
  EXPECT_TRUE(j["integration_error"].is_null());
}

}  // namespace
}  // namespace test_result_json
}  // namespace rodshape
