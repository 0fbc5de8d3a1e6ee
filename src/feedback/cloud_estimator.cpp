// cloud_estimator.cpp: the cloud's point-to-surface rows (cloud_estimator.hpp), fitted by the
// shared core with the held tip, the wrist wrench and the priors (state_fit.hpp).
#include "rodshape/feedback/cloud_estimator.hpp"

#include <cmath>
#include <sstream>
#include <string>

#include "cloud_rows.hpp"
#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/error.hpp"
#include "state_fit.hpp"

namespace rodshape {

namespace {

void validate_cloud(const CloudFrame& seen) {
  if (seen.points.size() > static_cast<std::size_t>(kMaxCloudPoints))
    throw InputError("CloudFrame.points", ": " + std::to_string(seen.points.size()) +
                                              " points, more than " +
                                              std::to_string(kMaxCloudPoints));
  for (std::size_t k = 0; k < seen.points.size(); ++k)
    if (!seen.points[k].allFinite())
      throw InputError("CloudFrame.points[" + std::to_string(k) + "]", " is not finite");
  if (seen.frames < 1)
    throw InputError("CloudFrame.frames", " = " + std::to_string(seen.frames) + " must be >= 1");
}

/// Where the fit starts when the prior's rod is far from the cloud (more than kFarStart of the
/// points outliers of its surface, as a cold start may be; a warm start's are the cloud's own
/// outliers): a first fit with the loss kWideScale times as wide, which follows the cloud's bulk
/// instead of discounting it, then one with the plain distances (no noise bias); else the prior's
/// mean (nullopt).
std::optional<StateHypothesis> wide_start(const ClampedRod& model,
                                          const CloudFrame& seen,
                                          double radius,
                                          const DepthSensorModel& sensor,
                                          const feedback_detail::HeldGrasp& grasp,
                                          const StatePrior& prior,
                                          const EstimationOptions& options) {
  constexpr double kWideScale = 10.0, kFarStart = 0.25;
  const feedback_detail::CloudRows wide(seen, radius, sensor, options, kWideScale * kCauchyScale,
                                        false);
  const RodConfiguration at_prior =
      integrate(estimated_rod(model, prior.stiffness_scale, prior.load_factor, options.gravity),
                prior.base_wrench);
  if (wide.outlier_fraction(at_prior) <= kFarStart) return std::nullopt;
  const StateEstimate first =
      feedback_detail::fit_state(model, wide, grasp, prior, options, std::nullopt);
  if (!first.converged() && first.status != SolveStatus::IterationLimit) return std::nullopt;
  // then the plain distances at the loss's own scale: near the rod, where the noise's outward
  // bias (cloud_rows.cpp) can be weighed
  const feedback_detail::CloudRows plain(seen, radius, sensor, options, kCauchyScale, false);
  const StateEstimate second = feedback_detail::fit_state(
      model, plain, grasp, prior, options, std::nullopt,
      StateHypothesis{first.base_wrench, first.stiffness_scale, first.load_factor});
  const StateEstimate& near = second.converged() ? second : first;
  return StateHypothesis{near.base_wrench, near.stiffness_scale, near.load_factor};
}

}  // namespace

StateEstimate estimate_state_from_cloud(const ClampedRod& model,
                                        const Pose& tip,
                                        const Pose& end_effector,
                                        const CloudFrame& seen,
                                        const DepthSensorModel& sensor,
                                        const StatePrior& prior,
                                        const EstimationOptions& options,
                                        const std::optional<StateHypothesis>& hypothesis) {
  sensor.validate();
  validate_cloud(seen);
  feedback_detail::validate_fit_input(model, prior, options, hypothesis);
  if (!model.properties.section)
    throw InputError(
        "RodProperties.section",
        ": the rod's section is not known, so its surface cannot be fitted to a cloud");
  const double averaged = std::sqrt(static_cast<double>(seen.frames));
  const WristNoise wrist = sensor.wrist.value_or(WristNoise{});
  feedback_detail::HeldGrasp grasp{tip, end_effector, seen.wrist,
                                   WristNoise{wrist.force / averaged, wrist.moment / averaged}};
  if (!sensor.wrist) grasp.wrist.reset();
  if (seen.points.empty() && !grasp.wrist)
    return feedback_detail::nothing_measured(
        "nothing was measured: the cloud has no point and there is no wrist wrench");
  const double radius = model.properties.section->circumscribed_radius();
  const feedback_detail::CloudRows cloud(seen, radius, sensor, options);
  return feedback_detail::fit_state(model, cloud, grasp, prior, options, hypothesis,
                                    wide_start(model, seen, radius, sensor, grasp, prior, options));
}

std::string unexplained(const StateEstimate& estimate, double max_residual) {
  if (!estimate.converged()) return estimate.message;
  std::ostringstream out;
  out.precision(3);
  const char* what = estimate.points > 0 ? "the cloud" : "the markers";
  if (estimate.points > 0 && estimate.outliers > kMaxOutlierFraction * estimate.points) {
    out << "the model does not explain " << what << ": " << estimate.outliers << " of "
        << estimate.points << " points are outliers (more than " << kMaxOutlierFraction * 100
        << " %)";
    return out.str();
  }
  if (!(estimate.residual <= max_residual)) {
    out << "the model does not explain " << what << " (residual " << estimate.residual
        << " > max_residual " << max_residual << ")";
    return out.str();
  }
  return {};
}

}  // namespace rodshape
