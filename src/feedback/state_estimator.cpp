// state_estimator.cpp: the weighted least-squares fit of the base wrench (and stiffness scale) to
// the markers, the held tip pose, the wrist wrench and the prior (state_estimator.hpp).
#include "rodshape/feedback/state_estimator.hpp"

#include <cmath>
#include <limits>
#include <optional>
#include <unsupported/Eigen/LevenbergMarquardt>
#include <vector>

#include "rodshape/core/physical_bounds.hpp"
#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/core/so3.hpp"
#include "rodshape/error.hpp"
#include "rodshape/optimisation/curve_distance.hpp"
#include "validation.hpp"

namespace rodshape {

namespace {

/// What the fit compares with: the visible markers (arc length, position), the held tip, the
/// gripper and its measured wrench.
struct Measurements {
  std::vector<double> s;
  std::vector<Eigen::Vector3d> markers;
  Pose tip, end_effector;
  std::optional<Wrench> wrist;
};

/// The residual r(x), x = (w, [log scale]), and its Jacobian, as Eigen's Levenberg–Marquardt
/// sees them.
class EstimationProblem : public Eigen::DenseFunctor<double> {
 public:
  EstimationProblem(const ClampedRod& model,
                    const Measurements& data,
                    const MarkerSensorModel& sensor,
                    const StatePrior& prior,
                    const EstimationOptions& options)
      : Eigen::DenseFunctor<double>(unknowns(options), rows(data, options)),
        model_(model),
        data_(data),
        sensor_(sensor),
        prior_(prior),
        options_(options),
        units_(model.properties.bending_wrench_units()),
        tip_whitening_(tip_whitening(options)),
        scale_index_(options.estimate_stiffness ? 6 : -1),
        load_index_(options.gravity ? (options.estimate_stiffness ? 7 : 6) : -1) {}

  static int unknowns(const EstimationOptions& options) {
    return 6 + (options.estimate_stiffness ? 1 : 0) + (options.gravity ? 1 : 0);
  }
  static int rows(const Measurements& data, const EstimationOptions& options) {
    return 3 * static_cast<int>(data.markers.size()) + 6 + (data.wrist ? 6 : 0) + 6 +
           (unknowns(options) - 6);
  }

  /// x = (w, [log scale], [λ]) at the prior's mean.
  InputType start() const {
    return at({prior_.base_wrench, prior_.stiffness_scale, prior_.load_factor});
  }
  /// W with Wᵀ W = Σ_tip⁻¹: W = L⁻¹ for Σ_tip = L Lᵀ, or diag(1/σ) from the two sigmas.
  static Matrix6d tip_whitening(const EstimationOptions& options) {
    if (options.tip_covariance)
      return options.tip_covariance->llt().matrixL().solve(Matrix6d::Identity());
    Vector6d weights;
    weights << Eigen::Vector3d::Constant(1.0 / options.tip_position_sigma),
        Eigen::Vector3d::Constant(1.0 / options.tip_rotation_sigma);
    return weights.asDiagonal();
  }

  /// x = (w, [log scale], [λ]) at `h`.
  InputType at(const StateHypothesis& h) const {
    InputType x(inputs());
    x.head<6>() = h.base_wrench.to_vector();
    if (scale_index_ >= 0) x(scale_index_) = std::log(h.stiffness_scale);
    if (load_index_ >= 0) x(load_index_) = h.load_factor;
    return x;
  }
  double scale_of(const InputType& x) const {
    return scale_index_ >= 0 ? std::exp(x(scale_index_)) : prior_.stiffness_scale;
  }
  double load_of(const InputType& x) const {
    return load_index_ >= 0 ? x(load_index_) : prior_.load_factor;
  }

  int operator()(const InputType& x, ValueType& r) {
    residual(x, r, nullptr);
    if (!r.allFinite()) r.setConstant(r.size(), 1e150);  // a bad point: the trust region shrinks
    return 0;
  }

  int df(const InputType& x, JacobianType& J) {
    J.setZero(values(), inputs());
    Eigen::VectorXd r(values());
    residual(x, r, &J);
    for (const int j : {scale_index_, load_index_}) {  // forward differences in log(scale), λ
      if (j < 0) continue;
      constexpr double h = 1e-6;
      InputType shifted = x;
      shifted(j) += h;
      Eigen::VectorXd r_shifted(values());
      residual(shifted, r_shifted, nullptr);
      J.col(j) = (r_shifted - r) / h;
    }
    residual(x, r, nullptr);  // leave the configuration at x
    return 0;
  }

