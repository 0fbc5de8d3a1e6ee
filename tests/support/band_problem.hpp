// band_problem.hpp: a small, quick plan problem for the sim tests: the paper's band (N = 50) and
// ten points on the band bent by the base wrench n(0) = [-0.3, 0, 0] N, m(0) = [0, 0.05, 0] N m
// (sampled at s = (i + ½) L / 10 from a fine integration), W1 = 1e-3, W2 = 1.
#pragma once

#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/samples/rubber_band.hpp"
#include "rodshape/trajectory/plan_problem.hpp"

namespace rodshape::testing {

inline PlanProblem band_problem() {
  PlanProblem problem;
  problem.rod = samples::rubber_band(ConstitutiveModel::Cosserat, 50);
  const RodConfiguration bent = integrate(samples::rubber_band(ConstitutiveModel::Cosserat, 200),
                                          {{-0.3, 0.0, 0.0}, {0.0, 0.05, 0.0}});
  for (int i = 0; i < 10; ++i) problem.target.points.push_back(bent.p[20 * i + 10]);
  problem.target.energy_weight = 1e-3;
  problem.target.distance_weight = 1.0;
  return problem;
}

}  // namespace rodshape::testing
