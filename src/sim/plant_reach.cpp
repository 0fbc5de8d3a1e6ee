// plant_reach.cpp: the plan's tip poses against the plant's reach (plant_reach.hpp).
#include "plant_reach.hpp"

#include <cmath>
#include <string>

#include "rodshape/error.hpp"
#include "rodshape/solvers/rod_reach.hpp"
#include "validation.hpp"

namespace rodshape {

namespace {

/// The farthest tip from its base (the clamp, or where a moving base is at that configuration)
/// among the plan's initial tip and waypoints, and its waypoint (0: the start).
std::pair<double, int> farthest_tip(const PlanResult& plan, const Pose& grasp_offset) {
  const auto distance = [&](const RodConfiguration& c) {
    if (c.p.empty()) return 0.0;
    return (compose(c.tip(), grasp_offset).position - c.p.front()).norm();
  };
  std::pair<double, int> farthest{distance(plan.initial_configuration), 0};
  for (std::size_t k = 0; k < plan.steps.size(); ++k) {
    const double d = distance(plan.steps[k].solution.configuration);
    if (d > farthest.first) farthest = {d, static_cast<int>(k) + 1};
  }
  return farthest;
}

}  // namespace

void check_plant_reach(const ClampedRod& real,
                       const PlanResult& plan,
                       const PlantModel& plant,
                       const ModelValidityLimits& limits) {
  using detail::format_value;
  const auto [distance, waypoint] = farthest_tip(plan, plant.grasp_offset);
  const double reach = max_tip_distance(real.properties, limits);
  if (!(distance > reach * (1.0 + 1e-12))) return;
  const double L = real.properties.length;
  // Straight and uniformly stretched is the least strain that reaches `distance`.
  const double stretch = distance / (L * real.properties.v_rest.z()) - 1.0;
  const std::string where =
      waypoint == 0 ? "at its start" : "at waypoint " + std::to_string(waypoint);
  throw InputError(plant.length ? "PlantModel.length" : "PlantModel",
                   std::string(plant.length ? " = " + format_value(L) + " m" : "") +
                       ": the plan holds the tip " + format_value(distance) + " m from the clamp " +
                       where + ", which would stretch the plant's rod of " + format_value(L) +
                       " m by " + format_value(std::round(100.0 * stretch)) +
                       " %, beyond PlanProblem.validity.max_axial_strain = " +
                       format_value(limits.max_axial_strain) + ": out of reach (at most " +
                       format_value(reach) + " m)");
}

}  // namespace rodshape
