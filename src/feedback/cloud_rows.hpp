// cloud_rows.hpp (private): a cloud's rows of the state fit (cloud_estimator.hpp's residual): one
// per point, the Cauchy row of the point's distance to the model's surface over its noise along
// the direction from the centreline, and their columns in w.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "rodshape/feedback/cloud_estimator.hpp"
#include "rodshape/feedback/cloud_measurement.hpp"
#include "state_fit.hpp"

namespace rodshape::feedback_detail {

/// The Cauchy row r = sign(z) c √log(1 + z²/c²) (r² = 2 ρ_c(z), c = `scale`, kCauchyScale in the
/// fit proper) and its slope dr/dz = z / ((1 + z²/c²) r).
struct CauchyRow {
  double value = 0.0, slope = 1.0;
};
CauchyRow cauchy_row(double z, double scale);
/// The Cauchy weight 1/(1 + z²/c²) of a point z σ away, c = kCauchyScale.
double cauchy_weight(double z);

/// A cloud point's σ along a direction n (cloud_measurement.hpp's model: axial σ_z(z, θ) along the
/// camera's ray, θ the ray's angle to n, the surface's normal; lateral px z / f across it, f the
/// mean focal length), at least `floor`. The depth
/// is clamped to the camera's range, where the model holds.
class PointNoise {
 public:
  PointNoise(const DepthSensorModel& sensor, double floor);
  double along(const Eigen::Vector3d& x, const Eigen::Vector3d& direction) const;
  /// The noise's variance along the unit vector `u` of a point on a surface of normal `normal`:
  /// uᵀΣu, Σ = σ_z² e eᵀ + σ_lat² (I - e eᵀ), e the ray (no floor).
  double variance(const Eigen::Vector3d& x,
                  const Eigen::Vector3d& normal,
                  const Eigen::Vector3d& u) const;

 private:
  Pose camera_;
  DepthNoiseModel noise_;
  double min_range_, max_range_, focal_, floor_;
};

/// A point's offset √(ρ² + v_t) from the axis and σ (cloud_rows.cpp).
struct PointWeight {
  double offset = 0.0, sigma = 0.0;
};

/// One row per cloud point: the Cauchy row of z_k = d_k / σ_k, d_k = |x_k - Γ| - √(ρ² + v_t,k);
/// each point's √(ρ² + v_t) and σ_k are frozen at the first configuration evaluated (the fit's
/// start: the previous estimate, or a far start's plain fits), so the fit is a fixed weighted
/// least squares and its Jacobian exact.
class CloudRows final : public MeasurementBlock {
 public:
  /// The points of `seen` (which must outlive the rows) against the tube of `radius` about the
  /// centreline, with the Cauchy loss of scale `scale` (in σ); `noise_bias` false: the plain
  /// distance |x - Γ| - ρ at the normal's σ (the wide first fit of a far start, whose directions
  /// to a wrong centreline make the bias's estimate meaningless).
  CloudRows(const CloudFrame& seen,
            double radius,
            const DepthSensorModel& sensor,
            const EstimationOptions& options,
            double scale = kCauchyScale,
            bool noise_bias = true);
  /// The fraction of the points that are outliers (Cauchy weight below kOutlierWeight) at
  /// `configuration`.
  double outlier_fraction(const RodConfiguration& configuration) const;
  int rows() const override { return static_cast<int>(points_.size()); }
  void evaluate(const ClampedRod& rod,
                const RodConfiguration& configuration,
                Eigen::VectorXd& r,
                Eigen::MatrixXd* J,
                int row) const override;
  /// The points and outliers at the estimate, and the residual without the outliers, each
  /// inlier's row its plain z.
  void finish(const ClampedRod& rod,
              const RodConfiguration& configuration,
              int total_rows,
              StateEstimate& estimate) const override;
  /// z_k of every point at `configuration`.
  std::vector<double> weighted_distances(const RodConfiguration& configuration) const;

 private:
  void freeze(const RodConfiguration& configuration) const;

  const std::vector<Eigen::Vector3d>& points_;
  double radius_;
  PointNoise noise_;
  double scale_;
  bool noise_bias_;
  mutable std::vector<PointWeight> weights_;  // frozen at the first evaluate()
};

}  // namespace rodshape::feedback_detail
