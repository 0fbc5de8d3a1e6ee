// test_follow_equilibrium.cpp: follow_equilibrium() — the continuation of a held rod's equilibrium
// along a path of boundary conditions: fixed and adaptive schedules, held and sampled tip paths, an
// analytical oracle (the circular arc under a pure end moment), and the events Lost, OtherBranch
// and Unstable.
//
// Error model (as in test_shooting_solver.cpp). Every substep stops at ||r||_∞ ≤ τ = 1e-10 (m, rad
// for a held tip, N, N·m for a free one). Two wrenches whose residuals for the same tip condition
// are both within τ differ, to first order, by |Δw_i| ≤ Σ_j |J⁻¹|_ij |Δr_j| with |Δr_j| ≤ 2τ (plus
// the round-off of a residual, 16 N ε); the factor 1.1 covers the change of J between them (its
// relative size is O(||J⁻¹|| τ / S) ≤ 1e-5 here). A held tip's position rows are R_dᵀ(p - p_d), so
// |p - p_d| ≤ √3 τ, and its rotation rows log(R_dᵀ R), so the angle is ≤ √3 τ.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <numbers>
#include <numeric>
#include <vector>

#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/error.hpp"
#include "rodshape/solvers/follow_equilibrium.hpp"
#include "rodshape/solvers/shooting_residual.hpp"
#include "rodshape/solvers/shooting_solver.hpp"
#include "support/analytic_rods.hpp"
#include "support/eigen_compare.hpp"
#include "support/input_error.hpp"
#include "support/solver_fixtures.hpp"

