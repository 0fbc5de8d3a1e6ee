#include "rodshape/solvers/integration_error.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <limits>

#include "rodshape/core/rod_integrator.hpp"

namespace rodshape {

double integration_error_estimate(const ClampedRod& rod,
                                  const BaseWrench& base_wrench,
                                  const RodConfiguration& coarse) {
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  if (!coarse.finite() || coarse.nodes() != rod.nodes()) return kInfinity;
  ClampedRod fine_rod = rod;
  fine_rod.substeps = 2 * rod.substeps;
  const RodConfiguration fine = integrate(fine_rod, base_wrench, Derivatives::None);
  if (!fine.finite()) return kInfinity;

  const double L = rod.properties.length;
  const double moment_unit = rod.properties.bending_wrench_units()(3);  // EI / L
  double difference = 0.0;
  for (int i = 0; i < coarse.nodes(); ++i) {
    const double position = (coarse.p[i] - fine.p[i]).norm() / L;
    const double angle = Eigen::AngleAxisd(coarse.R[i].transpose() * fine.R[i]).angle();
    const double moment = (coarse.m[i] - fine.m[i]).norm() / moment_unit;
    difference = std::max({difference, position, angle, moment});
  }
  return 16.0 / 15.0 * difference;
}

}  // namespace rodshape
