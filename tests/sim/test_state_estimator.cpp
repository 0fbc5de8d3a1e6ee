// Tests of the state estimator: a known base wrench (and stiffness scale) recovered from noise-free
// markers, no bias over many noisy seeds, and a posterior covariance that matches the spread.
#include <gtest/gtest.h>

#include <cmath>

#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/feedback/state_estimator.hpp"
#include "rodshape/samples/rubber_band.hpp"
#include "rodshape/sim/marker_sensor.hpp"

namespace rodshape {
namespace test_state_estimator {
namespace {

const BaseWrench kTrue{{-0.3, 0.1, 0.0}, {0.0, 0.08, 0.01}};

MarkerSensorModel noiseless() {
  MarkerSensorModel sensor;
  sensor.in_plane_noise = 0.0;
  sensor.depth_noise = 0.0;
  return sensor;
}

/// What the sensor sees of `rod` in the equilibrium of `w`, the gripper at the tip.
SensorFrame look(const ClampedRod& rod, const BaseWrench& w, MarkerSensor& sensor) {
  const RodConfiguration c = integrate(rod, w);
  PlantFrame frame;
  frame.end_effector = c.tip();
  frame.base_wrench = w;
  frame.configuration = c;
  return sensor.observe(frame, rod.properties.length);
}

/// A prior 0.3 bending units off in every component.
BaseWrench off_prior(const ClampedRod& rod) {
  return BaseWrench::from_vector(kTrue.to_vector() + 0.3 * rod.properties.bending_wrench_units());
}

TEST(StateEstimator, RecoversTheBaseWrenchFromNoiseFreeMarkers) {
  const ClampedRod rod = samples::rubber_band();
  MarkerSensor sensor(noiseless(), 1);
  const SensorFrame seen = look(rod, kTrue, sensor);
  const Pose tip = integrate(rod, kTrue).tip();
  // The markers weighed with σ = 1 µm (EstimationOptions::min_marker_sigma, 0.1 mm by default):
  // the model is exact here, so nothing is lost by trusting them that much.
  EstimationOptions options;
  options.min_marker_sigma = 1e-6;
  const StateEstimate estimate =
      estimate_state(rod, tip, tip, seen, noiseless(), {off_prior(rod)}, options);
  ASSERT_TRUE(estimate.converged()) << estimate.message;
  // The markers, the tip and the model are exact; only the weak prior (σ = 10 bending units, 0.3
  // away) pulls: its weight against the markers' (σ = 1 µm) leaves w within ~1e-9 relative. At
  // the default floor (100 times the σ) the pull is 1e4 times as large: 4e-5 relative, measured.
  EXPECT_LT((estimate.base_wrench.to_vector() - kTrue.to_vector()).norm(),
            1e-6 * kTrue.to_vector().norm())
      << estimate.base_wrench.to_vector().transpose();
}

TEST(StateEstimator, RecoversTheStiffnessScaleWithTheWristSensor) {
  // The real band 15 % softer: with its wrench measured at the wrist, the scale is identifiable
  // (the markers alone see only the shape, which a softer rod under a smaller wrench repeats).
  const ClampedRod rod = samples::rubber_band();
  const ClampedRod real = with_stiffness_scale(rod, 0.85);
  MarkerSensorModel model = noiseless();
  model.wrist = WristNoise{0.0, 0.0};
  MarkerSensor sensor(model, 1);
  const BaseWrench w_real = BaseWrench::from_vector(0.85 * kTrue.to_vector());
  const SensorFrame seen = look(real, w_real, sensor);
  const Pose tip = integrate(real, w_real).tip();
  EstimationOptions options;
  options.estimate_stiffness = true;
  model.wrist = WristNoise{1e-3, 1e-4};  // the fit's weights
  const StateEstimate estimate =
      estimate_state(rod, tip, tip, seen, model, {off_prior(rod)}, options);
  ASSERT_TRUE(estimate.converged()) << estimate.message;
  EXPECT_NEAR(estimate.stiffness_scale, 0.85, 1e-6);
  EXPECT_LT((estimate.base_wrench.to_vector() - w_real.to_vector()).norm(),
            1e-6 * w_real.to_vector().norm());
}

/// What a camera that sees no marker (dropout 1) and a noiseless wrist sensor give of the rod at
/// kTrue; `model` is left with that dropout and wrist.
SensorFrame blind_frame(const ClampedRod& rod, MarkerSensorModel& model) {
  model.dropout = 1.0;
  model.wrist = WristNoise{0.0, 0.0};
  MarkerSensor sensor(model, 1);
  return look(rod, kTrue, sensor);
}

TEST(StateEstimator, TheWristWrenchAloneFixesTheShape) {
  // A camera-free shape sensor: no marker is seen (dropout 1), but with the gripper's pose known
  // the wrench it measures is the tip's, and the tip wrench and pose fix the whole rod.
  const ClampedRod rod = samples::rubber_band();
  MarkerSensorModel model = noiseless();
  const SensorFrame seen = blind_frame(rod, model);
  ASSERT_EQ(seen.visible(), 0);
  const Pose tip = integrate(rod, kTrue).tip();
  model.wrist = WristNoise{1e-3, 1e-4};  // the fit's weights
  const StateEstimate estimate = estimate_state(rod, tip, tip, seen, model, {off_prior(rod)});
  ASSERT_TRUE(estimate.converged()) << estimate.message;
  EXPECT_LT((estimate.base_wrench.to_vector() - kTrue.to_vector()).norm(),
            1e-6 * kTrue.to_vector().norm());
}

TEST(StateEstimator, NothingMeasuredIsNoEstimate) {
  // Issue 24: no marker seen and no wrist wrench: the fit only restated its priors and called
  // that "converged, residual 0"; the closed loop then took it as consistent.
  const ClampedRod rod = samples::rubber_band();
  MarkerSensorModel model = noiseless();
  SensorFrame seen = blind_frame(rod, model);
  ASSERT_EQ(seen.visible(), 0);
  seen.wrist.reset();
  model.wrist.reset();  // no wrist sensor
  const Pose tip = integrate(rod, kTrue).tip();
  const StateEstimate estimate = estimate_state(rod, tip, tip, seen, model, {off_prior(rod)});
  EXPECT_FALSE(estimate.converged());
  EXPECT_TRUE(std::isnan(estimate.residual));
  EXPECT_NE(estimate.message.find("nothing was measured"), std::string::npos) << estimate.message;
}

TEST(StateEstimator, IsUnbiasedOverNoisySeeds) {
  // The Kinect-like noise (1 mm in plane, 3 mm in depth): over 40 seeds the mean estimate lies
  // within 4 standard errors of the truth in every component.
  const ClampedRod rod = samples::rubber_band(ConstitutiveModel::Cosserat, 50);
  const Pose tip = integrate(rod, kTrue).tip();
  constexpr int kSeeds = 40;
  Eigen::Matrix<double, 6, kSeeds> estimates;
  for (int k = 0; k < kSeeds; ++k) {
    MarkerSensor sensor(MarkerSensorModel{}, 100 + k);
    const SensorFrame seen = look(rod, kTrue, sensor);
    const StateEstimate e = estimate_state(rod, tip, tip, seen, MarkerSensorModel{}, {kTrue});
    ASSERT_TRUE(e.converged());
    estimates.col(k) = e.base_wrench.to_vector();
  }
  const Vector6d mean = estimates.rowwise().mean();
  for (int j = 0; j < 6; ++j) {
    const double sd = std::sqrt((estimates.row(j).array() - mean(j)).square().sum() / (kSeeds - 1));
    EXPECT_LE(std::abs(mean(j) - kTrue.to_vector()(j)), 4.0 * sd / std::sqrt(kSeeds) + 1e-12)
        << "component " << j << ": mean " << mean(j) << ", sd " << sd;
  }
}

TEST(StateEstimator, ATipCovarianceOfTheSigmasSquaredIsTheSigmas) {
  // The full covariance of the held tip replaces the two sigmas: diag(σ_p², σ_R²) must give the
  // same fit (the weights agree to rounding, so the estimates agree to the fit's own tolerance).
  const ClampedRod rod = samples::rubber_band(ConstitutiveModel::Cosserat, 50);
  const Pose tip = integrate(rod, kTrue).tip();
  MarkerSensor sensor(MarkerSensorModel{}, 7);
  const SensorFrame seen = look(rod, kTrue, sensor);
  EstimationOptions sigmas;
  sigmas.tip_position_sigma = 5e-3;
  sigmas.tip_rotation_sigma = 0.05;
  EstimationOptions covariance;
  Vector6d variances;
  variances << Eigen::Vector3d::Constant(25e-6), Eigen::Vector3d::Constant(25e-4);
  covariance.tip_covariance = Matrix6d(variances.asDiagonal());
  const StateEstimate a = estimate_state(rod, tip, tip, seen, MarkerSensorModel{}, {kTrue}, sigmas);
  const StateEstimate b =
      estimate_state(rod, tip, tip, seen, MarkerSensorModel{}, {kTrue}, covariance);
  ASSERT_TRUE(a.converged() && b.converged());
  EXPECT_LT((a.base_wrench.to_vector() - b.base_wrench.to_vector()).norm(),
            1e-9 * kTrue.to_vector().norm());
  EXPECT_NEAR(a.chi2, b.chi2, 1e-9 * a.chi2);
  EXPECT_LT((a.tip_covariance - b.tip_covariance).norm(), 1e-9 * a.tip_covariance.norm());
}

TEST(StateEstimator, TheTipCovarianceIsTheSpreadOverNoisySeeds) {
  // The held tip known only to 5 mm: the markers place it, and the posterior covariance must say
  // how well. Over 40 seeds of Kinect-like noise the normalised error eᵀ Σ⁻¹ e of the tip position
  // averages 3 (a χ² with 3 degrees of freedom: the mean of 40 has standard deviation √(6/40) =
  // 0.39); 4 of those either side.
  const ClampedRod rod = samples::rubber_band(ConstitutiveModel::Cosserat, 50);
  const Pose tip = integrate(rod, kTrue).tip();
  EstimationOptions options;
  options.tip_position_sigma = 5e-3;
  options.tip_rotation_sigma = 0.05;
  constexpr int kSeeds = 40;
  double nees = 0.0;
  for (int k = 0; k < kSeeds; ++k) {
    MarkerSensor sensor(MarkerSensorModel{}, 300 + k);
    const SensorFrame seen = look(rod, kTrue, sensor);
    const StateEstimate e =
        estimate_state(rod, tip, tip, seen, MarkerSensorModel{}, {kTrue}, options);
    ASSERT_TRUE(e.converged());
    const Eigen::Vector3d error = e.configuration.tip().position - tip.position;
    nees += error.dot(e.tip_covariance.topLeftCorner<3, 3>().ldlt().solve(error)) / kSeeds;
  }
  EXPECT_NEAR(nees, 3.0, 4.0 * std::sqrt(6.0 / kSeeds));
}

TEST(StateEstimator, AGivenHypothesisIsWhereTheDropOfChi2IsMeasured) {
  // prior_chi2 is χ² at the hypothesis (the plan's state) when one is given, else at the prior.
  const ClampedRod rod = samples::rubber_band(ConstitutiveModel::Cosserat, 50);
  const Pose tip = integrate(rod, kTrue).tip();
  MarkerSensor sensor(MarkerSensorModel{}, 11);
  const SensorFrame seen = look(rod, kTrue, sensor);
  const StateEstimate at_prior = estimate_state(rod, tip, tip, seen, MarkerSensorModel{}, {kTrue});
  const StateEstimate at_off = estimate_state(rod, tip, tip, seen, MarkerSensorModel{}, {kTrue}, {},
                                              StateHypothesis{off_prior(rod)});
  EXPECT_EQ(at_prior.chi2, at_off.chi2);                      // the same fit
  EXPECT_GT(at_off.prior_chi2, 100.0 * at_prior.prior_chi2);  // 0.3 bending units off: far
}

}  // namespace
}  // namespace test_state_estimator
}  // namespace rodshape
