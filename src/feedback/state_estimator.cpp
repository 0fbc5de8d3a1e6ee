// state_estimator.cpp: the weighted least-squares fit of the base wrench (and stiffness scale) to
// the markers, the held tip pose, the wrist wrench and the prior (state_estimator.hpp): the
// markers' rows, fitted by the shared core (state_fit.hpp).
#include "rodshape/feedback/state_estimator.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "rodshape/core/physical_bounds.hpp"
#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/error.hpp"
#include "rodshape/optimisation/curve_distance.hpp"
#include "state_fit.hpp"
#include "validation.hpp"

namespace rodshape {

namespace {

/// The visible markers (arc length, position), in the camera frame, each axis over its standard
/// deviation: Σ_c⁻¹ R_cᵀ (Γ(s_j; w) - m_j), three rows per marker.
class MarkerBlock final : public feedback_detail::MeasurementBlock {
 public:
  MarkerBlock(const ClampedRod& model,
              const SensorFrame& seen,
              const MarkerSensorModel& sensor,
              const EstimationOptions& options) {
    const std::vector<double> arc = sensor.arc_lengths(model.properties.length);
    for (std::size_t j = 0; j < seen.markers.size() && j < arc.size(); ++j) {
      if (!seen.markers[j]) continue;
      s_.push_back(arc[j]);
      markers_.push_back(*seen.markers[j]);
    }
    const double floor = options.min_marker_sigma;
    const Eigen::Vector3d sigma(std::max(sensor.in_plane_noise, floor),
                                std::max(sensor.in_plane_noise, floor),
                                std::max(sensor.depth_noise, floor));
    weight_ = sigma.cwiseInverse().asDiagonal() * sensor.camera.rotation.transpose();
  }

  bool empty() const { return markers_.empty(); }
  int rows() const override { return 3 * static_cast<int>(markers_.size()); }

  void evaluate(const ClampedRod& rod,
                const RodConfiguration& configuration,
                Eigen::VectorXd& r,
                Eigen::MatrixXd* J,
                int row) const override {
    for (std::size_t j = 0; j < markers_.size(); ++j, row += 3) {
      r.segment<3>(row) = weight_ * (curve_point(configuration, s_[j]) - markers_[j]);
      if (J) J->block<3, 6>(row, 0) = weight_ * curve_point_jacobian(rod, configuration, s_[j]);
    }
  }

 private:
  std::vector<double> s_;
  std::vector<Eigen::Vector3d> markers_;
  Eigen::Matrix3d weight_;
};

}  // namespace

void EstimationOptions::validate() const {
  detail::require_positive("EstimationOptions.tip_position_sigma", tip_position_sigma);
  detail::require_positive("EstimationOptions.tip_rotation_sigma", tip_rotation_sigma);
  detail::require_positive("EstimationOptions.prior_sigma", prior_sigma);
  detail::require_positive("EstimationOptions.stiffness_prior_sigma", stiffness_prior_sigma);
  if (gravity)
    require_magnitude_at_most("EstimationOptions.gravity", *gravity, bounds::kMaxGravity, "m/s^2");
  detail::require_positive("EstimationOptions.load_prior_sigma", load_prior_sigma);
  detail::require_positive("EstimationOptions.min_marker_sigma", min_marker_sigma);
  require_in_range("EstimationOptions.min_marker_sigma", min_marker_sigma, bounds::kMarkerNoise);
  detail::require_positive("EstimationOptions.min_cloud_sigma", min_cloud_sigma);
  require_in_range("EstimationOptions.min_cloud_sigma", min_cloud_sigma, bounds::kMarkerNoise);
  detail::require_positive("EstimationOptions.min_wrist_force_sigma", min_wrist_force_sigma);
  require_in_range("EstimationOptions.min_wrist_force_sigma", min_wrist_force_sigma,
                   {0.0, bounds::kMaxForce, "N"});
  detail::require_positive("EstimationOptions.min_wrist_moment_sigma", min_wrist_moment_sigma);
  require_in_range("EstimationOptions.min_wrist_moment_sigma", min_wrist_moment_sigma,
                   {0.0, bounds::kMaxForce, "N*m"});
  if (tip_covariance) {
    const Matrix6d& c = *tip_covariance;
    if (!c.allFinite() || !c.isApprox(c.transpose(), 1e-12) || c.llt().info() != Eigen::Success)
      throw InputError("EstimationOptions.tip_covariance",
                       " must be finite, symmetric and positive definite");
  }
  if (max_iterations < 1 || max_iterations > 1000)
    throw InputError("EstimationOptions.max_iterations",
                     " = " + std::to_string(max_iterations) + " must be in [1, 1000]");
}

ClampedRod with_stiffness_scale(const ClampedRod& rod, double scale) {
  ClampedRod scaled = rod;
  scaled.properties.K_tra *= scale;
  scaled.properties.K_rot *= scale;
  return scaled;
}

ClampedRod estimated_rod(const ClampedRod& rod,
                         double scale,
                         double load_factor,
                         const std::optional<Eigen::Vector3d>& gravity) {
  ClampedRod estimated = with_stiffness_scale(rod, scale);
  if (gravity) estimated.load.force += load_factor * rod.properties.mass_per_length * *gravity;
  return estimated;
}

StateEstimate estimate_state(const ClampedRod& model,
                             const Pose& tip,
                             const Pose& end_effector,
                             const SensorFrame& seen,
                             const MarkerSensorModel& sensor,
                             const StatePrior& prior,
                             const EstimationOptions& options,
                             const std::optional<StateHypothesis>& hypothesis) {
  feedback_detail::validate_fit_input(model, prior, options, hypothesis);
  const MarkerBlock markers(model, seen, sensor, options);
  feedback_detail::HeldGrasp grasp{tip, end_effector, seen.wrist,
                                   sensor.wrist.value_or(WristNoise{})};
  if (!sensor.wrist) grasp.wrist.reset();
  // No marker seen and no wrist wrench: the fit would only restate the priors (converged,
  // residual 0) and say nothing of the rod; such an estimate is not converged and is never acted
  // on.
  if (markers.empty() && !grasp.wrist)
    return feedback_detail::nothing_measured(
        "nothing was measured: no marker was seen and there is no wrist wrench");
  return feedback_detail::fit_state(model, markers, grasp, prior, options, hypothesis);
}

}  // namespace rodshape
