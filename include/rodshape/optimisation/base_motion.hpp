// base_motion.hpp: the base end (s = 0) held by a moving gripper (issue 21), as one shape
// optimisation sees it. Its variables become x = (w_b, ξ) ∈ R¹²: the base wrench in the base's
// frame, w_b = (R(0)ᵀ n(0), R(0)ᵀ m(0)), and the base pose about a reference pose T_ref,
//   p(0) = p_ref + δt,   R(0) = exp([δφ]×) R_ref,   ξ = (δt, δφ),
// with the world wrench w = (R(0) n_b, R(0) m_b). The cost gains the energy-free term
//   W_b W2 (|δt|² + L² |δφ|²) / L
// (the least motion of the base from T_ref, which makes a target that fixes the rod only up to a
// rigid motion unique; W2 the distance weight, so that W_b is a pure number).
#pragma once

#include <array>

#include "rodshape/core/pose.hpp"
#include "rodshape/optimisation/shape_constraints.hpp"
#include "rodshape/optimisation/workspace.hpp"

namespace rodshape {

struct BaseMotion {
  Pose reference;  // T_ref: ξ = 0 (the last step's base pose)
  /// Components of w_b the base gripper cannot transmit (force x, y, z, moment x, y, z): held at 0.
  std::array<bool, 6> released{};
  WrenchBounds wrench_bounds;  // on w_b (infinite: none)
  Workspace workspace;         // the set p(0) (and, with a reach shell, p(0) + R(0) t) stays in
  double motion_weight = 1e-3;  // W_b ≥ 0
  /// The largest |δφ_i| a step may turn the base by (a bound of the variables, rad).
  static constexpr double kMaxTurn = 1.5;
  /// Throws InputError naming "BaseMotion.<field>".
  void validate() const;
};

}  // namespace rodshape
