// bind_scene.cpp: the scene (core/obstacle.hpp, core/scene.hpp): the obstacle shapes, Obstacle,
// Scene, and the SceneResult a plan reports.
#include <algorithm>
#include <string>

#include "bindings.hpp"
#include "rodshape/core/scene.hpp"
#include "rodshape/error.hpp"
#include "rodshape/trajectory/plan_result.hpp"

namespace rodshape::python {

void bind_scene(py::module_& m) {
  py::class_<SphereObstacle> sphere(m, "SphereObstacle", "A ball: d(p) = |p - c| - r.");
  sphere
      .def(py::init([](const Eigen::Vector3d& center, double radius) {
             return SphereObstacle{center, radius};
           }),
           py::arg("center"), py::arg("radius"))
      .def_readwrite("radius", &SphereObstacle::radius, "m");
  def_part(sphere, "center", &SphereObstacle::center, "m");
  py::class_<BoxObstacle> box(m, "BoxObstacle",
                              "A box of full edges `size`, turned by `rotation`.");
  box.def(py::init([](const Eigen::Vector3d& center, const Eigen::Vector3d& size,
                      const Eigen::Matrix3d& rotation) {
            return BoxObstacle{center, size, rotation};
          }),
          py::arg("center"), py::arg("size"), py::arg("rotation") = Eigen::Matrix3d::Identity());
  def_part(box, "center", &BoxObstacle::center, "m");
  def_part(box, "size", &BoxObstacle::size, "m, full edges");
  def_part(box, "rotation", &BoxObstacle::rotation, "world_R_box");
  py::class_<CapsuleObstacle> capsule(m, "CapsuleObstacle",
                                      "The points within `radius` of [from, to].");
  capsule
      .def(py::init([](const Eigen::Vector3d& from, const Eigen::Vector3d& to, double radius) {
             return CapsuleObstacle{from, to, radius};
           }),
           py::arg("from_"), py::arg("to"), py::arg("radius"))
      .def_readwrite("radius", &CapsuleObstacle::radius, "m");
  def_part(capsule, "from_", &CapsuleObstacle::from, "m");
  def_part(capsule, "to", &CapsuleObstacle::to, "m");
  py::class_<HalfSpaceObstacle> half_space(
      m, "HalfSpaceObstacle", "Solid where normal·p > offset (free where normal·p <= offset).");
  half_space
      .def(py::init([](const Eigen::Vector3d& normal, double offset) {
             return HalfSpaceObstacle{normal, offset};
           }),
           py::arg("normal"), py::arg("offset"))
      .def_readwrite("offset", &HalfSpaceObstacle::offset, "m");
  def_part(half_space, "normal", &HalfSpaceObstacle::normal);
  py::enum_<ContactMode>(m, "ContactMode",
                         "What the rod may do with an obstacle: Avoid (keep the scene's "
                         "clearance) or Touch (rest on it: the gap >= 0, a reaction where it is 0)")
      .value("Avoid", ContactMode::Avoid)
      .value("Touch", ContactMode::Touch);
  py::class_<Obstacle> obstacle(m, "Obstacle");
  def_part(obstacle, "shape", &Obstacle::shape,
           "the obstacle's own SphereObstacle, BoxObstacle, CapsuleObstacle or HalfSpaceObstacle");
  obstacle
      .def(py::init([](const ObstacleShape& shape, const std::string& name) {
             return Obstacle{name, shape};
           }),
           py::arg("shape"), py::arg("name") = "")
      .def_readwrite("name", &Obstacle::name)
      .def_readwrite("contact", &Obstacle::contact,
                     "ContactMode.Avoid (plans keep clear) or ContactMode.Touch (equilibria rest "
                     "on it; plans refuse it)")
      .def_readwrite("friction", &Obstacle::friction,
                     "Coulomb's mu of a touchable obstacle; only 0 (frictionless) is solved")
      .def("validate", &Obstacle::validate, py::arg("field") = "obstacle",
           "Throws ValueError naming `field` for a bad shape, contact or friction")
      .def_property_readonly("kind", &Obstacle::kind)
      .def(
          "distance",
          [](const Obstacle& o, const Eigen::Vector3d& p) {
            const PointDistance d = o.distance(p);
            return py::make_tuple(d.distance, d.gradient);
          },
          py::arg("p"), "(signed distance m, its gradient) at p");
  // The scene's own list: append, del, [i] = ..., extend change the scene; a Python list or tuple
  // is taken where an ObstacleList is wanted.
  // Its storage is reserved for Scene::kMaxObstacles when Python first takes the list, and adding
  // beyond that is refused: an obstacle taken from it stays where it is when the list grows (an
  // append that reallocated left it reading freed memory: a crash).
  auto list = py::bind_vector<std::vector<Obstacle>>(
      m, "ObstacleList", "Scene.obstacles: the scene's own list of Obstacle");
  const auto refuse_growth = [](std::vector<Obstacle>& v, std::size_t more) {
    if (v.size() + more > Scene::kMaxObstacles)
      throw InputError("Scene.obstacles",
                       ": at most " + std::to_string(Scene::kMaxObstacles) + " obstacles");
    v.reserve(Scene::kMaxObstacles);  // a list made in Python: once, on its first growth
  };
  list.def(
      "append",
      [refuse_growth](std::vector<Obstacle>& v, const Obstacle& o) {
        refuse_growth(v, 1);
        v.push_back(o);
      },
      py::arg("x"), py::prepend(), "Add an obstacle at the end (at most 1000)");
  list.def(
      "insert",
      [refuse_growth](std::vector<Obstacle>& v, py::ssize_t i, const Obstacle& o) {
        refuse_growth(v, 1);
        const py::ssize_t n = static_cast<py::ssize_t>(v.size());
        if (i < 0) i += n;
        v.insert(v.begin() + std::clamp<py::ssize_t>(i, 0, n), o);
      },
      py::arg("i"), py::arg("x"), py::prepend(),
      "Insert an obstacle before index i (at most 1000)");
  list.def(
      "extend",
      [refuse_growth](std::vector<Obstacle>& v, const py::iterable& items) {
        std::vector<Obstacle> more;
        for (const py::handle item : items) more.push_back(item.cast<Obstacle>());
        refuse_growth(v, more.size());
        v.insert(v.end(), more.begin(), more.end());
      },
      py::arg("L"), py::prepend(), "Add the obstacles of L at the end (at most 1000 in all)");
  py::implicitly_convertible<py::list, std::vector<Obstacle>>();
  py::implicitly_convertible<py::tuple, std::vector<Obstacle>>();
  py::class_<Scene> scene(m, "Scene");
  scene.def(py::init<>())
      .def_readwrite("clearance", &Scene::clearance, "m, least gap of the rod's surface")
      .def_readwrite("rod_radius", &Scene::rod_radius, "m, the section's circumscribed radius")
      .def("validate", &Scene::validate);
  def_part(
      scene, "obstacles",
      [](Scene& owner) -> std::vector<Obstacle>& {
        owner.obstacles.reserve(Scene::kMaxObstacles);  // see ObstacleList
        return owner.obstacles;
      },
      "the ObstacleList, at most 1000 (assign a list, or change it in place)");
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
