// test_bundled_arm_names.cpp: `robot.urdf` naming a bundled arm ("fr3", "panda") instead of a file:
// each loads with its links and Franka's limits, a file path still reads the file, and a misspelt
// name is one line naming the field and the known names.
#include <gtest/gtest.h>

#include <string>

#include "rodshape/io/task_reader.hpp"
#include "support/input_error.hpp"

namespace rodshape {
namespace test_bundled_arm_names {
namespace {

// The robot section starts at line 12.
const std::string kPlan = R"(rod:
  length: 0.29
  nodes: 51
  section: {shape: rectangle, width: 0.02, height: 0.02}
  material: {young_modulus: 3.2e6, poisson_ratio: 0.5, density: 1392}
  stiffness: {EIx: 0.04, EIy: 0.04, GJ: 0.028}
target:
  points:
    - [0.126, 0.000, 0.133]
trajectory:
  steps: 3
robot:
  urdf: )";

PlanTask task_with(const std::string& urdf, const std::string& more = "") {
  return parse_plan_task(kPlan + urdf + "\n" + more, "plan.yaml");
}

std::string error_of(const std::string& urdf) {
  const std::string message = testing::input_error_message([&] { task_with(urdf); });
  EXPECT_EQ(message.find('\n'), std::string::npos) << "not one line: " << message;
  return message;
}

TEST(BundledArmNames, Fr3AndPandaLoad) {
  const PlanTask fr3 = task_with("fr3");
  ASSERT_TRUE(fr3.problem.arm.has_value());
  EXPECT_EQ(fr3.problem.arm->model.robot_name(), "fr3");
  EXPECT_EQ(fr3.problem.arm->model.base_link(), "fr3_link0");
  EXPECT_EQ(fr3.problem.arm->model.tip_link(), "fr3_link8");
  EXPECT_EQ(fr3.problem.arm->model.upper_limits()(5), 4.5169);
  EXPECT_EQ(fr3.problem.arm->model.jerk_limits()(0), 5000.0);
  EXPECT_TRUE(fr3.input_files.empty());  // no file was read

  const PlanTask panda = task_with("panda", "  tip_link: panda_link8\n");
  ASSERT_TRUE(panda.problem.arm.has_value());
  EXPECT_EQ(panda.problem.arm->model.robot_name(), "panda");
  EXPECT_EQ(panda.problem.arm->model.tip_link(), "panda_link8");
  EXPECT_EQ(panda.problem.arm->model.acceleration_limits()(1), 7.5);
}

TEST(BundledArmNames, AFilePathStillReadsTheFile) {
  const PlanTask task = task_with(std::string(RODSHAPE_SOURCE_DIR) + "/data/robots/fr3.urdf");
  ASSERT_TRUE(task.problem.arm.has_value());
  EXPECT_EQ(task.problem.arm->model.robot_name(), "fr3");
  EXPECT_EQ(task.input_files.size(), 1u);
}

TEST(BundledArmNames, AMisspeltNameIsNamedWithTheKnownNames) {
  EXPECT_EQ(error_of("fr4"),
            "plan.yaml:13: robot.urdf: 'fr4' is neither a bundled arm (fr3, panda) nor a URDF "
            "file; did you mean 'fr3'?");
  EXPECT_EQ(error_of("kuka"),
            "plan.yaml:13: robot.urdf: 'kuka' is neither a bundled arm (fr3, panda) nor a URDF "
            "file");
}

TEST(BundledArmNames, ABadLinkOfABundledArmIsNamedAtItsField) {
  const std::string message =
      testing::input_error_message([&] { task_with("fr3", "  tip_link: panda_link8\n"); });
  EXPECT_EQ(message.rfind("plan.yaml:14: robot.tip_link: the bundled FR3 URDF: unknown tip link "
                          "'panda_link8'",
                          0),
            0u)
      << message;
}

}  // namespace
}  // namespace test_bundled_arm_names
}  // namespace rodshape
