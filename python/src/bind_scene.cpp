// bind_scene.cpp: the scene (core/obstacle.hpp, core/scene.hpp): the obstacle shapes, Obstacle,
// Scene, and the SceneResult a plan reports.
#include <string>

#include "bindings.hpp"
#include "rodshape/core/scene.hpp"
#include "rodshape/trajectory/plan_result.hpp"

namespace rodshape::python {

void bind_scene(py::module_& m) {
  py::class_<SphereObstacle>(m, "SphereObstacle", "A ball: d(p) = |p - c| - r.")
      .def(py::init([](const Eigen::Vector3d& center, double radius) {
             return SphereObstacle{center, radius};
           }),
           py::arg("center"), py::arg("radius"))
      .def_readwrite("center", &SphereObstacle::center, "m")
      .def_readwrite("radius", &SphereObstacle::radius, "m");
  py::class_<BoxObstacle>(m, "BoxObstacle", "A box of full edges `size`, turned by `rotation`.")
      .def(py::init([](const Eigen::Vector3d& center, const Eigen::Vector3d& size,
                       const Eigen::Matrix3d& rotation) {
             return BoxObstacle{center, size, rotation};
           }),
           py::arg("center"), py::arg("size"), py::arg("rotation") = Eigen::Matrix3d::Identity())
      .def_readwrite("center", &BoxObstacle::center, "m")
      .def_readwrite("size", &BoxObstacle::size, "m, full edges")
      .def_readwrite("rotation", &BoxObstacle::rotation, "world_R_box");
  py::class_<CapsuleObstacle>(m, "CapsuleObstacle", "The points within `radius` of [from, to].")
      .def(py::init([](const Eigen::Vector3d& from, const Eigen::Vector3d& to, double radius) {
             return CapsuleObstacle{from, to, radius};
           }),
           py::arg("from_"), py::arg("to"), py::arg("radius"))
      .def_readwrite("from_", &CapsuleObstacle::from, "m")
      .def_readwrite("to", &CapsuleObstacle::to, "m")
      .def_readwrite("radius", &CapsuleObstacle::radius, "m");
  py::class_<HalfSpaceObstacle>(m, "HalfSpaceObstacle",
                                "Solid where normal·p > offset (free where normal·p <= offset).")
      .def(py::init([](const Eigen::Vector3d& normal, double offset) {
             return HalfSpaceObstacle{normal, offset};
           }),
           py::arg("normal"), py::arg("offset"))
      .def_readwrite("normal", &HalfSpaceObstacle::normal)
      .def_readwrite("offset", &HalfSpaceObstacle::offset, "m");
  py::class_<Obstacle>(m, "Obstacle")
      .def(py::init([](const ObstacleShape& shape, const std::string& name) {
             return Obstacle{name, shape};
           }),
           py::arg("shape"), py::arg("name") = "")
      .def_readwrite("name", &Obstacle::name)
      .def_readwrite("shape", &Obstacle::shape)
      .def_property_readonly("kind", &Obstacle::kind)
      .def(
          "distance",
          [](const Obstacle& o, const Eigen::Vector3d& p) {
            const PointDistance d = o.distance(p);
            return py::make_tuple(d.distance, d.gradient);
          },
          py::arg("p"), "(signed distance m, its gradient) at p");
  py::class_<Scene>(m, "Scene")
      .def(py::init<>())
      .def_readwrite("obstacles", &Scene::obstacles, "at most 1000")
      .def_readwrite("clearance", &Scene::clearance, "m, least gap of the rod's surface")
      .def_readwrite("rod_radius", &Scene::rod_radius, "m, the section's circumscribed radius")
      .def("validate", &Scene::validate);
  py::class_<RobotGapResult>(m, "RobotGapResult",
                             "The least gap of an arm's links to the scene or the rod over the "
                             "joint trajectory's samples.")
      .def_readonly("min_gap", &RobotGapResult::min_gap, "m")
      .def_readonly("margin", &RobotGapResult::margin, "min_gap minus its required gap, m")
      .def_readonly("sample", &RobotGapResult::sample, "the joint trajectory's sample")
      .def_readonly("t", &RobotGapResult::t, "its time, s")
      .def_readonly("step", &RobotGapResult::step, "the waypoint it moves towards")
      .def_readonly("link", &RobotGapResult::link, "the capsule's label, e.g. 'panda_link5'")
      .def_readonly("obstacle", &RobotGapResult::obstacle, "index into the obstacles; -1: the rod")
      .def_readonly("obstacle_name", &RobotGapResult::obstacle_name)
      .def_readonly("note", &RobotGapResult::note)
      .def("clear", &RobotGapResult::clear);
  py::class_<SceneResult>(m, "SceneResult", "A plan's least gap to its scene.")
      .def_readonly("clearance", &SceneResult::clearance)
      .def_readonly("min_gap", &SceneResult::min_gap, "m")
      .def_readonly("margin", &SceneResult::margin, "min_gap minus its required gap, m")
      .def_readonly("step", &SceneResult::step)
      .def_readonly("s", &SceneResult::s, "arc length, m")
      .def_readonly("obstacle", &SceneResult::obstacle)
      .def_readonly("obstacle_label", &SceneResult::obstacle_label)
      .def_readonly("detours", &SceneResult::detours)
      .def_readonly("robot", &SceneResult::robot,
                    "with an arm that has collision geometry, its RobotGapResult, else None")
      .def_property_readonly(
          "robot_min_gap",
          [](const SceneResult& r) -> std::optional<double> {
            if (!r.robot) return std::nullopt;
            return r.robot->min_gap;
          },
          "the least gap of the arm's links (m), or None")
      .def("clear", &SceneResult::clear);
}

}  // namespace rodshape::python
