// scene_section.cpp: the task file's `scene` section: clearance, margin, reach and the obstacles,
// each {shape, name?} and the fields of its shape (docs/task-file.md, "scene").
#include <string>

#include "io/plan_sections.hpp"
#include "io/task_sections.hpp"

namespace rodshape::io_detail {

namespace {

/// An obstacle's keys: its shape's, and those every obstacle has.
std::vector<std::string_view> keys(std::initializer_list<std::string_view> shape_keys) {
  std::vector<std::string_view> all = {"shape", "name", "contact", "friction"};
  all.insert(all.end(), shape_keys.begin(), shape_keys.end());
  return all;
}

ObstacleShape read_obstacle_shape(const YamlField& obstacle, const std::string& shape) {
  if (shape == "sphere") {
    obstacle.expect_mapping(keys({"center", "radius"}));
    return SphereObstacle{obstacle.require("center").vector3(),
                          obstacle.require("radius").number()};
  }
  if (shape == "box") {
    obstacle.expect_mapping(keys({"center", "size", "rotation"}));
    BoxObstacle box{obstacle.require("center").vector3(), obstacle.require("size").vector3(),
                    Eigen::Matrix3d::Identity()};
    if (const YamlField rotation = obstacle.get("rotation"); rotation.present())
      box.rotation = read_rotation(rotation);
    return box;
  }
  if (shape == "capsule") {
    obstacle.expect_mapping(keys({"from", "to", "radius"}));
    return CapsuleObstacle{obstacle.require("from").vector3(), obstacle.require("to").vector3(),
                           obstacle.require("radius").number()};
  }
  obstacle.expect_mapping(keys({"normal", "offset"}));
  return HalfSpaceObstacle{obstacle.require("normal").vector3(),
                           obstacle.require("offset").number()};
}

Obstacle read_obstacle(const YamlField& obstacle, int index) {
  if (!obstacle.present()) obstacle.fail(obstacle.path() + " is empty");
  // Any shape's keys first, so that a misspelt `shape` is named as such, not as missing.
  obstacle.expect_mapping(
      keys({"center", "radius", "size", "rotation", "from", "to", "normal", "offset"}));
  const std::string shape =
      obstacle.require("shape").choice({"sphere", "box", "capsule", "half_space"});
  Obstacle result;
  if (const YamlField name = obstacle.get("name"); name.present()) {
    result.name = name.text();
    if (result.name.empty() || result.name.size() > 100)
      name.fail_value("must have 1 to 100 characters");
  }
  result.shape = read_obstacle_shape(obstacle, shape);
  if (const YamlField contact = obstacle.get("contact"); contact.present())
    result.contact =
        contact.choice({"avoid", "touch"}) == "touch" ? ContactMode::Touch : ContactMode::Avoid;
  if (const YamlField friction = obstacle.get("friction"); friction.present())
    result.friction = friction.number();
  const std::string field = "Scene.obstacles[" + std::to_string(index) + "]";
  obstacle.located([&] { result.validate(field); });
  return result;
}

/// `scene.obstacles`: at most Scene::kMaxObstacles, each read and validated.
std::vector<Obstacle> read_obstacles(const YamlField& scene) {
  const YamlField obstacles = scene.require("obstacles");
  const std::vector<YamlField> elements = obstacles.elements();
  if (elements.size() > Scene::kMaxObstacles) {
    obstacles.fail(obstacles.path() + " has " + std::to_string(elements.size()) +
                   " entries; at most " + std::to_string(Scene::kMaxObstacles));
  }
  std::vector<Obstacle> result;
  for (std::size_t j = 0; j < elements.size(); ++j)
    result.push_back(read_obstacle(elements[j], static_cast<int>(j)));
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
  result.obstacles = read_obstacles(scene);
  scene.located([&] { result.validate(); });
  const std::vector<YamlField> elements = scene.require("obstacles").elements();
  for (std::size_t j = 0; j < elements.size(); ++j)
    if (result.obstacles[j].touchable())
      elements[j].require("contact").fail_value(
          "is solved by equilibrium tasks so far (rodshape equilibrium): a plan keeps the scene's "
          "clearance from every obstacle; give contact: avoid");
  return result;
}

Scene read_equilibrium_scene(const YamlField& scene, const std::optional<CrossSection>& section) {
  scene.expect_mapping({"obstacles"});
  Scene result;
  result.clearance = 0.0;
  result.rod_radius = section ? section->circumscribed_radius() : 0.0;
  result.obstacles = read_obstacles(scene);
  const std::vector<YamlField> elements = scene.require("obstacles").elements();
  for (std::size_t j = 0; j < elements.size(); ++j) {
    if (!result.obstacles[j].touchable())
      elements[j].fail(elements[j].path() +
                       ".contact: an equilibrium rests on its obstacles: give contact: touch "
                       "(avoid, the default, is for plans, which keep a clearance)");
  }
  if (!section)
    scene.fail(scene.path() + " needs rod.section: the rod's surface is what rests on an obstacle");
  scene.located([&] { result.validate(); });
  return result;
}

}  // namespace rodshape::io_detail
