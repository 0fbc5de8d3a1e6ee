// bind_trajectory.cpp: the plan's result (steps, end-effector path, tracking).
#include <array>
#include <optional>
#include <string>

#include "bindings.hpp"
#include "rodshape/error.hpp"
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

/// Per-sample vectors as an (samples, joints) array.
py::array_t<double> samples_of(const std::vector<Eigen::VectorXd>& rows) {
  const py::ssize_t cols = rows.empty() ? 0 : static_cast<py::ssize_t>(rows.front().size());
  py::array_t<double> out({static_cast<py::ssize_t>(rows.size()), cols});
  auto view = out.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < view.shape(0); ++i)
    for (py::ssize_t j = 0; j < cols; ++j) view(i, j) = rows[static_cast<std::size_t>(i)](j);
  return out;
}

void bind_joint_trajectory(py::module_& m) {
  py::class_<JointTrajectoryResult>(m, "JointTrajectoryResult",
                                    "The arm's joint trajectory along the end-effector path.")
      .def_property_readonly("status",
                             [](const JointTrajectoryResult& r) { return to_string(r.status); })
      .def_readonly("message", &JointTrajectoryResult::message)
      .def_readonly("joint_names", &JointTrajectoryResult::joint_names)
      .def_property_readonly(
          "t",
          [](const JointTrajectoryResult& r) {
            return py::array_t<double>(static_cast<py::ssize_t>(r.t.size()), r.t.data());
          },
          "(samples,) s")
      .def_property_readonly(
          "q", [](const JointTrajectoryResult& r) { return samples_of(r.q); },
          "(samples, joints) rad or m")
      .def_property_readonly(
          "qdot", [](const JointTrajectoryResult& r) { return samples_of(r.qdot); },
          "(samples, joints) rad/s or m/s")
      .def_readonly("slowdown", &JointTrajectoryResult::slowdown)
      .def_readonly("max_position_error", &JointTrajectoryResult::max_position_error, "m")
      .def_readonly("clearance_steps", &JointTrajectoryResult::clearance_steps,
                    "null-space steps that kept the links clear")
      .def("complete", &JointTrajectoryResult::complete)
      .def("brief", &JointTrajectoryResult::brief);
}

/// The arm of `p.arm` or `p.base_arm` as a property pair: the ArmModel (or None), placed by its
/// world_T_base.
std::optional<ArmModel> arm_model(const std::optional<PlanArm>& arm) {
  if (!arm) return std::nullopt;
  return arm->model;
}

void set_arm_model(std::optional<PlanArm>& arm, std::optional<ArmModel> model) {
  if (model)
    arm = PlanArm{std::move(*model), arm ? arm->placement : ArmPlacement{}};
  else
    arm.reset();
}

void bind_moving_base(py::module_& m) {
  py::class_<MovingBase> base(m, "MovingBase",
                              "The base end (s = 0) held by a moving gripper (issue 21), not a "
                              "fixed clamp: its grasp, wrench bounds and motion weight. Set "
                              "PlanProblem.moving_base to one (a copy is stored: change a "
                              "MovingBase, then assign it, or change PlanProblem.moving_base).");
  base.def(py::init<>())
      .def_readwrite("motion_weight", &MovingBase::motion_weight,
                     "W_b, the weight of the base's least motion from the step before (>= 0)")
      .def("validate", &MovingBase::validate);
  def_part(
      base, "released", [](MovingBase& b) -> std::array<bool, 6>& { return b.grasp.released; },
      "(6,) bool: base-frame base wrench components (fx, fy, fz, mx, my, mz) the base gripper "
      "cannot transmit (base_grasp.zero_wrench)");
  def_part(
      base, "base_to_end_effector",
      [](MovingBase& b) -> Pose& { return b.grasp.tip_to_end_effector; },
      "base_T_ee: the base gripper's pose is world_T_base · base_T_ee "
      "(base_grasp.base_to_end_effector)");
  def_part(
      base, "wrench_lower", [](MovingBase& b) -> Vector6d& { return b.wrench_bounds.lower; },
      "(6,) lower bounds on the base gripper's wrench, base frame (-inf: none)");
  def_part(
      base, "wrench_upper", [](MovingBase& b) -> Vector6d& { return b.wrench_bounds.upper; },
      "(6,) upper bounds on the base gripper's wrench, base frame (inf: none)");
}

