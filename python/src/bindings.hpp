// bindings.hpp: the binding functions of the Python module _rodshape, one per area (module.cpp
// calls them in the areas' order), the numpy conversions they share, and def_part, the one way a
// settable part of an object is bound.
#pragma once

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl_bind.h>

#include <array>
#include <cstddef>
#include <functional>
#include <type_traits>
#include <vector>

#include <Eigen/Core>

#include "rodshape/core/obstacle.hpp"

// Scene::obstacles is a bound list (ObstacleList, bind_scene.cpp), not a copy into a Python list:
// in every translation unit, before any use.
PYBIND11_MAKE_OPAQUE(std::vector<rodshape::Obstacle>)

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
/// `array` made read-only: a copy of a part (ShapeTarget.points) whose change would be lost.
py::array read_only(py::array array);

namespace detail {

template <typename T>
struct is_bool_array : std::false_type {};
template <std::size_t N>
struct is_bool_array<std::array<bool, N>> : std::true_type {};

/// `part`, a member of the Python object `owner`, as a Python object that is the member itself,
/// kept alive by `owner`: a bound struct or ObstacleList by reference, an Eigen vector or matrix as
/// a writable numpy view, a std::array<bool, N> as a writable numpy bool view, std::optional and
/// std::variant as what they hold (None when empty); a scalar or string as its value.
template <typename Part>
py::object part_object(Part& part, py::handle owner) {
  static_assert(sizeof(bool) == 1, "a numpy bool is one byte");
  if constexpr (is_bool_array<Part>::value)
    return py::array_t<bool>(static_cast<py::ssize_t>(part.size()), part.data(), owner);
  else
    return py::cast(part, py::return_value_policy::reference_internal, owner);
}

}  // namespace detail

/// Binds `name` as a settable part of the objects of `cls` (issue 43): `access(owner)` returns the
/// member (a lambda for a member of a member, or a pointer to member), `owner.name = value` assigns
/// it, and `owner.name` is the member itself (detail::part_object), never a copy, so that
/// `owner.name.field = x`, `owner.name[i] = x` and `owner.name.append(x)` change the owner.
/// pybind11's def_readwrite does so only for a bound struct: an Eigen member becomes a read-only
/// view, a std::array or std::vector a copy. An element taken from an ObstacleList (or a part of
/// one) refers into the list until the list changes, as a C++ reference does.
template <typename Class, typename Access, typename... Extra>
Class& def_part(Class& cls, const char* name, Access access, const Extra&... extra) {
  using Owner = typename Class::type;
  using Part = std::remove_reference_t<std::invoke_result_t<Access, Owner&>>;
  static_assert(!std::is_const_v<Part>, "def_part: access must return a mutable reference");
  // Both made methods here, so that a setter's TypeError says "self: Owner, arg0: Part" (the
  // package's named setter errors read arg0).
  py::cpp_function get(
      [access](py::object self) {
        return detail::part_object(std::invoke(access, self.cast<Owner&>()), self);
      },
      py::is_method(cls));
  py::cpp_function set(
      [access](Owner& owner, const Part& value) { std::invoke(access, owner) = value; },
      py::is_method(cls));
  return cls.def_property(name, get, set, extra...);
}

}  // namespace rodshape::python
