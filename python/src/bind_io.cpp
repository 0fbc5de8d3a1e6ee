// bind_io.cpp: task files in, the CLI's documents out. A task read here is checked as the CLI
// checks it (same readers, same messages), and each result's to_json() is the document the CLI
// writes for that task (same writers).
#include <optional>
#include <string>
#include <utility>

#include "bindings.hpp"
#include "rodshape/error.hpp"
#include "rodshape/feedback/cloud_estimator.hpp"
#include "rodshape/io/atomic_file.hpp"
#include "rodshape/io/equilibrium_answer.hpp"
#include "rodshape/io/estimate_task.hpp"
#include "rodshape/io/field_names.hpp"
#include "rodshape/io/output_files.hpp"
#include "rodshape/io/plan_mcap.hpp"
#include "rodshape/io/plan_output.hpp"
#include "rodshape/io/result_json.hpp"
#include "rodshape/io/task_reader.hpp"
#include "rodshape/io/validation_output.hpp"
#include "rodshape/sim/plan_validation.hpp"
#include "rodshape/solvers/equilibrium_analysis.hpp"
#include "rodshape/trajectory/plan.hpp"

namespace rodshape::python {

namespace {

/// An equilibrium task's result, with the task it answers: what `rodshape equilibrium` computes
/// and writes.
struct Equilibrium {
  EquilibriumAnswer answer;
  EquilibriumTask task;
  std::string to_json() const { return equilibrium_answer_json(answer, task); }
};

/// A plan task's result, with the task it answers (the writers need both).
struct Plan {
  PlanResult result;
  PlanTask task;
  std::string to_json() const { return plan_result_json(result, task); }
};

/// McapOptions of `compression` ("zstd", "none"); InputError naming it for another.
McapOptions mcap_options(const std::string& compression) {
  const std::optional<McapCompression> value = value_of(kMcapCompressionNames, compression);
  if (!value) throw InputError("compression", " = '" + compression + "': expected zstd or none");
  return {.compression = *value};
}

/// An estimate task's result: what `rodshape estimate` computes and writes.
struct Estimate {
  CloudEstimate result;
  EstimateTask task;
  std::string to_json() const { return estimate_result_json(task, result); }
};

struct Validation {
  ValidationResult result;
  PlanResult plan;
  PlanTask task;
  std::string to_json() const { return validation_json(result, plan, task); }
};

Equilibrium solve_task(const EquilibriumTask& task) {
  return {answer_equilibrium_task(task), task};
}

/// The (n × 3) rows of `points` (camera frame); InputError naming `points` for another shape.
std::vector<Eigen::Vector3d> cloud_rows(
    const py::array_t<double, py::array::c_style | py::array::forcecast>& points) {
  if (points.ndim() != 2 || points.shape(1) != 3)
    throw InputError("points", ": expected an (n, 3) array of x, y, z in the camera's frame");
  if (points.shape(0) > kMaxCloudPoints)
    throw InputError("points", ": " + std::to_string(points.shape(0)) + " points, more than " +
                                   std::to_string(kMaxCloudPoints));
  const auto view = points.unchecked<2>();
  std::vector<Eigen::Vector3d> rows;
  rows.reserve(static_cast<std::size_t>(view.shape(0)));
  for (py::ssize_t i = 0; i < view.shape(0); ++i) {
    rows.emplace_back(view(i, 0), view(i, 1), view(i, 2));
    if (!rows.back().allFinite())
      throw InputError("points[" + std::to_string(i) + "]", " is not finite");
  }
  return rows;
}

Estimate estimate_task(
    const EstimateTask& task,
    const py::array_t<double, py::array::c_style | py::array::forcecast>& points) {
  std::vector<Eigen::Vector3d> rows = cloud_rows(points);
  py::gil_scoped_release release;
  try {
    return {estimate_from_cloud(task, rows), task};
  } catch (const InputError& error) {
    throw InputError(task.equilibrium.source + ": " + in_task_names(error));
  }
}

Plan plan_task(const PlanTask& task) {
  try {
    return {plan(task.problem, task.options), task};
  } catch (const InputError& error) {
    throw InputError(task.locate(error));
  }
}

/// As `rodshape validate`; `progress(done, total)`, when given, is called with the GIL taken back
/// (ValidationOptions::progress), and the rest runs with the GIL released.
Validation validate_task(const PlanTask& task,
                         int runs,
                         std::uint64_t seed,
                         bool closed_loop,
                         int jobs,
                         const std::optional<py::function>& progress) {
  ValidationOptions options;
  options.runs = runs;
  options.seed = seed;
  options.closed_loop = closed_loop;
  options.jobs = jobs;
  options.loop = task.closed_loop;
  options.planning = task.options;
  if (progress) {
    // A pointer to the caller's function: copies of the callback never touch its reference count
    // without the GIL.
    const py::function* callback = &*progress;
    options.progress = [callback](int done, int total) {
      const py::gil_scoped_acquire gil;
      (*callback)(done, total);
    };
  }
  const py::gil_scoped_release release;
  try {
    PlanResult planned = plan(task.problem, task.options);
    ValidationResult result =
        validate_plan(task.problem, planned, task.plant, task.sensor_model(), options);
    return {std::move(result), std::move(planned), task};
  } catch (const InputError& error) {
    throw InputError(task.locate(error));
  }
}

void bind_tasks(py::module_& m) {
  // dynamic_attr: the package marks a task whose parts were taken to be changed in code.
  py::class_<EquilibriumTask> equilibrium_task_class(m, "EquilibriumTask", py::dynamic_attr(),
                                                     "An equilibrium task file, read and checked.");
  def_part(equilibrium_task_class, "scene", &EquilibriumTask::scene,
           "the obstacles the rod rests on (contact: touch)");
  equilibrium_task_class.def_readwrite("rod", &EquilibriumTask::rod)
      .def_readonly("source", &EquilibriumTask::source)
      .def_property_readonly("kind", [](const EquilibriumTask&) { return "equilibrium"; });
  py::class_<PlanTask> plan_task_class(m, "PlanTask", py::dynamic_attr(),
                                       "A plan task file, read and checked.");
  def_part(
      plan_task_class, "rod", [](PlanTask& t) -> ClampedRod& { return t.problem.rod; },
      "problem.rod");
  plan_task_class
      .def_property_readonly(
          "target_points",
          [](const PlanTask& t) { return read_only(rows_of(t.problem.target.points)); },
          "(k, 3) problem.target.points, read-only")
      .def_property_readonly(
          "arm",
          [](const PlanTask& t) -> std::optional<ArmModel> {
            if (!t.problem.arm) return std::nullopt;
            return t.problem.arm->model;
          },
          "the robot section's ArmModel, or None")
      .def_property_readonly(
          "base_arm",
          [](const PlanTask& t) -> std::optional<ArmModel> {
            if (!t.problem.base_arm) return std::nullopt;
            return t.problem.base_arm->model;
          },
          "the base_robot section's ArmModel (the arm holding the base end), or None")
      .def_readwrite("problem", &PlanTask::problem)
      .def_readwrite("options", &PlanTask::options)
      .def_readwrite("plant", &PlanTask::plant, "the simulated plant (PlantModel)")
      .def_readwrite("sensor", &PlanTask::sensor, "the simulated markers (MarkerSensorModel)")
      .def_readwrite("depth_sensor", &PlanTask::depth_sensor,
                     "the simulated depth camera (DepthSensorModel) with sensor.kind: depth, "
                     "which validate uses instead of the markers; else None")
      .def_readwrite("closed_loop", &PlanTask::closed_loop, "the ClosedLoopOptions")
      .def_readonly("source", &PlanTask::source)
      .def_property_readonly("kind", [](const PlanTask&) { return "plan"; });
  py::class_<EstimateTask>(m, "EstimateTask", py::dynamic_attr(),
                           "An estimate task file (rodshape estimate), read and checked.")
      .def_readwrite("equilibrium", &EstimateTask::equilibrium,
                     "the equilibrium task: rod, base, held tip (the fit's prior)")
      .def_readwrite("options", &EstimateTask::options)
      .def_readwrite("max_residual", &EstimateTask::max_residual,
                     "the largest residual of a fit the model explains")
      .def_property_readonly("source", [](const EstimateTask& t) { return t.equilibrium.source; })
      .def_property_readonly("kind", [](const EstimateTask&) { return "estimate"; });
  m.def("read_estimate_task", &read_estimate_task, py::arg("path"),
        "Reads an estimate task file (InputError with the CLI's message when it is bad).");
  m.def("read_equilibrium_task", &read_equilibrium_task, py::arg("path"),
        "Reads an equilibrium task file (InputError with the CLI's message when it is bad).");
  m.def("read_plan_task", &read_plan_task, py::arg("path"),
        "Reads a plan task file (InputError with the CLI's message when it is bad).");
}

void bind_outcomes(py::module_& m) {
  py::class_<Estimate>(m, "Estimate", "What `rodshape estimate` computes for a task and a cloud.")
      .def_property_readonly(
          "estimate", [](const Estimate& e) { return e.result.estimate; },
          "the StateEstimate (configuration, base wrench, covariances, ...)")
      .def_property_readonly(
          "explained", [](const Estimate& e) { return e.result.explained(); },
          "the model explains the cloud (the CLI's exit 0)")
      .def_property_readonly(
          "unexplained", [](const Estimate& e) { return e.result.unexplained; },
          "why not (\"\" when explained)")
      .def("to_json", &Estimate::to_json, "The JSON document `rodshape estimate` writes.");
  py::class_<Equilibrium>(m, "Equilibrium", "What `rodshape equilibrium` computes for a task.")
      .def_property_readonly(
          "analysis", [](const Equilibrium& e) { return e.answer.analysis; },
          "the EquilibriumAnalysis (stability, ...) of a task without a scene, else None")
      .def_property_readonly(
          "contact", [](const Equilibrium& e) { return e.answer.contact; },
          "the ContactEquilibriumResult of a task with a scene, else None")
      .def_property_readonly(
          "contacts",
          [](const Equilibrium& e) {
            return e.answer.contact ? e.answer.contact->contacts : std::vector<RodContact>{};
          },
          "the RodContact list (empty without a scene or when the rod clears it)")
      .def_property_readonly("configuration",
                             [](const Equilibrium& e) { return e.answer.solution().configuration; })
      .def_property_readonly("base_wrench",
                             [](const Equilibrium& e) { return e.answer.solution().base_wrench; })
      .def_property_readonly(
          "status",
          [](const Equilibrium& e) { return to_string(e.answer.solution().summary.status); })
      .def_property_readonly(
          "stable",
          [](const Equilibrium& e) -> py::object {
            if (!e.answer.analysis || !e.answer.analysis->stability) return py::none();
            return py::bool_(e.answer.analysis->stability->stable);
          },
          "the stability verdict; None when not converged or resting on a scene (not assessed)")
      .def("converged", [](const Equilibrium& e) { return e.answer.converged(); })
      .def("brief", [](const Equilibrium& e) { return e.answer.brief(); })
      .def("to_json", &Equilibrium::to_json, "The JSON document `rodshape equilibrium` writes.");
  py::class_<Plan>(m, "Plan", "What `rodshape plan` computes for a task.")
      .def_readonly("result", &Plan::result)
      .def_property_readonly(
          "task", [](const Plan& p) { return p.task; },
          "a read-only copy of the task the plan answers (python/rodshape/__init__.py)")
      .def_property_readonly("status", [](const Plan& p) { return to_string(p.result.status); })
      .def_property_readonly("steps", [](const Plan& p) { return p.result.steps; })
      .def_property_readonly(
          "scene", [](const Plan& p) { return p.result.scene; },
          "with a scene, its SceneResult (least gap, where), else None")
      .def("brief", [](const Plan& p) { return fields_in_task_names(p.result.brief()); })
      .def("to_json", &Plan::to_json, "The plan.json document `rodshape plan` writes.")
      .def(
          "write",
          [](const Plan& p, const std::string& directory, bool html) {
            return write_plan(directory, p.result, p.task, {.html = html});
          },
          py::arg("directory"), py::arg("html") = true,
          "Writes the files `rodshape plan` writes (plan.html unless html=False, and when three.js "
          "is installed: rodshape.html_unavailable()); returns their names.")
      .def(
          "write_mcap",
          [](const Plan& p, const std::string& path, const std::string& compression) {
            check_not_an_input(path, p.task.input_files);
            write_file_atomically(path,
                                  plan_mcap(p.result, p.task.problem, mcap_options(compression)));
          },
          py::arg("path"), py::arg("compression") = "zstd",
          "Writes plan.mcap (ROS 2 messages, docs/ros.md) to `path`, whole or not at all, never "
          "through a symbolic link; compression 'zstd' or 'none'.");
  py::class_<Validation>(m, "Validation", "What `rodshape validate` computes for a task.")
      .def_readonly("plan", &Validation::plan)
      .def_property_readonly("status",
                             [](const Validation& v) { return to_string(v.result.status); })
      .def_property_readonly("runs", [](const Validation& v) { return v.result.runs; })
      .def_property_readonly(
          "driven_by_joints", [](const Validation& v) { return v.result.driven_by_joints(); },
          "True when the plant was driven by the arm's joint trajectory through its forward "
          "kinematics (validation.json driven_by).")
      .def_property_readonly(
          "base_driven_by",
          [](const Validation& v) -> std::optional<std::string> {
            if (!v.task.problem.base_moves()) return std::nullopt;
            return base_driven_by(v.result);
          },
          "with a moving base, what drove the base end (validation.json base_driven_by: "
          "base_joint_trajectory, base_end_effector_path or clamp); None with a fixed clamp")
      .def("brief", [](const Validation& v) { return v.result.brief(); })
      .def("to_json", &Validation::to_json, "The validation.json document.")
      .def(
          "write",
          [](const Validation& v, const std::string& directory, bool html) {
            // one set, as the CLI writes it: all checked and written, then renamed
            OutputSet set = plan_outputs(v.plan, v.task, {.html = html});
            set.append(validation_outputs(v.result, v.plan, v.task, {.html = html}));
            return write_output_set(directory, std::move(set));
          },
          py::arg("directory"), py::arg("html") = true,
          "Writes the files `rodshape validate` writes (the HTML pages unless html=False).");
}

}  // namespace

void bind_io(py::module_& m) {
  m.def(
      "write_file_atomically",
      [](const std::string& path, const py::bytes& content) {
        write_file_atomically(path, std::string(content));
      },
      py::arg("path"), py::arg("content"),
      "Writes the bytes `content` to `path` whole or not at all, as the CLI writes its files (a "
      "device, a FIFO or a symbolic link at `path` is refused, never written into); InputError "
      "on failure.");
  m.def("html_unavailable", &html_unavailable,
        "Why the 3D pages (plan.html, validation.html) cannot be written: three.js not found "
        "(Debian: libjs-three); \"\" when they can.");
  bind_tasks(m);
  bind_outcomes(m);
  m.def("solve", &solve_task, py::arg("task"), py::call_guard<py::gil_scoped_release>(),
        "Solves an equilibrium task as `rodshape equilibrium` does (a stable equilibrium sought "
        "when the solve's is unstable).");
  m.def("estimate", &estimate_task, py::arg("task"), py::arg("points"),
        "Estimates the rod's equilibrium from one depth camera cloud, as `rodshape estimate` "
        "does: `points` an (n, 3) array of x, y, z in the frame of the task's sensor.camera (at "
        "most 10^6, finite).");
  m.def("plan", &plan_task, py::arg("task"), py::call_guard<py::gil_scoped_release>(),
        "Plans a plan task as `rodshape plan` does.");
  m.def("validate", &validate_task, py::arg("task"), py::arg("runs") = 1, py::arg("seed") = 1,
        py::arg("closed_loop") = false, py::arg("jobs") = 1, py::arg("progress") = py::none(),
        "Plans a plan task and carries the plan out in simulation, as `rodshape validate` does. "
        "jobs: closed-loop runs carried out at once (1 to 256; the result is the same for every "
        "value). progress: None or a callable progress(done, total), called as the runs (closed "
        "loop) or the plant's frames (open loop) are done, never two calls at once, the last with "
        "done == total; the GIL is released in between.");
}

}  // namespace rodshape::python
