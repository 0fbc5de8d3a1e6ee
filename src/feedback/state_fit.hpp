// state_fit.hpp (private): the one Levenberg–Marquardt core both state estimators share
// (state_estimator.hpp: markers; cloud_estimator.hpp: a point cloud). The unknowns are
// x = (w, [log scale], [λ]); the residual is, in this order,
//   r = (sensor rows, held tip, [wrist wrench], prior on w, [prior on log scale], [prior on λ]),
// each divided by its standard deviation (state_estimator.hpp's objective). The sensor rows come
// from a MeasurementBlock; the rest are the shared blocks below. Columns in w are exact (the
// integrator's node sensitivities); those in log scale and λ are forward differences.
#pragma once

#include <optional>
#include <string>

#include "rodshape/core/clamped_rod.hpp"
#include "rodshape/core/pose.hpp"
#include "rodshape/core/rod_configuration.hpp"
#include "rodshape/core/wrench.hpp"
#include "rodshape/feedback/marker_measurement.hpp"
#include "rodshape/feedback/state_estimator.hpp"

namespace rodshape::feedback_detail {

/// What a sensor contributes: its rows of r (weighted) and their columns in w.
class MeasurementBlock {
 public:
  virtual ~MeasurementBlock() = default;
  virtual int rows() const = 0;
  /// Writes r.segment(row, rows()) at `configuration` (of `rod`, the model with x's scale and
  /// λ applied) and, with J (AllNodes derivatives in `configuration`), J's rows there in w.
  virtual void evaluate(const ClampedRod& rod,
                        const RodConfiguration& configuration,
                        Eigen::VectorXd& r,
                        Eigen::MatrixXd* J,
                        int row) const = 0;
  /// Called once with the estimate's configuration and the residual's rows, after the fit (the
  /// cloud counts its outliers and reports the inliers' residual there). Default: nothing.
  virtual void finish(const ClampedRod& /*rod*/,
                      const RodConfiguration& /*configuration*/,
                      int /*total_rows*/,
                      StateEstimate& /*estimate*/) const {}
};

/// Where the arm holds the rod and what its wrist sensor says: the shared blocks' data.
struct HeldGrasp {
  Pose tip, end_effector;
  std::optional<Wrench> wrist;  // the measured wrench (absent: no wrist row)
  WristNoise wrist_noise;       // its standard deviations (before the floors)
};

/// Throws InputError for a prior, options or hypothesis out of range (the fit's own checks).
void validate_fit_input(const ClampedRod& model,
                        const StatePrior& prior,
                        const EstimationOptions& options,
                        const std::optional<StateHypothesis>& hypothesis);

/// The estimate that was not run: residual, χ² NaN, status NotRun, `why` its message.
StateEstimate nothing_measured(const std::string& why);

/// Fits x to `block`'s rows and the shared blocks, pulled to `prior` and starting from `start`
/// (else the prior's mean); its χ² is also evaluated at `hypothesis` (else the prior's mean).
/// Inputs must have passed validate_fit_input.
StateEstimate fit_state(const ClampedRod& model,
                        const MeasurementBlock& block,
                        const HeldGrasp& grasp,
                        const StatePrior& prior,
                        const EstimationOptions& options,
                        const std::optional<StateHypothesis>& hypothesis,
                        const std::optional<StateHypothesis>& start = std::nullopt);

}  // namespace rodshape::feedback_detail
