// stability.hpp: stability of a clamped–clamped equilibrium by the conjugate-point test (Bretl and
// McCarthy, IJRR 2014): the equilibrium is stable iff J(s) = d(pose at s)/d(base wrench) is
// non-singular for every s in (0, L]. The same test is applied to the Cosserat model (Till and
// Rucker extend it to shearable, extensible rods).
#pragma once

#include <optional>

#include "rodshape/core/clamped_rod.hpp"
#include "rodshape/core/rod_configuration.hpp"

namespace rodshape {

struct StabilityReport {
  bool stable = false;
  /// Where the first conjugate point lies (J(s) singular), if any.
  std::optional<double> conjugate_point_s;
  /// min over nodes s_i > 0 of σ_min(J̃(s_i)), where J̃ = diag(1/s, 1/s, 1/s, 1, 1, 1) J
  /// diag(EI/s², EI/s², EI/s², EI/s, EI/s, EI/s) is J made dimensionless with the scales of a
  /// cantilever of length s (EI the mean of EIx and EIy). J̃ tends to a constant as s → 0 (its
  /// bending blocks to [[1/3, 1/2], [1/2, 1]]), so this is comparable along the rod; 0 at a
  /// conjugate point.
  double min_singular_value = 0.0;
  /// σ_min(J̃(L)): how far the tip pose is from losing control of the shape.
  double tip_singular_value = 0.0;
  /// J(s) is singular along the whole rod, so the test does not apply: a straight Kirchhoff rod,
  /// whose tip cannot move along its tangent. `stable` is then false and means "not shown stable".
  bool degenerate = false;
};

/// `configuration` must come from integrate(rod, ..., Derivatives::AllNodes). A sign change of
/// det J̃ between nodes is a conjugate point; so is a local minimum of σ_min that a finer search
/// inside its two intervals drives below 1e-6 (a double root, as in a round rod, keeps the sign).
StabilityReport assess_stability(const ClampedRod& rod, const RodConfiguration& configuration);

}  // namespace rodshape
