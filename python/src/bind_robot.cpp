// bind_robot.cpp: an arm from URDF (Orocos KDL, urdfdom), its forward kinematics, Jacobian and
// reach, and inverse kinematics within the joint limits.
#include <optional>

#include "bindings.hpp"
#include "rodshape/robot/arm_model.hpp"
#include "rodshape/robot/inverse_kinematics.hpp"
#include "rodshape/samples/fr3.hpp"
#include "rodshape/samples/panda.hpp"

namespace rodshape::python {

namespace {

void bind_arm(py::module_& m) {
  py::class_<LinkCapsule>(m, "LinkCapsule",
                          "A link's collision capsule: the points within `radius` of [from, to] "
                          "in the link's frame.")
      .def_readonly("link", &LinkCapsule::link)
      .def_readonly("name", &LinkCapsule::name)
      .def_readonly("frame", &LinkCapsule::frame)
      .def_readonly("from_", &LinkCapsule::from, "m, in the link's frame")
      .def_readonly("to", &LinkCapsule::to, "m, in the link's frame")
      .def_readonly("radius", &LinkCapsule::radius, "m")
      .def("label", &LinkCapsule::label);
  py::class_<ArmModel>(m, "ArmModel",
                       "A serial arm: the chain from a base link to a tip link of a URDF, its "
                       "joint limits, forward kinematics and Jacobian (base frame).")
      .def_static("from_urdf_file", &ArmModel::from_urdf_file, py::arg("path"),
                  py::arg("base_link") = "", py::arg("tip_link") = "",
                  "Raises InputError when the file cannot be read or the chain is unusable.")
      .def_static("from_urdf_string", &ArmModel::from_urdf_string, py::arg("urdf"),
                  py::arg("base_link") = "", py::arg("tip_link") = "", py::arg("source") = "URDF")
      .def_property_readonly("robot_name", &ArmModel::robot_name)
      .def_property_readonly("base_link", &ArmModel::base_link)
      .def_property_readonly("tip_link", &ArmModel::tip_link)
      .def_property_readonly("joints", &ArmModel::joints, "number of moving joints n")
      .def_property_readonly("joint_names", &ArmModel::joint_names)
      .def_property_readonly("lower_limits", &ArmModel::lower_limits, "(n,) rad or m")
      .def_property_readonly("upper_limits", &ArmModel::upper_limits, "(n,) rad or m")
      .def_property_readonly("velocity_limits", &ArmModel::velocity_limits, "(n,) rad/s or m/s")
      .def_property_readonly("acceleration_limits", &ArmModel::acceleration_limits,
                             "(n,) rad/s² or m/s² (infinite unless set: a URDF holds none)")
      .def_property_readonly("jerk_limits", &ArmModel::jerk_limits,
                             "(n,) rad/s³ or m/s³ (infinite unless set)")
      .def(
          "forward_kinematics",
          [](const ArmModel& arm, const Eigen::VectorXd& q) { return arm.forward_kinematics(q); },
          py::arg("q"), "base_T_tip at joint positions q (n,): a Pose.")
      .def(
          "jacobian",
          [](const ArmModel& arm, const Eigen::VectorXd& q) {
            Pose pose;
            Eigen::Matrix<double, 6, Eigen::Dynamic> J;
            arm.forward_kinematics(q, pose, J);
            return Eigen::MatrixXd(J);
          },
          py::arg("q"), "(6, n) Jacobian of the tip's twist (v then ω, base frame).")
      .def_property_readonly("link_capsules", &ArmModel::link_capsules,
                             "the links' collision capsules read from the URDF's <collision>")
      .def_property_readonly("collision_notes", &ArmModel::collision_notes,
                             "what of the collision geometry was not read (meshes)")
      .def("reach", &ArmModel::reach, "An upper bound of the tip's distance from the base, m.")
      .def("check_joint_positions", &ArmModel::check_joint_positions, py::arg("q"),
           py::arg("what") = "q", py::arg("tolerance") = 1e-12,
           "Raises InputError unless q has n finite entries within the limits.");
  m.def("panda", &samples::panda,
        "The Franka Emika Panda bundled with rodshape (panda_link0 to the flange panda_link8).");
  m.def("panda_ready_pose", &samples::panda_ready_pose, "(7,) the Panda's ready pose, rad");
  m.def("fr3", &samples::fr3,
        "The Franka Research 3 bundled with rodshape (fr3_link0 to the flange fr3_link8).");
}

void bind_ik(py::module_& m) {
  py::class_<IkOptions>(m, "IkOptions")
      .def(py::init<>())
      .def_readwrite("position_tolerance", &IkOptions::position_tolerance, "m")
      .def_readwrite("rotation_tolerance", &IkOptions::rotation_tolerance, "rad")
      .def_readwrite("max_iterations", &IkOptions::max_iterations)
      .def_readwrite("max_restarts", &IkOptions::max_restarts)
      .def_readwrite("limit_avoidance_gain", &IkOptions::limit_avoidance_gain)
      .def_readwrite("random_seed", &IkOptions::random_seed);
  py::class_<IkResult>(m, "IkResult")
      .def_property_readonly("status", [](const IkResult& r) { return to_string(r.status); })
      .def_readonly("message", &IkResult::message)
      .def_readonly("q", &IkResult::q)
      .def_readonly("iterations", &IkResult::iterations)
      .def_readonly("restarts", &IkResult::restarts)
      .def_readonly("position_error", &IkResult::position_error, "m")
      .def_readonly("rotation_error", &IkResult::rotation_error, "rad")
      .def("converged", &IkResult::converged)
      .def("brief", &IkResult::brief);
  m.def(
      "solve_ik",
      [](const ArmModel& arm, const Pose& target, const std::optional<Eigen::VectorXd>& seed,
         const IkOptions& options) {
        return solve_ik(arm, target, seed ? *seed : default_seed(arm), options);
      },
      py::arg("arm"), py::arg("target"), py::arg("seed") = py::none(),
      py::arg("options") = IkOptions{}, py::call_guard<py::gil_scoped_release>(),
      "Joint positions that put the arm's tip link at `target` (base frame), within the limits, "
      "from `seed` (default: the ready pose for 7 joints, else zeros): an IkResult. A pose out of "
      "reach is a status.");
}

}  // namespace

void bind_robot(py::module_& m) {
  bind_arm(m);
  bind_ik(m);
}

}  // namespace rodshape::python
