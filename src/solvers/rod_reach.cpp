// rod_reach.cpp: the farthest tip of a rod within its model's range (rod_reach.hpp).
#include "rodshape/solvers/rod_reach.hpp"

#include <cmath>

#include "rodshape/error.hpp"
#include "validation.hpp"

namespace rodshape {

double max_tip_distance(const RodProperties& properties, const ModelValidityLimits& limits) {
  const Eigen::Vector3d& v_rest = properties.v_rest;
  if (properties.model == ConstitutiveModel::Kirchhoff) return properties.length * v_rest.norm();
  const Eigen::Vector3d largest_v(std::abs(v_rest.x()) + limits.max_shear_strain,
                                  std::abs(v_rest.y()) + limits.max_shear_strain,
                                  std::abs(v_rest.z()) + limits.max_axial_strain);
  return properties.length * largest_v.norm();
}

void check_within_reach(const ClampedRod& rod,
                        const Eigen::Vector3d& tip,
                        const ModelValidityLimits& limits,
                        const std::string& pose_field,
                        const std::string& limits_owner) {
  using detail::format_value;
  const double distance = (tip - rod.clamp.position).norm();
  const double reach = max_tip_distance(rod.properties, limits);
  // Round-off of the distance only: a Kirchhoff rod held straight is exactly at its reach.
  if (!(distance > reach * (1.0 + 1e-12))) return;
  const std::string how = rod.properties.model == ConstitutiveModel::Kirchhoff
                              ? "an inextensible rod (RodProperties.model = kirchhoff) of length " +
                                    format_value(rod.properties.length) + " m"
                              : "a rod of length " + format_value(rod.properties.length) +
                                    " m, stretched by at most " + limits_owner +
                                    ".max_axial_strain = " + format_value(limits.max_axial_strain) +
                                    " and sheared by at most " + limits_owner +
                                    ".max_shear_strain = " + format_value(limits.max_shear_strain);
  throw InputError(pose_field, ": the position is " + format_value(distance) +
                                   " m from the clamp, out of reach: " + how + " reaches at most " +
                                   format_value(reach) + " m");
}

}  // namespace rodshape
