// result_json.hpp: an equilibrium result as JSON text (the schema is in docs/task-file.md).
// Non-finite numbers are written as null. The JSON library stays private to rodshape.
#pragma once

#include <optional>
#include <string>

#include "rodshape/core/clamped_rod.hpp"
#include "rodshape/io/estimate_task.hpp"
#include "rodshape/solvers/contact_equilibrium.hpp"
#include "rodshape/solvers/equilibrium_analysis.hpp"
#include "rodshape/solvers/shooting_solver.hpp"
#include "rodshape/solvers/stability.hpp"

namespace rodshape {

/// The whole result document, ending with a newline. `stability` is absent when it was not assessed
/// (a free tip, or a solve that did not converge): "stable" and "stability" are then null.
std::string equilibrium_result_json(const ShootingResult& solution,
                                    const std::optional<StabilityResult>& stability,
                                    const ClampedRod& rod);
/// The document for an analysed equilibrium (what `rodshape equilibrium` writes): as above, plus
/// `stable_search`: null when no search was made, else {found, solves, message, solved_energy}
/// (the energy of the solve's own, unstable equilibrium, J).
std::string equilibrium_result_json(const EquilibriumAnalysis& analysis);

/// The document of an equilibrium resting on a scene's obstacles: as above with stability null
/// (not assessed with contacts), plus `least_gap` (m) and `contacts`, a list of {obstacle (its
/// name, or its index), s: [s_start, s_end] (equal for a point contact), force (the whole reaction
/// on the rod, N, world frame), max_line_force (N/m), end_forces: [at s_start, at s_end] (the
/// concentrated reactions, N), sticking (null: frictionless)}.
std::string contact_equilibrium_result_json(const ContactEquilibriumResult& result,
                                            const ClampedRod& rod,
                                            const Scene& scene);
/// The document `rodshape estimate` writes (docs/estimate.md): the estimated equilibrium in the
/// equilibrium document's keys (status and message the fit's; residual, integration_error and
/// stability null: no shooting solve and no stability test), plus `fit`: explained, why not,
/// the fit's residual, chi2, prior_chi2, parameters, iterations, points, used, rejected, the robust
/// loss, the base wrench's covariance and sigmas, the tip's covariance and the estimated tip's
/// offset from the task's held tip.
std::string estimate_result_json(const EstimateTask& task, const CloudEstimate& result);

}  // namespace rodshape
