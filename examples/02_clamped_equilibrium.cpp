// 02_clamped_equilibrium: the boundary-value problem. The gripper holds the band's tip 0.12 m
// aside, 0.22 m up, turned 90° about y; shooting finds the base wrench whose integration ends
// there, and the conjugate-point test says whether that equilibrium is stable. Same as
// 02_clamped_equilibrium.py.
#include <cstdio>

#include "rodshape/samples/rubber_band.hpp"
#include "rodshape/solvers/equilibrium_analysis.hpp"

int main() {
  using namespace rodshape;
  const ClampedRod rod = samples::rubber_band();
  ClampedTip tip;
  tip.pose.position = {0.12, 0.0, 0.22};
  tip.pose.rotation << 0, 0, 1,  // a quarter turn about y
      0, 1, 0,                   //
      -1, 0, 0;

  // Solve, check the held pose's validity and the stability (a stable one sought if unstable).
  const EquilibriumAnalysis analysis = analyse_equilibrium(rod, tip);
  std::printf("%s\n", analysis.brief().c_str());
  if (!analysis.converged()) return 1;
  const BaseWrench& w = analysis.solution.base_wrench;
  std::printf("n(0) = (%.5f, %.5f, %.5f) N, m(0) = (%.5f, %.5f, %.5f) N·m, energy %.6g J\n",
              w.force.x(), w.force.y(), w.force.z(), w.moment.x(), w.moment.y(), w.moment.z(),
              analysis.solution.configuration.energy);
  return 0;
}
