// rod_reach.hpp: how far from its clamp a rod can hold its tip without leaving the range of the
// model (model_validity.hpp). The tip is p(L) = p(0) + ∫₀ᴸ R v ds (paper, kinematics p' = R v) and
// |R v| = |v|, so |p(L) - p(0)| ≤ L max|v|: a tip held farther is out of reach, said before solving
// (issue 24, item 5) instead of after the solver's iteration limit.
#pragma once

#include <optional>
#include <string>

#include "rodshape/core/clamped_rod.hpp"
#include "rodshape/solvers/model_validity.hpp"
#include "rodshape/solvers/tip_condition.hpp"

namespace rodshape {

/// L max|v| over the strains `limits` allow: for a Cosserat rod
/// |v| ≤ √((|ṽx| + ε_s)² + (|ṽy| + ε_s)² + (|ṽz| + ε_a)²); for a Kirchhoff rod v = ṽ.
double max_tip_distance(const RodProperties& properties, const ModelValidityLimits& limits);

/// The held position nearest the clamp: a clamped tip's p_d; a grasp's p_d moved along its released
/// force axes (the tip slides freely along R_d e_i) to the point nearest `clamp`. Empty for a free
/// tip.
std::optional<Eigen::Vector3d> nearest_held_position(const Eigen::Vector3d& clamp,
                                                     const TipCondition& tip);

/// Throws InputError(pose_field, ": the position is ... m from the clamp, out of reach: ...") when
/// the held position nearest the clamp is farther from `rod.clamp` than max_tip_distance() (the
/// limits named as `limits_owner`.max_axial_strain etc.). A free tip passes.
void check_within_reach(const ClampedRod& rod,
                        const TipCondition& tip,
                        const ModelValidityLimits& limits,
                        const std::string& pose_field,
                        const std::string& limits_owner);

}  // namespace rodshape
