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

std::optional<Eigen::Vector3d> nearest_held_position(const Eigen::Vector3d& clamp,
                                                     const TipCondition& tip) {
  if (const auto* held = std::get_if<ClampedTip>(&tip)) return held->pose.position;
  const auto* grasp = std::get_if<GraspedTip>(&tip);
  if (!grasp) return std::nullopt;
  Eigen::Vector3d position = grasp->pose.position;
  for (int i = 0; i < 3; ++i) {  // R_d e_i are orthonormal: remove each released component
    if (!grasp->released[static_cast<std::size_t>(i)]) continue;
    const Eigen::Vector3d axis = grasp->pose.rotation.col(i);
    position -= axis.dot(position - clamp) * axis;
  }
  return position;
}

void check_within_reach(const ClampedRod& rod,
                        const TipCondition& tip,
                        const ModelValidityLimits& limits,
                        const std::string& pose_field,
                        const std::string& limits_owner) {
  using detail::format_value;
  const std::optional<Eigen::Vector3d> held = nearest_held_position(rod.clamp.position, tip);
  if (!held) return;
  const double distance = (*held - rod.clamp.position).norm();
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
