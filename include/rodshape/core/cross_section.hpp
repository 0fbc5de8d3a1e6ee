// cross_section.hpp: the rod's cross-section and its area and second moments.
#pragma once

#include <string>

namespace rodshape {

struct CrossSection {
  enum class Shape { Rectangle, Circle };
  Shape shape = Shape::Circle;
  double width = 0.0;   // m, along the section's local x (rectangle)
  double height = 0.0;  // m, along the section's local y (rectangle)
  double radius = 0.0;  // m (circle)

  static CrossSection rectangle(double width, double height) {
    return {Shape::Rectangle, width, height, 0.0};
  }
  static CrossSection circle(double radius) { return {Shape::Circle, 0.0, 0.0, radius}; }

  double area() const;
  /// Second moment of area about the local x axis (bending in the y–z plane): w h³/12 or πr⁴/4.
  double second_moment_x() const;
  /// Second moment of area about the local y axis: h w³/12 or πr⁴/4.
  double second_moment_y() const;
  /// Torsion constant J. The paper takes J = Ix + Iy (exact for a circle); for a rectangle we use
  /// Saint-Venant's series, J = a b³ (1/3 - 0.21 (b/a)(1 - b⁴/(12 a⁴))), a ≥ b, which is within
  /// 0.5%.
  double torsion_constant() const;
  /// The radius of the circle around the section: half the rectangle's diagonal, the circle's
  /// radius. The rod's surface lies within it of the centreline (a scene's clearance is kept by
  /// it).
  double circumscribed_radius() const;

  /// Throws InputError naming `field` (e.g. "rod.section") when a dimension is not finite and > 0.
  void validate(const std::string& field = "CrossSection") const;
};

}  // namespace rodshape
