// result_json.cpp: the equilibrium result document (schema in docs/task-file.md): the solver's
// account of the solve, then the configuration as json_format.cpp writes it (shared with `plan`).
#include "rodshape/io/result_json.hpp"

#include <string>

#include "io/json_format.hpp"
#include "rodshape/core/rod_properties.hpp"
#include "rodshape/solvers/solve_status.hpp"

namespace rodshape {

std::string equilibrium_result_json(const ShootingResult& solution,
                                    const std::optional<StabilityResult>& stability,
                                    const ClampedRod& rod) {
  using io_detail::Json;
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
  result.update(io_detail::configuration_json(solution.configuration, solution.base_wrench,
                                              stability, rod.properties.model));
  return io_detail::format_json(result);
}

}  // namespace rodshape
