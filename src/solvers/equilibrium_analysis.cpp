// equilibrium_analysis.cpp: solve, check the model's validity, assess stability, and seek a stable
// equilibrium when the solve's is unstable: four named stages.
#include "rodshape/solvers/equilibrium_analysis.hpp"

#include <utility>
#include <variant>

#include "rodshape/solvers/model_validity.hpp"
#include "rodshape/solvers/rod_reach.hpp"

namespace rodshape {

namespace {

/// Where a held tip's pose lives, for messages; empty for a free tip.
const char* held_pose_field(const TipCondition& tip) {
  if (std::holds_alternative<ClampedTip>(tip)) return "ClampedTip.pose";
  if (std::holds_alternative<GraspedTip>(tip)) return "GraspedTip.pose";
  return "";
}

/// Stage 2: a pose the user holds the tip at must not ask the model for more than it can say.
void check_held_pose(const EquilibriumAnalysis& analysis,
                     const TipCondition& tip,
                     const ShootingOptions& shooting) {
  const std::string field = held_pose_field(tip);
  if (field.empty()) return;
  check_model_validity(analysis.rod.properties, analysis.solution.configuration,
                       shooting.strain_limits, field, "ShootingOptions.strain_limits");
}

/// Stage 0: a held tip farther than the rod reaches within the model's range has no equilibrium
/// worth solving for.
void check_held_reach(const ClampedRod& rod,
                      const TipCondition& tip,
                      const ShootingOptions& shooting) {
  const std::string field = held_pose_field(tip);
  if (field.empty()) return;
  rod.validate();  // its length and strains first: the reach is made of them
  shooting.validate();
  check_within_reach(rod, tip, shooting.strain_limits, field, "ShootingOptions.strain_limits");
}

/// Stage 4: replace an unstable equilibrium by a stable one with the same boundary condition.
void seek_stable(EquilibriumAnalysis& analysis,
                 const TipCondition& tip,
                 const ShootingOptions& shooting) {
  StableEquilibriumResult search =
      seek_stable_equilibrium(analysis.rod, tip, analysis.solution, *analysis.stability, shooting);
  if (search.found) {
    analysis.solution = std::move(search.solution);
    analysis.rod.substeps = analysis.solution.summary.substeps;
    analysis.stability = search.stability;
    search.solution = {};  // held once, in analysis.solution
  }
  analysis.stable_search = std::move(search);
}

}  // namespace

std::string EquilibriumAnalysis::brief() const {
  std::string text = solution.summary.brief();
  if (stability) text += stability->stable ? ", stable" : ", unstable";
  if (stable_search) text += "; " + stable_search->message;
  return text;
}

EquilibriumAnalysis analyse_equilibrium(const ClampedRod& rod,
                                        const TipCondition& tip,
                                        const BaseWrench& initial,
                                        const ShootingOptions& shooting,
                                        const EquilibriumAnalysisOptions& options) {
  check_held_reach(rod, tip, shooting);
  // Stage 1: the shooting solve; the stability test needs the derivatives at every node.
  ShootingOptions solve = shooting;
  solve.output_derivatives = Derivatives::AllNodes;
  EquilibriumAnalysis analysis;
  analysis.solution = solve_equilibrium(rod, tip, initial, solve);
  analysis.rod = rod;
  analysis.rod.substeps = analysis.solution.summary.substeps;
  analysis.solved_energy = analysis.solution.configuration.energy;
  if (!analysis.converged()) return analysis;

  check_held_pose(analysis, tip, solve);
  // Stage 3: the second variation's verdict (conjugate points).
  analysis.stability = assess_stability(analysis.rod, analysis.solution.configuration, tip);
  if (!analysis.stability->stable && options.seek_stable) seek_stable(analysis, tip, solve);
  return analysis;
}

}  // namespace rodshape
