// physical_bounds.cpp: the checks of physical_bounds.hpp (docs/limits.md, "Physical sizes").
#include "rodshape/core/physical_bounds.hpp"

#include "validation.hpp"

namespace rodshape {

void require_in_range(const std::string& field, double value, const PhysicalRange& range) {
  using detail::format_value;
  detail::require_finite(field, value);
  if (value < range.min || value > range.max)
    throw InputError(field, " = " + format_value(value) + " must be in [" +
                                format_value(range.min) + ", " + format_value(range.max) + "] " +
                                range.unit + " (docs/limits.md)");
}

void require_magnitude_at_most(const std::string& field,
                               const Eigen::Vector3d& value,
                               double max,
                               const char* unit) {
  using detail::format_value;
  detail::require_finite(field, value);
  if (value.stableNorm() > max)  // stableNorm: |[1e300, 0, 0]| is 1e300, not inf
    throw InputError(field, " has magnitude " + format_value(value.stableNorm()) + " " + unit +
                                "; at most " + format_value(max) + " " + unit +
                                " (docs/limits.md)");
}

}  // namespace rodshape
