// material.hpp: a linear elastic, isotropic material.
#pragma once

#include <string>

namespace rodshape {

struct Material {
  double young_modulus = 0.0;  // E, Pa
  double poisson_ratio = 0.0;  // ν, in (-1, 0.5]
  double density = 0.0;        // ρ, kg/m³ (0: weightless)

  /// G = E / (2 (1 + ν)).
  double shear_modulus() const { return young_modulus / (2.0 * (1.0 + poisson_ratio)); }

  /// Throws InputError naming `field` (e.g. "rod.material.young_modulus").
  void validate(const std::string& field = "Material") const;
};

}  // namespace rodshape
