// equilibrium_answer.hpp: what `rodshape equilibrium` (and Python's rodshape.solve) computes for
// an equilibrium task: the free rod's analysis, or, with a scene, its equilibrium resting on the
// scene's touchable obstacles. One place, so that both faces answer a task alike.
#pragma once

#include <optional>
#include <string>

#include "rodshape/io/equilibrium_task.hpp"
#include "rodshape/solvers/contact_equilibrium.hpp"
#include "rodshape/solvers/equilibrium_analysis.hpp"

namespace rodshape {

struct EquilibriumAnswer {
  /// Without a scene: the analysis (stability, a stable equilibrium sought when unstable).
  std::optional<EquilibriumAnalysis> analysis;
  /// With a scene: the equilibrium resting on its obstacles (no stability verdict yet).
  std::optional<ContactEquilibriumResult> contact;

  const ShootingResult& solution() const;
  bool converged() const { return solution().summary.converged(); }
  /// The analysis' brief, or the solve's and the contacts'.
  std::string brief() const;
};

/// Solves `task`; an InputError (a held pose beyond the model's validity or inside an obstacle)
/// is rethrown in task-file names prefixed with task.source.
EquilibriumAnswer answer_equilibrium_task(const EquilibriumTask& task);

/// The JSON document `rodshape equilibrium` writes for `answer` to `task`.
std::string equilibrium_answer_json(const EquilibriumAnswer& answer, const EquilibriumTask& task);

}  // namespace rodshape
