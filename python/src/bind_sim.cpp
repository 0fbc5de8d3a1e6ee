// bind_sim.cpp: the simulated experiment's results (validate() is bound with the task in io).
#include <optional>

#include "bindings.hpp"
#include "rodshape/feedback/marker_measurement.hpp"
#include "rodshape/feedback/shape_controller.hpp"
#include "rodshape/sim/plan_validation.hpp"
#include "rodshape/sim/plant_model.hpp"

namespace rodshape::python {

namespace {

py::array_t<double> array_of(const std::vector<double>& values) {
  return py::array_t<double>(static_cast<py::ssize_t>(values.size()), values.data());
}

}  // namespace

void bind_models(py::module_& m) {
  py::class_<PlantModel> plant(m, "PlantModel",
                               "The simulated experiment's real rod, where it differs from the "
                               "planner's (a plan task's plant section).");
  def_part(plant, "gravity", &PlantModel::gravity,
           "(3,) m/s², world frame: the one gravity on the real rod, or None: planner_gravity");
  def_part(plant, "planner_gravity", &PlantModel::planner_gravity,
           "(3,) m/s²: the planner's gravity (the task's), whose weight the plant's replaces");
  def_part(plant, "rest_curvature", &PlantModel::rest_curvature, "ũ (3,) 1/m, or None");
  plant.def(py::init<>())
      .def_readwrite("stiffness_scale", &PlantModel::stiffness_scale, "on every stiffness, > 0")
      .def_readwrite("length", &PlantModel::length, "m, or None: the planner's")
      .def_readwrite("mass_per_length", &PlantModel::mass_per_length,
                     "ρA, kg/m, or None: the planner's")
      .def_readwrite("grasp_offset", &PlantModel::grasp_offset,
                     "the tip's actual pose in the commanded tip frame")
      .def("validate", &PlantModel::validate)
      .def("real_rod", &PlantModel::real_rod, py::arg("planned"),
           "The planner's rod as the plant has it.");
  py::class_<MarkerSensorModel>(m, "MarkerSensorModel",
                                "Markers at even arc lengths seen by a camera (a plan task's "
                                "sensor section).")
      .def(py::init<>())
      .def_readwrite("markers", &MarkerSensorModel::markers, "1 … 1000")
      .def_readwrite("in_plane_noise", &MarkerSensorModel::in_plane_noise, "σ, m")
      .def_readwrite("depth_noise", &MarkerSensorModel::depth_noise, "σ, m")
      .def_readwrite("dropout", &MarkerSensorModel::dropout, "probability, [0, 1]")
      .def_readwrite("frame_rate", &MarkerSensorModel::frame_rate, "Hz, (0, 1000]")
      .def_readwrite("camera", &MarkerSensorModel::camera, "world_T_camera (z: the depth)")
      .def("validate", &MarkerSensorModel::validate);
  py::class_<DepthNoiseModel>(m, "DepthNoiseModel",
                              "A depth camera's noise (Fankhauser et al. 2015's Kinect v2 model): "
                              "axial σ_z(z, θ) = a0 + a1 z + a2 z² + incidence z^1.5 θ²/(π/2 − θ)² "
                              "along the ray, lateral_pixels across it.")
      .def(py::init<>())
      .def_readwrite("a0", &DepthNoiseModel::a0, "m")
      .def_readwrite("a1", &DepthNoiseModel::a1, "m/m")
      .def_readwrite("a2", &DepthNoiseModel::a2, "m/m²")
      .def_readwrite("incidence", &DepthNoiseModel::incidence, "m/m^1.5")
      .def_readwrite("lateral_pixels", &DepthNoiseModel::lateral_pixels, "px");
  py::class_<DepthSensorModel>(m, "DepthSensorModel",
                               "A pinhole depth camera seeing the rod's surface as a point cloud "
                               "(a plan task's sensor section with kind: depth).")
      .def(py::init<>())
      .def_readwrite("width", &DepthSensorModel::width, "pixels, 1 … 4096")
      .def_readwrite("height", &DepthSensorModel::height, "pixels, 1 … 4096")
      .def_readwrite("fov_x_deg", &DepthSensorModel::fov_x_deg, "degrees, (0, 180)")
      .def_readwrite("fov_y_deg", &DepthSensorModel::fov_y_deg, "degrees, (0, 180)")
      .def_readwrite("min_range", &DepthSensorModel::min_range, "m")
      .def_readwrite("max_range", &DepthSensorModel::max_range, "m")
      .def_readwrite("points", &DepthSensorModel::points, "per frame, 1 … 100000")
      .def_readwrite("noise", &DepthSensorModel::noise, "the DepthNoiseModel")
      .def_readwrite("outliers", &DepthSensorModel::outliers, "fraction of flying pixels, [0, 1)")
      .def_readwrite("frame_rate", &DepthSensorModel::frame_rate, "Hz, (0, 1000]")
      .def_readwrite("camera", &DepthSensorModel::camera, "world_T_camera (z: the depth)")
      .def("validate", &DepthSensorModel::validate);
}

void bind_closed_loop(py::module_& m) {
  py::class_<ClosedLoopOptions> loop(
      m, "ClosedLoopOptions", "The closed loop's checkpoints (a plan task's closed_loop section).");
  // The estimator's options by the task file's names (ClosedLoopOptions::estimation).
  def_part(
      loop, "estimate_stiffness",
      [](ClosedLoopOptions& o) -> bool& { return o.estimation.estimate_stiffness; },
      "also estimate a factor on every stiffness");
  def_part(
      loop, "gravity",
      [](ClosedLoopOptions& o) -> std::optional<Eigen::Vector3d>& { return o.estimation.gravity; },
      "(3,) m/s², world frame: the gravity the model may lack, whose weight's factor λ is then "
      "estimated too; or None");
  def_part(
      loop, "tip_position_sigma",
      [](ClosedLoopOptions& o) -> double& { return o.estimation.tip_position_sigma; },
      "m: how well the arm knows where it holds the tip");
  def_part(
      loop, "tip_rotation_sigma",
      [](ClosedLoopOptions& o) -> double& { return o.estimation.tip_rotation_sigma; }, "rad");
  def_part(
      loop, "prior_sigma", [](ClosedLoopOptions& o) -> double& { return o.estimation.prior_sigma; },
      "the base wrench prior's standard deviation, in bending units");
  loop.def(py::init<>())
      .def_readwrite("replan", &ClosedLoopOptions::replan)
      .def_readwrite("significance", &ClosedLoopOptions::significance,
                     "act on an estimate when its χ² drop exceeds k + significance·√(2k); < 0: "
                     "on every estimate")
      .def_readwrite("max_residual", &ClosedLoopOptions::max_residual,
                     "use an estimate only when its RMS weighted residual is at most this")
      .def_readwrite("max_energy_ratio", &ClosedLoopOptions::max_energy_ratio,
                     "take a re-planned step only when its energy is at most this × the replaced "
                     "step's")
      .def_readwrite("horizon", &ClosedLoopOptions::horizon, "steps optimised per re-plan; 0: all")
      .def_readwrite("estimate_grasp_offset", &ClosedLoopOptions::estimate_grasp_offset)
      .def_readwrite("checkpoint_frames", &ClosedLoopOptions::checkpoint_frames)
      .def_readwrite("fuse", &ClosedLoopOptions::fuse,
                     "each estimate's posterior is the next one's prior (recursive least squares)")
      .def("validate", &ClosedLoopOptions::validate);
  py::class_<StateEstimate>(m, "StateEstimate", "The rod's state fitted to what the sensors saw.")
      .def_property_readonly(
          "status", [](const StateEstimate& e) { return to_string(e.status); },
          "the fit's SolveStatus: converged, iteration_limit, non_finite, not_run (nothing "
          "measured)")
      .def_property_readonly("converged", &StateEstimate::converged)
      .def_readonly("base_wrench", &StateEstimate::base_wrench)
      .def_readonly("stiffness_scale", &StateEstimate::stiffness_scale)
      .def_readonly("load_factor", &StateEstimate::load_factor, "λ, the weight's factor")
      .def_readonly("residual", &StateEstimate::residual)
      .def_readonly("chi2", &StateEstimate::chi2)
      .def_readonly("prior_chi2", &StateEstimate::prior_chi2)
      .def_readonly("parameters", &StateEstimate::parameters)
      .def_readonly("stiffness_sigma", &StateEstimate::stiffness_sigma,
                    "posterior standard deviation of log(stiffness scale); 0 if not estimated")
      .def_readonly("load_factor_sigma", &StateEstimate::load_factor_sigma,
                    "posterior standard deviation of λ; 0 if not estimated")
      .def_readonly("tip_covariance", &StateEstimate::tip_covariance,
                    "6×6 posterior covariance of the tip pose (position m, world; angle rad, body)")
      .def_readonly("base_wrench_covariance", &StateEstimate::base_wrench_covariance,
                    "6×6 posterior covariance of the base wrench (N, N·m)")
      .def_readonly("points", &StateEstimate::points, "the cloud's points fitted (0: markers)")
      .def_readonly("outliers", &StateEstimate::outliers,
                    "of those, the points the robust loss discounts at the estimate")
      .def_readonly("configuration", &StateEstimate::configuration)
      .def_readonly("message", &StateEstimate::message);
  py::class_<Checkpoint>(m, "Checkpoint", "One checkpoint of a closed-loop run.")
      .def_readonly("t", &Checkpoint::t, "s")
      .def_readonly("waypoint", &Checkpoint::waypoint)
      .def_readonly("estimate", &Checkpoint::estimate)
      .def_readonly("grasp_offset", &Checkpoint::grasp_offset)
      .def_readonly("consistent", &Checkpoint::consistent)
      .def_readonly("significant", &Checkpoint::significant)
      .def_readonly("replanned", &Checkpoint::replanned)
      .def_readonly("message", &Checkpoint::message);
}

void bind_sim(py::module_& m) {
  bind_models(m);
  bind_closed_loop(m);
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
      .def_readonly("min_gap", &ValidationRun::min_gap,
                    "m, the least gap to the plan's scene over the frames (inf without one)")
      .def_property_readonly("time", [](const ValidationRun& r) { return array_of(r.time); })
      .def_property_readonly("error_3d",
                             [](const ValidationRun& r) { return array_of(r.error_3d); })
      .def_property_readonly("error_2d",
                             [](const ValidationRun& r) { return array_of(r.error_2d); })
      .def_property_readonly("true_error",
                             [](const ValidationRun& r) { return array_of(r.true_error); })
      .def_readonly("final", &ValidationRun::final)
      .def_readonly("checkpoints", &ValidationRun::checkpoints)
      .def_readonly("events", &ValidationRun::events)
      .def_readonly("driven_by_joints", &ValidationRun::driven_by_joints);
}

}  // namespace rodshape::python
