// intermediate_targets.hpp: the objective points of each step of the trajectory (paper, "Optimal
// trajectory generation"): p_init is the projection of each objective point on the initial shape,
// and the n_inter sets of step i = 1 … n_inter are
//   p^i = p_init + i (p_obj - p_init) / n_inter,
// so that the last step is p_obj itself. (The paper writes (i - 1), which stops one step short.)
#pragma once

#include <Eigen/Core>
#include <vector>

#include "rodshape/core/clamped_rod.hpp"
#include "rodshape/core/rod_configuration.hpp"

namespace rodshape {

using PointSet = std::vector<Eigen::Vector3d>;

/// The initial rod's point at each arc length (clamped to [0, L]): p_init by arc length, the
/// point of the initial rod that is the same material point as the objective point is on the
/// target (its arc length on the target curve, FeasibilityResult::arc_lengths). Between nodes,
/// the rod is integrated from the node before (pose_between_nodes), so `initial` must carry
/// Derivatives::AllNodes; throws InputError otherwise.
PointSet points_at_arc_lengths(const ClampedRod& rod,
                               const RodConfiguration& initial,
                               const std::vector<double>& arc_lengths);

/// The closest point of the initial curve Γ_0 to each objective point (continuous in s).
PointSet project_onto_initial_shape(const RodConfiguration& initial, const PointSet& objective);

/// p_init + fraction (p_obj - p_init); exactly p_obj when fraction is 1. Throws InputError when
/// the two sets differ in size.
PointSet objective_set(const PointSet& initial, const PointSet& objective, double fraction);

/// The chain clamp → p_1 → … → p_n bent from `initial` to `objective`: link j (from the point
/// before, the clamp for j = 1) keeps its direction turned by `fraction` of the rotation that
/// takes its initial direction to its target one (the least rotation, slerp), and its length is
/// interpolated linearly; the points are the chain's joints. Exactly `objective` when fraction is
/// 1, `initial` when 0. A link of zero length at either end is interpolated linearly. Throws
/// InputError when the two sets differ in size.
PointSet turned_objective_set(const Eigen::Vector3d& clamp,
                              const PointSet& initial,
                              const PointSet& objective,
                              double fraction);

/// The rigid motion x → R (x - from_centroid) + to_centroid that best takes one point set onto
/// another in the least-squares sense (Kabsch's SVD, a proper rotation). Where the fit leaves a
/// turn free (a set on a line: the covariance has rank ≤ 1), the least rotation taking the line's
/// direction onto the other set's principal one.
struct RigidAlignment {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d from_centroid = Eigen::Vector3d::Zero();
  Eigen::Vector3d to_centroid = Eigen::Vector3d::Zero();
};
RigidAlignment best_rigid_alignment(const PointSet& from, const PointSet& to);

/// With a moving base (issue 21) the chain from a fixed clamp says little: the target is seen
/// from the initial frame after the best rigid alignment (the target moved back by it), the chain
/// `base` → p_1 → … → p_n bent there as turned_objective_set does, and the result carried by the
/// alignment interpolated (its centroid on a line, its rotation slerped from I):
///   q_i(f) = c_init + f (c_obj - c_init) + R(f) (s_i(f) - c_init),  R(f) = exp(f log R).
/// Exactly `objective` when fraction is 1, `initial` when 0.
PointSet aligned_objective_set(const Eigen::Vector3d& base,
                               const PointSet& initial,
                               const PointSet& objective,
                               double fraction);

/// The n_inter intermediate sets, objective_set(i / n_inter) for i = 1 … n_inter; throws InputError
/// ("trajectory.steps") when n_inter < 1 and when the two sets differ in size.
std::vector<PointSet> intermediate_targets(const PointSet& initial,
                                           const PointSet& objective,
                                           int n_inter);

}  // namespace rodshape
