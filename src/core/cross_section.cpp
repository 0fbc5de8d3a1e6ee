#include "rodshape/core/cross_section.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "rodshape/core/physical_bounds.hpp"
#include "validation.hpp"

namespace rodshape {

double CrossSection::area() const {
  return shape == Shape::Rectangle ? width * height : std::numbers::pi * radius * radius;
}

double CrossSection::second_moment_x() const {
  return shape == Shape::Rectangle ? width * height * height * height / 12.0
                                   : std::numbers::pi * std::pow(radius, 4) / 4.0;
}

double CrossSection::second_moment_y() const {
  return shape == Shape::Rectangle ? height * width * width * width / 12.0
                                   : std::numbers::pi * std::pow(radius, 4) / 4.0;
}

double CrossSection::torsion_constant() const {
  if (shape == Shape::Circle) return std::numbers::pi * std::pow(radius, 4) / 2.0;
  const double a = std::max(width, height);  // long side
  const double b = std::min(width, height);  // short side
  const double ratio = b / a;
  return a * b * b * b * (1.0 / 3.0 - 0.21 * ratio * (1.0 - std::pow(ratio, 4) / 12.0));
}

void CrossSection::validate(const std::string& field) const {
  if (shape == Shape::Rectangle) {
    detail::require_positive(field + ".width", width);
    require_in_range(field + ".width", width, bounds::kSectionSize);
    detail::require_positive(field + ".height", height);
    require_in_range(field + ".height", height, bounds::kSectionSize);
  } else {
    detail::require_positive(field + ".radius", radius);
    require_in_range(field + ".radius", radius, bounds::kSectionSize);
  }
}

double CrossSection::circumscribed_radius() const {
  return shape == Shape::Rectangle ? 0.5 * std::hypot(width, height) : radius;
}

}  // namespace rodshape
