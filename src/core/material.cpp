#include "rodshape/core/material.hpp"

#include "rodshape/core/physical_bounds.hpp"
#include "validation.hpp"

namespace rodshape {

void Material::validate(const std::string& field) const {
  detail::require_positive(field + ".young_modulus", young_modulus);
  require_in_range(field + ".young_modulus", young_modulus, bounds::kYoungModulus);
  detail::require_finite(field + ".poisson_ratio", poisson_ratio);
  if (!(poisson_ratio > -1.0 && poisson_ratio <= 0.5))
    throw InputError(field + ".poisson_ratio",
                     " = " + detail::format_value(poisson_ratio) + " must be in (-1, 0.5]");
  detail::require_non_negative(field + ".density", density);
  require_in_range(field + ".density", density, bounds::kDensity);
}

}  // namespace rodshape
