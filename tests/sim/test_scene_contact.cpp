// test_scene_contact.cpp: the plant against the plan's scene. A frame whose rod overlaps an
// obstacle opens one contact event (its first frame, the deepest overlap of the contact); leaving
// closes it, touching again opens another; the least gap is over every frame. In a validation, the
// bundled post example's plant keeps its gap (≥ the clearance, no contact); an obstacle the planner
// was not told of, on the plant's way, is a contact (status contact) naming it.
#include <gtest/gtest.h>

#include <string>

#include "rodshape/io/task_reader.hpp"
#include "rodshape/sim/plan_validation.hpp"
#include "rodshape/trajectory/plan.hpp"
#include "sim/scene_contact.hpp"

namespace rodshape {
namespace test_scene_contact {
namespace {

PlantFrame frame_along_z(double t, double x) {
  PlantFrame frame;
  frame.t = t;
  for (int i = 0; i <= 10; ++i) frame.configuration.p.emplace_back(x, 0.0, 0.01 * i);
  return frame;
}

TEST(SceneContact, OneEventPerContactWithItsDeepestOverlap) {
  Scene scene;
  scene.rod_radius = 0.002;
  scene.obstacles = {{"ball", SphereObstacle{{0.0, 0.0, 0.05}, 0.01}}};
  sim_detail::SceneContact contact(scene, Eigen::Vector3d::Zero());
  contact.see(frame_along_z(0.0, 0.03));    // gap 0.03 - 0.01 - 0.002 = 18 mm
  contact.see(frame_along_z(0.1, 0.011));   // overlap 1 mm
  contact.see(frame_along_z(0.2, 0.009));   // overlap 3 mm: the same contact
  contact.see(frame_along_z(0.3, 0.02));    // clear
  contact.see(frame_along_z(0.4, 0.0115));  // a second contact, 0.5 mm
  ASSERT_EQ(contact.contacts().size(), 2u);
  EXPECT_EQ(contact.contacts()[0].kind, PlantEvent::Kind::Contact);
  EXPECT_DOUBLE_EQ(contact.contacts()[0].t, 0.1);
  EXPECT_NEAR(contact.contacts()[0].depth, 0.003, 1e-15);
  EXPECT_EQ(contact.contacts()[0].obstacle, 0);
  EXPECT_NE(contact.contacts()[0].message.find("'ball'"), std::string::npos);
  EXPECT_DOUBLE_EQ(contact.contacts()[1].t, 0.4);
  EXPECT_NEAR(contact.contacts()[1].depth, 0.0005, 1e-15);
  EXPECT_NEAR(contact.min_gap(), -0.003, 1e-15);
}

// Issue 43, 4a: the message said the onset's overlap ("1 mm deep") where `depth` and the least
// gap say 3 mm; it says the deepest frame, when and where along the rod, as `depth` does.
TEST(SceneContact, TheMessageSaysTheDeepestFrameAsTheDepthDoes) {
  Scene scene;
  scene.rod_radius = 0.002;
  scene.obstacles = {{"ball", SphereObstacle{{0.0, 0.0, 0.05}, 0.01}}};
  sim_detail::SceneContact contact(scene, Eigen::Vector3d::Zero());
  contact.see(frame_along_z(0.1, 0.011));  // overlap 1 mm: the onset
  contact.see(frame_along_z(0.2, 0.009));  // overlap 3 mm, nearest at node 5 (s = 0.05 m)
  contact.see(frame_along_z(0.3, 0.010));  // 2 mm: shallower, the message keeps the deepest
  ASSERT_EQ(contact.contacts().size(), 1u);
  const PlantEvent& event = contact.contacts()[0];
  EXPECT_NEAR(event.depth, 0.003, 1e-15);
  EXPECT_NEAR(-contact.min_gap(), event.depth, 1e-15);
  EXPECT_NE(event.message.find("from t = 0.1 s"), std::string::npos) << event.message;
  EXPECT_NE(event.message.find("deepest 3 mm at t = 0.2 s, s = 0.05 m"), std::string::npos)
      << event.message;
  EXPECT_EQ(event.message.find("1 mm"), std::string::npos) << event.message;
}

TEST(SceneContact, ThePostExamplesPlantKeepsItsGapAndAnUnplannedObstacleIsAContact) {
  const PlanTask task =
      read_plan_task(std::string(RODSHAPE_SOURCE_DIR) + "/examples/plan_around_post.yaml");
  const PlanResult plan = rodshape::plan(task.problem, task.options);
  ASSERT_TRUE(plan.complete()) << plan.message;
  MarkerSensorModel sensor;
  sensor.frame_rate = 10.0;
  const ValidationResult clear = validate_plan(task.problem, plan, PlantModel{}, sensor);
  EXPECT_EQ(clear.status, ValidationStatus::Complete) << clear.message;
  ASSERT_EQ(clear.runs.size(), 1u);
  // The nominal plant is the planner's rod: its frames are states the tracking checked.
  EXPECT_GE(clear.runs[0].min_gap, task.problem.scene.clearance - SceneResult::kTolerance);

  PlanProblem unplanned = task.problem;
  // A ball where the final rod's middle node is: the plant ends inside it.
  const Eigen::Vector3d middle = plan.steps.back().solution.configuration.p[50];
  unplanned.scene.obstacles.push_back({"unplanned", SphereObstacle{middle, 0.005}});
  const ValidationResult hit = validate_plan(unplanned, plan, PlantModel{}, sensor);
  EXPECT_EQ(hit.status, ValidationStatus::Contact) << hit.message;
  EXPECT_NE(hit.message.find("'unplanned'"), std::string::npos) << hit.message;
  EXPECT_LT(hit.runs[0].min_gap, 0.0);
}

}  // namespace
}  // namespace test_scene_contact
}  // namespace rodshape
