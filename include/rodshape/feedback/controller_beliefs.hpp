// controller_beliefs.hpp: what the shape controller believes of the rod's static
// parameters (the model's corrections and the grasp offset) and how well, as priors for the next
// estimate (state_estimator.hpp) and as the model the plan is made again with
// (shape_controller.hpp).
#pragma once

#include <cmath>
#include <optional>

#include "rodshape/core/pose.hpp"
#include "rodshape/core/wrench.hpp"
#include "rodshape/feedback/closed_loop_options.hpp"
#include "rodshape/feedback/state_estimator.hpp"

namespace rodshape {

/// What the controller believes of the static parameters. `acting`: what the plan uses. `fused`:
/// what all estimates so far say (with ClosedLoopOptions::fuse, each estimate's posterior, with its
/// covariance, is the next one's prior: recursive least squares; else the last estimate acted
/// on). The estimates are tested against `acting`, and one acted on makes `fused` the new `acting`.
struct ControllerBeliefs {
  /// The rod's static parameters: the model's corrections and the grasp offset.
  struct StaticParameters {
    double stiffness_scale = 1.0, load_factor = 0.0;
    Pose offset;
  };
  StaticParameters acting, fused;
  std::optional<double> stiffness_sigma, load_factor_sigma;  // unset: EstimationOptions'
  /// The offset's covariance in the tip frame (position, then the rotation's angle); unset: the
  /// loop's grasp_offset sigmas.
  std::optional<Matrix6d> offset_covariance;

  StatePrior prior(const BaseWrench& planned) const {
    return {planned, fused.stiffness_scale, fused.load_factor, stiffness_sigma, load_factor_sigma};
  }
  StateHypothesis hypothesis(const BaseWrench& planned) const {
    return {planned, acting.stiffness_scale, acting.load_factor};
  }
  /// The tip is fitted around commanded · offset, as well as the offset and the arm are known:
  /// Σ_tip = Ad Σ_offset Adᵀ + Σ_arm, Ad = diag(R_commanded, I).
  EstimationOptions estimation(const ClosedLoopOptions& loop, const Pose& commanded) const {
    EstimationOptions options = loop.estimation;
    if (!loop.estimate_grasp_offset) return options;
    if (!offset_covariance) {
      options.tip_position_sigma =
          std::hypot(loop.grasp_offset_position_sigma, loop.estimation.tip_position_sigma);
      options.tip_rotation_sigma =
          std::hypot(loop.grasp_offset_rotation_sigma, loop.estimation.tip_rotation_sigma);
      return options;
    }
    const Matrix6d Ad = frame_change(commanded);
    Vector6d arm;
    arm << Eigen::Vector3d::Constant(std::pow(loop.estimation.tip_position_sigma, 2)),
        Eigen::Vector3d::Constant(std::pow(loop.estimation.tip_rotation_sigma, 2));
    const Matrix6d covariance = Ad * *offset_covariance * Ad.transpose();
    options.tip_covariance = 0.5 * (covariance + covariance.transpose());
    options.tip_covariance->diagonal() += arm;
    return options;
  }
  /// An estimate taken in (with fusion always, else only when acted on).
  void take(const StateEstimate& e, const Pose& commanded, const ClosedLoopOptions& loop) {
    fused.stiffness_scale = e.stiffness_scale;
    fused.load_factor = e.load_factor;
    if (loop.estimate_grasp_offset)
      fused.offset = compose(inverse(commanded), e.configuration.tip());
    if (!loop.fuse) return;
    if (loop.estimation.estimate_stiffness) stiffness_sigma = e.stiffness_sigma;
    if (loop.estimation.gravity) load_factor_sigma = e.load_factor_sigma;
    if (loop.estimate_grasp_offset) {  // offset = commanded⁻¹ · tip: position turned by R_cᵀ
      const Matrix6d Ad = frame_change(commanded);
      offset_covariance = Ad.transpose() * e.tip_covariance * Ad;
    }
  }
  /// diag(R, I): a position error from the tip frame to the world's (the rotation's angle is
  /// body-frame in both).
  static Matrix6d frame_change(const Pose& commanded) {
    Matrix6d Ad = Matrix6d::Identity();
    Ad.topLeftCorner<3, 3>() = commanded.rotation;
    return Ad;
  }
};

}  // namespace rodshape