/// The placement of `arm`, to be changed in place; InputError saying how when there is no arm.
Pose& world_T_base(std::optional<PlanArm>& arm, const char* name, const char* arm_name) {
  if (!arm)
    throw InputError(std::string("PlanProblem.") + name + ": set PlanProblem." + arm_name +
                     " first (no arm, no placement)");
  return arm->placement.world_T_base;
}

void bind_problem(py::module_& m) {
  bind_moving_base(m);
  py::class_<InitialState>(m, "InitialState",
                           "The equilibrium a plan starts from: rest(), held_at(tip pose) or "
                           "equilibrium(base wrench or configuration).")
      .def_static("rest", &InitialState::rest)
      .def_static("held_at", &InitialState::held_at, py::arg("tip"))
      .def_static("equilibrium", py::overload_cast<const BaseWrench&>(&InitialState::equilibrium),
                  py::arg("base_wrench"))
      .def_static("equilibrium",
                  py::overload_cast<const RodConfiguration&>(&InitialState::equilibrium),
                  py::arg("configuration"));
  py::class_<PlanProblem> problem_class(
      m, "PlanProblem",
      "What a plan is asked for: the rod, the target, the grasp's "
      "released components, strain limits, the initial equilibrium, "
      "optionally an arm.");
  def_part(
      problem_class, "released",
      [](PlanProblem& p) -> std::array<bool, 6>& { return p.grasp.released; },
      "(6,) bool: grasp-frame tip wrench components (fx, fy, fz, mx, my, mz) the grasp cannot "
      "transmit");
  def_part(
      problem_class, "world_T_base",
      [](PlanProblem& p) -> Pose& { return world_T_base(p.arm, "world_T_base", "arm"); },
      "where the arm stands (InputError without an arm)");
  def_part(
      problem_class, "base_world_T_base",
      [](PlanProblem& p) -> Pose& {
        return world_T_base(p.base_arm, "base_world_T_base", "base_arm");
      },
      "where the base arm stands (InputError without a base arm)");
  problem_class
      .def(py::init([](const ClampedRod& rod, const ShapeTarget& target,
                       const InitialState& initial, const std::array<bool, 6>& released) {
             PlanProblem problem;
             problem.rod = rod;
             problem.target = target;
             problem.initial = initial;
             problem.grasp.released = released;
             return problem;
           }),
           py::arg("rod"), py::arg("target"), py::arg("initial") = InitialState::rest(),
           py::arg("released") = std::array<bool, 6>{})
      .def_readwrite("rod", &PlanProblem::rod)
      .def_readwrite("target", &PlanProblem::target)
      .def_readwrite("initial", &PlanProblem::initial)
      .def_readwrite("scene", &PlanProblem::scene, "the cell's obstacles (a Scene)")
      .def_property(
          "max_curvature", [](const PlanProblem& p) { return p.limits.max_curvature; },
          [](PlanProblem& p, std::optional<double> k) { p.limits.max_curvature = k; }, "1/m")
      .def_property(
          "arm", [](const PlanProblem& p) { return arm_model(p.arm); },
          [](PlanProblem& p, std::optional<ArmModel> arm) { set_arm_model(p.arm, arm); },
          "the ArmModel holding the tip (placed by world_T_base), or None")
      .def_readwrite("moving_base", &PlanProblem::moving_base,
                     "a MovingBase when the base end is held by a moving gripper, None for a "
                     "fixed clamp at rod.clamp (the base's initial pose)")
      .def_property(
          "base_arm", [](const PlanProblem& p) { return arm_model(p.base_arm); },
          [](PlanProblem& p, std::optional<ArmModel> arm) { set_arm_model(p.base_arm, arm); },
          "the ArmModel holding the base end (placed by base_world_T_base; needs moving_base), "
          "or None")
      .def("base_moves", &PlanProblem::base_moves)
      .def("validate", &PlanProblem::validate);
  py::class_<PlanOptions>(m, "PlanOptions")
      .def(py::init<>())
      .def_readwrite("steps", &PlanOptions::steps, "n_inter, 1 … 1000")
      .def_readwrite("horizon", &PlanOptions::horizon,
                     "plan only the first `horizon` steps (0: all): a receding horizon")
      .def_readwrite("optimiser", &PlanOptions::optimiser)
      .def_readwrite("track_between_waypoints", &PlanOptions::track_between_waypoints)
      .def_readwrite("tracking_substeps", &PlanOptions::tracking_substeps)
      .def_readwrite("max_refinements", &PlanOptions::max_refinements)
      .def_readwrite("scene_margin", &PlanOptions::scene_margin,
                     "fraction of the clearance added to each step's required gaps")
      .def_readwrite("scene_reach", &PlanOptions::scene_reach,
                     "m: a step keeps clear of the obstacles this near its start or points")
      .def_readwrite("scene_detour", &PlanOptions::scene_detour,
                     "search a detour where the straight motion drags the rod through one")
      .def_property(
          "interpolation", [](const PlanOptions& o) { return to_string(o.interpolation); },
          [](PlanOptions& o, const std::string& name) {
            if (const auto scheme = value_of(kObjectiveInterpolationNames, name)) {
              o.interpolation = *scheme;
              return;
            }
            throw InputError("PlanOptions.interpolation",
                             " = '" + name +
                                 "' must be auto, shape, arc_length, projection, pose "
                                 "or search");
          },
          "auto (default), shape, arc_length, projection, pose or search")
      .def_readwrite("reach_tolerance", &PlanOptions::reach_tolerance,
                     "m: complete only when the final shape passes within it of every target "
                     "point (None: 1 % of the rod's length)")
      .def_property(
          "max_linear_speed", [](const PlanOptions& o) { return o.end_effector.max_linear_speed; },
          [](PlanOptions& o, double v) { o.end_effector.max_linear_speed = v; }, "m/s")
      .def_property(
          "sample_rate", [](const PlanOptions& o) { return o.end_effector.sample_rate; },
          [](PlanOptions& o, double r) {
            o.end_effector.sample_rate = r;
            o.base_end_effector.sample_rate = r;  // one clock for both grippers
          },
          "Hz")
      .def_property(
          "base_max_linear_speed",
          [](const PlanOptions& o) { return o.base_end_effector.max_linear_speed; },
          [](PlanOptions& o, double v) { o.base_end_effector.max_linear_speed = v; },
          "m/s, the base gripper's (a moving base)")
      .def_property(
          "base_max_angular_speed",
          [](const PlanOptions& o) { return o.base_end_effector.max_angular_speed; },
          [](PlanOptions& o, double v) { o.base_end_effector.max_angular_speed = v; },
          "rad/s, the base gripper's (a moving base)")
      .def("validate", &PlanOptions::validate);
}

}  // namespace

