// contact_cases.hpp: the pieces the contact tests (tests/solvers/test_contact_*.cpp) and the
// contact benchmark share: a rod laid along world x, a heavy strip, touchable obstacles.
#pragma once

#include <Eigen/Core>
#include <string>

#include "rodshape/core/clamped_rod.hpp"
#include "rodshape/core/scene.hpp"

namespace rodshape::testing {

/// d1 = y, d2 = z, d3 = x: the rod's tangent along world x, its section's local y up.
inline Eigen::Matrix3d along_x() {
  Eigen::Matrix3d R;
  R.col(0) = Eigen::Vector3d::UnitY();
  R.col(1) = Eigen::Vector3d::UnitZ();
  R.col(2) = Eigen::Vector3d::UnitX();
  return R;
}

/// An obstacle the rod may rest on (contact: touch).
inline Obstacle touchable(const std::string& name, const ObstacleShape& shape) {
  Obstacle o;
  o.name = name;
  o.shape = shape;
  o.contact = ContactMode::Touch;
  return o;
}

/// A scene of one touchable table, solid below z = 0.
inline Scene table_scene(const std::string& name = "table") {
  Scene scene;
  scene.obstacles.push_back(touchable(name, HalfSpaceObstacle{-Eigen::Vector3d::UnitZ(), 0.0}));
  return scene;
}

/// What a heavy strip is: its length, bending stiffness (both axes; GJ = 0.8 EI), weight per
/// length and circular section's radius.
struct StripSpec {
  double length = 0.6;    // m
  double EI = 1e-3;       // N·m²
  double weight = 0.5;    // N/m
  double radius = 0.002;  // m
};

/// The strip clamped at `clamp` along x (stiff in shear and extension: 1e6 N).
inline ClampedRod heavy_strip(const StripSpec& spec,
                              ConstitutiveModel model,
                              const Eigen::Vector3d& clamp,
                              int intervals) {
  ClampedRod rod;
  rod.properties.length = spec.length;
  rod.properties.model = model;
  rod.properties.K_rot = Eigen::Vector3d(spec.EI, spec.EI, 0.8 * spec.EI);
  rod.properties.K_tra = Eigen::Vector3d(1e6, 1e6, 1e6);
  rod.properties.section = CrossSection::circle(spec.radius);
  rod.load.force = Eigen::Vector3d(0.0, 0.0, -spec.weight);
  rod.clamp = {clamp, along_x()};
  rod.intervals = intervals;
  return rod;
}

}  // namespace rodshape::testing
