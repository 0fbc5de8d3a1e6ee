// scene_contact.cpp: see scene_contact.hpp.
#include "scene_contact.hpp"

#include <sstream>

namespace rodshape::sim_detail {

SceneContact::SceneContact(const Scene& scene, const Eigen::Vector3d& clamp)
    : scene_(scene), required_(scene.required_gaps(clamp)), open_(scene.obstacles.size(), -1) {}

void SceneContact::see(const PlantFrame& frame) {
  const std::vector<Eigen::Vector3d>& p = frame.configuration.p;
  for (std::size_t j = 0; j < scene_.obstacles.size(); ++j) {
    const Obstacle& obstacle = scene_.obstacles[j];
    const double gap = scene_.obstacle_gap(j, p, required_[j]).gap;
    min_gap_ = std::min(min_gap_, gap);
    // The clamp's mount may be touched where the clamp itself touches it (its own gap).
    const bool touching = gap < std::min(0.0, required_[j]);
    if (!touching) {
      open_[j] = -1;
      continue;
    }
    if (open_[j] >= 0) {  // the same contact, deeper or not
      PlantEvent& event = contacts_[static_cast<std::size_t>(open_[j])];
      event.depth = std::max(event.depth, -gap);
      continue;
    }
    std::ostringstream message;
    message.precision(3);
    message << "at t = " << frame.t << " s the rod would touch obstacle "
            << obstacle.label(static_cast<int>(j)) << ", " << -gap * 1e3
            << " mm deep (the plant models no contact)";
    PlantEvent event;
    event.kind = PlantEvent::Kind::Contact;
    event.t = frame.t;
    event.obstacle = static_cast<int>(j);
    event.depth = -gap;
    event.message = message.str();
    open_[j] = static_cast<int>(contacts_.size());
    contacts_.push_back(event);
  }
}

}  // namespace rodshape::sim_detail
