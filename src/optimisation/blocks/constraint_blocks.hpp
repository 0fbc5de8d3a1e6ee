// constraint_blocks.hpp (private): the constraint blocks of the shape optimisation (one .cpp each),
// made by ShapeProblem from what it is given. Each cites its rows' formula in its .cpp.
#pragma once

#include <memory>

#include "rodshape/core/clamped_rod.hpp"
#include "rodshape/optimisation/constraint_block.hpp"
#include "rodshape/optimisation/shape_constraints.hpp"
#include "rodshape/optimisation/shape_problem.hpp"
#include "rodshape/optimisation/workspace.hpp"

namespace rodshape::blocks {

/// The tip pose in the workspace (box, balls, half-spaces, reach shell).
std::unique_ptr<ConstraintBlock> workspace(const Workspace& workspace);
/// A moving base's pose (p(0), R(0)) in its workspace (issue 21).
std::unique_ptr<ConstraintBlock> base_workspace(const Workspace& workspace);
/// The tip wrench components the grasp cannot transmit are zero.
std::unique_ptr<ConstraintBlock> grasp(const Grasp& grasp);
/// |u - ũ|² ≤ κ_max² at every node.
std::unique_ptr<ConstraintBlock> curvature(const RodProperties& properties,
                                           int nodes,
                                           double max_curvature);
/// |v_z - ṽ_z| ≤ ε_max at every node (Cosserat).
std::unique_ptr<ConstraintBlock> axial_strain(const RodProperties& properties,
                                              int nodes,
                                              double max_axial_strain);
/// The rod's segments clear of the scene's obstacles by their required gaps.
std::unique_ptr<ConstraintBlock> clearance(const Clearance& clearance, int intervals);

}  // namespace rodshape::blocks
