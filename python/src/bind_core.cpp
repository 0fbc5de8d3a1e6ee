// bind_core.cpp: poses, wrenches, rod properties, the clamped rod, configurations and integrate().
#include "bindings.hpp"
#include "rodshape/core/clamped_rod.hpp"
#include "rodshape/core/physical_bounds.hpp"
#include "rodshape/core/pose.hpp"
#include "rodshape/core/rod_configuration.hpp"
#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/core/wrench.hpp"
#include "rodshape/samples/rubber_band.hpp"

namespace rodshape::python {

namespace {

void bind_pose_and_wrench(py::module_& m) {
  py::class_<Pose> pose(m, "Pose", "A pose: position (3,) m and rotation (3, 3), world frame.");
  pose.def(py::init([](const Eigen::Vector3d& position, const Eigen::Matrix3d& rotation) {
             return Pose{position, rotation};
           }),
           py::arg("position") = Eigen::Vector3d::Zero(),
           py::arg("rotation") = Eigen::Matrix3d::Identity());
  def_part(pose, "position", &Pose::position);
  def_part(pose, "rotation", &Pose::rotation);
  pose.def("__repr__", [](const Pose& p) {
    return "Pose(position=[" + std::to_string(p.position.x()) + ", " +
           std::to_string(p.position.y()) + ", " + std::to_string(p.position.z()) + "])";
  });
  py::class_<Wrench> wrench(m, "Wrench",
                            "A wrench: force (3,) N and moment (3,) N·m, world frame. BaseWrench "
                            "is the same type: n(0), m(0), the unknown of the shooting method.");
  wrench
      .def(py::init([](const Eigen::Vector3d& force, const Eigen::Vector3d& moment) {
             return Wrench{force, moment};
           }),
           py::arg("force") = Eigen::Vector3d::Zero(), py::arg("moment") = Eigen::Vector3d::Zero())
      .def("to_vector", &Wrench::to_vector, "(force, moment) as a (6,) array");
  def_part(wrench, "force", &Wrench::force);
  def_part(wrench, "moment", &Wrench::moment);
  m.attr("BaseWrench") = m.attr("Wrench");
}

void bind_rod(py::module_& m) {
  py::enum_<ConstitutiveModel>(m, "ConstitutiveModel")
      .value("Cosserat", ConstitutiveModel::Cosserat)
      .value("Kirchhoff", ConstitutiveModel::Kirchhoff);
  py::class_<RodProperties> properties(m, "RodProperties",
                                       "The constants of the constitutive law (SI).");
  properties.def(py::init<>())
      .def_readwrite("length", &RodProperties::length, "L, m")
      .def_readwrite("model", &RodProperties::model)
      .def_readwrite("mass_per_length", &RodProperties::mass_per_length, "ρA, kg/m");
  def_part(properties, "K_tra", &RodProperties::K_tra, "diag(GA, GA, EA), N");
  def_part(properties, "K_rot", &RodProperties::K_rot, "diag(EIx, EIy, GJ), N·m²");
  def_part(properties, "v_rest", &RodProperties::v_rest);
  def_part(properties, "u_rest", &RodProperties::u_rest, "precurvature ũ, 1/m");
  py::class_<DistributedLoad> load(m, "DistributedLoad");
  load.def(py::init<>());
  def_part(load, "force", &DistributedLoad::force, "f, N/m");
  def_part(load, "moment", &DistributedLoad::moment, "l, N·m/m");
  py::class_<ClampedRod>(m, "ClampedRod",
                         "A rod clamped at s = 0: properties, distributed load, clamp pose, "
                         "intervals N (N + 1 nodes).")
      .def(py::init<>())
      .def_readwrite("properties", &ClampedRod::properties)
      .def_readwrite("load", &ClampedRod::load)
      .def_readwrite("clamp", &ClampedRod::clamp)
      .def_readwrite("intervals", &ClampedRod::intervals)
      .def_readwrite("substeps", &ClampedRod::substeps)
      .def_property_readonly("nodes", &ClampedRod::nodes)
      .def("validate", &ClampedRod::validate, "Raises InputError naming the field.");
  m.def("rubber_band", &samples::rubber_band, py::arg("model") = ConstitutiveModel::Cosserat,
        py::arg("intervals") = 100, "The paper's rubber band, clamped at the origin along +z.");
}

void bind_configuration(py::module_& m) {
  py::enum_<Derivatives>(m, "Derivatives")
      .value("None_", Derivatives::None)
      .value("Tip", Derivatives::Tip)
      .value("AllNodes", Derivatives::AllNodes);
  py::class_<RodConfiguration>(m, "RodConfiguration", "The rod at its N + 1 nodes.")
      .def_property_readonly(
          "s",
          [](const RodConfiguration& c) {
            return py::array_t<double>(static_cast<py::ssize_t>(c.s.size()), c.s.data());
          },
          "(N + 1,) arc lengths, m")
      .def_property_readonly(
          "positions", [](const RodConfiguration& c) { return rows_of(c.p); },
          "(N + 1, 3) p(s_i), m")
      .def_property_readonly(
          "rotations", [](const RodConfiguration& c) { return stack_of(c.R); },
          "(N + 1, 3, 3) R(s_i)")
      .def_property_readonly(
          "forces", [](const RodConfiguration& c) { return rows_of(c.n); },
          "(N + 1, 3) n(s_i), N, world frame")
      .def_property_readonly(
          "moments", [](const RodConfiguration& c) { return rows_of(c.m); },
          "(N + 1, 3) m(s_i), N·m, world frame")
      .def_property_readonly(
          "u", [](const RodConfiguration& c) { return rows_of(c.u); },
          "(N + 1, 3) curvature and twist, 1/m, body frame")
      .def_property_readonly(
          "v", [](const RodConfiguration& c) { return rows_of(c.v); },
          "(N + 1, 3) shear and stretch, body frame")
      .def_readonly("energy", &RodConfiguration::energy, "elastic energy, J")
      .def_property_readonly("tip", &RodConfiguration::tip, "the tip pose p(L), R(L)")
      .def_property_readonly("tip_wrench", &RodConfiguration::tip_wrench, "n(L), m(L)")
      .def_property_readonly("base_wrench", &RodConfiguration::base_wrench, "n(0), m(0)")
      .def_property_readonly("nodes", &RodConfiguration::nodes);
  m.def(
      "integrate",
      [](const ClampedRod& rod, const BaseWrench& base_wrench, Derivatives derivatives) {
        // The library's integrate() checks nothing (hot path); from Python it is an entry point.
        rod.validate();
        require_magnitude_at_most("base_wrench.force", base_wrench.force, bounds::kMaxForce, "N");
        require_magnitude_at_most("base_wrench.moment", base_wrench.moment, bounds::kMaxForce,
                                  "N*m");
        return integrate(rod, base_wrench, derivatives);
      },
      py::arg("rod"), py::arg("base_wrench") = BaseWrench{},
      py::arg("derivatives") = Derivatives::None, py::call_guard<py::gil_scoped_release>(),
      "The rod integrated from its clamp with base wrench n(0), m(0) (RK4, one step per "
      "interval unless rod.substeps): a RodConfiguration. InputError for a bad rod or a wrench "
      "that is not finite.");
}

}  // namespace

void bind_core(py::module_& m) {
  bind_pose_and_wrench(m);
  bind_rod(m);
  bind_configuration(m);
}

}  // namespace rodshape::python
