// scene_section.cpp: the task file's `scene` section: clearance, margin, reach and the obstacles,
// each {shape, name?} and the fields of its shape (docs/task-file.md, "scene").
#include <string>

#include "io/plan_sections.hpp"
#include "io/task_sections.hpp"

namespace rodshape::io_detail {

namespace {

ObstacleShape read_obstacle_shape(const YamlField& obstacle, const std::string& shape) {
  if (shape == "sphere") {
    obstacle.expect_mapping({"shape", "name", "center", "radius"});
    return SphereObstacle{obstacle.require("center").vector3(),
                          obstacle.require("radius").number()};
  }
  if (shape == "box") {
    obstacle.expect_mapping({"shape", "name", "center", "size", "rotation"});
    BoxObstacle box{obstacle.require("center").vector3(), obstacle.require("size").vector3(),
                    Eigen::Matrix3d::Identity()};
    if (const YamlField rotation = obstacle.get("rotation"); rotation.present())
      box.rotation = read_rotation(rotation);
    return box;
  }
  if (shape == "capsule") {
    obstacle.expect_mapping({"shape", "name", "from", "to", "radius"});
    return CapsuleObstacle{obstacle.require("from").vector3(), obstacle.require("to").vector3(),
                           obstacle.require("radius").number()};
  }
  obstacle.expect_mapping({"shape", "name", "normal", "offset"});
  return HalfSpaceObstacle{obstacle.require("normal").vector3(),
                           obstacle.require("offset").number()};
}

Obstacle read_obstacle(const YamlField& obstacle, int index) {
  if (!obstacle.present()) obstacle.fail(obstacle.path() + " is empty");
  const std::string shape =
      obstacle.require("shape").choice({"sphere", "box", "capsule", "half_space"});
  Obstacle result;
  if (const YamlField name = obstacle.get("name"); name.present()) {
    result.name = name.text();
    if (result.name.empty() || result.name.size() > 100)
      name.fail_value("must have 1 to 100 characters");
  }
  result.shape = read_obstacle_shape(obstacle, shape);
  const std::string field = "Scene.obstacles[" + std::to_string(index) + "]";
  obstacle.located([&] { result.validate(field); });
  return result;
}

}  // namespace

Scene read_scene_section(const YamlField& scene,
                         const std::optional<CrossSection>& section,
                         PlanOptions& options) {
  scene.expect_mapping({"clearance", "margin", "reach", "detour", "obstacles"});
  if (!section) {
    scene.fail(scene.path() +
               " needs rod.section, which is missing: the rod's surface (its centreline inflated "
               "by the section's circumscribed radius) is what keeps the clearance");
  }
  Scene result;
  result.rod_radius = section->circumscribed_radius();
  if (const YamlField clearance = scene.get("clearance"); clearance.present())
    result.clearance = clearance.number();
  if (const YamlField margin = scene.get("margin"); margin.present())
    options.scene_margin = margin.number();
  if (const YamlField reach = scene.get("reach"); reach.present())
    options.scene_reach = reach.number();
  if (const YamlField detour = scene.get("detour"); detour.present())
    options.scene_detour = detour.boolean();
  const YamlField obstacles = scene.require("obstacles");
  const std::vector<YamlField> elements = obstacles.elements();
  if (elements.size() > Scene::kMaxObstacles) {
    obstacles.fail(obstacles.path() + " has " + std::to_string(elements.size()) +
                   " entries; at most " + std::to_string(Scene::kMaxObstacles));
  }
  for (std::size_t j = 0; j < elements.size(); ++j)
    result.obstacles.push_back(read_obstacle(elements[j], static_cast<int>(j)));
  scene.located([&] { result.validate(); });
  return result;
}

}  // namespace rodshape::io_detail
