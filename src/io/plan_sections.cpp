// plan_sections.cpp: the readers of the sections that a plan task adds (see plan_sections.hpp).
#include "io/plan_sections.hpp"

#include <filesystem>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "io/did_you_mean.hpp"
#include "io/task_sections.hpp"
#include "rodshape/error.hpp"
#include "rodshape/io/field_names.hpp"
#include "rodshape/samples/bundled_arms.hpp"
#include "validation.hpp"

namespace rodshape::io_detail {

namespace {

void read_number(const YamlField& section, std::string_view key, double& value) {
  if (const YamlField field = section.get(key); field.present()) value = field.number();
}

/// A whole number in [min, max] (the library's bound, docs/limits.md), said as written when not.
void read_integer(const YamlField& section, std::string_view key, int& value, int min, int max) {
  if (const YamlField field = section.get(key); field.present()) value = field.integer_in(min, max);
}

/// A list of at most `max` entries.
std::vector<YamlField> bounded_elements(const YamlField& list, std::size_t max) {
  std::vector<YamlField> elements = list.elements();
  if (elements.size() > max)
    list.fail(list.path() + " has " + std::to_string(elements.size()) + " entries; at most " +
              std::to_string(max));
  return elements;
}

Workspace::Ball read_ball(const YamlField& ball) {
  ball.expect_mapping({"center", "radius"});
  return {ball.require("center").vector3(), ball.require("radius").number()};
}

std::vector<Workspace::Ball> read_balls(const YamlField& balls) {
  std::vector<Workspace::Ball> result;
  for (const YamlField& ball : bounded_elements(balls, Workspace::kMaxSets))
    result.push_back(read_ball(ball));
  return result;
}

/// {force, moment} into `bound`, where each vector given replaces the three components it covers.
void read_bound(const YamlField& field, Eigen::Ref<Vector6d> bound) {
  field.expect_mapping({"force", "moment"});
  if (const YamlField force = field.get("force"); force.present())
    bound.head<3>() = force.vector3();
  if (const YamlField moment = field.get("moment"); moment.present())
    bound.tail<3>() = moment.vector3();
}

}  // namespace

void read_target_section(const YamlField& target, ShapeTarget& result) {
  target.expect_mapping({"points", "squared_distances"},
                        {{"energy", "energy belongs in the top-level section weights"},
                         {"distance", "distance belongs in the top-level section weights"},
                         {"weights", "weights is a top-level section, not part of target"}});
  result.points.clear();
  for (const YamlField& point : bounded_elements(target.require("points"), ShapeTarget::kMaxPoints))
    result.points.push_back(point.vector3());
  if (const YamlField squared = target.get("squared_distances"); squared.present())
    result.squared_distances = squared.boolean();
}

void read_weights_section(const YamlField& weights, ShapeTarget& target) {
  weights.expect_mapping({"energy", "distance"});
  read_number(weights, "energy", target.energy_weight);
  read_number(weights, "distance", target.distance_weight);
}

Workspace read_workspace_section(const YamlField& workspace) {
  workspace.expect_mapping({"box", "inside", "outside", "half_spaces"});
  Workspace result;
  if (const YamlField box = workspace.get("box"); box.present()) {
    box.expect_mapping({"lower", "upper"});
    result.box = Workspace::Box{box.require("lower").vector3(), box.require("upper").vector3()};
  }
  if (const YamlField inside = workspace.get("inside"); inside.present())
    result.inside = read_balls(inside);
  if (const YamlField outside = workspace.get("outside"); outside.present())
    result.outside = read_balls(outside);
  if (const YamlField half_spaces = workspace.get("half_spaces"); half_spaces.present()) {
    for (const YamlField& half : bounded_elements(half_spaces, Workspace::kMaxSets)) {
      half.expect_mapping({"normal", "offset"});
      result.half_spaces.push_back(
          {half.require("normal").vector3(), half.require("offset").number()});
    }
  }
  return result;
}

Grasp read_grasp_section(const YamlField& grasp) {
  grasp.expect_mapping(
      {"zero_wrench", "tip_to_end_effector"},
      {{"released",
        "a plan's grasp names the wrench it cannot transmit as "
        "zero_wrench (axes fx, fy, fz, mx, my, mz)"},
       {"base_to_end_effector", "the base gripper's offset is base_grasp.base_to_end_effector"},
       {"wrench_bounds", "the tip's wrench bounds are the top-level section wrench_bounds"}});
  Grasp result;
  if (const YamlField axes = grasp.get("zero_wrench"); axes.present())
    result.released = read_wrench_axes(axes);
  if (const YamlField offset = grasp.get("tip_to_end_effector"); offset.present())
    result.tip_to_end_effector = read_pose(offset);
  return result;
}

void read_base_grasp_section(const YamlField& grasp, MovingBase& base) {
  grasp.expect_mapping({"zero_wrench", "base_to_end_effector", "wrench_bounds"},
                       {{"released",
                         "the base grasp names the wrench it cannot transmit as "
                         "zero_wrench (axes fx, fy, fz, mx, my, mz)"},
                        {"tip_to_end_effector",
                         "the base gripper's offset is base_grasp.base_to_end_effector "
                         "(base_T_ee)"}});
  if (const YamlField axes = grasp.get("zero_wrench"); axes.present())
    base.grasp.released = read_wrench_axes(axes);
  if (const YamlField offset = grasp.get("base_to_end_effector"); offset.present())
    base.grasp.tip_to_end_effector = read_pose(offset);
  if (const YamlField bounds = grasp.get("wrench_bounds"); bounds.present()) {
    base.wrench_bounds = read_wrench_bounds_section(bounds);
    check_wrench_bounds(base.wrench_bounds, bounds);
  }
}

void check_wrench_bounds(const WrenchBounds& bounds, const YamlField& field) {
  static const char* const kNames[6] = {"force[0]",  "force[1]",  "force[2]",
                                        "moment[0]", "moment[1]", "moment[2]"};
  for (int k = 0; k < 6; ++k) {
    if (bounds.lower(k) > bounds.upper(k))
      field.fail(field.path() + ": lower." + kNames[k] + " is above upper." + kNames[k]);
  }
}

InitialState read_initial_section(const YamlField& initial) {
  initial.expect_mapping({"tip", "base_wrench"},
                         {{"position", "give the initial tip pose as initial.tip"},
                          {"rotation", "give the initial tip pose as initial.tip"}});
  const YamlField tip = initial.get("tip");
  const YamlField wrench = initial.get("base_wrench");
  if (tip.present() && wrench.present())
    wrench.fail(wrench.path() + ": give initial.tip or initial.base_wrench, not both");
  if (tip.present()) return InitialState::held_at(read_pose(tip));
  if (wrench.present()) return InitialState::equilibrium(read_wrench(wrench));
  return InitialState::rest();
}

StrainLimits read_limits_section(const YamlField& limits) {
  limits.expect_mapping({"max_curvature", "max_axial_strain", "model"});
  StrainLimits result;
  if (const YamlField field = limits.get("max_curvature"); field.present())
    result.max_curvature = field.number();
  if (const YamlField field = limits.get("max_axial_strain"); field.present())
    result.max_axial_strain = field.number();
  return result;
}

ModelValidityLimits read_model_validity(const YamlField& limits) {
  ModelValidityLimits result;
  const YamlField model = limits.get("model");
  if (!model.present()) return result;
  model.expect_mapping({"max_axial_strain", "max_shear_strain"});
  if (const YamlField field = model.get("max_axial_strain"); field.present())
    result.max_axial_strain = field.positive_number();
  if (const YamlField field = model.get("max_shear_strain"); field.present())
    result.max_shear_strain = field.positive_number();
  return result;
}

WrenchBounds read_wrench_bounds_section(const YamlField& bounds) {
  bounds.expect_mapping({"lower", "upper"});
  WrenchBounds result;
  if (const YamlField lower = bounds.get("lower"); lower.present()) read_bound(lower, result.lower);
  if (const YamlField upper = bounds.get("upper"); upper.present()) read_bound(upper, result.upper);
  return result;
}

namespace {

ObjectiveInterpolation read_interpolation(const YamlField& field) {
  const std::string name = field.choice(names_of(kObjectiveInterpolationNames));
  return *value_of(kObjectiveInterpolationNames, name);  // choice() accepted only these names
}

}  // namespace

void read_trajectory_section(const YamlField& trajectory, PlanOptions& options) {
  trajectory.expect_mapping(
      {"steps", "max_linear_speed", "max_angular_speed", "max_linear_acceleration",
       "max_angular_acceleration", "rate", "track", "tracking_substeps", "max_refinements",
       "interpolation", "base_end_effector", "reach_tolerance"},
      {{"n_inter", "the number of intermediate steps is trajectory.steps"},
       {"base_max_linear_speed",
        "the base gripper's limits are trajectory.base_end_effector.max_linear_speed etc."}});
  read_integer(trajectory, "steps", options.steps, 1, PlanOptions::kMaxSteps);
  EndEffectorLimits& limits = options.end_effector;
  read_number(trajectory, "max_linear_speed", limits.max_linear_speed);
  read_number(trajectory, "max_angular_speed", limits.max_angular_speed);
  read_number(trajectory, "max_linear_acceleration", limits.max_linear_acceleration);
  read_number(trajectory, "max_angular_acceleration", limits.max_angular_acceleration);
  read_number(trajectory, "rate", limits.sample_rate);
  if (limits.sample_rate > EndEffectorLimits::kMaxSampleRate)
    trajectory.get("rate").fail_value("must be <= " +
                                      detail::format_value(EndEffectorLimits::kMaxSampleRate));
  if (const YamlField track = trajectory.get("track"); track.present())
    options.track_between_waypoints = track.boolean();
  read_integer(trajectory, "tracking_substeps", options.tracking_substeps, 1,
               PlanOptions::kMaxTrackingSubsteps);
  read_integer(trajectory, "max_refinements", options.max_refinements, 0,
               PlanOptions::kMaxRefinements);
  if (const YamlField interpolation = trajectory.get("interpolation"); interpolation.present())
    options.interpolation = read_interpolation(interpolation);
  if (const YamlField reach = trajectory.get("reach_tolerance"); reach.present())
    options.reach_tolerance = reach.positive_number();

  // The base gripper: the tip's limits (one clock, one sample rate), with its own keys over them.
  options.base_end_effector = options.end_effector;
  if (const YamlField base = trajectory.get("base_end_effector"); base.present()) {
    base.expect_mapping({"max_linear_speed", "max_angular_speed", "max_linear_acceleration",
                         "max_angular_acceleration"},
                        {{"rate",
                          "the two grippers move on one clock: the sample rate is "
                          "trajectory.rate"}});
    // The tip's first, so that a bad tip limit is not blamed on the base's copy of it.
    trajectory.located([&] { options.end_effector.validate(); });
    EndEffectorLimits& base_limits = options.base_end_effector;
    read_number(base, "max_linear_speed", base_limits.max_linear_speed);
    read_number(base, "max_angular_speed", base_limits.max_angular_speed);
    read_number(base, "max_linear_acceleration", base_limits.max_linear_acceleration);
    read_number(base, "max_angular_acceleration", base_limits.max_angular_acceleration);
    located_as(base, "EndEffectorLimits", base.path(), [&] { base_limits.validate(); });
  }
}

void read_optimiser_section(const YamlField& optimizer, ShapeOptimiserOptions& options) {
  optimizer.expect_mapping({"max_iterations", "tolerance", "constraint_tolerance", "multi_starts",
                            "print_level", "confine_to_scale"});
  read_integer(optimizer, "max_iterations", options.max_iterations, 0,
               ShapeOptimiserOptions::kMaxIterations);
  read_number(optimizer, "tolerance", options.tolerance);
  read_number(optimizer, "constraint_tolerance", options.constraint_tolerance);
  read_integer(optimizer, "multi_starts", options.multi_starts, 0,
               ShapeOptimiserOptions::kMaxMultiStarts);
  read_integer(optimizer, "print_level", options.print_level, 0, 12);
  if (const YamlField confine = optimizer.get("confine_to_scale"); confine.present())
    options.confine_to_scale = confine.boolean();
}

namespace {

/// The fields of `robot` and `base_robot`: the arm (its URDF read) and its options.
/// The arm's seed goes to options.joints.seed (the tip's arm) or options.base_seed (`base_arm`);
/// the other options are the two arms' shared ones.
PlanArm read_arm(const YamlField& robot,
                 const std::string& task_directory,
                 PlanTask& task,
                 bool base_arm) {
  ArmPlanOptions& options = task.options.arm;
  const std::string name = robot.path();
  robot.expect_mapping(
      {"urdf", "base_link", "tip_link", "base", "flange_to_end_effector", "seed", "reach", "links"},
      {{"flange_T_ee", "the end effector on the flange is " + name + ".flange_to_end_effector"},
       {"tool", "the end effector on the flange is " + name + ".flange_to_end_effector"},
       {"world_T_base", "the arm's base in the world is " + name + ".base"}});
  const YamlField urdf = robot.require("urdf");
  const std::string urdf_text = urdf.text();
  std::filesystem::path path(urdf_text);
  if (path.is_relative() && !task_directory.empty())
    path = std::filesystem::path(task_directory) / path;
  const YamlField base_link = robot.get("base_link");
  const YamlField tip_link = robot.get("tip_link");
  const std::string base_name = base_link.present() ? base_link.text() : "";
  const std::string tip_name = tip_link.present() ? tip_link.text() : "";
  // A bundled arm's name ("fr3", "panda"), else a file; a word that is neither is a misspelt name.
  const bool word = urdf_text.find_first_of("/.") == std::string::npos;
  const bool bundled = word && samples::is_bundled_arm(urdf_text);
  if (word && !bundled && !std::filesystem::exists(path)) {
    const std::optional<std::string> near = io_detail::closest_match(urdf_text, {"fr3", "panda"});
    urdf.fail(urdf.path() + ": '" + urdf_text + "' is neither a bundled arm (" +
              samples::bundled_arm_names() + ") nor a URDF file" +
              (near ? "; did you mean '" + *near + "'?" : ""));
  }

  std::optional<ArmModel> arm;
  try {
    arm = bundled ? samples::bundled_arm(urdf_text, base_name, tip_name)
                  : ArmModel::from_urdf_file(path.string(), base_name, tip_name);
  } catch (const InputError& error) {
    // Say which field the URDF's complaint is about.
    const std::string message = error.what();
    const auto mentions = [&](const char* text) { return message.find(text) != std::string::npos; };
    if (mentions(": unknown base link") && base_link.present())
      base_link.fail(base_link.path() + ": " + message);
    if ((mentions(": unknown tip link") || mentions(" is not below base link")) &&
        tip_link.present())
      tip_link.fail(tip_link.path() + ": " + message);
    urdf.fail(urdf.path() + ": " + message);
  }

  if (!bundled) task.input_files.push_back(path.string());  // never an output of the run (issue 24)
  PlanArm result{std::move(*arm), {}};
  if (const YamlField base = robot.get("base"); base.present())
    result.placement.world_T_base = read_pose(base);
  if (const YamlField offset = robot.get("flange_to_end_effector"); offset.present())
    result.placement.flange_T_ee = read_pose(offset);
  if (const YamlField seed = robot.get("seed"); seed.present()) {
    const std::vector<YamlField> values = seed.elements();
    Eigen::VectorXd q(static_cast<Eigen::Index>(values.size()));
    for (std::size_t i = 0; i < values.size(); ++i)
      q(static_cast<Eigen::Index>(i)) = values[i].number();
    seed.located([&] { result.model.check_joint_positions(q, seed.path()); });
    (base_arm ? options.base_seed : options.joints.seed) = q;
  }
  if (const YamlField reach = robot.get("reach"); reach.present()) {
    reach.expect_mapping({"use", "margin", "tightening", "max_replans", "samples"});
    if (const YamlField use = reach.get("use"); use.present()) options.use_reach = use.boolean();
    read_number(reach, "margin", options.reach_margin);
    read_number(reach, "tightening", options.replan_tightening);
    read_integer(reach, "max_replans", options.max_replans, 0, ArmPlanOptions::kMaxReplans);
    read_integer(reach, "samples", options.reach.samples, 1, ArmReachOptions::kMaxSamples);
    located_as(reach, "ArmPlanOptions", name, [&] { options.validate(); });
  }
  if (const YamlField links = robot.get("links"); links.present()) {
    links.expect_mapping({"clearance", "influence"});
    if (const YamlField clearance = links.get("clearance"); clearance.present())
      options.link_clearance = clearance.boolean();
    read_number(links, "influence", options.link_influence);
    located_as(links, "ArmPlanOptions", name, [&] { options.validate(); });
  }
  return result;
}

}  // namespace

void read_robot_section(const YamlField& robot, const std::string& task_directory, PlanTask& task) {
  task.problem.arm.emplace(read_arm(robot, task_directory, task, false));
}

void read_base_robot_section(const YamlField& robot,
                             const YamlField& tip_robot,
                             const std::string& task_directory,
                             PlanTask& task) {
  // One ArmPlanOptions serves both arms (all but the seed): said once.
  for (const char* key : {"reach", "links"})
    if (const YamlField field = robot.get(key);
        field.present() && tip_robot.present() && tip_robot.has(key))
      field.fail(field.path() + ": the two arms share their " + key +
                 " options: give them once, in robot." + key);
  task.problem.base_arm.emplace(read_arm(robot, task_directory, task, true));
}

void located_as(const YamlField& field,
                std::string_view library,
                std::string_view task_name,
                const std::function<void()>& call) {
  try {
    call();
  } catch (const InputError& error) {
    const std::string& name = error.field();
    if (name.starts_with(library)) {
      std::string renamed(task_name);
      std::string rest = name.substr(library.size());
      // ArmPlanOptions' own fields are said in the robot section's names (reach.margin, ...).
      if (library == "ArmPlanOptions") {
        const std::string robot_name = task_field_name(name);  // "robot.reach.margin"
        rest = robot_name.starts_with("robot") ? robot_name.substr(5) : rest;
      }
      field.fail_located(renamed + rest + fields_in_task_names(error.problem()));
    }
    field.fail_located(in_task_names(error));
  }
}

}  // namespace rodshape::io_detail
