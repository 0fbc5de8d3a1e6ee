// scene_json.cpp: the scene's part of plan.json.
#include "io/scene_json.hpp"

#include "overloaded.hpp"
#include "rodshape/robot/arm_clearance.hpp"

namespace rodshape::io_detail {

Json obstacle_json(const Obstacle& obstacle) {
  const ObstacleDescription description = obstacle.describe();
  Json json;
  json["shape"] = description.kind;
  json["name"] = description.name.empty() ? Json(nullptr) : Json(description.name);
  for (const ObstacleField& field : description.fields) {
    json[field.key] =
        std::visit(detail::Overloaded{[](double x) { return json_number(x); },
                                      [](const Eigen::Vector3d& v) { return json_vector(v); },
                                      [](const Eigen::Matrix3d& R) { return json_quaternion(R); }},
                   field.value);
  }
  return json;
}

Json scene_json(const Scene& scene, const std::optional<SceneResult>& result, bool two_arms) {
  // Two arms keep clear of each other with or without a scene: their gap is reported then too.
  if (scene.empty() && !(two_arms && result && result->robot)) return nullptr;
  Json json;
  json["clearance"] = json_number(scene.clearance);
  json["rod_radius"] = json_number(scene.rod_radius);
  Json obstacles = Json::array();
  for (const Obstacle& obstacle : scene.obstacles) obstacles.push_back(obstacle_json(obstacle));
  json["obstacles"] = std::move(obstacles);
  if (!result) return json;
  json["min_gap"] = json_number(result->min_gap);
  json["margin"] = json_number(result->margin);
  json["clear"] = result->clear();
  json["min_gap_at"] = nullptr;
  if (result->obstacle >= 0) {
    const std::string& name = scene.obstacles[static_cast<std::size_t>(result->obstacle)].name;
    json["min_gap_at"] = {{"step", result->step},
                          {"s", json_number(result->s)},
                          {"obstacle", name.empty() ? Json(result->obstacle) : Json(name)}};
  }
  json["obstacles_per_step"] = result->obstacles_per_step;
  json["detours"] = result->detours;
  if (result->robot) {  // with an arm that has collision geometry
    const RobotGapResult& robot = *result->robot;
    json["robot_min_gap"] = json_number(robot.min_gap);
    json["robot_margin"] = json_number(robot.margin);
    json["robot_clear"] = robot.clear();
    json["robot_min_gap_at"] = {
        {"sample", robot.sample},
        {"t", json_number(robot.t)},
        {"step", robot.step},
        {"link", robot.link},
        {"obstacle", robot.obstacle == kOtherArm   ? Json("other_arm")
                     : robot.obstacle < 0          ? Json("rod")
                     : robot.obstacle_name.empty() ? Json(robot.obstacle)
                                                   : Json(robot.obstacle_name)}};
    if (two_arms) {  // whose link (a plan with one arm keeps its document)
      json["robot_min_gap_at"]["arm"] = robot.arm;
      json["robot_min_gap_at"]["other_link"] =
          robot.obstacle == kOtherArm ? Json(robot.other_link) : Json(nullptr);
    }
  }
  return json;
}

}  // namespace rodshape::io_detail
