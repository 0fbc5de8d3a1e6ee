// result_json.cpp: the equilibrium result document (schema in docs/task-file.md): the solver's
// account of the solve, then the configuration as json_format.cpp writes it (shared with `plan`).
#include "rodshape/io/result_json.hpp"

#include <string>

#include "io/json_format.hpp"
#include "rodshape/core/rod_properties.hpp"
#include "rodshape/solvers/solve_status.hpp"

namespace rodshape {

namespace {

using io_detail::Json;

Json result_document(const ShootingResult& solution,
                     const std::optional<StabilityResult>& stability,
                     const ClampedRod& rod) {
  const ShootingSummary& summary = solution.summary;

  Json result;
  result["status"] = to_string(summary.status);
  result["message"] = summary.message;
  result["residual"] = io_detail::json_number(summary.residual_norm);
  result["iterations"] = summary.iterations;
  result["chord_steps"] = summary.chord_steps;
  result["integrations"] = summary.integrations;
  result["jacobian_evaluations"] = summary.jacobian_evaluations;
  result["continuation_steps"] = summary.continuation_steps;
  result["integration_error"] = io_detail::json_number(summary.integration_error);
  result["substeps"] = summary.substeps;
  result.update(io_detail::configuration_json(solution.configuration, solution.base_wrench,
                                              stability, rod.properties));
  return result;
}

Json stable_search_json(const std::optional<StableEquilibriumResult>& search,
                        double solved_energy) {
  if (!search) return nullptr;
  Json j;
  j["found"] = search->found;
  j["solves"] = search->solves;
  j["message"] = search->message;
  j["solved_energy"] = io_detail::json_number(solved_energy);
  return j;
}

}  // namespace

std::string equilibrium_result_json(const ShootingResult& solution,
                                    const std::optional<StabilityResult>& stability,
                                    const ClampedRod& rod) {
  return io_detail::format_json(result_document(solution, stability, rod));
}

std::string equilibrium_result_json(const EquilibriumAnalysis& analysis) {
  Json result = result_document(analysis.solution, analysis.stability, analysis.rod);
  result["stable_search"] = stable_search_json(analysis.stable_search, analysis.solved_energy);
  return io_detail::format_json(result);
}

}  // namespace rodshape
