// cloud_estimator.hpp: the rod's state from a depth camera's point cloud (issue 22): the same
// unknowns as estimate_state (state_estimator.hpp: the base wrench w, optionally the stiffness
// scale and the weight's factor λ, the held tip within its prior, the wrist wrench, a weak prior)
// with the markers' rows replaced by one point-to-surface row per cloud point x_k:
//   d_k(w) = |x_k - Γ(s_k; w)| - √(ρ² + v_t),  s_k = argmin_s |x_k - Γ(s; w)|,
// v_t the point's noise variance along the section's circle (across the normal: it moves a point
// away from the axis by v_t/(2ρ) on average, most where the ray grazes the tube; zero noise: the
// plain distance to the tube; src/feedback/cloud_rows.cpp),
// Γ the model's centreline (cubic Hermite between nodes, optimisation/curve_distance.hpp), s_k
// found by a k-d tree (nanoflann) over the nodes, then on the intervals next to the nearest one,
// and ρ the section's circumscribed radius: the rod's surface as the library knows it (the tube
// the scene's clearance keeps, the simulated depth camera's capsules; a point past an end is
// measured to the end node, the capsule's cap). Each d_k is divided by the point's noise along
// n_k = (x_k - Γ)/|x_k - Γ|, the surface's normal (cloud_measurement.hpp's model: axial σ_z(z, θ)
// along the camera's ray e, θ its angle to n_k; lateral σ = px z / f across it):
//   σ_k² = σ_z² (n_k·e)² + σ_lat² (1 - (n_k·e)²) + v_t²/(2ρ²),  σ_k ≥ min_cloud_sigma,
// and passed through the Cauchy loss ρ_c(z) = (c²/2) log(1 + z²/c²), c = kCauchyScale (in σ),
// as the row r_k = sign(z_k) √(2 ρ_c(z_k)) (Σ r_k² = 2 Σ ρ_c; r ≈ z near 0): a point 10 σ away
// weighs 1/18 of an inlier in the fit, so outliers do not drag it. Derivatives: dd_k/dw =
// -n_kᵀ dΓ(s_k)/dw exactly (the envelope argument: s_k is a minimiser; the integrator's node
// sensitivities), times the loss' slope over σ_k. Each point's √(ρ² + v_t) and σ_k are frozen
// at the fit's start (the previous estimate, or a far start's plain fits): the fit is then a
// fixed weighted least squares, its Jacobian exact (tests/feedback/test_cloud_estimator.cpp
// checks it against finite differences). A start far from the cloud (more than a quarter of the
// points outliers of its surface) is first fitted with the loss ten times as wide, which follows
// the cloud's bulk; the fit proper starts where that one ends.
#pragma once

#include <optional>
#include <string>

#include "rodshape/core/clamped_rod.hpp"
#include "rodshape/core/pose.hpp"
#include "rodshape/feedback/cloud_measurement.hpp"
#include "rodshape/feedback/state_estimator.hpp"

namespace rodshape {

/// The Cauchy loss' scale c, in units of a point's σ: 95 % efficiency at Gaussian noise.
inline constexpr double kCauchyScale = 2.3849;
/// A point whose Cauchy weight 1/(1 + z²/c²) at the estimate is below this (|z| > 3c ≈ 7.2 σ)
/// is an outlier (StateEstimate::outliers); it is left out of StateEstimate::residual.
inline constexpr double kOutlierWeight = 0.1;
/// The most points a cloud may have (a Kinect v2 frame has 512 × 424 = 217 088 pixels).
inline constexpr int kMaxCloudPoints = 1'000'000;
/// A cloud estimate is explained when at most this fraction of its points are outliers (and its
/// residual is within the caller's bound: explains_cloud).
inline constexpr double kMaxOutlierFraction = 0.5;

/// Estimates the state of `model` held at `tip` (the prior of the tip pose) from the cloud `seen`
/// (world frame) of `sensor`, the gripper at `end_effector` (for the wrist wrench, whose sensor is
/// sensor.wrist, its noise divided by √seen.frames), starting from and pulled to `prior`; its χ²
/// is also evaluated at `hypothesis`. StateEstimate::chi2 and prior_chi2 are the robust objective
/// Σ r² (near the truth the inliers' rows are ≈ z, so the drop prior_chi2 - chi2 is still about χ²
/// with `parameters` degrees of freedom); StateEstimate::residual is the RMS of the weighted rows
/// with the outliers left out, each inlier's row its plain z (about 1 at the sensor's noise);
/// points and outliers count the cloud. An empty cloud without a wrist wrench is NotRun. Throws
/// InputError for a bad sensor model, options or prior, a non-finite point, or more than
/// kMaxCloudPoints points.
StateEstimate estimate_state_from_cloud(
    const ClampedRod& model,
    const Pose& tip,
    const Pose& end_effector,
    const CloudFrame& seen,
    const DepthSensorModel& sensor,
    const StatePrior& prior,
    const EstimationOptions& options = {},
    const std::optional<StateHypothesis>& hypothesis = std::nullopt);

/// Empty when `estimate` (from a cloud or markers) is one the model explains: converged, its
/// residual ≤ max_residual and at most kMaxOutlierFraction of its points outliers; else why not,
/// one sentence ("the model does not explain the cloud: residual 3.1 > 2").
std::string unexplained(const StateEstimate& estimate, double max_residual);

}  // namespace rodshape
