// main.cpp: a program that uses the installed rodshape package. It integrates the paper's rubber
// band from a guessed base wrench, then solves its clamped–clamped equilibrium with the tip held
// 0.12 m aside, 0.22 m up and turned 90° about y, and tests the equilibrium's stability.
// Exit status: 0 when the solve converged, 1 otherwise.
#include <Eigen/Geometry>
#include <cstdio>
#include <numbers>

#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/samples/rubber_band.hpp"
#include "rodshape/solvers/shooting_solver.hpp"
#include "rodshape/solvers/stability.hpp"

int main() {
  using namespace rodshape;

  // The paper's rubber band (L = 0.29 m, 2 × 2 cm section, E = 3.2 MPa, ν = 0.5, identified EI and
  // GJ), clamped at the origin, tangent along +z, 100 intervals.
  const ClampedRod rod = samples::rubber_band();

  // Forward problem: the shape for a given internal wrench at the clamp, n(0) and m(0).
  const BaseWrench bending{{0.0, 0.0, 0.0}, {0.0, 0.05, 0.0}};  // 0.05 N·m about y
  const RodConfiguration bent = integrate(rod, bending);
  std::printf("integrated: tip at (%.4f, %.4f, %.4f) m, energy %.4g J\n", bent.tip().position.x(),
              bent.tip().position.y(), bent.tip().position.z(), bent.energy);

  // Boundary-value problem: the gripper holds the tip pose.
  ClampedTip tip;
  tip.pose.position = {0.12, 0.0, 0.22};
  tip.pose.rotation =
      Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitY()).toRotationMatrix();
  const ShootingResult solution = solve_equilibrium(rod, tip);
  std::printf("equilibrium: %s\n", solution.summary.brief().c_str());
  if (!solution.summary.converged()) return 1;

  const StabilityResult stability = assess_stability(rod, solution.configuration);
  std::printf("energy %.6g J, %s (min sigma %.3g)\n", solution.configuration.energy,
              stability.stable ? "stable" : "not shown stable", stability.min_singular_value);
  return 0;
}
