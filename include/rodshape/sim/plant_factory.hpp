// plant_factory.hpp: the plants by name (PlantModel::model): "quasi_static" (QuasiStaticPlant,
// the only one today). A new plant is registered by one line in src/sim/plant_factory.cpp.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "rodshape/sim/plant_interface.hpp"

namespace rodshape {

/// The names make_plant() knows, in the order they were registered.
std::vector<std::string> plant_names();

/// The maker of the plant named `model`; throws InputError naming PlantModel.model (with the
/// names known) for any other.
PlantMaker plant_maker(const std::string& model);

/// The plant named `model` of `setup`, at rest: plant_maker(model)(setup).
std::unique_ptr<Plant> make_plant(const std::string& model, const PlantSetup& setup);

}  // namespace rodshape
