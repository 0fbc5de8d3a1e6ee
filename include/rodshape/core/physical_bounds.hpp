// physical_bounds.hpp: the range of every physical size a user can set (docs/limits.md, "Physical
// sizes"). Each is far wider than any rod a robot handles, and narrow enough that the products the
// solvers form (EA·L², the bending units EI/L² and EI/L, positions to the absolute tolerance 1e-10)
// stay representable: `rod.length: 1e300` or `1e-300` is bad input naming the field, not a
// "singular" solve.
#pragma once

#include <Eigen/Core>
#include <string>

namespace rodshape {

/// A closed range [min, max] of a size, in `unit` (for messages).
struct PhysicalRange {
  double min;
  double max;
  const char* unit;
};

namespace bounds {
/// A rod's length (and a plant's): 0.1 mm … 10 km. Positions are solved to 1e-10 m, so a rod
/// much longer than 1e4 m would be asked for a relative accuracy below double round-off.
inline constexpr PhysicalRange kLength{1e-4, 1e4, "m"};
/// A section's width, height or radius: 1 µm … 100 m.
inline constexpr PhysicalRange kSectionSize{1e-6, 1e2, "m"};
/// Young's modulus: 1 Pa (softer than any solid) … 1e20 Pa.
inline constexpr PhysicalRange kYoungModulus{1.0, 1e20, "Pa"};
/// Density: 0 … 1e5 kg/m³ (four times osmium's).
inline constexpr PhysicalRange kDensity{0.0, 1e5, "kg/m^3"};
/// Each stiffness EA, GA (N), EIx, EIy, GJ (N·m²): 1e-20 … 1e20.
inline constexpr PhysicalRange kStiffness{1e-20, 1e20, "N or N*m^2"};
/// A mass per length: 0 … 1e9 kg/m, the largest density times the largest section (1e4 m²).
inline constexpr PhysicalRange kMassPerLength{0.0, 1e9, "kg/m"};
/// The largest |value| of a position (m), of a gravity (m/s², 1000 g) and of a force or moment
/// (a load per length, a wrench).
inline constexpr double kMaxPosition = 1e4;  // m, as kLength
inline constexpr double kMaxGravity = 1e4;   // m/s²
inline constexpr double kMaxForce = 1e20;    // N, N·m, N/m, N·m/m
/// A marker's position noise (a standard deviation): 0 … 1 m; a marker seen a metre off its
/// place measures nothing.
inline constexpr PhysicalRange kMarkerNoise{0.0, 1.0, "m"};
/// A rest curvature turns the whole rod through at most this angle, |ũ| L (rad): 1e4 rad is
/// about 1600 turns.
inline constexpr double kMaxRestTurn = 1e4;
/// A Cosserat rod's EA·L²/EI (and GA·L²/EI) at most: beyond, the extension and shear compliances
/// L/EA are below the round-off of the bending terms and the rod is a Kirchhoff rod to double
/// precision; the conjugate-point test's verdict then depends on round-off (issue 24, item 8).
inline constexpr double kMaxStretchToBendRatio = 1e16;
}  // namespace bounds

/// Throws InputError(field, " = <value> must be in [min, max] <unit>") when `value` is not finite
/// or outside `range`.
void require_in_range(const std::string& field, double value, const PhysicalRange& range);

/// Throws InputError(field, ...) when a component of `value` is not finite or |value| > `max`
/// (`unit` for the message).
void require_magnitude_at_most(const std::string& field,
                               const Eigen::Vector3d& value,
                               double max,
                               const char* unit);

}  // namespace rodshape
