// tip_stiffness.hpp: the second half of the stability test for a tip that is not held in every
// direction (free or partly released): the stiffness of the held rod's tip over the free
// directions.
//
// The second variation of the potential over variations with δ(pose at 0) = 0 is positive
// definite iff (i) it is on the variations that also keep the tip pose (the conjugate-point test of
// assess_stability(rod, configuration)) and (ii) its Schur complement on the tip's free directions
// is: the Hessian of the held rod's equilibrium energy with respect to the tip pose, less the dead
// tip load's work, K = d(n(L), m(L))/d(p(L), θ(L)) = Λ X⁻¹ with X = d(p(L), θ(L))/dw and
// Λ = d(n(L), m(L))/dw (at an equilibrium the gradient vanishes, so K does not depend on the
// coordinates of the pose). Tip loads are dead (fixed in the world frame), as in the solver.
#pragma once

#include <array>

#include "rodshape/core/clamped_rod.hpp"
#include "rodshape/core/rod_configuration.hpp"

namespace rodshape {

/// The smallest generalised eigenvalue λ of sym(K_f) x = λ K0_f x, K_f the tip stiffness over the
/// free directions (`free[i]`: force x, y, z then moment x, y, z of the grasp frame `grasp`, world
/// rotation) and K0_f that of the unloaded straight rod (EI, GA, GJ of `rod`, and an axial
/// compliance of at least the bending one, L³ (1/EIx + 1/EIy)/6): 1 for the unloaded rod when
/// EA ≥ 3 EI/L², ≤ 0 when the tip can move at no cost or with a gain of energy (unstable). The
/// same for any scale of the stiffnesses. NaN when X is singular (a conjugate point at s = L) or
/// nothing is free. `configuration` needs tip derivatives (Tip or AllNodes).
double tip_stiffness_eigenvalue(const ClampedRod& rod,
                                const RodConfiguration& configuration,
                                const Eigen::Matrix3d& grasp,
                                const std::array<bool, 6>& free);

}  // namespace rodshape
