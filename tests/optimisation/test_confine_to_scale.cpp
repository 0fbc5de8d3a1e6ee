// test_confine_to_scale.cpp: ShapeOptimiserOptions::confine_to_scale keeps IPOPT's iterates within
// the rod's scale (WrenchBounds::from_scale) without changing an optimisation that stays inside.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/optimisation/shape_optimiser.hpp"
#include "rodshape/samples/rubber_band.hpp"

namespace rodshape {
namespace test_confine_to_scale {
namespace {

TEST(WrenchBoundsFromScale, AreTheDocumentedMultiplesOfTheStiffnesses) {
  ClampedRod rod = samples::rubber_band();
  const WrenchBounds bounds = WrenchBounds::from_scale(rod);
  const double L = rod.properties.length;
  const double M = 4.0 * std::numbers::pi * 0.04 / L;  // max(EIx, EIy, GJ) = 0.04 N·m²
  const double F = 0.5 * rod.properties.K_tra.maxCoeff();
  for (int j = 0; j < 3; ++j) {
    EXPECT_DOUBLE_EQ(bounds.upper(j), F);
    EXPECT_DOUBLE_EQ(bounds.upper(j + 3), M);
    EXPECT_EQ(bounds.lower(j), -bounds.upper(j));
    EXPECT_EQ(bounds.lower(j + 3), -bounds.upper(j + 3));
  }
  // A moment of M about x bends the unloaded rod by two full turns: 4π = M L / EI.
  EXPECT_NEAR(M * L / rod.properties.K_rot.x(), 4.0 * std::numbers::pi, 1e-12);
  // The weight adds what it can carry: f L to the force, f L² / 2 to the moment.
  rod.load.force = {0.0, 0.0, -5.5};
  const WrenchBounds heavy = WrenchBounds::from_scale(rod);
  EXPECT_DOUBLE_EQ(heavy.upper(0), F + 5.5 * L);
  EXPECT_DOUBLE_EQ(heavy.upper(3), M + 0.5 * 5.5 * L * L);
}

/// Six points scattered around the band's clamp, some behind it, far from any shape the band can
/// take (found by a seeded search of random point sets), fitted by squared distance alone: the
/// unconfined optimum coils the band with a base wrench beyond the box (8.75 times it when the
/// dense Newton differenced its Hessian at every iteration, 1.25 times with its SR1 model: a
/// different local optimum of the same far-fetched fit, both outside).
ShapeTarget scattered_target() {
  ShapeTarget target;
  target.points = {{-0.21437055311548173, -0.1922538628363058, 0.27474823702620077},
                   {-0.11387445395537953, 0.02834107449085117, -0.24989514142143784},
                   {-0.039994702004954252, 0.25259612585003738, -0.13036816544028937},
                   {0.17614199955571766, 0.2917338868714392, -0.048745662571956762},
                   {0.0023730871392005468, -0.11979655180017665, -0.094016939981777459},
                   {-0.14451853769977022, 0.09418339016396271, 0.073953494023501903}};
  target.energy_weight = 0.0;
  target.distance_weight = 1.0;
  target.squared_distances = true;
  return target;
}

double box_ratio(const ShapeResult& result, const WrenchBounds& box) {
  return (result.base_wrench.to_vector().cwiseAbs().array() / box.upper.array()).maxCoeff();
}

TEST(ConfineToScale, AnOptimumBeyondTheRodsScaleIsNotConverged) {
  const ClampedRod rod = samples::rubber_band();
  const WrenchBounds box = WrenchBounds::from_scale(rod);
  ShapeProblem problem(rod, scattered_target());
  ShapeOptimiserOptions free;
  free.confine_to_scale = false;
  const ShapeResult unconfined = optimise_shape(problem, BaseWrench{}, free);
  // The premise: left alone, IPOPT "converges" on a coiled band far beyond the box.
  ASSERT_TRUE(unconfined.converged()) << unconfined.brief();
  EXPECT_GT(box_ratio(unconfined, box), 1.0);

  const ShapeResult confined = optimise_shape(problem, BaseWrench{});
  EXPECT_FALSE(confined.converged());
  EXPECT_EQ(confined.status, SolveStatus::Diverged) << confined.brief();
  EXPECT_TRUE(confined.ipopt.beyond_scale);
  EXPECT_NE(confined.message.find("beyond the rod's scale"), std::string::npos) << confined.message;
  EXPECT_LE(box_ratio(confined, box), 1.0);
  EXPECT_TRUE(confined.configuration.finite());
  // It says so early, not after IPOPT's 500 iterations.
  EXPECT_LT(confined.ipopt.iterations, 100);
}

TEST(ConfineToScale, ChangesNothingInside) {
  // The band bent by a wrench well inside the box: with or without, the same iterates.
  const ClampedRod rod = samples::rubber_band();
  const RodConfiguration bent = integrate(rod, {{-0.3, 0.1, 0.0}, {0.0, 0.08, 0.01}});
  ShapeTarget target;
  for (int i = 10; i <= 100; i += 10) target.points.push_back(bent.p[i]);
  target.energy_weight = 1e-3;
  target.distance_weight = 1.0;
  ShapeProblem problem(rod, target);
  ShapeOptimiserOptions free;
  free.confine_to_scale = false;
  const ShapeResult a = optimise_shape(problem, BaseWrench{}, free);
  const ShapeResult b = optimise_shape(problem, BaseWrench{});
  ASSERT_TRUE(b.converged()) << b.brief();
  EXPECT_EQ(a.ipopt.iterations, b.ipopt.iterations);
  EXPECT_EQ(a.base_wrench.to_vector(), b.base_wrench.to_vector());
}

}  // namespace
}  // namespace test_confine_to_scale
}  // namespace rodshape
