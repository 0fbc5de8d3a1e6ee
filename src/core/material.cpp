#include "rodshape/core/material.hpp"

#include "validation.hpp"

namespace rodshape {

void Material::validate(const std::string& field) const {
  detail::require_positive(field + ".young_modulus", young_modulus);
  detail::require_finite(field + ".poisson_ratio", poisson_ratio);
  if (!(poisson_ratio > -1.0 && poisson_ratio <= 0.5))
    throw InputError(field + ".poisson_ratio",
                     " = " + detail::format_value(poisson_ratio) + " must be in (-1, 0.5]");
  detail::require_non_negative(field + ".density", density);
}

}  // namespace rodshape
