// state_estimator.hpp: the rod's state from what the sensors see: the base wrench w = (n(0), m(0))
// (and optionally a stiffness scale) that best explains the visible markers, the held tip pose and,
// with a wrist sensor, the measured wrench, in the least-squares sense, each residual divided by
// its standard deviation:
//   min Σ_j |Σ_c⁻¹ R_cᵀ (Γ(s_j; w) - m_j)|² + |(p(L) - p_d)/σ_p|² + |log(R_dᵀ R(L))/σ_R|²
//       + |(W(w) - W_meas)/σ_W|² + |(w - w_prior)/σ_prior|²,
// solved by Levenberg–Marquardt with the integrator's exact derivatives in w (a forward difference
// in the stiffness scale). The shape controller estimates the rod this way at each checkpoint
// (shape_controller.hpp). From a depth camera's cloud instead of markers: cloud_estimator.hpp (the
// same Levenberg–Marquardt core and tip, wrist and prior rows).
#pragma once

#include <optional>
#include <string>

#include "rodshape/core/clamped_rod.hpp"
#include "rodshape/core/pose.hpp"
#include "rodshape/core/rod_configuration.hpp"
#include "rodshape/core/wrench.hpp"
#include "rodshape/feedback/marker_measurement.hpp"
#include "rodshape/solvers/solve_status.hpp"

