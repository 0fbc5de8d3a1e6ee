// state_fit.cpp: the Levenberg–Marquardt core of the state estimators, with the shared residual
// blocks: the held tip, the wrist wrench and the priors (state_fit.hpp).
#include "state_fit.hpp"

#include <cmath>
#include <limits>
#include <unsupported/Eigen/LevenbergMarquardt>

#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/core/so3.hpp"
#include "rodshape/error.hpp"
#include "validation.hpp"

namespace rodshape::feedback_detail {

namespace {

/// The residual r(x), x = (w, [log scale], [λ]), and its Jacobian, as Eigen's Levenberg–Marquardt
/// sees them.
class EstimationProblem : public Eigen::DenseFunctor<double> {
 public:
  EstimationProblem(const ClampedRod& model,
                    const MeasurementBlock& block,
                    const HeldGrasp& grasp,
                    const StatePrior& prior,
                    const EstimationOptions& options)
      : Eigen::DenseFunctor<double>(unknowns(options), rows(block, grasp, options)),
        model_(model),
        block_(block),
        grasp_(grasp),
        prior_(prior),
        options_(options),
        units_(model.properties.bending_wrench_units()),
        tip_whitening_(tip_whitening(options)),
        scale_index_(options.estimate_stiffness ? 6 : -1),
        load_index_(options.gravity ? (options.estimate_stiffness ? 7 : 6) : -1) {}

  static int unknowns(const EstimationOptions& options) {
    return 6 + (options.estimate_stiffness ? 1 : 0) + (options.gravity ? 1 : 0);
  }
  static int rows(const MeasurementBlock& block,
                  const HeldGrasp& grasp,
                  const EstimationOptions& options) {
    return block.rows() + 6 + (grasp.wrist ? 6 : 0) + 6 + (unknowns(options) - 6);
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
    rod_ = estimated_rod(model_, scale_of(x), load_of(x), options_.gravity);
    const Vector6d w = x.head<6>();
    configuration_ =
        integrate(rod_, BaseWrench::from_vector(w), J ? Derivatives::AllNodes : Derivatives::None);
    block_.evaluate(rod_, configuration_, r, J, 0);
    int row = block_.rows();
    held_tip(r, J, row);
    if (grasp_.wrist) wrist(r, J, row);
    priors(x, r, J, row);
  }

  /// The posterior's spread at x: Σ = (JᵀJ)⁻¹ (the residuals are weighted), reported as the
  /// base wrench's covariance, the scale's and λ's standard deviations and the tip pose's
  /// covariance J_tip Σ J_tipᵀ.
  void posterior(const InputType& x, StateEstimate& estimate) {
    JacobianType J;
    df(x, J);
    const Eigen::MatrixXd information = J.transpose() * J;
    const Eigen::MatrixXd sigma =
        information.ldlt().solve(Eigen::MatrixXd::Identity(inputs(), inputs()));
    estimate.base_wrench_covariance = sigma.topLeftCorner<6, 6>();
    if (scale_index_ >= 0) estimate.stiffness_sigma = std::sqrt(sigma(scale_index_, scale_index_));
    if (load_index_ >= 0) estimate.load_factor_sigma = std::sqrt(sigma(load_index_, load_index_));
    const int row = block_.rows();  // the held tip's rows
    const Eigen::MatrixXd tip_jacobian =
        tip_whitening_.triangularView<Eigen::Lower>().solve(J.middleRows(row, 6));
    const Matrix6d covariance = tip_jacobian * sigma * tip_jacobian.transpose();
    estimate.tip_covariance = 0.5 * (covariance + covariance.transpose());
  }

  const ClampedRod& rod() const { return rod_; }
  const RodConfiguration& configuration() const { return configuration_; }

 private:
  /// The tip where the arm holds it: position and body-frame rotation error.
  void held_tip(Eigen::VectorXd& r, JacobianType* J, int& row) const {
    const Pose tip = configuration_.tip();
    Vector6d error;
    error << tip.position - grasp_.tip.position,
        log_so3(grasp_.tip.rotation.transpose() * tip.rotation);
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
    const Eigen::Matrix3d Rt = grasp_.end_effector.rotation.transpose();
    const Wrench tip = configuration_.tip_wrench();
    const Eigen::Vector3d arm = configuration_.tip().position - grasp_.end_effector.position;
    const double sf = std::max(grasp_.wrist_noise.force, options_.min_wrist_force_sigma),
                 sm = std::max(grasp_.wrist_noise.moment, options_.min_wrist_moment_sigma);
    r.segment<3>(row) = (-(Rt * tip.force) - grasp_.wrist->force) / sf;
    r.segment<3>(row + 3) =
        (-(Rt * (tip.moment + arm.cross(tip.force))) - grasp_.wrist->moment) / sm;
    if (J) {
      const RodConfiguration& c = configuration_;
      J->block<3, 6>(row, 0) = -(Rt * c.tip_dn_dw) / sf;
      J->block<3, 6>(row + 3, 0) =
          -(Rt * (c.tip_dm_dw - hat(tip.force) * c.tip_dp_dw + hat(arm) * c.tip_dn_dw)) / sm;
    }
    row += 6;
  }

