// bind_sim.cpp: the simulated experiment's results (validate() is bound with the task in io).
#include "bindings.hpp"
#include "rodshape/sim/plan_validation.hpp"

namespace rodshape::python {

namespace {

py::array_t<double> array_of(const std::vector<double>& values) {
  return py::array_t<double>(static_cast<py::ssize_t>(values.size()), values.data());
}

}  // namespace

void bind_sim(py::module_& m) {
  py::class_<ShapeError>(m, "ShapeError", "The paper's error at one frame, m.")
      .def_readonly("error_3d", &ShapeError::error_3d)
      .def_readonly("error_2d", &ShapeError::error_2d)
      .def_readonly("true_error", &ShapeError::true_error)
      .def_readonly("true_max_distance", &ShapeError::true_max_distance);
  py::class_<PlantEvent>(m, "PlantEvent")
      .def_property_readonly("kind", [](const PlantEvent& e) { return to_string(e.kind); })
      .def_readonly("t", &PlantEvent::t)
      .def_readonly("energy_released", &PlantEvent::energy_released)
      .def_readonly("message", &PlantEvent::message);
  py::class_<ValidationRun>(m, "ValidationRun", "One run: the errors at each frame (m).")
      .def_readonly("seed", &ValidationRun::seed)
      .def_readonly("closed_loop", &ValidationRun::closed_loop)
      .def_property_readonly("time", [](const ValidationRun& r) { return array_of(r.time); })
      .def_property_readonly("error_3d",
                             [](const ValidationRun& r) { return array_of(r.error_3d); })
      .def_property_readonly("error_2d",
                             [](const ValidationRun& r) { return array_of(r.error_2d); })
      .def_property_readonly("true_error",
                             [](const ValidationRun& r) { return array_of(r.true_error); })
      .def_readonly("final", &ValidationRun::final)
      .def_readonly("events", &ValidationRun::events);
}

}  // namespace rodshape::python
