// equilibrium_analysis.hpp: what `rodshape equilibrium` (and Python's rodshape.solve) do with a
// clamped rod and its tip condition: solve for the base wrench (shooting), check that a held pose
// stays within the model's validity, assess the equilibrium's stability and, when it is unstable,
// seek a stable equilibrium with the same boundary condition and return that instead.
#pragma once

#include <optional>
#include <string>

#include "rodshape/core/clamped_rod.hpp"
#include "rodshape/core/wrench.hpp"
#include "rodshape/solvers/shooting_solver.hpp"
#include "rodshape/solvers/stability.hpp"
#include "rodshape/solvers/stable_equilibrium.hpp"
#include "rodshape/solvers/tip_condition.hpp"

namespace rodshape {

struct EquilibriumAnalysisOptions {
  /// When the solve's equilibrium is unstable, look for a stable one (seek_stable_equilibrium).
  bool seek_stable = true;
};

struct EquilibriumAnalysis {
  /// The equilibrium returned: the stable one found when the solve's was unstable and the search
  /// succeeded, else the solve's own (derivatives at every node).
  ShootingResult solution;
  /// The rod with the sub-steps `solution` was integrated with.
  ClampedRod rod;
  /// The verdict on `solution`; absent when the solve did not converge.
  std::optional<StabilityResult> stability;
  /// The search for a stable equilibrium, when the solve's was unstable and seek_stable was set.
  std::optional<StableEquilibriumResult> stable_search;
  /// Energy of the solve's own equilibrium (J), whether or not it was replaced.
  double solved_energy = 0.0;

  bool converged() const { return solution.summary.converged(); }
  /// "converged, |r| = …, 12 iterations, …, stable" plus what the stability search did.
  std::string brief() const;
};

/// Solves `rod` held by `tip` from `initial` (shooting), then: for a held tip (clamped or
/// grasped), check_model_validity on the converged shape (throws InputError naming
/// "ClampedTip.pose" or "GraspedTip.pose"); assess_stability; and, when unstable and
/// options.seek_stable, seek_stable_equilibrium, returning the stable equilibrium it finds.
EquilibriumAnalysis analyse_equilibrium(const ClampedRod& rod,
                                        const TipCondition& tip,
                                        const BaseWrench& initial = {},
                                        const ShootingOptions& shooting = {},
                                        const EquilibriumAnalysisOptions& options = {});

}  // namespace rodshape
