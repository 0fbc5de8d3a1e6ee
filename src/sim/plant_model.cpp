// plant_model.cpp: the real rod from the planner's, with the plant's parameters.
#include "rodshape/sim/plant_model.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "rodshape/core/physical_bounds.hpp"
#include "rodshape/error.hpp"
#include "rodshape/sim/plant_factory.hpp"
#include "validation.hpp"

namespace rodshape {

namespace {

using detail::format_value;

/// One of the plant's five stiffnesses: planned × stiffness_scale × its factor.
struct PlantStiffness {
  const char* name;  // "EIx"
  const char* unit;  // "N*m^2"
  double planned;    // the planner's
  double factor;     // PlantModel::factors'
};

/// Each stiffness of the plant's rod, scale × factor × the planner's, within bounds::kStiffness,
/// or InputError naming the plant's field that took it out (issue 43: `plant.stiffness_scale:
/// 1e300` was reported as the planner's `rod.stiffness.EIx`): the scale unless it is 1, else the
/// factor, with the range that field may take for this rod.
void check_plant_stiffnesses(const PlantModel& plant, const RodProperties& planned) {
  const StiffnessFactors& f = plant.factors;
  const std::array<PlantStiffness, 5> all = {{
      {"EIx", "N*m^2", planned.K_rot.x(), f.EIx},
      {"EIy", "N*m^2", planned.K_rot.y(), f.EIy},
      {"GJ", "N*m^2", planned.K_rot.z(), f.GJ},
      {"GA", "N", planned.K_tra.x(), f.GA},
      {"EA", "N", planned.K_tra.z(), f.EA},
  }};
  const PhysicalRange& range = bounds::kStiffness;
  // The scale's range: every stiffness within bounds, s × K × f ∈ [min, max].
  double scale_min = 0.0, scale_max = std::numeric_limits<double>::infinity();
  for (const PlantStiffness& k : all) {
    if (!std::isfinite(k.planned)) continue;  // a Kirchhoff rod's K_tra "not given" (+inf)
    scale_min = std::max(scale_min, range.min / (k.planned * k.factor));
    scale_max = std::min(scale_max, range.max / (k.planned * k.factor));
  }
  for (const PlantStiffness& k : all) {
    if (!std::isfinite(k.planned)) continue;
    const double value = plant.stiffness_scale * k.planned * k.factor;
    if (value >= range.min && value <= range.max) continue;
    const std::string factor = k.factor != 1.0 ? format_value(k.factor) + " x " : "";
    const std::string made = std::string(k.name) + " = " + format_value(plant.stiffness_scale) +
                             " x " + factor + "the planner's " + format_value(k.planned) + " " +
                             k.unit + " = " + format_value(value) + " " + k.unit + ", outside [" +
                             format_value(range.min) + ", " + format_value(range.max) + "] " +
                             k.unit;
    if (plant.stiffness_scale != 1.0 || k.factor == 1.0)
      throw InputError("PlantModel.stiffness_scale",
                       " = " + format_value(plant.stiffness_scale) + " makes the plant's " + made +
                           "; with this rod (and these factors) it must be in [" +
                           format_value(scale_min) + ", " + format_value(scale_max) +
                           "] (docs/limits.md)");
    const double base = plant.stiffness_scale * k.planned;
    throw InputError(std::string("PlantModel.factors.") + k.name,
                     " = " + format_value(k.factor) + " makes the plant's " + made +
                         "; with this rod it must be in [" + format_value(range.min / base) + ", " +
                         format_value(range.max / base) + "] (docs/limits.md)");
  }
}

/// The plant's rod against the bounds that its own length, factors and rest curvature move
/// (the planner's rod met them): the rest curvature's turn |ũ| L (bounds::kMaxRestTurn) and a
/// Cosserat rod's EA L²/EI and GA L²/EI (bounds::kMaxStretchToBendRatio), each named by the plant's
/// field that took it out.
void check_plant_derived(const PlantModel& plant, const RodProperties& k) {
  const double turn = k.u_rest.norm() * k.length;
  if (!(turn <= bounds::kMaxRestTurn)) {
    const std::string what = "turns the plant's rod of length " + format_value(k.length) +
                             " m through |u| L = " + format_value(turn) + " rad, beyond " +
                             format_value(bounds::kMaxRestTurn) + " rad";
    if (plant.rest_curvature)
      throw InputError("PlantModel.rest_curvature",
                       ": |u| = " + format_value(k.u_rest.norm()) + " 1/m " + what +
                           "; |u| must be at most " +
                           format_value(bounds::kMaxRestTurn / k.length) + " 1/m (docs/limits.md)");
    throw InputError("PlantModel.length",
                     " = " + format_value(k.length) + " m with the planner's rest curvature of " +
                         format_value(k.u_rest.norm()) + " 1/m " + what + "; it must be at most " +
                         format_value(bounds::kMaxRestTurn / k.u_rest.norm()) +
                         " m (docs/limits.md)");
  }
  if (k.model != ConstitutiveModel::Cosserat) return;
  const double EI = std::min(k.K_rot.x(), k.K_rot.y());
  const bool axial = k.K_tra.z() >= k.K_tra.x();
  const double K = axial ? k.K_tra.z() : k.K_tra.x();
  const double ratio = K * k.length * k.length / EI;
  if (ratio <= bounds::kMaxStretchToBendRatio) return;
  const char* name = axial ? "EA" : "GA";
  const double factor = axial ? plant.factors.EA : plant.factors.GA;
  const bool bending_factor = plant.factors.EIx != 1.0 || plant.factors.EIy != 1.0;
  const std::string field = factor != 1.0    ? std::string("PlantModel.factors.") + name
                            : bending_factor ? std::string("PlantModel.factors.") +
                                                   (k.K_rot.x() <= k.K_rot.y() ? "EIx" : "EIy")
                            : plant.length ? "PlantModel.length"
                                           : "PlantModel";
  throw InputError(field, ": the plant's rod has " + std::string(name) + " = " + format_value(K) +
                              " N, EI = " + format_value(EI) +
                              " N*m^2 and L = " + format_value(k.length) + " m: " + name +
                              "*L^2/EI = " + format_value(ratio) + ", beyond " +
                              format_value(bounds::kMaxStretchToBendRatio) +
                              ": a Cosserat rod that stiff in extension is a Kirchhoff rod to "
                              "double precision");
}

}  // namespace

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
  (void)plant_maker(model);  // a plant make_plant() knows
}

ClampedRod PlantModel::real_rod(const ClampedRod& planned) const {
  validate();
  check_plant_stiffnesses(*this, planned.properties);
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
  check_plant_derived(*this, k);
  const Eigen::Vector3d g = acting_gravity();
  if (!g.isZero() && !mass_per_length && !(k.mass_per_length > 0.0))
    throw InputError(
        gravity ? "PlantModel.gravity" : "PlantModel.planner_gravity",
        ": the rod's mass per length is not known (give PlantModel.mass_per_length, or "
        "a density for the planner's rod)");
  // One gravity acts on the real rod: its weight f = ρA g replaces the planner's
  // (docs/task-file.md, "plant"). Where both are the same the difference is exactly zero.
  rod.load.force += k.mass_per_length * g - planned.properties.mass_per_length * planner_gravity;
  try {
    rod.validate();
  } catch (const InputError& error) {  // what the checks above leave: said as the plant's
    throw InputError("PlantModel", ": the planner's rod with the plant's parameters: " +
                                       std::string(error.what()));
  }
  return rod;
}

}  // namespace rodshape
