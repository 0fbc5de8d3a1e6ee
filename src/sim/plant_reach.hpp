// plant_reach.hpp (private to sim): the plant must reach every tip pose the plan holds it at
// (rod_reach.hpp): a plant shorter than the plan's rod would be stretched beyond the model's range,
// said as such before driving it (issue 24, item 5) instead of as an unstable plant.
#pragma once

#include "rodshape/sim/plant_model.hpp"
#include "rodshape/solvers/model_validity.hpp"
#include "rodshape/trajectory/plan_result.hpp"

namespace rodshape {

/// Throws InputError naming PlantModel.length (PlantModel when the length is the planner's) when
/// the plan's initial tip or a waypoint's, moved by the plant's grasp offset, is farther from its
/// base (the clamp; with a moving base, where the base is at that pose) than
/// max_tip_distance(real.properties, limits).
void check_plant_reach(const ClampedRod& real,
                       const PlanResult& plan,
                       const PlantModel& plant,
                       const ModelValidityLimits& limits);

}  // namespace rodshape