  /// The prior on w, in bending units, and those of the scale and λ (their columns are
  /// differenced in df()).
  void priors(const InputType& x, Eigen::VectorXd& r, JacobianType* J, int& row) const {
    const Vector6d w = x.head<6>();
    r.segment<6>(row) =
        (w - prior_.base_wrench.to_vector()).cwiseQuotient(options_.prior_sigma * units_);
    if (J) J->block<6, 6>(row, 0) = (options_.prior_sigma * units_).cwiseInverse().asDiagonal();
    row += 6;
    if (scale_index_ >= 0)
      r(row++) = (x(scale_index_) - std::log(prior_.stiffness_scale)) /
                 prior_.stiffness_sigma.value_or(options_.stiffness_prior_sigma);
    if (load_index_ >= 0)
      r(row++) = (x(load_index_) - prior_.load_factor) /
                 prior_.load_factor_sigma.value_or(options_.load_prior_sigma);
  }

  const ClampedRod& model_;
  const MeasurementBlock& block_;
  const HeldGrasp& grasp_;
  StatePrior prior_;
  const EstimationOptions& options_;
  Vector6d units_;
  Matrix6d tip_whitening_;
  int scale_index_, load_index_;
  ClampedRod rod_;
  RodConfiguration configuration_;
};

SolveStatus status_of(const Eigen::VectorXd& r, Eigen::LevenbergMarquardtSpace::Status status) {
  using namespace Eigen::LevenbergMarquardtSpace;
  if (!r.allFinite()) return SolveStatus::NonFinite;
  if (status == ImproperInputParameters) return SolveStatus::NotRun;
  if (status == TooManyFunctionEvaluation) return SolveStatus::IterationLimit;
  return SolveStatus::Converged;
}

}  // namespace

void validate_fit_input(const ClampedRod& model,
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
  if (hypothesis) {
    detail::require_positive("StateHypothesis.stiffness_scale", hypothesis->stiffness_scale);
    detail::require_finite("StateHypothesis.load_factor", hypothesis->load_factor);
  }
}

StateEstimate nothing_measured(const std::string& why) {
  StateEstimate estimate;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  estimate.residual = estimate.chi2 = estimate.prior_chi2 = nan;
  estimate.message = why;
  return estimate;
}

StateEstimate fit_state(const ClampedRod& model,
                        const MeasurementBlock& block,
                        const HeldGrasp& grasp,
                        const StatePrior& prior,
                        const EstimationOptions& options,
                        const std::optional<StateHypothesis>& hypothesis,
                        const std::optional<StateHypothesis>& start) {
  EstimationProblem problem(model, block, grasp, prior, options);
  Eigen::LevenbergMarquardt<EstimationProblem> lm(problem);
  lm.setMaxfev(10 * options.max_iterations);
  Eigen::VectorXd r(problem.values());
  problem.residual(hypothesis ? problem.at(*hypothesis) : problem.start(), r, nullptr);
  StateEstimate estimate;
  estimate.prior_chi2 = r.squaredNorm();
  estimate.parameters = problem.inputs();
  Eigen::VectorXd x = start ? problem.at(*start) : problem.start();
  const auto status = lm.minimize(x);
  problem.residual(x, r, nullptr);
  estimate.chi2 = r.squaredNorm();
  estimate.base_wrench = BaseWrench::from_vector(x.head<6>());
  estimate.stiffness_scale = problem.scale_of(x);
  estimate.load_factor = problem.load_of(x);
  estimate.residual = std::sqrt(r.squaredNorm() / static_cast<double>(r.size()));
  estimate.iterations = static_cast<int>(lm.iterations());
  estimate.status = status_of(r, status);
  if (estimate.converged()) problem.posterior(x, estimate);
  estimate.configuration = problem.configuration();
  block.finish(problem.rod(), estimate.configuration, problem.values(), estimate);
  estimate.message = estimate.converged() ? "converged" : "the fit did not converge";
  return estimate;
}

}  // namespace rodshape::feedback_detail