void bind_trajectory(py::module_& m) {
  bind_joint_trajectory(m);
  bind_problem(m);
  py::class_<PlanStep>(m, "PlanStep", "One optimal shape of the plan.")
      .def_readonly("fraction", &PlanStep::fraction)
      .def_readonly("inserted", &PlanStep::inserted)
      .def_readonly("detour", &PlanStep::detour, "a waypoint of a detour around the scene")
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
      .def_readonly("end_effector", &PlanStep::end_effector)
      .def_readonly("base_end_effector", &PlanStep::base_end_effector,
                    "the base gripper's pose (a fixed clamp: the clamp's)")
      .def_property_readonly(
          "base_pose",
          [](const PlanStep& s) {
            const RodConfiguration& c = s.solution.configuration;
            return c.nodes() > 0 ? Pose{c.p.front(), c.R.front()} : Pose{};
          },
          "the rod's base pose p(0), R(0) at this step");
  py::class_<TrackingResult>(m, "TrackingResult")
      .def_readonly("performed", &TrackingResult::performed)
      .def_readonly("jump", &TrackingResult::jump)
      .def_readonly("peak_energy", &TrackingResult::peak_energy)
      .def_readonly("peak_curvature", &TrackingResult::peak_curvature)
      .def_readonly("note", &TrackingResult::note);
  py::class_<PlanResult>(m, "PlanResult")
      .def_property_readonly(
          "status", [](const PlanResult& r) { return to_string(r.status); },
          "complete, snap_through, partial, infeasible or collision")
      .def_readonly("message", &PlanResult::message)
      .def_readonly("horizon", &PlanResult::horizon, "the steps planned under a horizon, else 0")
      .def_readonly("target_distance", &PlanResult::target_distance,
                    "m: the largest distance from the final shape to a target point")
      .def_readonly("target_point", &PlanResult::target_point, "that point's index")
      .def_readonly("reach_tolerance", &PlanResult::reach_tolerance,
                    "m: the reach tolerance the plan was judged with")
      .def_readonly("options", &PlanResult::options, "the PlanOptions the plan was made with")
      .def_readonly("steps", &PlanResult::steps)
      .def_readonly("initial_configuration", &PlanResult::initial_configuration)
      .def_readonly("initial_wrench", &PlanResult::initial_wrench)
      .def_readonly("tracking", &PlanResult::tracking)
      .def_readonly("scene", &PlanResult::scene, "with a scene, its SceneResult, else None")
      .def_property_readonly(
          "interpolation",
          [](const PlanResult& r) {
            py::list tried;
            for (const InterpolationTrial& t : r.interpolation.tried) {
              py::dict trial;
              trial["scheme"] = to_string(t.scheme);
              trial["status"] = to_string(t.status);
              trial["peak_ratio"] = t.peak_ratio;
              trial["note"] = t.note;
              tried.append(trial);
            }
            py::dict result;
            result["used"] = to_string(r.interpolation.used);
            result["tried"] = tried;
            return result;
          },
          "{'used': scheme, 'tried': [{'scheme', 'status', 'peak_ratio', 'note'}, ...]}")
      .def_property_readonly(
          "joints",
          [](const PlanResult& r) -> std::optional<JointTrajectoryResult> {
            if (!r.arm) return std::nullopt;
            return r.arm->joints;
          },
          "with an arm, the JointTrajectoryResult along the path, else None")
      .def_property_readonly(
          "arm_status",
          [](const PlanResult& r) -> std::optional<std::string> {
            if (!r.arm) return std::nullopt;
            return r.arm->brief();
          },
          "with an arm, \"reachable: ...\" or why not, else None")
      .def_property_readonly(
          "end_effector_path", [](const PlanResult& r) { return path_arrays(r.end_effector_path); },
          "{'t': (n,) s, 'positions': (n, 3) m, 'rotations': (n, 3, 3)}")
      .def_property_readonly(
          "base_end_effector_path",
          [](const PlanResult& r) { return path_arrays(r.base_end_effector_path); },
          "the base gripper's path on the same clock, as end_effector_path (empty arrays with a "
          "fixed clamp)")
      .def_property_readonly(
          "base_joints",
          [](const PlanResult& r) -> std::optional<JointTrajectoryResult> {
            if (!r.base_arm) return std::nullopt;
            return r.base_arm->joints;
          },
          "with a base arm, its JointTrajectoryResult along the base path, else None")
      .def_property_readonly(
          "base_arm_status",
          [](const PlanResult& r) -> std::optional<std::string> {
            if (!r.base_arm) return std::nullopt;
            return r.base_arm->brief();
          },
          "with a base arm, \"reachable: ...\" or why not, else None")
      .def("complete", &PlanResult::complete)
      .def(
          "brief", &PlanResult::brief,
          "One line: status, steps (of the steps requested), final distance and energy, tracking.");
  m.def(
      "plan_problem",
      [](const PlanProblem& problem, const PlanOptions& options) { return plan(problem, options); },
      py::arg("problem"), py::arg("options") = PlanOptions{},
      py::call_guard<py::gil_scoped_release>(),
      "Plans a PlanProblem built in Python (rodshape.plan plans a task file): a PlanResult. "
      "Raises InputError for bad input; an infeasible target or a failed step is a status.");
}

}  // namespace rodshape::python
