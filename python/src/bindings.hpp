// bindings.hpp: the binding functions of the Python module _rodshape, one per area (module.cpp
// calls them in the areas' order), and the numpy conversions they share.
#pragma once

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <vector>

#include <Eigen/Core>

namespace rodshape::python {

namespace py = pybind11;

void bind_core(py::module_& m);
void bind_scene(py::module_& m);
void bind_solvers(py::module_& m);
void bind_optimisation(py::module_& m);
void bind_robot(py::module_& m);
void bind_trajectory(py::module_& m);
void bind_sim(py::module_& m);
void bind_io(py::module_& m);

/// A list of 3-vectors as an (n, 3) float64 array.
py::array_t<double> rows_of(const std::vector<Eigen::Vector3d>& vectors);
/// A list of 3 × 3 matrices as an (n, 3, 3) float64 array.
py::array_t<double> stack_of(const std::vector<Eigen::Matrix3d>& matrices);

}  // namespace rodshape::python
