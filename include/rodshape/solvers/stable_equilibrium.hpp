// stable_equilibrium.hpp: from an unstable equilibrium to a stable one with the same boundary
// condition. A rod held at both ends can rest in several equilibria; a cold solve may converge to
// an unstable one (e.g. the planar shape of a compressed band, which buckles out of plane). The
// search loads the rod with a small distributed force across its shape (an imperfection that
// breaks the symmetry), solves, and removes the load step by step (halving it, each solve direct
// from the last), so that the rod settles on a neighbouring branch; the stable equilibrium of
// least energy is kept.
#pragma once

#include <string>

#include "rodshape/core/clamped_rod.hpp"
#include "rodshape/solvers/shooting_solver.hpp"
#include "rodshape/solvers/stability.hpp"
#include "rodshape/solvers/tip_condition.hpp"

namespace rodshape {

struct StableEquilibriumResult {
  bool found = false;
  ShootingResult solution;    // the stable equilibrium when found (all-node derivatives)
  StabilityResult stability;  // its verdict
  int solves = 0;             // perturbed solves tried
  /// What was done ("… a stable one of energy 1.2 J was found by loading the rod across its
  /// shape …"), or why none was found.
  std::string message;
  std::string brief() const { return message; }
};

/// Seeks a stable equilibrium of `rod` held by `tip` near the converged, unstable `unstable`
/// (with its StabilityResult `verdict`). Imperfection loads of 0.3, 1 and 3 EI/L³ per length,
/// both ways along the axis of least spread of the shape (the normal of a planar shape); each is
/// halved eight times and then removed (10 direct solves). Among the stable equilibria found at
/// the first magnitude that gives any, the least energy wins. At most 60 direct solves.
StableEquilibriumResult seek_stable_equilibrium(const ClampedRod& rod,
                                                const TipCondition& tip,
                                                const ShootingResult& unstable,
                                                const StabilityResult& verdict,
                                                const ShootingOptions& options = {});

}  // namespace rodshape
