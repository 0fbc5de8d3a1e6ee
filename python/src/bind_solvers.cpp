// bind_solvers.cpp: tip conditions, the shooting solver, stability, the analysed equilibrium and
// the equilibrium resting on obstacles.
#include "bindings.hpp"
#include "rodshape/solvers/contact_equilibrium.hpp"
#include "rodshape/solvers/equilibrium_analysis.hpp"
#include "rodshape/solvers/shooting_solver.hpp"
#include "rodshape/solvers/solve_status.hpp"
#include "rodshape/solvers/stability.hpp"
#include "rodshape/solvers/tip_condition.hpp"

namespace rodshape::python {

namespace {

void bind_tips(py::module_& m) {
  py::class_<FreeTip>(m, "FreeTip", "Clamped–free: the tip carries a given wrench (world frame).")
      .def(py::init([](const Wrench& w) { return FreeTip{w}; }), py::arg("wrench") = Wrench{})
      .def_readwrite("wrench", &FreeTip::wrench);
  py::class_<ClampedTip>(m, "ClampedTip", "Clamped–clamped: the tip held at a pose.")
      .def(py::init([](const Pose& p) { return ClampedTip{p}; }), py::arg("pose"))
      .def_readwrite("pose", &ClampedTip::pose);
  py::class_<GraspedTip> grasped(m, "GraspedTip",
                                 "The tip held at a pose except along released axes (fx, fy, fz, "
                                 "mx, my, mz of the grasp frame), which carry no wrench.");
  grasped
      .def(py::init([](const Pose& p, const std::array<bool, 6>& released) {
             return GraspedTip{p, released};
           }),
           py::arg("pose"), py::arg("released"))
      .def_readwrite("pose", &GraspedTip::pose);
  def_part(grasped, "released", &GraspedTip::released, "(6,) bool: the released axes");
}

void bind_results(py::module_& m) {
  py::class_<ShootingOptions>(m, "ShootingOptions")
      .def(py::init<>())
      .def_readwrite("max_iterations", &ShootingOptions::max_iterations)
      .def_readwrite("residual_tolerance", &ShootingOptions::residual_tolerance)
      .def_readwrite("continuation", &ShootingOptions::continuation);
  py::class_<ShootingSummary>(m, "ShootingSummary")
      .def_property_readonly("status", [](const ShootingSummary& s) { return to_string(s.status); })
      .def_readonly("message", &ShootingSummary::message)
      .def_readonly("iterations", &ShootingSummary::iterations)
      .def_readonly("integrations", &ShootingSummary::integrations)
      .def_readonly("residual_norm", &ShootingSummary::residual_norm)
      .def_readonly("substeps", &ShootingSummary::substeps)
      .def("converged", &ShootingSummary::converged)
      .def("brief", &ShootingSummary::brief);
  py::class_<ShootingResult>(m, "ShootingResult")
      .def_readonly("summary", &ShootingResult::summary)
      .def_readonly("base_wrench", &ShootingResult::base_wrench)
      .def_readonly("configuration", &ShootingResult::configuration)
      .def("converged", [](const ShootingResult& r) { return r.summary.converged(); })
      .def("brief", &ShootingResult::brief);
  py::class_<StabilityResult>(m, "StabilityResult")
      .def_readonly("stable", &StabilityResult::stable)
      .def_readonly("conjugate_point_s", &StabilityResult::conjugate_point_s)
      .def_readonly("min_singular_value", &StabilityResult::min_singular_value)
      .def_readonly("tip_singular_value", &StabilityResult::tip_singular_value)
      .def_readonly("degenerate", &StabilityResult::degenerate)
      .def("brief", &StabilityResult::brief);
  py::class_<RodContact>(m, "RodContact", "One patch of contact: an interval of s on an obstacle.")
      .def_readonly("obstacle", &RodContact::obstacle, "index into the scene's obstacles")
      .def_readonly("s_start", &RodContact::s_start, "m")
      .def_readonly("s_end", &RodContact::s_end, "m (s_start for a point contact)")
      .def_readonly("force", &RodContact::force, "the whole reaction on the rod, N, world")
      .def_readonly("max_line_force", &RodContact::max_line_force, "N/m (0 at a point)")
      .def_readonly("start_force", &RodContact::start_force, "concentrated reaction at s_start, N")
      .def_readonly("end_force", &RodContact::end_force, "concentrated reaction at s_end, N")
      .def("point", &RodContact::point);
  py::class_<ContactEquilibriumResult>(m, "ContactEquilibriumResult",
                                       "An equilibrium resting on touchable obstacles.")
      .def_readonly("shooting", &ContactEquilibriumResult::shooting,
                    "the ShootingResult (summary, base wrench, configuration)")
      .def_readonly("contacts", &ContactEquilibriumResult::contacts, "the RodContact list")
      .def_readonly("least_gap", &ContactEquilibriumResult::least_gap, "m")
      .def_readonly("active_set_iterations", &ContactEquilibriumResult::active_set_iterations)
      .def_readonly("newton_iterations", &ContactEquilibriumResult::newton_iterations)
      .def("brief", &ContactEquilibriumResult::brief);
}

void bind_functions(py::module_& m) {
  m.def(
      "solve_equilibrium",
      [](const ClampedRod& rod, const TipCondition& tip, const BaseWrench& guess,
         const ShootingOptions& options) { return solve_equilibrium(rod, tip, guess, options); },
      py::arg("rod"), py::arg("tip"), py::arg("guess") = BaseWrench{},
      py::arg("options") = ShootingOptions{}, py::call_guard<py::gil_scoped_release>(),
      "The base wrench that puts the rod in equilibrium with `tip` (FreeTip, ClampedTip or "
      "GraspedTip), by shooting: a ShootingResult.");
  m.def(
      "solve_contact_equilibrium",
      [](const ClampedRod& rod, const TipCondition& tip, const Scene& scene,
         const BaseWrench& guess, const ShootingOptions& options) {
        return solve_contact_equilibrium(rod, tip, scene, guess, options);
      },
      py::arg("rod"), py::arg("tip"), py::arg("scene"), py::arg("guess") = BaseWrench{},
      py::arg("options") = ShootingOptions{}, py::call_guard<py::gil_scoped_release>(),
      "The equilibrium of the rod held by `tip` resting on the scene's obstacles whose contact "
      "is ContactMode.Touch (frictionless): a ContactEquilibriumResult.");
  m.def(
      "assess_stability",
      [](const ClampedRod& rod, const RodConfiguration& c, const TipCondition& tip) {
        return assess_stability(rod, c, tip);
      },
      py::arg("rod"), py::arg("configuration"), py::arg("tip") = TipCondition{ClampedTip{}},
      py::call_guard<py::gil_scoped_release>(),
      "The conjugate-point test (and the tip stiffness for free directions); the "
      "configuration must carry Derivatives.AllNodes.");
  py::class_<EquilibriumAnalysis>(m, "EquilibriumAnalysis",
                                  "A solved equilibrium, its stability and, when it was unstable, "
                                  "the search for a stable one.")
      .def_readonly("solution", &EquilibriumAnalysis::solution)
      .def_readonly("stability", &EquilibriumAnalysis::stability)
      .def_readonly("solved_energy", &EquilibriumAnalysis::solved_energy)
      .def_property_readonly("configuration",
                             [](const EquilibriumAnalysis& a) { return a.solution.configuration; })
      .def("converged", &EquilibriumAnalysis::converged)
      .def("brief", &EquilibriumAnalysis::brief);
  m.def(
      "analyse_equilibrium",
      [](const ClampedRod& rod, const TipCondition& tip, const BaseWrench& guess,
         const ShootingOptions& shooting, bool seek_stable) {
        EquilibriumAnalysisOptions options;
        options.seek_stable = seek_stable;
        return analyse_equilibrium(rod, tip, guess, shooting, options);
      },
      py::arg("rod"), py::arg("tip"), py::arg("guess") = BaseWrench{},
      py::arg("shooting") = ShootingOptions{}, py::arg("seek_stable") = true,
      py::call_guard<py::gil_scoped_release>(),
      "solve_equilibrium, the held pose's validity and the stability; when the equilibrium is "
      "unstable and seek_stable, a stable one is sought: an EquilibriumAnalysis.");
}

}  // namespace

void bind_solvers(py::module_& m) {
  bind_tips(m);
  bind_results(m);
  bind_functions(m);
}

}  // namespace rodshape::python
