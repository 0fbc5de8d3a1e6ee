// bind_optimisation.cpp: shape targets, their feasibility, and the paper's shape optimisation over
// the base wrench (ShapeProblem solved by IPOPT).
#include <array>
#include <optional>
#include <utility>

#include "bindings.hpp"
#include "rodshape/optimisation/shape_optimiser.hpp"
#include "rodshape/optimisation/shape_problem.hpp"
#include "rodshape/optimisation/shape_target.hpp"

namespace rodshape::python {

namespace {

using PointRows = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;

std::vector<Eigen::Vector3d> points_of(const PointRows& rows) {
  std::vector<Eigen::Vector3d> points;
  points.reserve(static_cast<std::size_t>(rows.rows()));
  for (Eigen::Index i = 0; i < rows.rows(); ++i) points.emplace_back(rows.row(i).transpose());
  return points;
}

void bind_target(py::module_& m) {
  py::class_<ShapeTarget>(m, "ShapeTarget",
                          "The wanted shape: k objective points (ordered from the clamp to the "
                          "tip) and the weights of F = W1 E / L + W2 Σ dist(Γ, p_obj,i).")
      .def(py::init([](const PointRows& points, double energy_weight, double distance_weight) {
             ShapeTarget target;
             target.points = points_of(points);
             target.energy_weight = energy_weight;
             target.distance_weight = distance_weight;
             return target;
           }),
           py::arg("points"), py::arg("energy_weight") = ShapeTarget{}.energy_weight,
           py::arg("distance_weight") = ShapeTarget{}.distance_weight)
      .def_property(
          "points", [](const ShapeTarget& t) { return read_only(rows_of(t.points)); },
          [](ShapeTarget& t, const PointRows& points) { t.points = points_of(points); },
          "(k, 3) objective points p_obj,i, m, world frame (read-only: assign a whole array)")
      .def_readwrite("energy_weight", &ShapeTarget::energy_weight, "W1 ≥ 0")
      .def_readwrite("distance_weight", &ShapeTarget::distance_weight, "W2 ≥ 0")
      .def_readwrite("squared_distances", &ShapeTarget::squared_distances)
      .def_readwrite("distance_smoothing", &ShapeTarget::distance_smoothing, "δ, m")
      .def("validate", &ShapeTarget::validate, "Raises InputError naming the field.");
  py::class_<FeasibilityResult>(m, "FeasibilityResult")
      .def_readonly("feasible", &FeasibilityResult::feasible)
      .def_readonly("reason", &FeasibilityResult::reason)
      .def_readonly("offending_point", &FeasibilityResult::offending_point)
      .def_readonly("curve_length", &FeasibilityResult::curve_length, "m")
      .def_readonly("reach", &FeasibilityResult::reach, "m")
      .def_readonly("arc_lengths", &FeasibilityResult::arc_lengths, "per point, m")
      .def("brief", &FeasibilityResult::brief);
  m.def("check_feasibility", &check_feasibility, py::arg("target"), py::arg("rod"),
        py::arg("max_axial_strain") = 0.0,
        "Whether a rod clamped at rod.clamp can pass through the target's points (judged on the "
        "chord-length spline through them).");
}

void bind_options_and_result(py::module_& m) {
  py::class_<ShapeOptimiserOptions>(m, "ShapeOptimiserOptions")
      .def(py::init<>())
      .def_readwrite("max_iterations", &ShapeOptimiserOptions::max_iterations)
      .def_readwrite("tolerance", &ShapeOptimiserOptions::tolerance)
      .def_readwrite("constraint_tolerance", &ShapeOptimiserOptions::constraint_tolerance)
      .def_readwrite("multi_starts", &ShapeOptimiserOptions::multi_starts)
      .def_readwrite("print_level", &ShapeOptimiserOptions::print_level)
      .def_readwrite("assess_stability", &ShapeOptimiserOptions::assess_stability)
      .def_readwrite("confine_to_scale", &ShapeOptimiserOptions::confine_to_scale)
      .def("validate", &ShapeOptimiserOptions::validate);
  py::class_<ShapeCostBreakdown>(m, "ShapeCostBreakdown")
      .def_readonly("cost", &ShapeCostBreakdown::cost, "F")
      .def_readonly("energy", &ShapeCostBreakdown::energy, "E, J")
      .def_readonly("energy_term", &ShapeCostBreakdown::energy_term, "W1 E / L")
      .def_readonly("distance_term", &ShapeCostBreakdown::distance_term, "W2 Σ dist")
      .def_readonly("distances", &ShapeCostBreakdown::distances, "per objective point, m")
      .def_readonly("max_distance", &ShapeCostBreakdown::max_distance, "m");
  py::class_<ShapeResult>(m, "ShapeResult", "An optimal shape: its base wrench and configuration.")
      .def_property_readonly("status", [](const ShapeResult& r) { return to_string(r.status); })
      .def_readonly("message", &ShapeResult::message)
      .def_readonly("base_wrench", &ShapeResult::base_wrench)
      .def_readonly("configuration", &ShapeResult::configuration)
      .def_readonly("cost", &ShapeResult::cost)
      .def_readonly("max_constraint_violation", &ShapeResult::max_constraint_violation)
      .def_readonly("stability", &ShapeResult::stability, "a StabilityResult, or None")
      .def_property_readonly("iterations", [](const ShapeResult& r) { return r.ipopt.iterations; })
      .def_readonly("starts_tried", &ShapeResult::starts_tried)
      .def("converged", &ShapeResult::converged)
      .def("brief", &ShapeResult::brief);
}

/// The paper's problem without an arm: the grasp's released components and the strain limits as
/// keywords, the workspace unbounded unless a box is given.
ShapeResult optimise(const ClampedRod& rod,
                     const ShapeTarget& target,
                     const BaseWrench& guess,
                     const ShapeOptimiserOptions& options,
                     const std::array<bool, 6>& released,
                     std::optional<double> max_curvature,
                     std::optional<double> max_axial_strain,
                     std::optional<std::pair<Eigen::Vector3d, Eigen::Vector3d>> box) {
  Workspace workspace;
  if (box) workspace.box = Workspace::Box{box->first, box->second};
  Grasp grasp;
  grasp.released = released;
  StrainLimits limits;
  limits.max_curvature = max_curvature;
  limits.max_axial_strain = max_axial_strain;
  ShapeProblem problem(rod, target, workspace, grasp, limits);
  return optimise_shape(problem, guess, options);
}

}  // namespace

void bind_optimisation(py::module_& m) {
  bind_target(m);
  bind_options_and_result(m);
  m.def("optimise_shape", &optimise, py::arg("rod"), py::arg("target"),
        py::arg("guess") = BaseWrench{}, py::arg("options") = ShapeOptimiserOptions{},
        py::arg("released") = std::array<bool, 6>{}, py::arg("max_curvature") = py::none(),
        py::arg("max_axial_strain") = py::none(), py::arg("box") = py::none(),
        py::call_guard<py::gil_scoped_release>(),
        "The base wrench minimising F for `target` (IPOPT, started from `guess`): a ShapeResult. "
        "`released`: the six grasp-frame tip wrench components (fx, fy, fz, mx, my, mz) the grasp "
        "cannot transmit; `max_curvature` (1/m) and `max_axial_strain` bound the strain at every "
        "node; `box`: (lower, upper) corners, m, the tip must stay in. Raises InputError for bad "
        "input; a failed solve is a status.");
}

}  // namespace rodshape::python
