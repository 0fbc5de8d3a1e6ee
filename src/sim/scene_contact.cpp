// scene_contact.cpp: see scene_contact.hpp.
#include "scene_contact.hpp"

#include <sstream>

namespace rodshape::sim_detail {

namespace {

/// The arc length at `t` along segment [p_i, p_{i+1}] (i = `segment`): the configuration's s
/// when it has one per node, else the polyline's length up to there.
double contact_arc_length(const RodConfiguration& rod, int segment, double t) {
  const auto i = static_cast<std::size_t>(segment);
  if (rod.s.size() == rod.p.size()) return rod.s[i] + t * (rod.s[i + 1] - rod.s[i]);
  double s = 0.0;
  for (std::size_t k = 0; k < i; ++k) s += (rod.p[k + 1] - rod.p[k]).norm();
  return s + t * (rod.p[i + 1] - rod.p[i]).norm();
}

/// "from t = 0.1 s the rod would touch obstacle 'ball', deepest 3 mm at t = 0.2 s, s = 0.05 m
/// along the rod": the onset, then the deepest frame of the contact (the event's depth).
std::string describe_contact(const PlantEvent& event,
                             const std::string& obstacle,
                             double deepest_t,
                             double deepest_s) {
  std::ostringstream message;
  message.precision(3);
  message << "from t = " << event.t << " s the rod would touch obstacle " << obstacle
          << ", deepest " << event.depth * 1e3 << " mm at t = " << deepest_t
          << " s, s = " << deepest_s << " m along the rod (the plant models no contact)";
  return message.str();
}

}  // namespace

SceneContact::SceneContact(const Scene& scene, const Eigen::Vector3d& clamp)
    : scene_(scene), required_(scene.required_gaps(clamp)), open_(scene.obstacles.size(), -1) {}

void SceneContact::see(const PlantFrame& frame) {
  const std::vector<Eigen::Vector3d>& p = frame.configuration.p;
  for (std::size_t j = 0; j < scene_.obstacles.size(); ++j) {
    const Obstacle& obstacle = scene_.obstacles[j];
    const SceneGap measured = scene_.obstacle_gap(j, p, required_[j]);
    const double gap = measured.gap;
    min_gap_ = std::min(min_gap_, gap);
    // The clamp's mount may be touched where the clamp itself touches it (its own gap).
    const bool touching = gap < std::min(0.0, required_[j]);
    if (!touching) {
      open_[j] = -1;
      continue;
    }
    const bool opens = open_[j] < 0;
    if (opens) {
      PlantEvent event;
      event.kind = PlantEvent::Kind::Contact;
      event.t = frame.t;
      event.obstacle = static_cast<int>(j);
      event.depth = -gap;
      open_[j] = static_cast<int>(contacts_.size());
      contacts_.push_back(event);
    }
    // The message says the deepest frame so far, as `depth` does.
    PlantEvent& event = contacts_[static_cast<std::size_t>(open_[j])];
    if (!opens && !(-gap > event.depth)) continue;
    event.depth = -gap;
    event.message =
        describe_contact(event, obstacle.label(static_cast<int>(j)), frame.t,
                         contact_arc_length(frame.configuration, measured.segment, measured.t));
  }
}

}  // namespace rodshape::sim_detail
