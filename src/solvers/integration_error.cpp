#include "rodshape/solvers/integration_error.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <limits>

#include "rodshape/core/rod_integrator.hpp"
#include "step_doubling.hpp"

namespace rodshape {

namespace detail {

ComparisonRod comparison_rod(const ClampedRod& rod) {
  ComparisonRod h{rod, 1, true};
  if (rod.substeps % 2 == 0) {
    h.rod.substeps = rod.substeps / 2;
  } else if (rod.intervals % 2 == 0) {
    h.rod.intervals = rod.intervals / 2;
    h.stride = 2;
  } else {
    h.rod.substeps = 2 * rod.substeps;
    h.coarse = false;
  }
  return h;
}

double step_doubling_error(const ClampedRod& rod,
                           const RodConfiguration& c,
                           const ComparisonRod& compared,
                           const RodConfiguration& other) {
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  if (!c.finite() || c.nodes() != rod.nodes() || !other.finite()) return kInfinity;
  const double L = rod.properties.length;
  const double moment_unit = rod.properties.bending_wrench_units()(3);  // EI / L
  double difference = 0.0;
  for (int j = 0; j < other.nodes(); ++j) {
    const int i = compared.stride * j;
    const double position = (c.p[i] - other.p[j]).norm() / L;
    const double angle = Eigen::AngleAxisd(c.R[i].transpose() * other.R[j]).angle();
    const double moment = (c.m[i] - other.m[j]).norm() / moment_unit;
    difference = std::max({difference, position, angle, moment});
  }
  // RK4 is of order 4: e(2h) ≈ 16 e(h), so |Δ| = 15 e(h) (coarser) or 15 e(h/2) = 15/16 e(h).
  return (compared.coarse ? 1.0 / 15.0 : 16.0 / 15.0) * difference;
}

}  // namespace detail

double integration_error_estimate(const ClampedRod& rod,
                                  const BaseWrench& base_wrench,
                                  const RodConfiguration& c) {
  if (!c.finite() || c.nodes() != rod.nodes()) return std::numeric_limits<double>::infinity();
  // Steps twice as long where possible (half the cost), else twice as short.
  const detail::ComparisonRod compared = detail::comparison_rod(rod);
  const RodConfiguration other = integrate(compared.rod, base_wrench, Derivatives::None);
  return detail::step_doubling_error(rod, c, compared, other);
}

}  // namespace rodshape
