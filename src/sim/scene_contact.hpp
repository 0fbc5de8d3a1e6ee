// scene_contact.hpp (private): the plant's rod against the plan's scene, frame by frame: its least
// gap, and a contact event where its surface would touch an obstacle (gap < 0). The plant models no
// contact force: the event says what a real rod would hit, when and how deep; one event per
// obstacle and contact, at its first frame, with the deepest penetration of that contact (its
// depth, and its message: the onset, then the deepest frame's time and arc length).
#pragma once

#include <limits>
#include <vector>

#include "rodshape/core/scene.hpp"
#include "rodshape/sim/plant.hpp"

namespace rodshape::sim_detail {

class SceneContact {
 public:
  /// `scene` may be empty (then nothing is measured); the clamp fixes the mount rule's gaps.
  SceneContact(const Scene& scene, const Eigen::Vector3d& clamp);
  /// Measures the frame's rod.
  void see(const PlantFrame& frame);
  /// The least gap over the frames seen (+inf without a scene), m.
  double min_gap() const { return min_gap_; }
  /// The contact events, in order.
  const std::vector<PlantEvent>& contacts() const { return contacts_; }

 private:
  const Scene& scene_;
  std::vector<double> required_;
  std::vector<int> open_;  // per obstacle: the index of its open contact event, or -1
  double min_gap_ = std::numeric_limits<double>::infinity();
  std::vector<PlantEvent> contacts_;
};

}  // namespace rodshape::sim_detail
