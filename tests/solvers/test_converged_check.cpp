// test_converged_check.cpp: "converged" means a finite configuration whose residual and
// integration error are within tolerance (issue 12, item 2), and held poses beyond the model's
// validity are bad input (item 3).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/core/strain_extremes.hpp"
#include "rodshape/error.hpp"
#include "rodshape/solvers/follow_equilibrium.hpp"
#include "rodshape/solvers/integration_error.hpp"
#include "rodshape/solvers/model_validity.hpp"
#include "rodshape/solvers/shooting_residual.hpp"
#include "rodshape/solvers/shooting_solver.hpp"
#include "support/analytic_rods.hpp"
#include "support/solver_fixtures.hpp"

namespace rodshape {
namespace test_converged_check {
namespace {

using std::numbers::pi;

/// The invariant every converged solution keeps: finite, residual (recomputed from the returned
/// configuration) and integration error (re-estimated) within the tolerances.
void expect_converged_means_accurate(const ClampedRod& rod,
                                     const TipCondition& tip,
                                     const ShootingResult& solution,
                                     const ShootingOptions& options = {}) {
  if (!solution.summary.converged()) return;
  ClampedRod solved = rod;
  solved.substeps = solution.summary.substeps;
  EXPECT_TRUE(solution.configuration.finite()) << solution.summary.brief();
  const Vector6d r = shooting_residual(tip, solution.configuration);
  EXPECT_TRUE(r.allFinite());
  EXPECT_LE(r.lpNorm<Eigen::Infinity>(), options.residual_tolerance);
  EXPECT_LE(integration_error_estimate(solved, solution.base_wrench, solution.configuration),
            options.integration_tolerance)
      << solution.summary.brief();
}

/// examples/cantilever_gravity.yaml: a 1 m steel wire of radius `radius`, clamped horizontally at
/// (0, 0, 1), along world +x, under gravity `g`.
ClampedRod cantilever(double radius, const Eigen::Vector3d& g) {
  RodDescription description;
  description.length = 1.0;
  description.section = CrossSection::circle(radius);
  description.material = Material{200e9, 0.3, 7850.0};
  ClampedRod rod;
  rod.properties = make_rod_properties(description);
  rod.load = DistributedLoad::gravity(rod.properties.mass_per_length, g);
  rod.clamp.position = {0, 0, 1};
  rod.clamp.rotation << 0, 0, 1, 0, 1, 0, -1, 0, 0;
  rod.validate();
  return rod;
}

TEST(ConvergedCheck, LoadsTheIssueFoundNeverConvergeToANonFiniteShape) {
  // Issue 12: each of these reported "converged", |r| = 0, with null (NaN) nodes.
  const Eigen::Vector3d g{0, 0, -9.81};
  struct Case {
    const char* name;
    ClampedRod rod;
    TipCondition tip;
  };
  const Case cases[] = {
      {"band, tip force 1e4 N", testing::rubber_band(), FreeTip{{{1e4, 0, 0}, {0, 0, 0}}}},
      {"band, tip force 3e4 N", testing::rubber_band(), FreeTip{{{3e4, 0, 0}, {0, 0, 0}}}},
      {"band, tip force 1e6 N", testing::rubber_band(), FreeTip{{{1e6, 0, 0}, {0, 0, 0}}}},
      {"cantilever, tip force 1e6 N", cantilever(1e-3, g), FreeTip{{{0, 0, 1e6}, {0, 0, 0}}}},
      {"cantilever, gravity 1e6", cantilever(1e-3, {0, 0, 1e6}), FreeTip{}},
      {"cantilever, radius 1.3e-6", cantilever(1.3e-6, g), FreeTip{}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const ShootingResult solution = solve_equilibrium(c.rod, c.tip);
    expect_converged_means_accurate(c.rod, c.tip, solution);
    if (!solution.summary.converged()) {
      EXPECT_FALSE(solution.summary.message.empty());
      EXPECT_NE(solution.summary.status, SolveStatus::NotRun);
    }
  }
}

/// The band under an end moment about x that coils it `turns` times: constant curvature κ =
/// 2π turns / L, the arc of constant_strain_pose.
struct CoiledBand {
  ClampedRod rod = testing::rubber_band();
  double kappa;
  FreeTip tip;
  explicit CoiledBand(double turns) : kappa(2.0 * pi * turns / testing::kBandLength) {
    tip.wrench.moment = {testing::kBandEI * kappa, 0, 0};
  }
};

TEST(ConvergedCheck, FollowedPathsEndOnFiniteAccurateShapes) {
  // The continuation the planner uses: the band's free tip loaded from 0 to 1e4 N in 4 substeps.
  // Each substep is a solve_equilibrium, so each accepted state obeys its invariant, and so does
  // the end of a path followed to the end.
  const ClampedRod rod = testing::rubber_band();
  for (const double force : {1e4, 1e6}) {
    SCOPED_TRACE(force);
    EquilibriumPath path;
    path.tip_at = [force](double sigma) { return FreeTip{{{sigma * force, 0, 0}, {0, 0, 0}}}; };
    FollowOptions options;
    options.substeps = 4;
    const FollowResult followed = follow_equilibrium(rod, path, {}, options);
    for (const FollowedState& state : followed.states) {
      EXPECT_TRUE(state.solve.converged());
      EXPECT_LE(state.solve.integration_error, options.shooting.integration_tolerance);
    }
    if (followed.followed()) {
      EXPECT_TRUE(followed.configuration.finite());
      expect_converged_means_accurate(rod, path.tip_at(1.0),
                                      ShootingResult{followed.states.back().solve,
                                                     followed.base_wrench, followed.configuration});
    } else {
      EXPECT_FALSE(followed.message.empty());
    }
  }
}

TEST(ConvergedCheck, CoilingMomentIsNotConvergedWithoutSubsteps) {
  // 24 turns on 100 intervals: κh = 1.5 rad per step, RK4's angle error κL (κh)⁴/1920 ≈ 0.4 rad.
  const CoiledBand band(24);
  ShootingOptions options;
  options.max_substeps = 1;
  const ShootingResult solution = solve_equilibrium(band.rod, band.tip, {}, options);
  EXPECT_EQ(solution.summary.status, SolveStatus::DiscretisationTooCoarse)
      << solution.summary.brief() << " " << solution.summary.message;
  EXPECT_GT(solution.summary.integration_error, options.integration_tolerance);
  EXPECT_NE(solution.summary.message.find("max_substeps"), std::string::npos);
}

TEST(ConvergedCheck, CoilingMomentConvergesWithSubstepsToTheAnalyticArc) {
  const CoiledBand band(24);
  const ShootingOptions options;  // max_substeps = 64
  const ShootingResult solution = solve_equilibrium(band.rod, band.tip, {}, options);
  ASSERT_TRUE(solution.summary.converged()) << solution.summary.message;
  EXPECT_GT(solution.summary.substeps, 1);
  EXPECT_LE(solution.summary.integration_error, options.integration_tolerance);
  expect_converged_means_accurate(band.rod, band.tip, solution, options);
  // Compared with the arc: the error model of analytic_rods.hpp at N × substeps steps.
  const int steps = band.rod.intervals * solution.summary.substeps;
  const double L = testing::kBandLength;
  const Eigen::Vector3d u{band.kappa, 0, 0};
  for (int i = 0; i <= band.rod.intervals; i += 10) {
    const double s = solution.configuration.s[i];
    const testing::AnalyticPose exact = testing::constant_strain_pose(s, u);
    EXPECT_LE((solution.configuration.p[i] - exact.position).norm(),
              testing::rk4_error_bound(L, band.kappa, steps))
        << "node " << i;
  }
  // ... and the estimate was right about the error it promised: |Δp| / L within the tolerance.
  const testing::AnalyticPose tip = testing::constant_strain_pose(L, u);
  EXPECT_LE((solution.configuration.p.back() - tip.position).norm() / L,
            options.integration_tolerance);
}

TEST(ConvergedCheck, EstimateMatchesTheTrueErrorOfTheArcWithinAFactorOfTwo) {
  // Step doubling is an estimate; on the arc it should be the true error to leading order.
  const CoiledBand band(4);  // κh = 0.25 rad
  const RodConfiguration c = integrate(band.rod, BaseWrench{{0, 0, 0}, band.tip.wrench.moment});
  const double estimate = integration_error_estimate(band.rod, c.base_wrench(), c);
  const double L = testing::kBandLength;
  double true_error = 0.0;
  for (int i = 0; i < c.nodes(); ++i) {
    const testing::AnalyticPose exact = testing::constant_strain_pose(c.s[i], {band.kappa, 0, 0});
    true_error = std::max({true_error, (c.p[i] - exact.position).norm() / L,
                           Eigen::AngleAxisd(c.R[i].transpose() * exact.rotation).angle()});
  }
  EXPECT_GT(true_error, 1e-9);  // well above round-off, so the comparison means something
  EXPECT_GT(estimate, 0.5 * true_error);
  EXPECT_LT(estimate, 2.0 * true_error);
}

TEST(ModelValidity, TipHeldAtTheClampIsRejectedAsCompression) {
  // Issue 12: the band held with its tip at the clamp "converged", stable. The shortest
  // equilibrium there squashes it: v_z ≈ 0.
  const ClampedRod rod = testing::rubber_band();
  const ClampedTip tip{Pose{}};
  const ShootingResult solution = solve_equilibrium(rod, tip);
  ASSERT_TRUE(solution.summary.converged()) << solution.summary.message;
  try {
    check_model_validity(rod.properties, solution.configuration, ModelValidityLimits{},
                         "ClampedTip.pose", "ShootingOptions.strain_limits");
    ADD_FAILURE() << "accepted; strains: axial "
                  << strain_extremes(rod.properties, solution.configuration).max_axial;
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_EQ(error.field(), "ClampedTip.pose") << message;
    EXPECT_NE(message.find("compressed"), std::string::npos) << message;
  }
}

TEST(ModelValidity, TipHeldBeyondTheRodsLengthIsRejectedAsStretching) {
  // A plan's initial.tip 1.0 m from the clamp of the 0.29 m band: stretched 3.45×.
  const ClampedRod rod = testing::rubber_band();
  Pose far;
  far.position = {0, 0, 1.0};
  const ClampedTip tip{far};
  const ShootingResult solution = solve_equilibrium(rod, tip);
  ASSERT_TRUE(solution.summary.converged()) << solution.summary.message;
  EXPECT_NEAR(strain_extremes(rod.properties, solution.configuration).max_axial, 1.0 / 0.29 - 1.0,
              1e-6);
  try {
    check_model_validity(rod.properties, solution.configuration, ModelValidityLimits{},
                         "PlanProblem.initial.tip", "PlanProblem.validity");
    ADD_FAILURE() << "accepted";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_EQ(error.field(), "PlanProblem.initial.tip") << message;
    EXPECT_NE(message.find("stretched"), std::string::npos) << message;
    EXPECT_NE(message.find("PlanProblem.validity.max_axial_strain"), std::string::npos) << message;
  }
  // The limit is the task's: a looser one accepts it.
  ModelValidityLimits loose;
  loose.max_axial_strain = 3.0;
  EXPECT_NO_THROW(check_model_validity(rod.properties, solution.configuration, loose, "tip", "l"));
}

TEST(ModelValidity, TheBundledBandPoseIsAccepted) {
  const ClampedRod rod = testing::rubber_band();
  Pose pose;
  pose.position = {0.12, 0.0, 0.22};
  pose.rotation = Eigen::AngleAxisd(pi / 2, Eigen::Vector3d::UnitY()).toRotationMatrix();
  const ShootingResult solution = solve_equilibrium(rod, ClampedTip{pose});
  ASSERT_TRUE(solution.summary.converged());
  EXPECT_NO_THROW(check_model_validity(rod.properties, solution.configuration,
                                       ModelValidityLimits{}, "tip", "l"));
}

TEST(ModelValidity, LimitsAreValidated) {
  ShootingOptions options;
  options.strain_limits.max_axial_strain = 0.0;
  EXPECT_THROW(options.validate(), InputError);
  options = {};
  options.max_substeps = 0;
  EXPECT_THROW(options.validate(), InputError);
  options = {};
  options.integration_tolerance = std::nan("");
  EXPECT_THROW(options.validate(), InputError);
}

}  // namespace
}  // namespace test_converged_check
}  // namespace rodshape
