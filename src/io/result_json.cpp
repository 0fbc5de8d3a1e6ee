// result_json.cpp: the equilibrium result document (schema in docs/task-file.md): the solver's
// account of the solve, then the configuration as json_format.cpp writes it (shared with `plan`).
#include "rodshape/io/result_json.hpp"

#include <cmath>
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

Json matrix_json(const Matrix6d& m) {
  Json rows = Json::array();
  for (int i = 0; i < 6; ++i) {
    Json row = Json::array();
    for (int j = 0; j < 6; ++j) row.push_back(io_detail::json_number(m(i, j)));
    rows.push_back(row);
  }
  return rows;
}

Json fit_json(const EstimateTask& task, const CloudEstimate& result) {
  const StateEstimate& e = result.estimate;
  Json fit;
  fit["status"] = to_string(e.status);
  fit["explained"] = result.explained();
  fit["message"] = result.explained() ? "the model explains the cloud" : result.unexplained;
  fit["residual"] = io_detail::json_number(e.residual);
  fit["max_residual"] = task.max_residual;
  fit["chi2"] = io_detail::json_number(e.chi2);
  fit["prior_chi2"] = io_detail::json_number(e.prior_chi2);
  fit["parameters"] = e.parameters;
  fit["iterations"] = e.iterations;
  fit["points"] = e.points;
  fit["used"] = e.points - e.outliers;
  fit["rejected"] = e.outliers;
  fit["robust_loss"] = {{"kind", "cauchy"}, {"scale", kCauchyScale}};
  Json sigma = Json::array();
  for (int k = 0; k < 6; ++k)
    sigma.push_back(io_detail::json_number(std::sqrt(e.base_wrench_covariance(k, k))));
  fit["base_wrench_sigma"] = sigma;
  fit["base_wrench_covariance"] = matrix_json(e.base_wrench_covariance);
  fit["tip_covariance"] = matrix_json(e.tip_covariance);
  if (!e.configuration.p.empty() && result.prior.summary.converged()) {
    const Pose held = result.prior.configuration.tip(), estimated = e.configuration.tip();
    fit["tip_offset"] = io_detail::json_pose(compose(inverse(held), estimated));
  } else {
    fit["tip_offset"] = nullptr;
  }
  return fit;
}

}  // namespace

std::string estimate_result_json(const EstimateTask& task, const CloudEstimate& result) {
  ShootingResult solution;
  solution.summary.status = result.estimate.status;
  solution.summary.message = result.estimate.message;
  solution.summary.iterations = result.estimate.iterations;
  solution.base_wrench = result.estimate.base_wrench;
  solution.configuration = result.estimate.configuration;
  if (solution.configuration.p.empty()) {  // not run: the task's own equilibrium
    solution.configuration = result.prior.configuration;
    solution.base_wrench = result.prior.base_wrench;
  }
  const ClampedRod rod = estimated_rod(task.equilibrium.rod, result.estimate.stiffness_scale,
                                       result.estimate.load_factor, task.options.gravity);
  Json document = result_document(solution, std::nullopt, rod);
  document["fit"] = fit_json(task, result);
  return io_detail::format_json(document);
}

std::string equilibrium_result_json(const ShootingResult& solution,
                                    const std::optional<StabilityResult>& stability,
                                    const ClampedRod& rod) {
  return io_detail::format_json(result_document(solution, stability, rod));
}

std::string contact_equilibrium_result_json(const ContactEquilibriumResult& result,
                                            const ClampedRod& rod,
                                            const Scene& scene) {
  Json document = result_document(result.shooting, std::nullopt, rod);
  document["least_gap"] = io_detail::json_number(result.least_gap);
  Json contacts = Json::array();
  for (const RodContact& c : result.contacts) {
    const Obstacle& o = scene.obstacles[static_cast<std::size_t>(c.obstacle)];
    Json entry;
    entry["obstacle"] = o.name.empty() ? Json(c.obstacle) : Json(o.name);
    entry["s"] = {io_detail::json_number(c.s_start), io_detail::json_number(c.s_end)};
    entry["force"] = {io_detail::json_number(c.force.x()), io_detail::json_number(c.force.y()),
                      io_detail::json_number(c.force.z())};
    entry["max_line_force"] = io_detail::json_number(c.max_line_force);
    entry["end_forces"] = {io_detail::json_number(c.start_force),
                           io_detail::json_number(c.end_force)};
    entry["sticking"] = nullptr;
    contacts.push_back(entry);
  }
  document["contacts"] = contacts;
  return io_detail::format_json(document);
}

std::string equilibrium_result_json(const EquilibriumAnalysis& analysis) {
  Json result = result_document(analysis.solution, analysis.stability, analysis.rod);
  result["stable_search"] = stable_search_json(analysis.stable_search, analysis.solved_energy);
  return io_detail::format_json(result);
}

}  // namespace rodshape
