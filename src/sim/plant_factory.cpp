// plant_factory.cpp: the registry of plants (plant_factory.hpp).
#include "rodshape/sim/plant_factory.hpp"

#include <utility>

#include "rodshape/error.hpp"
#include "rodshape/sim/quasi_static_plant.hpp"

namespace rodshape {

namespace {

template <class P>
std::unique_ptr<Plant> make_plant_of(const PlantSetup& setup) {
  return std::make_unique<P>(setup);
}

/// Each plant by its name: one line a plant.
const std::vector<std::pair<std::string, PlantMaker>>& plant_registry() {
  static const std::vector<std::pair<std::string, PlantMaker>> plants = {
      {"quasi_static", make_plant_of<QuasiStaticPlant>},
  };
  return plants;
}

}  // namespace

std::vector<std::string> plant_names() {
  std::vector<std::string> names;
  for (const auto& [name, maker] : plant_registry()) names.push_back(name);
  return names;
}

PlantMaker plant_maker(const std::string& model) {
  for (const auto& [name, maker] : plant_registry())
    if (name == model) return maker;
  std::string known;
  for (const std::string& name : plant_names()) known += (known.empty() ? "" : ", ") + name;
  throw InputError("PlantModel.model", " = '" + model + "' is not a plant; known: " + known);
}

std::unique_ptr<Plant> make_plant(const std::string& model, const PlantSetup& setup) {
  return plant_maker(model)(setup);
}

}  // namespace rodshape
