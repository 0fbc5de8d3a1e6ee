#include "rodshape/samples/rubber_band.hpp"

#include <Eigen/Geometry>
#include <numbers>

namespace rodshape::samples {

RodDescription rubber_band_description(ConstitutiveModel model) {
  RodDescription band;
  band.length = 0.29;  // m
  band.model = model;
  band.section = CrossSection::rectangle(0.02, 0.02);  // m
  band.material = Material{3.2e6, 0.5, 1392.0};        // E (Pa), ν, ρ (kg/m³)
  band.stiffness.EIx = 0.04;                           // N·m², identified
  band.stiffness.EIy = 0.04;
  band.stiffness.GJ = 0.028;
  return band;
}

ClampedRod rubber_band(ConstitutiveModel model, int intervals) {
  ClampedRod rod;
  rod.properties = make_rod_properties(rubber_band_description(model));
  rod.intervals = intervals;
  rod.validate();
  return rod;
}

Pose bent_tip() {
  Pose pose;
  pose.position = {0.12, 0.0, 0.22};
  pose.rotation =
      Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitY()).toRotationMatrix();
  return pose;
}

}  // namespace rodshape::samples
