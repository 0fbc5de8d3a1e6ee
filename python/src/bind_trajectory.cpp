// bind_trajectory.cpp: the plan's result (steps, end-effector path, tracking).
#include "bindings.hpp"
#include "rodshape/trajectory/plan.hpp"

namespace rodshape::python {

namespace {

/// The path as arrays: t (n,), positions (n, 3), rotations (n, 3, 3).
py::dict path_arrays(const std::vector<TimedPose>& path) {
  std::vector<double> t;
  std::vector<Eigen::Vector3d> p;
  std::vector<Eigen::Matrix3d> R;
  for (const TimedPose& sample : path) {
    t.push_back(sample.t);
    p.push_back(sample.pose.position);
    R.push_back(sample.pose.rotation);
  }
  py::dict d;
  d["t"] = py::array_t<double>(static_cast<py::ssize_t>(t.size()), t.data());
  d["positions"] = rows_of(p);
  d["rotations"] = stack_of(R);
  return d;
}

}  // namespace

void bind_trajectory(py::module_& m) {
  py::class_<PlanStep>(m, "PlanStep", "One optimal shape of the plan.")
      .def_readonly("fraction", &PlanStep::fraction)
      .def_readonly("inserted", &PlanStep::inserted)
      .def_property_readonly(
          "objective_points", [](const PlanStep& s) { return rows_of(s.objective_points); },
          "(k, 3) this step's objective points, m")
      .def_property_readonly("configuration",
                             [](const PlanStep& s) { return s.solution.configuration; })
      .def_property_readonly("base_wrench",
                             [](const PlanStep& s) { return s.solution.base_wrench; })
      .def_property_readonly("energy", [](const PlanStep& s) { return s.solution.cost.energy; })
      .def_property_readonly("max_distance",
                             [](const PlanStep& s) { return s.solution.cost.max_distance; })
      .def_readonly("end_effector", &PlanStep::end_effector);
  py::class_<TrackingResult>(m, "TrackingResult")
      .def_readonly("performed", &TrackingResult::performed)
      .def_readonly("jump", &TrackingResult::jump)
      .def_readonly("peak_energy", &TrackingResult::peak_energy)
      .def_readonly("peak_curvature", &TrackingResult::peak_curvature)
      .def_readonly("note", &TrackingResult::note);
  py::class_<PlanResult>(m, "PlanResult")
      .def_property_readonly(
          "status", [](const PlanResult& r) { return to_string(r.status); },
          "complete, snap_through, partial or infeasible")
      .def_readonly("message", &PlanResult::message)
      .def_readonly("steps", &PlanResult::steps)
      .def_readonly("initial_configuration", &PlanResult::initial_configuration)
      .def_readonly("initial_wrench", &PlanResult::initial_wrench)
      .def_readonly("tracking", &PlanResult::tracking)
      .def_property_readonly(
          "end_effector_path", [](const PlanResult& r) { return path_arrays(r.end_effector_path); },
          "{'t': (n,) s, 'positions': (n, 3) m, 'rotations': (n, 3, 3)}")
      .def("complete", &PlanResult::complete);
}

}  // namespace rodshape::python