  /// r(x) and, with J, its columns in w from the integrator's derivatives.
  void residual(const InputType& x, Eigen::VectorXd& r, JacobianType* J) {
    const ClampedRod rod = estimated_rod(model_, scale_of(x), load_of(x), options_.gravity);
    const Vector6d w = x.head<6>();
    configuration_ =
        integrate(rod, BaseWrench::from_vector(w), J ? Derivatives::AllNodes : Derivatives::None);
    int row = 0;
    markers(rod, r, J, row);
    held_tip(r, J, row);
    if (data_.wrist) wrist(r, J, row);
    // The prior, in bending units.
    r.segment<6>(row) =
        (w - prior_.base_wrench.to_vector()).cwiseQuotient(options_.prior_sigma * units_);
    if (J) J->block<6, 6>(row, 0) = (options_.prior_sigma * units_).cwiseInverse().asDiagonal();
    row += 6;
    // The priors of the scale and λ (their columns are differenced in df()).
    if (scale_index_ >= 0)
      r(row++) = (x(scale_index_) - std::log(prior_.stiffness_scale)) /
                 prior_.stiffness_sigma.value_or(options_.stiffness_prior_sigma);
    if (load_index_ >= 0)
      r(row++) = (x(load_index_) - prior_.load_factor) /
                 prior_.load_factor_sigma.value_or(options_.load_prior_sigma);
  }

  /// The posterior's spread at x: Σ = (JᵀJ)⁻¹ (the residuals are weighted), reported as the
  /// scale's and λ's standard deviations and the tip pose's covariance J_tip Σ J_tipᵀ.
  void posterior(const InputType& x, StateEstimate& estimate) {
    JacobianType J;
    df(x, J);
    const Eigen::MatrixXd information = J.transpose() * J;
    const Eigen::MatrixXd sigma =
        information.ldlt().solve(Eigen::MatrixXd::Identity(inputs(), inputs()));
    if (scale_index_ >= 0) estimate.stiffness_sigma = std::sqrt(sigma(scale_index_, scale_index_));
    if (load_index_ >= 0) estimate.load_factor_sigma = std::sqrt(sigma(load_index_, load_index_));
    const int row = 3 * static_cast<int>(data_.markers.size());  // the held tip's rows
    const Eigen::MatrixXd tip_jacobian =
        tip_whitening_.triangularView<Eigen::Lower>().solve(J.middleRows(row, 6));
    const Matrix6d covariance = tip_jacobian * sigma * tip_jacobian.transpose();
    estimate.tip_covariance = 0.5 * (covariance + covariance.transpose());
  }

  const RodConfiguration& configuration() const { return configuration_; }

 private:
  /// Markers in the camera frame, each axis over its standard deviation.
  void markers(const ClampedRod& rod, Eigen::VectorXd& r, JacobianType* J, int& row) const {
    const Eigen::Matrix3d Rc = sensor_.camera.rotation.transpose();
    const double floor = options_.min_marker_sigma;
    const Eigen::Vector3d sigma(std::max(sensor_.in_plane_noise, floor),
                                std::max(sensor_.in_plane_noise, floor),
                                std::max(sensor_.depth_noise, floor));
    const Eigen::Matrix3d W = sigma.cwiseInverse().asDiagonal() * Rc;
    for (std::size_t j = 0; j < data_.markers.size(); ++j, row += 3) {
      r.segment<3>(row) = W * (curve_point(configuration_, data_.s[j]) - data_.markers[j]);
      if (J) J->block<3, 6>(row, 0) = W * curve_point_jacobian(rod, configuration_, data_.s[j]);
    }
  }

  /// The tip where the arm holds it: position and body-frame rotation error.
  void held_tip(Eigen::VectorXd& r, JacobianType* J, int& row) const {
    const Pose tip = configuration_.tip();
    Vector6d error;
    error << tip.position - data_.tip.position,
        log_so3(data_.tip.rotation.transpose() * tip.rotation);
    r.segment<6>(row) = tip_whitening_ * error;
    if (J) {
      Matrix6d dtip_dw;
      dtip_dw << configuration_.tip_dp_dw, configuration_.tip_dtheta_dw;
      J->block<6, 6>(row, 0) = tip_whitening_ * dtip_dw;
    }
    row += 6;
  }

