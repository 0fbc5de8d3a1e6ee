// plan_sections.hpp (private to the io area): the readers of the sections a plan task adds to the
// rod sections of task_sections.hpp: target, weights, workspace, grasp, initial, limits,
// wrench_bounds, trajectory and optimizer. As there, numbers are checked for being numbers and
// finite here and their ranges by the library's validate() functions (ShapeTarget, Workspace,
// StrainLimits, PlanOptions), located in the file by task_reader.cpp.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "io/yaml_field.hpp"
#include "rodshape/core/cross_section.hpp"
#include "rodshape/core/pose.hpp"
#include "rodshape/core/scene.hpp"
#include "rodshape/io/plan_task.hpp"
#include "rodshape/optimisation/shape_constraints.hpp"
#include "rodshape/optimisation/shape_optimiser.hpp"
#include "rodshape/optimisation/shape_target.hpp"
#include "rodshape/optimisation/workspace.hpp"
#include "rodshape/trajectory/plan.hpp"

namespace rodshape::io_detail {

/// The task-file defaults of the weights, which differ from ShapeTarget's (1, 1): with W1 = 1 the
/// energy term W1 E / L of a bent rubber band (about 0.5 N) outweighs millimetre distances by far,
/// so the plan would trade the shape for a lower energy. W1 = 1e-3 keeps the energy as the
/// tie-breaker between shapes that pass through the points, as the paper uses it.
inline constexpr double kDefaultEnergyWeight = 1e-3;
inline constexpr double kDefaultDistanceWeight = 1.0;

/// `target`: points (a list of [x, y, z]), squared_distances. Into `target`.
void read_target_section(const YamlField& target, ShapeTarget& result);

/// `weights`: energy (W1), distance (W2). Fields left out keep the values in `target`.
void read_weights_section(const YamlField& weights, ShapeTarget& target);

/// `workspace`: box {lower, upper}, inside and outside (lists of {center, radius}), half_spaces
/// (a list of {normal, offset}).
Workspace read_workspace_section(const YamlField& workspace);

/// `grasp`: zero_wrench (axes among fx ... mz), tip_to_end_effector (a pose).
Grasp read_grasp_section(const YamlField& grasp);

/// `base_grasp` (a moving base, issue 21): zero_wrench (axes among fx ... mz, of the base wrench
/// in the base's frame), base_to_end_effector (a pose, base_T_ee), wrench_bounds ({lower, upper}
/// as the top-level wrench_bounds, on the base gripper's wrench). Into `base`.
void read_base_grasp_section(const YamlField& grasp, MovingBase& base);

/// `initial`: tip (a pose) or base_wrench {force, moment}; the rod at rest when both are left out.
InitialState read_initial_section(const YamlField& initial);

/// `limits`: max_curvature, max_axial_strain (and `model`, read by read_model_validity()).
StrainLimits read_limits_section(const YamlField& limits);

/// `limits.model`: max_axial_strain, max_shear_strain, the model's validity for the initial tip.
ModelValidityLimits read_model_validity(const YamlField& limits);

/// `wrench_bounds`: lower and upper, each {force, moment}; an omitted vector is unbounded.
WrenchBounds read_wrench_bounds_section(const YamlField& bounds);

/// Lower bounds above upper ones, said at `field` in its own names ("<path>: lower.force[0] is
/// above upper.force[0]").
void check_wrench_bounds(const WrenchBounds& bounds, const YamlField& field);

/// `trajectory`: steps, speeds, accelerations, rate, track, tracking_substeps, and
/// base_end_effector (the base gripper's speeds and accelerations, each the tip's when left out).
/// Into `options`: options.base_end_effector is the tip's limits with base_end_effector's keys
/// over them.
void read_trajectory_section(const YamlField& trajectory, PlanOptions& options);

/// `optimizer`: max_iterations, tolerance, constraint_tolerance, multi_starts, print_level.
void read_optimiser_section(const YamlField& optimizer, ShapeOptimiserOptions& options);

/// `scene`: clearance, margin and reach (into `options`), obstacles (a list of {shape, name, and
/// the shape's fields}). Needs the rod's section (its circumscribed radius is the rod's).
Scene read_scene_section(const YamlField& scene,
                         const std::optional<CrossSection>& section,
                         PlanOptions& options);

/// An equilibrium task's `scene`: obstacles only, each `contact: touch` (the rod rests on them;
/// frictionless). Needs the rod's section.
Scene read_equilibrium_scene(const YamlField& scene, const std::optional<CrossSection>& section);

/// `robot`: urdf (relative to `task_directory` unless absolute), base_link, tip_link, base (a
/// pose), flange_to_end_effector (a pose), seed (joint positions). Reads the URDF; its errors are
/// reported at the field they concern (robot.tip_link for an unknown tip link, else robot.urdf).
/// Into `task`: problem.arm and options.arm.
void read_robot_section(const YamlField& robot, const std::string& task_directory, PlanTask& task);

/// `base_robot` (issue 21): the fields of `robot`, for the arm that holds the base end (s = 0).
/// Into `task`: problem.base_arm, its seed options.arm.base_seed; its reach and links are the
/// options the two arms share (options.arm), given in one of the two sections (`tip_robot`, the
/// `robot` section, absent or not).
void read_base_robot_section(const YamlField& robot,
                             const YamlField& tip_robot,
                             const std::string& task_directory,
                             PlanTask& task);

/// Runs `call` (a library validate()); an InputError whose field starts with `library` (for
/// instance "Workspace") is said at `field` with that prefix replaced by `task_name`
/// ("base_workspace"), any other as located() says it.
void located_as(const YamlField& field,
                std::string_view library,
                std::string_view task_name,
                const std::function<void()>& call);

}  // namespace rodshape::io_detail
