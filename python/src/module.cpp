// module.cpp: the compiled part of the rodshape Python package. It only calls the areas' binding
// functions, lowest area first; the Python package (python/rodshape/__init__.py) re-exports it.
#include "bindings.hpp"
#include "rodshape/error.hpp"
#include "rodshape/version.hpp"

namespace rodshape::python {

py::array_t<double> rows_of(const std::vector<Eigen::Vector3d>& vectors) {
  py::array_t<double> out({static_cast<py::ssize_t>(vectors.size()), py::ssize_t{3}});
  auto view = out.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < view.shape(0); ++i)
    for (py::ssize_t k = 0; k < 3; ++k) view(i, k) = vectors[static_cast<std::size_t>(i)](k);
  return out;
}

py::array_t<double> stack_of(const std::vector<Eigen::Matrix3d>& matrices) {
  py::array_t<double> out(
      {static_cast<py::ssize_t>(matrices.size()), py::ssize_t{3}, py::ssize_t{3}});
  auto view = out.mutable_unchecked<3>();
  for (py::ssize_t i = 0; i < view.shape(0); ++i)
    for (py::ssize_t r = 0; r < 3; ++r)
      for (py::ssize_t c = 0; c < 3; ++c)
        view(i, r, c) = matrices[static_cast<std::size_t>(i)](r, c);
  return out;
}

py::array read_only(py::array array) {
  array.attr("setflags")(py::arg("write") = false);
  return array;
}

}  // namespace rodshape::python

PYBIND11_MODULE(_rodshape, m) {
  namespace py = pybind11;
  using namespace rodshape::python;
  m.doc() = "rodshape: shape planning of deformable linear objects (static Cosserat rods)";
  m.attr("__version__") = rodshape::version();
  // Bad input: a ValueError that carries the library's one-line message.
  py::register_exception<rodshape::InputError>(m, "InputError", PyExc_ValueError);
  bind_core(m);
  bind_scene(m);
  bind_solvers(m);
  bind_optimisation(m);
  bind_robot(m);
  bind_trajectory(m);
  bind_sim(m);
  bind_io(m);
}