namespace rodshape {
namespace test_follow_equilibrium {
namespace {

using testing::CompareMatrices;
using testing::input_error_message;
using testing::kEps;
using testing::rotation_angle;

constexpr double kTau = ShootingOptions{}.residual_tolerance;  // 1e-10
const double kSqrt3 = std::sqrt(3.0);

/// Round-off of one residual evaluation with N intervals (m, rad).
double residual_round_off(const ClampedRod& rod) { return 16.0 * rod.intervals * kEps; }

/// The base wrench of scaled components ξ (bending units, see wrench_scale()).
BaseWrench scaled_wrench(const ClampedRod& rod, const Vector6d& xi) {
  return Wrench::from_vector(xi.cwiseProduct(testing::wrench_scale(rod)));
}

Vector6d vec6(double a, double b, double c, double d, double e, double f) {
  Vector6d v;
  v << a, b, c, d, e, f;
  return v;
}

/// Per-component bound on |w - w_ref| when the residuals of w and w_ref for `tip` differ by at
/// most |Δr| ≤ dr (componentwise): |J⁻¹| dr × 1.1, J at w_ref.
Vector6d wrench_bound(const ClampedRod& rod,
                      const TipCondition& tip,
                      const BaseWrench& w_ref,
                      const Vector6d& dr) {
  const Matrix6d J = testing::residual_jacobian(rod, tip, w_ref);
  return 1.1 * J.inverse().cwiseAbs() * dr;
}

::testing::AssertionResult WithinBound(const Vector6d& actual,
                                       const Vector6d& expected,
                                       const Vector6d& bound) {
  const Vector6d error = (actual - expected).cwiseAbs();
  if (actual.allFinite() && (error.array() <= bound.array()).all())
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "\nactual   " << actual.transpose() << "\nexpected " << expected.transpose()
         << "\n|error|  " << error.transpose() << "\nbound    " << bound.transpose();
}

/// The held tip's pose is the commanded one: within √3 τ in position and angle (plus round-off).
void expect_tip_at(const Pose& tip, const Pose& commanded, const ClampedRod& rod) {
  const double allowed = kSqrt3 * kTau + residual_round_off(rod);
  EXPECT_LE((tip.position - commanded.position).norm(), allowed);
  EXPECT_LE(rotation_angle(tip.rotation, commanded.rotation), allowed);
}

bool finite(const RodConfiguration& c) {
  for (int i = 0; i < c.nodes(); ++i)
    if (!c.p[i].allFinite() || !c.R[i].allFinite() || !c.n[i].allFinite() || !c.m[i].allFinite())
      return false;
  return std::isfinite(c.energy);
}

/// The work counts of the accepted substeps, added up.
ShootingSummary sum_of_states(const FollowResult& result) {
  ShootingSummary sum;
  for (const FollowedState& state : result.states) {
    sum.iterations += state.solve.iterations;
    sum.chord_steps += state.solve.chord_steps;
    sum.integrations += state.solve.integrations;
    sum.jacobian_evaluations += state.solve.jacobian_evaluations;
  }
  return sum;
}

// ---- held tip, fixed schedule
// -------------------------------------------------------------------

// Between two poses of the rubber band bent by about 1 rad in different directions: K = 8 substeps.
TEST(FollowEquilibrium, HeldTipPathEndsAtTheDirectSolveAndHoldsTheInterpolatedPoses) {
  const ClampedRod rod = testing::rubber_band();
  const BaseWrench wA = scaled_wrench(rod, vec6(0.3, -0.2, 0.1, 0.5, 0.8, -0.3));
  const BaseWrench wB = scaled_wrench(rod, vec6(-0.4, 0.5, 0.2, -0.6, 0.4, 0.7));
  const Pose A = integrate(rod, wA).tip(), B = integrate(rod, wB).tip();
  constexpr int K = 8;
  FollowOptions options;
  options.substeps = K;
  const FollowResult result = follow_equilibrium(rod, held_tip_path(A, B), wA, options);

  ASSERT_EQ(result.event, FollowEvent::None) << result.brief();
  EXPECT_TRUE(result.followed());
  ASSERT_EQ(result.states.size(), static_cast<std::size_t>(K));
  EXPECT_EQ(result.sigma, 1.0);
  EXPECT_EQ(result.event_sigma, 1.0);
  EXPECT_EQ(result.brief().rfind("followed to the end in 8 substeps", 0), 0u) << result.brief();
  double previous = 0.0;
  for (int j = 0; j < K; ++j) {
    SCOPED_TRACE("substep " + std::to_string(j + 1));
    const FollowedState& state = result.states[j];
    EXPECT_EQ(state.sigma, static_cast<double>(j + 1) / K);  // σ_j = j / K, exactly
    EXPECT_GT(state.sigma, previous);
    previous = state.sigma;
    expect_tip_at(state.tip, interpolate(A, B, state.sigma), rod);
    EXPECT_TRUE(state.solve.converged()) << state.solve.brief();
    EXPECT_LE(state.solve.residual_norm, kTau);
    EXPECT_EQ(state.solve.continuation_steps, 0);  // direct solves only
    EXPECT_FALSE(state.stability.has_value());     // not asked for
  }

  // The last state is the direct solve at the end pose (from zero: the round trip of wB).
  const ClampedTip end{interpolate(A, B, 1.0)};
  const ShootingResult direct = solve_equilibrium(rod, end);
  ASSERT_TRUE(direct.summary.converged()) << direct.brief();
  const Vector6d dr = Vector6d::Constant(2.0 * (kTau + residual_round_off(rod)));
  const Vector6d bound = wrench_bound(rod, end, direct.base_wrench, dr);
  EXPECT_TRUE(WithinBound(result.base_wrench.to_vector(), direct.base_wrench.to_vector(), bound));
  EXPECT_TRUE(
      WithinBound(result.base_wrench.to_vector(), wB.to_vector(), bound));  // the pose's own wrench
  const Pose direct_tip = direct.configuration.tip();
  EXPECT_LE((result.states.back().tip.position - direct_tip.position).norm(),
            2.0 * (kSqrt3 * kTau + residual_round_off(rod)));
  EXPECT_LE(rotation_angle(result.states.back().tip.rotation, direct_tip.rotation),
            2.0 * (kSqrt3 * kTau + residual_round_off(rod)));

  // The result is the last state, with the final derivatives (AllNodes by default).
  EXPECT_EQ(result.base_wrench.to_vector(), result.states.back().base_wrench.to_vector());
  EXPECT_EQ(result.configuration.nodes(), rod.nodes());
  EXPECT_EQ(result.configuration.derivatives, Derivatives::AllNodes);
  EXPECT_EQ(result.configuration.tip().position, result.states.back().tip.position);
  EXPECT_EQ(result.configuration.energy, result.states.back().energy);

  // The counts add up; the total's status and residual are the last substep's.
  const ShootingSummary sum = sum_of_states(result);
  EXPECT_EQ(result.total.integrations, sum.integrations);
  EXPECT_EQ(result.total.iterations, sum.iterations);
  EXPECT_EQ(result.total.chord_steps, sum.chord_steps);
  EXPECT_EQ(result.total.jacobian_evaluations, sum.jacobian_evaluations);
  EXPECT_EQ(result.total.continuation_steps, K);
  EXPECT_EQ(result.total.status, SolveStatus::Converged);
  EXPECT_EQ(result.total.residual_norm, result.states.back().solve.residual_norm);
  EXPECT_GT(sum.integrations, 0);
}

// The substeps after the first start from the predictor (the last root plus the path's tangent
// -B⁻¹ r from the last Jacobian estimate; from the third on, plus the last Euler error, which makes
// it of second order): on this smooth path of small equal steps the second-order prediction is
// within the endgame's range, so each substep from the third on is one integration with
// derivatives and no Levenberg–Marquardt step; and every root is the one the direct solve finds
// from the last root (the predictor changes the start, not the branch), within the bound of two
// residuals within τ.
TEST(FollowEquilibrium, SubstepsAfterTheFirstStartFromThePredictorAndFindTheDirectSolvesRoot) {
  const ClampedRod rod = testing::rubber_band();
  const BaseWrench wA = scaled_wrench(rod, vec6(0.3, -0.2, 0.1, 0.5, 0.8, -0.3));
  const BaseWrench wB = scaled_wrench(rod, vec6(-0.4, 0.5, 0.2, -0.6, 0.4, 0.7));
  const Pose A = integrate(rod, wA).tip(), B = integrate(rod, wB).tip();
  constexpr int K = 32;  // steps of about 0.06 rad
  FollowOptions options;
  options.substeps = K;
  const FollowResult result = follow_equilibrium(rod, held_tip_path(A, B), wA, options);
  ASSERT_TRUE(result.followed()) << result.brief();
  ASSERT_EQ(result.states.size(), static_cast<std::size_t>(K));

  const Vector6d dr = Vector6d::Constant(2.0 * (kTau + residual_round_off(rod)));
  for (int j = 1; j < K; ++j) {
    SCOPED_TRACE("substep " + std::to_string(j + 1));
    const FollowedState& state = result.states[j];
    if (j >= 2) {
      EXPECT_EQ(state.solve.jacobian_evaluations, 1) << state.solve.brief();
      EXPECT_EQ(state.solve.iterations, 0) << state.solve.brief();
    }
    const ClampedTip tip{interpolate(A, B, state.sigma)};
    const ShootingResult direct = solve_equilibrium(rod, tip, result.states[j - 1].base_wrench);
    ASSERT_TRUE(direct.summary.converged()) << direct.brief();
    EXPECT_TRUE(WithinBound(state.base_wrench.to_vector(), direct.base_wrench.to_vector(),
                            wrench_bound(rod, tip, direct.base_wrench, dr)));
  }
}

// ---- analytical oracle: the circular arc under a pure end moment
// ---------------------------------

// A straight rod whose held tip is turned about the normal x and placed where a circular arc of
// curvature κ ends. n = 0, m = EI κ e_x solves it exactly for both models: m is constant (m' = -p'
// × n = 0), u = K_rot⁻¹ Rᵀ m = κ e_x (Rᵀ leaves e_x alone) and v = K_tra⁻¹ Rᵀ n + e_z = e_z (no
// shear, no extension), so p and R are constant_strain_pose(s, κ e_x). The path turns the tip
// from 0 to π/2 along these arcs (κ(σ) = σ π / (2L)); every followed state must be this wrench.
// The discrete rod reaches the exact arc's tip with the wrench off by J⁻¹ times the integrator's
// tip error (rk4_error_bound / rk4_angle_error_bound, O((κh)⁴)) plus τ.
class FollowArc : public ::testing::TestWithParam<ConstitutiveModel> {};

TEST_P(FollowArc, BaseWrenchIsThePureEndMomentAlongThePath) {
  const ClampedRod rod = testing::rubber_band(GetParam());
  const double L = rod.properties.length, EI = rod.properties.K_rot.x();
  const double kappa_end = std::numbers::pi / (2.0 * L);
  const auto arc_tip = [L](double kappa) {
    const testing::AnalyticPose tip = testing::constant_strain_pose(L, {kappa, 0.0, 0.0});
    return Pose{tip.position, tip.rotation};
  };
  const EquilibriumPath path{
      [&](double sigma) -> TipCondition { return ClampedTip{arc_tip(sigma * kappa_end)}; }, false};
  constexpr int K = 6;
  FollowOptions options;
  options.substeps = K;
  const FollowResult result = follow_equilibrium(rod, path, BaseWrench{}, options);
  ASSERT_EQ(result.event, FollowEvent::None) << result.brief();
  ASSERT_EQ(result.states.size(), static_cast<std::size_t>(K));

  double worst = 0.0;  // largest |error| / bound, for the log
  for (const FollowedState& state : result.states) {
    const double kappa = state.sigma * kappa_end;
    SCOPED_TRACE(to_string(GetParam()) + ", kappa = " + std::to_string(kappa));
    const BaseWrench exact{Eigen::Vector3d::Zero(), Eigen::Vector3d(EI * kappa, 0.0, 0.0)};
    const double position_error = testing::rk4_error_bound(L, kappa, rod.intervals);
    const double angle_error = testing::rk4_angle_error_bound(L, kappa, rod.intervals);
    Vector6d dr;
    dr << Eigen::Vector3d::Constant(position_error + kTau),
        Eigen::Vector3d::Constant(angle_error + kTau);
    const Vector6d bound = wrench_bound(rod, path.tip_at(state.sigma), exact, dr);
    EXPECT_TRUE(WithinBound(state.base_wrench.to_vector(), exact.to_vector(), bound));
    worst = std::max(worst, (state.base_wrench.to_vector() - exact.to_vector())
                                .cwiseAbs()
                                .cwiseQuotient(bound)
                                .maxCoeff());
    // n and m are constant along the rod: the tip carries the same wrench.
    EXPECT_TRUE(WithinBound(state.tip_wrench.to_vector(), exact.to_vector(),
                            bound + Vector6d::Constant(16.0 * rod.intervals * kEps)));
    // E = ½ EI κ² L; dE/dm_x = κ L.
    EXPECT_NEAR(state.energy, 0.5 * EI * kappa * kappa * L,
                kappa * L * bound[3] + 16.0 * rod.intervals * kEps);
  }
  std::cout << "[ arc ] " << to_string(GetParam()) << ": m_x = " << result.base_wrench.moment.x()
            << " vs EI kappa = " << EI * kappa_end << ", largest error / bound " << worst << ", "
            << result.brief() << "\n";
}

INSTANTIATE_TEST_SUITE_P(BothModels,
                         FollowArc,
                         ::testing::Values(ConstitutiveModel::Cosserat,
                                           ConstitutiveModel::Kirchhoff),
                         [](const auto& info) { return to_string(info.param); });

// ---- sampled tip path
// ----------------------------------------------------------------------------

// K = 7 tip poses of known equilibria w_k; substeps = K - 1 visits sample k at σ = k / (K - 1),
// so the followed wrench is w_k (a skipped or repeated sample would be off by a whole step).
TEST(FollowEquilibrium, SampledTipPathWithKMinusOneSubstepsVisitsExactlyTheSamples) {
  const ClampedRod rod = testing::rubber_band();
  constexpr int K = 7;
  const Vector6d xi_end = vec6(0.5, -0.4, 0.2, 0.9, -0.6, 0.4);
  std::vector<BaseWrench> w;
  std::vector<TipCondition> samples;
  for (int k = 0; k < K; ++k) {
    // A walk whose steps are not all alike (the last samples curl back a little).
    const double t = static_cast<double>(k) / (K - 1);
    const Vector6d xi = t * xi_end + 0.3 * std::sin(3.0 * t) * vec6(0.0, 0.5, 0.0, 0.0, 0.0, 1.0);
    w.push_back(scaled_wrench(rod, xi));
    samples.push_back(ClampedTip{integrate(rod, w.back()).tip()});
  }
  FollowOptions options;
  options.substeps = K - 1;
  const FollowResult result = follow_equilibrium(rod, sampled_tip_path(samples), w[0], options);
  ASSERT_EQ(result.event, FollowEvent::None) << result.brief();
  ASSERT_EQ(result.states.size(), static_cast<std::size_t>(K - 1));
  for (int k = 1; k < K; ++k) {
    SCOPED_TRACE("sample " + std::to_string(k));
    const FollowedState& state = result.states[k - 1];
    EXPECT_EQ(state.sigma, static_cast<double>(k) / (K - 1));
    const Pose& sample = std::get<ClampedTip>(samples[k]).pose;
    expect_tip_at(state.tip, sample, rod);
    const Vector6d dr = Vector6d::Constant(kTau + 2.0 * residual_round_off(rod));
    EXPECT_TRUE(WithinBound(state.base_wrench.to_vector(), w[k].to_vector(),
                            wrench_bound(rod, samples[k], w[k], dr)));
  }
}

// ---- lost
// ---------------------------------------------------------------------------------------

// An inextensible (Kirchhoff) band bent by about 2.5 rad, whose held tip is pulled along a line to
// 1.3 L from the clamp, its rotation kept: beyond σ* where the line crosses |p| = L no equilibrium
// exists (and before it the held tip's tilt keeps the rod from straightening), so the path is lost
// at or before σ*.
TEST(FollowEquilibrium, TipPulledBeyondTheRodsLengthIsLostAndKeepsTheLastEquilibrium) {
  const ClampedRod rod = testing::rubber_band(ConstitutiveModel::Kirchhoff);
  const double L = rod.properties.length;
  const BaseWrench wA = scaled_wrench(rod, vec6(0.2, 0.0, 0.0, 0.0, 2.5, 0.0));
  const Pose A = integrate(rod, wA).tip();
  Pose B = A;
  B.position = 1.3 * L * A.position.normalized();
  constexpr int K = 20;
  FollowOptions options;
  options.substeps = K;
  const FollowResult result = follow_equilibrium(rod, held_tip_path(A, B), wA, options);
  std::cout << "[ lost ] " << result.brief() << "\n";

  ASSERT_EQ(result.event, FollowEvent::Lost) << result.brief();
  EXPECT_FALSE(result.followed());
  // The first σ_j whose commanded tip lies beyond L.
  double beyond = 1.0;
  for (int j = K; j >= 1; --j)
    if (interpolate(A, B, static_cast<double>(j) / K).position.norm() > L)
      beyond = static_cast<double>(j) / K;
  EXPECT_LE(result.event_sigma, beyond);
  EXPECT_GT(result.event_sigma, result.sigma);
  EXPECT_DOUBLE_EQ(result.event_sigma, result.sigma + 1.0 / K);  // the next substep failed
  EXPECT_FALSE(result.failed_solve.converged()) << result.failed_solve.brief();
  EXPECT_GT(result.failed_solve.residual_norm, kTau);
  EXPECT_EQ(result.total.status, result.failed_solve.status);
  EXPECT_NE(result.message.find("could not be followed"), std::string::npos) << result.message;
  EXPECT_EQ(result.brief().rfind("lost", 0), 0u) << result.brief();

  ASSERT_FALSE(result.states.empty());  // A itself is bent: the first substeps are followed
  EXPECT_EQ(result.states.back().sigma, result.sigma);
  for (const FollowedState& state : result.states) {
    EXPECT_TRUE(state.solve.converged()) << state.solve.brief();
    expect_tip_at(state.tip, interpolate(A, B, state.sigma), rod);
    EXPECT_LE(state.tip.position.norm(), L);  // inextensible
  }
  // The failed substep's work is counted too.
  const ShootingSummary sum = sum_of_states(result);
  EXPECT_EQ(result.total.integrations, sum.integrations + result.failed_solve.integrations);
  EXPECT_EQ(result.total.continuation_steps, static_cast<int>(result.states.size()) + 1);

  // The result is the last followed equilibrium, finite, with the final derivatives.
  EXPECT_EQ(result.base_wrench.to_vector(), result.states.back().base_wrench.to_vector());
  ASSERT_EQ(result.configuration.nodes(), rod.nodes());
  EXPECT_TRUE(finite(result.configuration));
  EXPECT_TRUE(
      CompareMatrices(result.configuration.tip().position, result.states.back().tip.position, 0.0));
  EXPECT_EQ(result.configuration.derivatives, options.final_derivatives);
}

// The very first substep fails (one iteration per solve, the tip asked to turn by 2 rad at once):
// nothing is followed, and the result is the start equilibrium — not an empty configuration.
TEST(FollowEquilibrium, LostAtTheFirstSubstepReturnsTheStartEquilibrium) {
  const ClampedRod rod = testing::rubber_band();
  const BaseWrench start = scaled_wrench(rod, vec6(0.1, 0.0, 0.0, 0.3, 0.0, 0.0));
  const Pose A = integrate(rod, start).tip();
  const Pose B = integrate(rod, scaled_wrench(rod, vec6(1.0, 0.0, 0.0, -2.0, 1.0, 0.5))).tip();
  FollowOptions options;
  options.substeps = 1;
  options.shooting.max_iterations = 1;
  const FollowResult result = follow_equilibrium(rod, held_tip_path(A, B), start, options);
  ASSERT_EQ(result.event, FollowEvent::Lost) << result.brief();
  EXPECT_TRUE(result.states.empty());
  EXPECT_EQ(result.sigma, 0.0);
  EXPECT_EQ(result.event_sigma, 1.0);
  EXPECT_EQ(result.base_wrench.to_vector(), start.to_vector());
  ASSERT_EQ(result.configuration.nodes(), rod.nodes());
  EXPECT_TRUE(finite(result.configuration));
  expect_tip_at(result.configuration.tip(), A, rod);
  EXPECT_EQ(result.configuration.derivatives, options.final_derivatives);
}

// ---- other branch
// -------------------------------------------------------------------------------

/// A rod buckled between its clamps (tip at 0.8 L): the first mode bulging towards +y or -y, two
/// distinct stable equilibria for the same tip pose (EIy > EIx: no neutral turning). As in
/// tests/trajectory/test_plan.cpp.
struct BuckledBranches {
  ClampedRod rod;
  ClampedTip tip;
  ShootingResult up, down;
  double bulge = 0.0;  // m, the up shape's largest |y|
};

BuckledBranches buckled_branches() {
  BuckledBranches b;
  b.rod.properties.length = testing::kBandLength;
  b.rod.properties.K_rot = {testing::kBandEI, 0.06, testing::kBandGJ};
  b.rod.properties.K_tra = {testing::kBandGA, testing::kBandGA, testing::kBandEA};
  b.rod.intervals = 50;
  const double L = b.rod.properties.length, EI = testing::kBandEI;
  const double euler = 4.0 * std::numbers::pi * std::numbers::pi * EI / (L * L);
  b.tip = ClampedTip{{{0.0, 0.0, 0.8 * L}, Eigen::Matrix3d::Identity()}};
  b.up = solve_equilibrium(b.rod, b.tip, {{0, 0, -1.05 * euler}, {EI / L, 0, 0}});
  b.down = solve_equilibrium(b.rod, b.tip, {{0, 0, -1.05 * euler}, {-EI / L, 0, 0}});
  for (const auto& p : b.up.configuration.p) b.bulge = std::max(b.bulge, std::abs(p.y()));
  return b;
}

// The tip stays where it is: the rod stays up. Expecting the down shape is OtherBranch (the two
// differ by about twice the bulge); expecting the up shape is None, within the bound of two
// equilibria at the same tip (|Δp_i| ≤ |dp_i/dw| |Δw|).
TEST(FollowEquilibrium, ArrivalOnAnotherBranchThanExpectedIsOtherBranch) {
  const BuckledBranches b = buckled_branches();
  ASSERT_TRUE(b.up.summary.converged() && b.down.summary.converged());
  ASSERT_GT(b.bulge, 0.03);
  ASSERT_GT(node_deviation(b.up.configuration, b.down.configuration), b.bulge);
  const EquilibriumPath still = held_tip_path(b.tip.pose, b.tip.pose);

  const FollowResult other =
      follow_equilibrium(b.rod, still, b.up.base_wrench, {}, &b.down.configuration);
  EXPECT_EQ(other.event, FollowEvent::OtherBranch) << other.brief();
  EXPECT_GT(other.arrival_deviation, b.bulge);
  EXPECT_EQ(other.sigma, 1.0);
  EXPECT_EQ(other.event_sigma, 1.0);
  EXPECT_EQ(other.states.size(), 10u);  // followed to the end, then compared
  EXPECT_NE(other.message.find("another branch"), std::string::npos) << other.message;

  const FollowResult same =
      follow_equilibrium(b.rod, still, b.up.base_wrench, {}, &b.up.configuration);
  EXPECT_EQ(same.event, FollowEvent::None) << same.brief();
  const Vector6d dw = wrench_bound(b.rod, b.tip, b.up.base_wrench,
                                   Vector6d::Constant(2.0 * (kTau + residual_round_off(b.rod))));
  double dp_dw = 0.0;  // max over nodes of the induced ∞-norm of dp_i/dw
  for (const Matrix36d& D : b.up.configuration.dp_dw)
    dp_dw = std::max(dp_dw, D.cwiseAbs().rowwise().sum().maxCoeff());
  EXPECT_LE(same.arrival_deviation, kSqrt3 * dp_dw * dw.maxCoeff());
  EXPECT_GE(same.arrival_deviation, 0.0);
}

// ---- adaptive schedule, loads ramped from rest
// --------------------------------------------------

// The band as a cantilever (free tip) under ten times its weight across its axis (f L³/EI ≈ 33:
// the tip swings by more than 1 rad). With 3 iterations per solve the direct solve fails, so the
// adaptive schedule started with the whole step must halve it; it reaches σ = 1 on dyadic steps
// that are not all equal, and arrives at the equilibrium solve_equilibrium() finds (the base
// force is f L in closed form: n' = -f).
TEST(FollowEquilibrium, AdaptiveRampOfAHeavyLoadHalvesItsStepsAndArrivesAtTheEquilibrium) {
  ClampedRod rod = testing::rubber_band();
  rod.load = DistributedLoad::gravity(testing::kBandMassPerLength, {0.0, -98.1, 0.0});
  const FreeTip tip{};
  FollowOptions options;
  options.shooting.max_iterations = 3;
  options.adaptive = true;
  options.initial_step = 1.0;

  ShootingOptions direct_options = options.shooting;
  direct_options.continuation = false;
  const ShootingResult direct = solve_equilibrium(rod, tip, {}, direct_options);
  ASSERT_FALSE(direct.summary.converged()) << "the case must be beyond a direct solve";

  const EquilibriumPath ramp{[tip](double) -> TipCondition { return tip; }, true};
  const FollowResult result = follow_equilibrium(rod, ramp, BaseWrench{}, options);
  std::cout << "[ ramp ] " << result.brief() << ", sigma:";
  for (const FollowedState& s : result.states) std::cout << " " << s.sigma;
  std::cout << "\n";
  ASSERT_EQ(result.event, FollowEvent::None) << result.brief();
  ASSERT_FALSE(result.states.empty());
  EXPECT_EQ(result.sigma, 1.0);
  EXPECT_EQ(result.states.back().sigma, 1.0);
  std::vector<double> steps;
  double previous = 0.0;
  for (const FollowedState& state : result.states) {
    const double step = state.sigma - previous;
    EXPECT_GT(step, 0.0);
    EXPECT_GE(step, 1.0 / options.max_substeps);
    int exponent = 0;  // 2^-k, but for the last step, which is what remains of the path
    if (state.sigma < 1.0) {
      EXPECT_EQ(std::frexp(step, &exponent), 0.5) << "step " << step << " is not 2^-k";
    }
    EXPECT_TRUE(state.solve.converged());
    steps.push_back(step);
    previous = state.sigma;
  }
  EXPECT_NE(*std::min_element(steps.begin(), steps.end()),
            *std::max_element(steps.begin(), steps.end()));
  // The failed attempts are in the total, not in the states.
  EXPECT_GT(result.total.continuation_steps, static_cast<int>(result.states.size()));
  EXPECT_GT(result.total.integrations, sum_of_states(result).integrations);

  const ShootingResult reference = solve_equilibrium(rod, tip);
  ASSERT_TRUE(reference.summary.converged()) << reference.brief();
  const Vector6d dr = Vector6d::Constant(2.0 * kTau + 32.0 * rod.intervals * kEps);
  EXPECT_TRUE(WithinBound(result.base_wrench.to_vector(), reference.base_wrench.to_vector(),
                          wrench_bound(rod, tip, reference.base_wrench, dr)));
  const Eigen::Vector3d fL = rod.load.force * rod.properties.length;
  EXPECT_TRUE(CompareMatrices(result.base_wrench.force, fL, kTau + 16.0 * kEps * fL.norm()));
}

// ---- options and input
// ---------------------------------------------------------------------------

TEST(FollowEquilibriumInput, BadOptionsAreInputErrorsNamingTheField) {
  const ClampedRod rod = testing::rubber_band();
  const Pose rest = integrate(rod, BaseWrench{}).tip();
  const EquilibriumPath path = held_tip_path(rest, rest);
  const auto message = [&](const FollowOptions& options) {
    return input_error_message([&] { follow_equilibrium(rod, path, {}, options); });
  };
  const auto field = [&](const FollowOptions& options) {
    try {
      follow_equilibrium(rod, path, {}, options);
    } catch (const InputError& e) {
      return e.field();
    }
    return std::string("(nothing thrown)");
  };
  FollowOptions options;
  options.substeps = 0;
  EXPECT_EQ(message(options).rfind("FollowOptions.substeps = 0", 0), 0u) << message(options);
  EXPECT_EQ(field(options), "FollowOptions.substeps");
  options = {};
  options.max_substeps = 0;
  EXPECT_EQ(message(options).rfind("FollowOptions.max_substeps = 0", 0), 0u) << message(options);
  EXPECT_EQ(field(options), "FollowOptions.max_substeps");
  for (double bad : {0.0, -0.125, std::numeric_limits<double>::quiet_NaN(),
                     std::numeric_limits<double>::infinity()}) {
    options = {};
    options.initial_step = bad;
    EXPECT_EQ(field(options), "FollowOptions.initial_step") << bad << ": " << message(options);
  }
  // (also checked when the schedule is fixed: the options are validated as a whole)
  options = {};
  options.arrival_stability = true;
  options.final_derivatives = Derivatives::Tip;
  EXPECT_EQ(field(options), "FollowOptions.arrival_stability") << message(options);
  options = {};
  options.shooting.residual_tolerance = -1.0;
  EXPECT_NE(message(options).find("ShootingOptions.residual_tolerance"), std::string::npos)
      << message(options);
  // Good options throw nothing.
  EXPECT_EQ(message(FollowOptions{}), "");
}

TEST(FollowEquilibriumInput, BadPathOrStartIsAnInputError) {
  const ClampedRod rod = testing::rubber_band();
  const std::string no_path =
      input_error_message([&] { follow_equilibrium(rod, EquilibriumPath{}, {}); });
  EXPECT_EQ(no_path.rfind("EquilibriumPath.tip_at", 0), 0u) << no_path;
  const Pose rest = integrate(rod, BaseWrench{}).tip();
  BaseWrench nan_start;
  nan_start.moment.y() = std::numeric_limits<double>::quiet_NaN();
  const std::string start =
      input_error_message([&] { follow_equilibrium(rod, held_tip_path(rest, rest), nan_start); });
  EXPECT_EQ(start.rfind("start.moment", 0), 0u) << start;
  const std::string one_sample = input_error_message([&] { sampled_tip_path({ClampedTip{rest}}); });
  EXPECT_NE(one_sample.find("at least 2 samples"), std::string::npos) << one_sample;
}

// ---- stability
// ----------------------------------------------------------------------------------

/// The band (EIy > EIx) clamped straight and its held tip pushed towards the clamp along its axis
/// by twice the shortening at the Euler load of the clamped–clamped rod, P_E = 4π² EIx / L²: the
/// straight shape is followed by symmetry (a straight guess leaves no lateral residual), and it is
/// unstable once the axial force exceeds the critical load. That load is P_E up to the shear
/// (P_E/GA ≈ 4%) and extension (≈ 3%) corrections, so the first unstable substep has |n| > 0.9
/// P_E and the last stable one |n| < 1.1 P_E.
struct StraightCompression {
  ClampedRod rod;
  EquilibriumPath path;
  double euler = 0.0;
};

StraightCompression straight_compression() {
  StraightCompression c;
  c.rod.properties.length = testing::kBandLength;
  c.rod.properties.K_rot = {testing::kBandEI, 0.06, testing::kBandGJ};
  c.rod.properties.K_tra = {testing::kBandGA, testing::kBandGA, testing::kBandEA};
  c.rod.intervals = 50;
  const double L = c.rod.properties.length;
  c.euler = 4.0 * std::numbers::pi * std::numbers::pi * testing::kBandEI / (L * L);
  const Pose rest = integrate(c.rod, BaseWrench{}).tip();
  Pose pushed = rest;
  pushed.position.z() -= 2.0 * c.euler * L / testing::kBandEA;
  c.path = held_tip_path(rest, pushed);
  return c;
}

TEST(FollowEquilibrium, StabilityAtEverySubstepStopsAtTheFirstUnstableState) {
  const StraightCompression c = straight_compression();
  FollowOptions options;
  options.substeps = 20;
  options.stability_every_substep = true;
  const FollowResult result = follow_equilibrium(c.rod, c.path, {}, options);
  std::cout << "[ unstable ] " << result.brief() << "\n";
  ASSERT_EQ(result.event, FollowEvent::Unstable) << result.brief();
  ASSERT_GE(result.states.size(), 2u);
  EXPECT_LT(result.states.size(), 20u);
  EXPECT_EQ(result.event_sigma, result.states.back().sigma);
  EXPECT_EQ(result.sigma, result.event_sigma);
  for (std::size_t k = 0; k < result.states.size(); ++k) {
    const FollowedState& state = result.states[k];
    ASSERT_TRUE(state.stability.has_value());
    const bool last = k + 1 == result.states.size();
    EXPECT_EQ(state.stability->stable, !last) << state.stability->brief();
  }
  const FollowedState& unstable = result.states.back();
  EXPECT_TRUE(unstable.stability->conjugate_point_s.has_value()) << unstable.stability->brief();
  EXPECT_GT(-unstable.base_wrench.force.z(), 0.9 * c.euler);
  EXPECT_LT(-result.states[result.states.size() - 2].base_wrench.force.z(), 1.1 * c.euler);
  // The state's stability is the assessment of its own equilibrium.
  const StabilityResult again =
      assess_stability(c.rod, integrate(c.rod, unstable.base_wrench, Derivatives::AllNodes));
  EXPECT_EQ(again.stable, unstable.stability->stable);
  EXPECT_EQ(again.conjugate_point_s, unstable.stability->conjugate_point_s);
}

// With ramp_loads the equilibrium at σ is that of the rod under σ times its load: a state's
// stability is the assessment of that rod (whose refinement between nodes integrates its ODE), not
// of the fully loaded one. A held tip bent far from rest under ten times the band's weight, on a
// coarse rod (N = 20) so that the refinement matters.
TEST(FollowEquilibrium, RampedLoadStatesAreAssessedWithTheirOwnLoad) {
  ClampedRod rod = testing::rubber_band(ConstitutiveModel::Cosserat, 20);
  rod.load = DistributedLoad::gravity(testing::kBandMassPerLength, {0.0, -98.1, 0.0});
  const Pose target = integrate(rod, scaled_wrench(rod, vec6(0.5, 0.3, -1.0, 0.4, 2.5, 0.3))).tip();
  ClampedRod unloaded = rod;
  unloaded.load = {};
  EquilibriumPath path = held_tip_path(integrate(unloaded, BaseWrench{}).tip(), target);
  path.ramp_loads = true;
  FollowOptions options;
  options.substeps = 8;
  options.stability_every_substep = true;
  const FollowResult result = follow_equilibrium(rod, path, BaseWrench{}, options);
  ASSERT_EQ(result.event, FollowEvent::None) << result.brief();
  for (const FollowedState& state : result.states) {
    SCOPED_TRACE("sigma = " + std::to_string(state.sigma));
    ClampedRod at_sigma = rod;
    at_sigma.load.force *= state.sigma;
    at_sigma.substeps = state.solve.substeps;  // as the solve integrated it
    const StabilityResult own =
        assess_stability(at_sigma, integrate(at_sigma, state.base_wrench, Derivatives::AllNodes));
    ASSERT_TRUE(state.stability.has_value());
    EXPECT_EQ(state.stability->stable, own.stable);
    // The same configuration assessed twice: equal but for round-off.
    EXPECT_TRUE(testing::CompareScalars(state.stability->min_singular_value, own.min_singular_value,
                                        64.0 * kEps));
  }
}

// The same path without the test at every substep is followed to its end silently (the straight
// equilibrium exists all along); the arrival test then finds it unstable.
TEST(FollowEquilibrium, UnstableArrivalIsFoundOnlyWhenAskedFor) {
  const StraightCompression c = straight_compression();
  FollowOptions options;
  options.substeps = 20;
  const FollowResult silent = follow_equilibrium(c.rod, c.path, {}, options);
  EXPECT_EQ(silent.event, FollowEvent::None) << silent.brief();
  EXPECT_FALSE(silent.arrival_stability.has_value());
  options.arrival_stability = true;
  const FollowResult result = follow_equilibrium(c.rod, c.path, {}, options);
  ASSERT_EQ(result.event, FollowEvent::Unstable) << result.brief();
  EXPECT_EQ(result.states.size(), 20u);
  EXPECT_EQ(result.event_sigma, 1.0);
  for (const FollowedState& state : result.states) EXPECT_FALSE(state.stability.has_value());
  ASSERT_TRUE(result.arrival_stability.has_value());
  EXPECT_FALSE(result.arrival_stability->stable);
  EXPECT_TRUE(result.arrival_stability->conjugate_point_s.has_value());
}

}  // namespace
}  // namespace test_follow_equilibrium
}  // namespace rodshape
