// cloud_estimator.cpp: the cloud's point-to-surface rows (cloud_estimator.hpp), fitted by the
// shared core with the held tip, the wrist wrench and the priors (state_fit.hpp).
#include "rodshape/feedback/cloud_estimator.hpp"

#include <cmath>
#include <sstream>
#include <string>

#include "cloud_rows.hpp"
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
  const feedback_detail::CloudRows cloud(seen, model.properties.section->circumscribed_radius(),
                                         sensor, options);
  return feedback_detail::fit_state(model, cloud, grasp, prior, options, hypothesis);
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
