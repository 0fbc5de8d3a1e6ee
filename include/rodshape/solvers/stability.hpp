// stability.hpp: stability of a clamped–clamped equilibrium by the conjugate-point test (Bretl and
// McCarthy, IJRR 2014): the equilibrium is stable iff J(s) = d(pose at s)/d(base wrench) is
// non-singular for every s in (0, L]. The same test is applied to the Cosserat model (Till and
// Rucker extend it to shearable, extensible rods).
#pragma once

#include <optional>

#include "rodshape/core/clamped_rod.hpp"
#include "rodshape/core/rod_configuration.hpp"

namespace rodshape {

struct StabilityResult {
  bool stable = false;
  /// Where the first conjugate point lies (J(s) singular), if any.
  std::optional<double> conjugate_point_s;
  /// min over nodes s_i > 0 of σ_min(J̃(s_i)), where J̃(s) = J(s) C(s)⁻¹ is J relative to the
  /// unloaded straight rod of length s (C(s) its compliance, in the clamp frame). J̃ = I for that
  /// rod, so 1 means "as controllable as the unloaded rod" and 0 a conjugate point.
  double min_singular_value = 0.0;
  /// σ_min(J̃(L)): how far the tip pose is from losing control of the shape.
  double tip_singular_value = 0.0;
  /// The test does not decide: J(s) is singular along the whole rod (a straight Kirchhoff rod,
  /// whose tip cannot move along its tangent), or only at s = L (a neutral direction, e.g. the
  /// planar buckled shape of a rod with EIx = EIy, which turns about the line of its clamps at no
  /// cost). `stable` is then false and means "not shown stable".
  bool degenerate = false;
  /// One line: "stable (min σ̃ = 0.43, at the tip 0.61)", "unstable: conjugate point at s = 0.12 m"
  /// or "not shown stable: degenerate (…)".
  std::string brief() const;
};

/// `configuration` must come from integrate(rod, ..., Derivatives::AllNodes). A sign change of
/// det J̃ between nodes is a conjugate point; so is a local minimum of σ_min that a finer search
/// inside its two intervals drives below 1e-6 (a double root, as in a round rod, keeps the sign).
StabilityResult assess_stability(const ClampedRod& rod, const RodConfiguration& configuration);

}  // namespace rodshape
