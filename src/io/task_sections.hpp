// task_sections.hpp (private to the io area): one reader per section of a task file. A command's
// reader (task_reader.cpp for `equilibrium`) lists the top-level sections it accepts and calls
// these; later commands (`plan`, ...) reuse them and add their own sections.
#pragma once

#include <Eigen/Core>
#include <array>
#include <optional>
#include <string_view>
#include <vector>

#include "io/yaml_field.hpp"
#include "rodshape/core/distributed_load.hpp"
#include "rodshape/core/pose.hpp"
#include "rodshape/core/rod_properties.hpp"
#include "rodshape/core/wrench.hpp"
#include "rodshape/solvers/shooting_solver.hpp"
#include "rodshape/solvers/tip_condition.hpp"
#include "rodshape/trajectory/plan_problem.hpp"

namespace rodshape::io_detail {

/// What the `rod` section says.
struct RodSection {
  RodDescription description;     // material only when young_modulus and poisson_ratio are given
  std::optional<double> density;  // rod.material.density, kg/m³, when given
  int nodes = 101;                // rod.nodes: N + 1 sample points, both ends included
};

/// The largest rod.nodes accepted: ClampedRod::kMaxIntervals + 1 (docs/limits.md, "Sizes"). A
/// plan accepts fewer: kMaxPlanNodes.
inline constexpr int kMaxNodes = ClampedRod::kMaxIntervals + 1;
inline constexpr int kMaxPlanNodes = PlanProblem::kMaxIntervals + 1;

/// `rod`: length, nodes, model, section, material, stiffness, rest_curvature.
RodSection read_rod_section(const YamlField& rod);

/// make_rod_properties() with errors located in the file, and ρA from the density alone when the
/// rod is otherwise given by its stiffness.
RodProperties build_rod_properties(const RodSection& rod, const YamlField& rod_field);

/// Top-level `gravity` (weight f = ρ A g) and `distributed_load` ({force, moment} per length,
/// world frame), added together.
DistributedLoad read_distributed_load(const YamlField& root, const RodSection& rod);

/// A rotation: a quaternion [w, x, y, z] (norm within 1e-6 of 1, then normalised) or a 3×3 matrix
/// given as three rows (orthonormal within 1e-6, det +1, then projected onto SO(3)).
Eigen::Matrix3d read_rotation(const YamlField& rotation);

/// `position` (required) and `rotation` (default identity) of a mapping that may hold other keys.
Pose read_pose_fields(const YamlField& pose);

/// A pose mapping {position, rotation}.
Pose read_pose(const YamlField& pose);

/// {force, moment}, each [x, y, z] and zero when omitted.
Wrench read_wrench(const YamlField& wrench);

/// A list of wrench axes among fx, fy, fz, mx, my, mz (each at most once), in the order force x, y,
/// z, moment x, y, z: `tip.released` and `grasp.zero_wrench`.
std::array<bool, 6> read_wrench_axes(const YamlField& axes);

/// `tip`: {position, rotation} clamped, {position, rotation, released} grasped, {wrench} free.
TipCondition read_tip_condition(const YamlField& tip);

/// `solver`: max_iterations, tolerance, continuation, max_continuation_steps, initial_wrench.
/// Fields left out keep the values already in `options` and `initial_wrench`.
void read_solver_section(const YamlField& solver,
                         ShootingOptions& options,
                         BaseWrench& initial_wrench);

}  // namespace rodshape::io_detail