  /// The rod's wrench on the gripper in its frame: -R_eeᵀ n(L), -R_eeᵀ (m(L) + (p(L) - p_ee) ×
  /// n(L)).
  void wrist(Eigen::VectorXd& r, JacobianType* J, int& row) const {
    const Eigen::Matrix3d Rt = data_.end_effector.rotation.transpose();
    const Wrench tip = configuration_.tip_wrench();
    const Eigen::Vector3d arm = configuration_.tip().position - data_.end_effector.position;
    const double sf = std::max(sensor_.wrist->force, options_.min_wrist_force_sigma),
                 sm = std::max(sensor_.wrist->moment, options_.min_wrist_moment_sigma);
    r.segment<3>(row) = (-(Rt * tip.force) - data_.wrist->force) / sf;
    r.segment<3>(row + 3) =
        (-(Rt * (tip.moment + arm.cross(tip.force))) - data_.wrist->moment) / sm;
    if (J) {
      const RodConfiguration& c = configuration_;
      J->block<3, 6>(row, 0) = -(Rt * c.tip_dn_dw) / sf;
      J->block<3, 6>(row + 3, 0) =
          -(Rt * (c.tip_dm_dw - hat(tip.force) * c.tip_dp_dw + hat(arm) * c.tip_dn_dw)) / sm;
    }
    row += 6;
  }

  const ClampedRod& model_;
  const Measurements& data_;
  const MarkerSensorModel& sensor_;
  StatePrior prior_;
  const EstimationOptions& options_;
  Vector6d units_;
  Matrix6d tip_whitening_;
  int scale_index_, load_index_;
  RodConfiguration configuration_;
};

Measurements gather(const ClampedRod& model,
                    const Pose& tip,
                    const Pose& end_effector,
                    const SensorFrame& seen,
                    const MarkerSensorModel& sensor) {
  Measurements data{{}, {}, tip, end_effector, seen.wrist};
  const std::vector<double> s = sensor.arc_lengths(model.properties.length);
  for (std::size_t j = 0; j < seen.markers.size() && j < s.size(); ++j) {
    if (!seen.markers[j]) continue;
    data.s.push_back(s[j]);
    data.markers.push_back(*seen.markers[j]);
  }
  if (!sensor.wrist) data.wrist.reset();
  return data;
}

/// No marker seen and no wrist wrench: the fit would only restate the priors (converged, residual
/// 0) and say nothing of the rod; such an estimate is not converged and is never acted on.
StateEstimate nothing_measured() {
  StateEstimate estimate;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  estimate.residual = estimate.chi2 = estimate.prior_chi2 = nan;
  estimate.message = "nothing was measured: no marker was seen and there is no wrist wrench";
  return estimate;
}

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
  options.validate();
  detail::require_positive("StatePrior.stiffness_scale", prior.stiffness_scale);
  detail::require_finite("StatePrior.load_factor", prior.load_factor);
  if (prior.stiffness_sigma)
    detail::require_positive("StatePrior.stiffness_sigma", *prior.stiffness_sigma);
  if (prior.load_factor_sigma)
    detail::require_positive("StatePrior.load_factor_sigma", *prior.load_factor_sigma);
  if (options.gravity && !(model.properties.mass_per_length > 0.0))
    throw InputError("EstimationOptions.gravity",
                     ": the rod's mass per length is not known, so its weight cannot be estimated");
  const Measurements data = gather(model, tip, end_effector, seen, sensor);
  if (data.markers.empty() && !data.wrist) return nothing_measured();
  EstimationProblem problem(model, data, sensor, prior, options);
  Eigen::LevenbergMarquardt<EstimationProblem> lm(problem);
  lm.setMaxfev(10 * options.max_iterations);
  Eigen::VectorXd r(problem.values());
  if (hypothesis) {
    detail::require_positive("StateHypothesis.stiffness_scale", hypothesis->stiffness_scale);
    detail::require_finite("StateHypothesis.load_factor", hypothesis->load_factor);
  }
  problem.residual(hypothesis ? problem.at(*hypothesis) : problem.start(), r, nullptr);
  StateEstimate estimate;
  estimate.prior_chi2 = r.squaredNorm();
  estimate.parameters = problem.inputs();
  Eigen::VectorXd x = problem.start();
  const auto status = lm.minimize(x);
  problem.residual(x, r, nullptr);
  estimate.chi2 = r.squaredNorm();
  estimate.base_wrench = BaseWrench::from_vector(x.head<6>());
  estimate.stiffness_scale = problem.scale_of(x);
  estimate.load_factor = problem.load_of(x);
  estimate.residual = std::sqrt(r.squaredNorm() / static_cast<double>(r.size()));
  estimate.iterations = static_cast<int>(lm.iterations());
  estimate.status = !r.allFinite() ? SolveStatus::NonFinite
                    : status == Eigen::LevenbergMarquardtSpace::ImproperInputParameters
                        ? SolveStatus::NotRun
                    : status == Eigen::LevenbergMarquardtSpace::TooManyFunctionEvaluation
                        ? SolveStatus::IterationLimit
                        : SolveStatus::Converged;
  if (estimate.converged()) problem.posterior(x, estimate);
  estimate.configuration = problem.configuration();
  estimate.message = estimate.converged() ? "converged" : "the fit did not converge";
  return estimate;
}

}  // namespace rodshape
