// plant_model.cpp: the real rod from the planner's, with the plant's parameters.
#include "rodshape/sim/plant_model.hpp"

#include "rodshape/core/physical_bounds.hpp"
#include "rodshape/error.hpp"
#include "validation.hpp"

namespace rodshape {

void PlantModel::validate() const {
  detail::require_positive("PlantModel.stiffness_scale", stiffness_scale);
  detail::require_positive("PlantModel.factors.EA", factors.EA);
  detail::require_positive("PlantModel.factors.GA", factors.GA);
  detail::require_positive("PlantModel.factors.EIx", factors.EIx);
  detail::require_positive("PlantModel.factors.EIy", factors.EIy);
  detail::require_positive("PlantModel.factors.GJ", factors.GJ);
  if (length) detail::require_positive("PlantModel.length", *length);
  if (length) require_in_range("PlantModel.length", *length, bounds::kLength);
  if (mass_per_length) detail::require_non_negative("PlantModel.mass_per_length", *mass_per_length);
  if (mass_per_length)
    require_in_range("PlantModel.mass_per_length", *mass_per_length, bounds::kMassPerLength);
  if (gravity)
    require_magnitude_at_most("PlantModel.gravity", *gravity, bounds::kMaxGravity, "m/s^2");
  require_magnitude_at_most("PlantModel.planner_gravity", planner_gravity, bounds::kMaxGravity,
                            "m/s^2");
  if (rest_curvature) detail::require_finite("PlantModel.rest_curvature", *rest_curvature);
  detail::require_pose("PlantModel.grasp_offset", grasp_offset);
}

ClampedRod PlantModel::real_rod(const ClampedRod& planned) const {
  validate();
  ClampedRod rod = planned;
  RodProperties& k = rod.properties;
  // K_tra = diag(GA, GA, EA), K_rot = diag(EIx, EIy, GJ)
  k.K_tra =
      stiffness_scale * k.K_tra.cwiseProduct(Eigen::Vector3d(factors.GA, factors.GA, factors.EA));
  k.K_rot =
      stiffness_scale * k.K_rot.cwiseProduct(Eigen::Vector3d(factors.EIx, factors.EIy, factors.GJ));
  if (length) k.length = *length;
  if (mass_per_length) k.mass_per_length = *mass_per_length;
  if (rest_curvature) k.u_rest = *rest_curvature;
  const Eigen::Vector3d g = acting_gravity();
  if (!g.isZero() && !mass_per_length && !(k.mass_per_length > 0.0))
    throw InputError(
        gravity ? "PlantModel.gravity" : "PlantModel.planner_gravity",
        ": the rod's mass per length is not known (give PlantModel.mass_per_length, or "
        "a density for the planner's rod)");
  // One gravity acts on the real rod: its weight f = ρA g replaces the planner's
  // (docs/task-file.md, "plant"). Where both are the same the difference is exactly zero.
  rod.load.force += k.mass_per_length * g - planned.properties.mass_per_length * planner_gravity;
  rod.validate();
  return rod;
}

}  // namespace rodshape
