// task_reader.cpp: the task files of `equilibrium` and `plan`: which top-level sections each has,
// in which order they are read, and the final whole-task checks. Both share the rod sections (rod,
// gravity, distributed_load, base).
#include "rodshape/io/task_reader.hpp"

#include <filesystem>
#include <sstream>
#include <string_view>
#include <vector>

#include "capped_file.hpp"
#include "io/plan_sections.hpp"
#include "io/sim_sections.hpp"
#include "io/task_sections.hpp"
#include "io/yaml_field.hpp"
#include "rodshape/error.hpp"
#include "rodshape/io/field_names.hpp"
#include "rodshape/trajectory/plan.hpp"

namespace rodshape {

namespace {

using io_detail::YamlField;

/// The top-level sections of an equilibrium task. The plan task lists its own and reuses the
/// section readers.
const std::vector<std::string_view>& equilibrium_sections() {
  static const std::vector<std::string_view> sections = {
      "rod", "gravity", "distributed_load", "base", "tip", "solver", "scene"};
  return sections;
}

const std::vector<io_detail::KeyHint>& equilibrium_hints() {
  static const std::vector<io_detail::KeyHint> hints = {
      {"target", "target is a section of plan tasks (rodshape plan), not of equilibrium"},
      {"weights", "weights is a section of plan tasks (rodshape plan), not of equilibrium"},
      {"workspace", "workspace is a section of plan tasks (rodshape plan), not of equilibrium"},
      {"grasp",
       "grasp is a section of plan tasks (rodshape plan); for equilibrium, release axes with "
       "tip.released"},
      {"initial", "initial is a section of plan tasks (rodshape plan), not of equilibrium"},
      {"limits", "limits is a section of plan tasks (rodshape plan), not of equilibrium"},
      {"wrench_bounds",
       "wrench_bounds is a section of plan tasks (rodshape plan), not of equilibrium"},
      {"trajectory", "trajectory is a section of plan tasks (rodshape plan), not of equilibrium"},
      {"optimizer", "optimizer is a section of plan tasks (rodshape plan); equilibrium has solver"},
      {"robot", "robot is a section of plan tasks (rodshape plan), not of equilibrium"},
      {"base_grasp", "base_grasp is a section of plan tasks (rodshape plan), not of equilibrium"},
      {"base_workspace",
       "base_workspace is a section of plan tasks (rodshape plan), not of equilibrium"},
      {"base_robot", "base_robot is a section of plan tasks (rodshape plan), not of equilibrium"},
  };
  return hints;
}

const std::vector<std::string_view>& plan_sections() {
  static const std::vector<std::string_view> sections = {
      "rod",        "gravity",        "distributed_load",
      "base",       "target",         "weights",
      "workspace",  "grasp",          "initial",
      "limits",     "wrench_bounds",  "trajectory",
      "optimizer",  "robot",          "plant",
      "sensor",     "closed_loop",    "scene",
      "base_grasp", "base_workspace", "base_robot"};
  return sections;
}

const std::vector<io_detail::KeyHint>& plan_hints() {
  static const std::vector<io_detail::KeyHint> hints = {
      {"tip",
       "a plan decides the tip pose itself: give the pose the robot starts from as initial.tip, "
       "and what the grasp cannot transmit as grasp.zero_wrench"},
      {"solver",
       "solver is the equilibrium command's shooting solver; a plan's optimiser options are in "
       "optimizer"},
      {"base_arm", "the arm that holds the base end is the section base_robot"},
      {"base_wrench_bounds", "the base gripper's wrench bounds are base_grasp.wrench_bounds"},
  };
  return hints;
}

/// A plan's `base` keys besides the pose: moving and motion_weight (issue 21).
struct BaseKeys {
  std::optional<bool> moving;
  std::optional<double> motion_weight;
};

/// The sections both commands share: rod, gravity, distributed_load, base. The rod's section, when
/// given, into `section` (a scene needs it). With `base_keys` (a plan), `base` may also say
/// moving and motion_weight, read into it; without (equilibrium), they are refused.
ClampedRod read_clamped_rod(const YamlField& root,
                            std::optional<CrossSection>* section_out = nullptr,
                            BaseKeys* base_keys = nullptr) {
  ClampedRod rod;
  const YamlField rod_field = root.require("rod");
  const io_detail::RodSection section = io_detail::read_rod_section(rod_field);
  if (section_out != nullptr) *section_out = section.description.section;
  rod.properties = io_detail::build_rod_properties(section, rod_field);
  rod.intervals = section.nodes - 1;
  rod.load = io_detail::read_distributed_load(root, section);
  if (const YamlField base = root.get("base"); base.present()) {
    if (base_keys == nullptr) {
      base.expect_mapping(
          {"position", "rotation"},
          {{"moving",
            "base.moving is a key of plan tasks (rodshape plan): an equilibrium's base "
            "is a fixed clamp"},
           {"motion_weight", "base.motion_weight is a key of plan tasks (rodshape plan)"}});
    } else {
      base.expect_mapping({"position", "rotation", "moving", "motion_weight"});
      if (const YamlField moving = base.get("moving"); moving.present())
        base_keys->moving = moving.boolean();
      if (const YamlField weight = base.get("motion_weight"); weight.present())
        base_keys->motion_weight = weight.number();
    }
    // A plan's `base: {moving: true}` alone keeps the default pose (origin, identity).
    if (base_keys == nullptr || base.has("position") || base.has("rotation"))
      rod.clamp = io_detail::read_pose_fields(base);
  }
  rod_field.located([&] { rod.validate(); });
  return rod;
}

/// The cap on a task file's size (docs/limits.md). yaml-cpp needs about 250 MB of memory and
/// several seconds for 1 MiB of YAML; the examples are under 5 KB, and 1 MiB holds some 40,000
/// target points.
constexpr detail::FileCap kTaskFileCap{detail::kMiB, "a task file", "cannot read"};

std::string read_text_file(const std::string& path) {
  return detail::read_capped_file(path, kTaskFileCap);
}

}  // namespace

namespace {

/// An equilibrium task's sections, read from `root` (whose keys were checked).
EquilibriumTask read_equilibrium_sections(const YamlField& root, const std::string& source_name) {
  EquilibriumTask task;
  task.source = source_name;
  std::optional<CrossSection> section;
  task.rod = read_clamped_rod(root, &section);
  task.tip = io_detail::read_tip_condition(root.require("tip"));
  if (const YamlField scene = root.get("scene"); scene.present())
    task.scene = io_detail::read_equilibrium_scene(scene, section);
  if (const YamlField solver = root.get("solver"); solver.present()) {
    io_detail::read_solver_section(solver, task.options, task.initial_wrench);
  }

  // Whole-task checks by the library; their messages name the field, we add file and line.
  root.located([&] {
    task.options.validate();
    check_solve_cost(task.rod, task.options);
  });
  return task;
}

/// An estimate task's sections: an equilibrium task's and `sensor`, which must be a depth camera.
const std::vector<std::string_view>& estimate_sections() {
  static const std::vector<std::string_view> sections = [] {
    std::vector<std::string_view> all = equilibrium_sections();
    all.push_back("sensor");
    return all;
  }();
  return sections;
}

/// The base end held by a moving gripper (issue 21): base.moving, base.motion_weight, base_grasp,
/// base_workspace, trajectory.base_end_effector and base_robot (which implies base.moving). With
/// a fixed clamp (base.moving false or left out, no base_robot) the others are bad input.
void read_moving_base(const YamlField& root,
                      const BaseKeys& base_keys,
                      const std::string& task_directory,
                      PlanTask& task) {
  const YamlField base = root.get("base");
  const YamlField base_robot = root.get("base_robot");
  if (base_robot.present() && base_keys.moving == false)
    base.get("moving").fail(
        "base.moving = false, but base_robot holds the base end: an arm moves it (leave out "
        "base.moving, or set it true)");
  const bool moving = base_robot.present() || base_keys.moving.value_or(false);
  if (!moving) {
    const std::string why =
        " needs a moving base: set base.moving: true (or give base_robot, the arm that holds "
        "the base end); without it the base is a fixed clamp";
    if (base_keys.motion_weight) base.get("motion_weight").fail("base.motion_weight" + why);
    for (const char* section : {"base_grasp", "base_workspace"})
      if (const YamlField field = root.get(section); field.present())
        field.fail(field.path() + why);
    if (const YamlField trajectory = root.get("trajectory"); trajectory.present())
      if (const YamlField limits = trajectory.get("base_end_effector"); limits.present())
        limits.fail(limits.path() + why);
    return;
  }
  MovingBase& moving_base = task.problem.moving_base.emplace();
  if (base_keys.motion_weight) moving_base.motion_weight = *base_keys.motion_weight;
  if (const YamlField grasp = root.get("base_grasp"); grasp.present())
    io_detail::read_base_grasp_section(grasp, moving_base);
  if (const YamlField workspace = root.get("base_workspace"); workspace.present()) {
    moving_base.workspace = io_detail::read_workspace_section(workspace);
    io_detail::located_as(workspace, "Workspace", "base_workspace",
                          [&] { moving_base.workspace.validate(); });
  }
  if (base_robot.present())
    io_detail::read_base_robot_section(base_robot, root.get("robot"), task_directory, task);
}

}  // namespace

EquilibriumTask parse_equilibrium_task(const std::string& yaml_text,
                                       const std::string& source_name) {
  const YamlField root = io_detail::parse_yaml(yaml_text, source_name);
  root.expect_mapping(equilibrium_sections(), equilibrium_hints());
  return read_equilibrium_sections(root, source_name);
}

EstimateTask parse_estimate_task(const std::string& yaml_text, const std::string& source_name) {
  const YamlField root = io_detail::parse_yaml(yaml_text, source_name);
  root.expect_mapping(estimate_sections(), equilibrium_hints());
  if (const YamlField scene = root.get("scene"); scene.present())
    scene.fail("scene: rodshape estimate fits a free rod to its cloud; contact is not estimated");
  EstimateTask task;
  task.equilibrium = read_equilibrium_sections(root, source_name);
  const YamlField sensor = root.require("sensor");
  SensorModel model = io_detail::read_sensor_section(sensor);
  const auto* depth = std::get_if<DepthSensorModel>(&model);
  if (!depth)
    sensor.fail(
        "sensor: rodshape estimate reads a depth camera's cloud: give sensor.kind: depth (and "
        "sensor.camera, the frame of the cloud's points)");
  task.sensor = *depth;
  if (std::holds_alternative<FreeTip>(task.equilibrium.tip))
    root.require("tip").fail(
        "tip: rodshape estimate needs where the gripper holds the rod (tip.pose, a clamped or "
        "grasped tip): the fit's prior");
  if (!task.equilibrium.rod.properties.section)
    root.require("rod").fail(
        "rod: rodshape estimate needs rod.section: the cloud is of the rod's surface (its "
        "centreline inflated by the section's circumscribed radius)");
  return task;
}

EstimateTask read_estimate_task(const std::string& path) {
  return parse_estimate_task(read_text_file(path), path);
}

namespace {

/// A plan's problem sections: target (with the default weights), weights, workspace, grasp,
/// initial, limits (and the model's validity), wrench_bounds.
void read_problem_sections(const YamlField& root, PlanProblem& problem) {
  problem.target.energy_weight = io_detail::kDefaultEnergyWeight;
  problem.target.distance_weight = io_detail::kDefaultDistanceWeight;
  io_detail::read_target_section(root.require("target"), problem.target);
  if (const YamlField weights = root.get("weights"); weights.present())
    io_detail::read_weights_section(weights, problem.target);
  if (const YamlField workspace = root.get("workspace"); workspace.present())
    problem.workspace = io_detail::read_workspace_section(workspace);
  if (const YamlField grasp = root.get("grasp"); grasp.present())
    problem.grasp = io_detail::read_grasp_section(grasp);
  if (const YamlField initial = root.get("initial"); initial.present())
    problem.initial = io_detail::read_initial_section(initial);
  if (const YamlField limits = root.get("limits"); limits.present()) {
    problem.limits = io_detail::read_limits_section(limits);
    problem.validity = io_detail::read_model_validity(limits);
  }
  if (const YamlField bounds = root.get("wrench_bounds"); bounds.present()) {
    problem.wrench_bounds = io_detail::read_wrench_bounds_section(bounds);
    io_detail::check_wrench_bounds(problem.wrench_bounds, bounds);
  }
}

/// The planner's options: trajectory, optimizer.
void read_planner_sections(const YamlField& root, PlanTask& task) {
  if (const YamlField trajectory = root.get("trajectory"); trajectory.present())
    io_detail::read_trajectory_section(trajectory, task.options);
  if (const YamlField optimizer = root.get("optimizer"); optimizer.present())
    io_detail::read_optimiser_section(optimizer, task.options.optimiser);
}

/// What a validation simulates: plant (and the planner's gravity), sensor, closed_loop.
void read_simulation_sections(const YamlField& root, PlanTask& task) {
  if (const YamlField plant = root.get("plant"); plant.present())
    task.plant = io_detail::read_plant_section(plant);
  task.plant.planner_gravity = io_detail::read_planner_gravity(root);
  if (const YamlField sensor = root.get("sensor"); sensor.present()) {
    SensorModel model = io_detail::read_sensor_section(sensor);
    if (auto* depth = std::get_if<DepthSensorModel>(&model))
      task.depth_sensor = *depth;
    else
      task.sensor = std::get<MarkerSensorModel>(model);
  }
  if (const YamlField loop = root.get("closed_loop"); loop.present())
    task.closed_loop = io_detail::read_closed_loop_section(loop);
}

}  // namespace

PlanTask parse_plan_task(const std::string& yaml_text, const std::string& source_name) {
  const YamlField root = io_detail::parse_yaml(yaml_text, source_name);
  root.expect_mapping(plan_sections(), plan_hints());

  PlanTask task;
  task.source = source_name;
  task.lines = root.key_lines(2);
  PlanProblem& problem = task.problem;
  std::optional<CrossSection> section;
  BaseKeys base_keys;
  problem.rod = read_clamped_rod(root, &section, &base_keys);
  if (problem.rod.nodes() > io_detail::kMaxPlanNodes) {
    root.get("rod").get("nodes").fail_value(
        "must be <= " + std::to_string(io_detail::kMaxPlanNodes) + " for a plan");
  }
  read_problem_sections(root, problem);
  read_planner_sections(root, task);
  read_simulation_sections(root, task);
  if (const YamlField scene = root.get("scene"); scene.present())
    problem.scene = io_detail::read_scene_section(scene, section, task.options);
  if (task.depth_sensor) {  // the depth camera sees the rod's surface: the scene's radius
    if (!section)
      root.get("sensor").get("kind").fail(
          "sensor.kind: depth needs rod.section, which is missing: the depth camera sees the "
          "rod's surface (its centreline inflated by the section's circumscribed radius)");
    problem.scene.rod_radius = section->circumscribed_radius();
  }
  const std::string task_directory = std::filesystem::path(source_name).parent_path().string();
  if (const YamlField robot = root.get("robot"); robot.present())
    io_detail::read_robot_section(robot, task_directory, task);
  read_moving_base(root, base_keys, task_directory, task);

  // Whole-task checks by the library; their messages name the field, we add file and line. (That
  // the workspace holds the initial tip is checked by plan(), which solves the initial
  // equilibrium.)
  root.located([&] {
    problem.validate();
    task.options.validate();
  });
  // The plant's rod (the planner's with the plant's parameters) before any plan: its bounds are
  // said as the plant's fields (plant.stiffness_scale, not the planner's rod.stiffness.EIx).
  if (const YamlField plant = root.get("plant"); plant.present())
    plant.located([&] { (void)task.plant.real_rod(problem.rod); });
  // The sizes' product (each has its own bound): said in the task's names, at no one line.
  try {
    check_plan_cost(problem, task.options);
  } catch (const InputError& error) {
    throw InputError(source_name + ": " + fields_in_task_names(error.what()));
  }
  return task;
}

EquilibriumTask read_equilibrium_task(const std::string& path) {
  return parse_equilibrium_task(read_text_file(path), path);
}

PlanTask read_plan_task(const std::string& path) {
  PlanTask task = parse_plan_task(read_text_file(path), path);
  task.input_files.insert(task.input_files.begin(), path);
  return task;
}

}  // namespace rodshape