namespace rodshape {

struct EstimationOptions {
  /// Also estimate a factor on every stiffness (identifiable from the wrist wrench, or from the
  /// weight when the rod is loaded: scaling the stiffnesses and w together leaves a weightless
  /// rod's shape unchanged).
  bool estimate_stiffness = false;
  double tip_position_sigma = 1e-4;  // m: how well the arm knows where it holds the tip
  double tip_rotation_sigma = 1e-3;  // rad
  /// The held tip's full covariance (position in m, world frame, then the rotation's body-frame
  /// angle in rad), symmetric positive definite; given, it replaces the two sigmas above (a
  /// recursive estimate passes an earlier posterior this way).
  std::optional<Matrix6d> tip_covariance;
  /// The prior's standard deviation, in bending units (EI/L² for forces, EI/L for moments): weak,
  /// it only picks the branch where the measurements do not.
  double prior_sigma = 10.0;
  double stiffness_prior_sigma = 1.0;  // on log(scale)
  /// The gravity the model may lack (m/s², world frame): given, a factor λ on the rod's weight
  /// ρA g is estimated too (the planner's model neglects the weight: λ = 0; the real band's is
  /// λ = 1). Needs the rod's mass per length.
  std::optional<Eigen::Vector3d> gravity;
  double load_prior_sigma = 1.0;  // on λ
  /// The least standard deviations the measurements are weighed with (issue 22): a sensor more
  /// precise than the model can explain (a perfect one: zero noise) is weighed as if it had this
  /// much noise, so that the residual, the χ² gate and the guards stay in units the model can meet.
  /// Without noise, the model's own error under the unmodelled plant of docs/validation.md gave
  /// RMS weighted residuals of 2–34 at σ = 1 µm (every estimate discarded); at the marker floor,
  /// 0.1 mm, they are 0.01–0.7 and every estimate is used. The floor lies below the averaged
  /// Kinect-like noise (0.26 mm in the image plane over 15 frames), which it leaves alone. Each is
  /// > 0; the markers' at most 1 m, the wrist's at most 1e20.
  double min_marker_sigma = 1e-4;        // m
  double min_wrist_force_sigma = 1e-3;   // N (about a laboratory force/torque sensor's resolution)
  double min_wrist_moment_sigma = 1e-4;  // N·m
  /// The least standard deviation a cloud point's distance to the surface is weighed with
  /// (cloud_estimator.hpp): 0.2 mm, twice the markers' floor, as a section's dimensions (and so
  /// its surface about the centreline) are rarely known better; far below a Kinect v2's
  /// single-frame noise (1–2 mm at 1 m), which it leaves alone. > 0, at most 1 m.
  double min_cloud_sigma = 2e-4;  // m
  int max_iterations = 50;
  void validate() const;
};

/// Where the fit starts and what it is pulled to. The standard deviations of the scale and λ,
/// when given, replace EstimationOptions' (a recursive estimate: an earlier estimate's posterior
/// as this one's prior).
struct StatePrior {
  BaseWrench base_wrench;
  double stiffness_scale = 1.0;
  double load_factor = 0.0;                              // λ
  std::optional<double> stiffness_sigma = std::nullopt;  // on log(scale)
  std::optional<double> load_factor_sigma = std::nullopt;
};

/// The state an estimate is tested against (StateEstimate::prior_chi2): the base wrench and the
/// model's corrections that the plan assumes. Absent, the prior's mean.
struct StateHypothesis {
  BaseWrench base_wrench;
  double stiffness_scale = 1.0;
  double load_factor = 0.0;  // λ
};

struct StateEstimate {
  /// Converged: the fit stopped at a finite point within Levenberg–Marquardt's tolerances.
  /// IterationLimit: it ran out of evaluations (EstimationOptions::max_iterations); NonFinite: its
  /// residual is not finite; NotRun: nothing was measured (no marker seen, no wrist wrench), or
  /// the fit could not start (a cloud with no point and no wrist wrench too). Only a converged
  /// estimate is acted on.
  SolveStatus status = SolveStatus::NotRun;
  bool converged() const { return status == SolveStatus::Converged; }
  BaseWrench base_wrench;
  double stiffness_scale = 1.0;
  double load_factor = 0.0;  // λ (with EstimationOptions::gravity)
  /// √(Σ r² / rows) of the weighted residuals: about 1 when the model explains the measurements to
  /// their noise.
  double residual = 0.0;
  /// Σ r² of the weighted residuals at the estimate, and at the hypothesis (the prior's mean unless
  /// one is given): the drop prior_chi2 - chi2 is about χ² with `parameters` degrees of freedom
  /// when the hypothesis is the truth, and larger when the measurements say otherwise.
  double chi2 = 0.0, prior_chi2 = 0.0;
  int parameters = 6;  // the unknowns fitted: w, and the stiffness scale and λ when estimated
  int iterations = 0;
  /// The posterior's standard deviations (Gauss–Newton, (JᵀJ)⁻¹ of the weighted residuals at the
  /// estimate) of log(stiffness scale) and λ when estimated (else 0), and the covariance of the
  /// estimated tip pose (position in m, then the rotation's body-frame angle in rad).
  double stiffness_sigma = 0.0, load_factor_sigma = 0.0;
  Matrix6d tip_covariance = Matrix6d::Zero();
  /// The posterior covariance of w = (n(0), m(0)) (N, N·m), the same (JᵀJ)⁻¹'s block.
  Matrix6d base_wrench_covariance = Matrix6d::Zero();
  /// From a cloud (cloud_estimator.hpp; 0 for markers): the points fitted, and of those the
  /// outliers, which the robust loss discounts at the estimate (their weight below 0.1).
  int points = 0, outliers = 0;
  RodConfiguration configuration;  // of the estimate (the model with the scale applied)
  std::string message;
};

/// Estimates the state of `model` (the planner's rod) held at `tip` (the commanded tip pose) from
/// the frame `seen` of `sensor`, the gripper at `end_effector` (for the wrist wrench), starting
/// from and pulled to `prior`; its χ² is also evaluated at `hypothesis`.
StateEstimate estimate_state(const ClampedRod& model,
                             const Pose& tip,
                             const Pose& end_effector,
                             const SensorFrame& seen,
                             const MarkerSensorModel& sensor,
                             const StatePrior& prior,
                             const EstimationOptions& options = {},
                             const std::optional<StateHypothesis>& hypothesis = std::nullopt);

/// `rod` with every stiffness multiplied by `scale`.
ClampedRod with_stiffness_scale(const ClampedRod& rod, double scale);
/// `rod` (the planner's model) as an estimate says it is: stiffnesses scaled by `scale`, and its
/// weight λ ρA g added (with `gravity`).
ClampedRod estimated_rod(const ClampedRod& rod,
                         double scale,
                         double load_factor,
                         const std::optional<Eigen::Vector3d>& gravity);

}  // namespace rodshape
