#include "rodshape/solvers/integration_error.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <limits>
#include <optional>

#include "rodshape/core/rod_integrator.hpp"

namespace rodshape {

namespace {

/// The same rod integrated with steps twice as long, and how its nodes map onto the rod's: half
/// the sub-steps when they are even, else half the intervals (node i there is node `stride` i of
/// the rod's). Empty when neither halves (an odd number of intervals and of sub-steps).
struct Halved {
  ClampedRod rod;
  int stride = 1;
};

std::optional<Halved> halved(const ClampedRod& rod) {
  Halved h{rod, 1};
  if (rod.substeps % 2 == 0) {
    h.rod.substeps = rod.substeps / 2;
  } else if (rod.intervals % 2 == 0) {
    h.rod.intervals = rod.intervals / 2;
    h.stride = 2;
  } else {
    return std::nullopt;
  }
  return h;
}

}  // namespace

double integration_error_estimate(const ClampedRod& rod,
                                  const BaseWrench& base_wrench,
                                  const RodConfiguration& c) {
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  if (!c.finite() || c.nodes() != rod.nodes()) return kInfinity;
  // Steps twice as long where possible (a quarter of the cost), else twice as short.
  const std::optional<Halved> coarse = halved(rod);
  ClampedRod other_rod = coarse ? coarse->rod : rod;
  if (!coarse) other_rod.substeps = 2 * rod.substeps;
  const int stride = coarse ? coarse->stride : 1;
  const RodConfiguration other = integrate(other_rod, base_wrench, Derivatives::None);
  if (!other.finite()) return kInfinity;

  const double L = rod.properties.length;
  const double moment_unit = rod.properties.bending_wrench_units()(3);  // EI / L
  double difference = 0.0;
  for (int j = 0; j < other.nodes(); ++j) {
    const int i = stride * j;
    const double position = (c.p[i] - other.p[j]).norm() / L;
    const double angle = Eigen::AngleAxisd(c.R[i].transpose() * other.R[j]).angle();
    const double moment = (c.m[i] - other.m[j]).norm() / moment_unit;
    difference = std::max({difference, position, angle, moment});
  }
  // RK4 is of order 4: e(2h) ≈ 16 e(h), so |Δ| = 15 e(h) (coarser) or 15 e(h/2) = 15/16 e(h).
  return (coarse ? 1.0 / 15.0 : 16.0 / 15.0) * difference;
}

}  // namespace rodshape
