// 01_integrate: the forward problem. The paper's rubber band, clamped at the origin along +z, is
// integrated from a base wrench n(0), m(0): p' = R v, R' = R û, n' = -f, m' = -p' × n - l. An end
// moment M about y bends an inextensible rod into an arc of radius EI / M, so the tip can be
// checked against the circle. Same as 01_integrate.py.
#include <cmath>
#include <cstdio>

#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/samples/rubber_band.hpp"

int main() {
  using namespace rodshape;
  const ClampedRod rod = samples::rubber_band(ConstitutiveModel::Kirchhoff, 100);
  const double M = 0.05;                               // N·m about y
  const BaseWrench w{{0.0, 0.0, 0.0}, {0.0, M, 0.0}};  // n(0), m(0)
  const RodConfiguration c = integrate(rod, w);

  const double L = rod.properties.length, EI = rod.properties.K_rot.y(), r = EI / M;
  const Eigen::Vector3d arc_tip(r * (1 - std::cos(L / r)), 0.0, r * std::sin(L / r));
  std::printf("nodes %d, tip (%.6f, %.6f, %.6f) m, energy %.6g J\n", c.nodes(),
              c.tip().position.x(), c.tip().position.y(), c.tip().position.z(), c.energy);
  std::printf("distance to the arc's tip %.2e m, energy M²L/(2EI) = %.6g J\n",
              (c.tip().position - arc_tip).norm(), M * M * L / (2 * EI));
  return (c.tip().position - arc_tip).norm() < 1e-9 ? 0 : 1;
}
