// contact_equilibrium.hpp: the clamped rod's equilibrium resting on touchable obstacles
// (Obstacle::contact = Touch), frictionless (issue 45).
//
// The gap g(s) = d(p(s)) - h(s) is the obstacle's signed distance at the centreline less the
// section's support distance along the normal ν = ∇d (its radius; for a rectangle
// ½w|d1·ν| + ½h|d2·ν|, the reaction still through the centreline). The contact set is a list of
// patches, each on one obstacle:
//  * a segment [a, b] lying on a plane (a half-space, a box's face) that the load presses the rod
//    onto: there the reaction is the line force λ = -f·ν along ν, and a rod on the plane with
//    n·ν = 0 and m·(ν × t) = 0 stays on it (for a Kirchhoff rod exactly; for a Cosserat rod too,
//    its shear along ν being then 0). A free end inside the rod carries a point reaction P ν: at a
//    touch-down a, g = 0 and g' = 0 before it and the two plane conditions after it; at a lift-off
//    b, nothing more (its s and P are fixed by the rest); at the clamp the two plane conditions on
//    the base wrench; a segment to a held tip repeats two of the tip's conditions (least squares).
//  * a point contact s_c on any shape: P ν with g = 0 and the mean of g'(s⁻), g'(s⁺) zero; at a
//    free tip (the tip resting on the obstacle at an angle), P ν joins the tip's wrench and only
//    g(L) = 0 is asked; it becomes a segment to the tip when the rod rises towards the tip.
// This is the Kirchhoff rod's contact: its reaction is concentrated at a lift-off (a shearable
// rod's line reaction peaks there in a layer of length √(EI/GA) instead; the two differ in the
// lying length by about that, and a Cosserat rod dips into the surface behind a point force by
// about P/GA times the layer). The ends are located between nodes by the conditions, not snapped
// to them. A rod lying along a curved surface (wrapped round a peg) is not solved: its penetrating
// run becomes a point contact, and further penetrations further ones (docs/limits.md).
//
// The unknowns (the base wrench, each end's s and P) solve those conditions and the tip condition
// by Gauss–Newton on a central-difference Jacobian kept up to date by Broyden's updates; the
// contact set is then updated (a pulling reaction drops its patch or turns a segment into a point,
// a penetration of the free span adds one) until it is consistent. The load is applied in steps
// from the weightless rod's free equilibrium, the contact set followed from step to step.
#pragma once

#include <string>
#include <vector>

#include "rodshape/core/clamped_rod.hpp"
#include "rodshape/core/contact_loads.hpp"
#include "rodshape/core/scene.hpp"
#include "rodshape/solvers/shooting_solver.hpp"
#include "rodshape/solvers/tip_condition.hpp"

namespace rodshape {

/// One patch of contact in an equilibrium: an interval of s on one obstacle.
struct RodContact {
  int obstacle = -1;                  // index into the scene's obstacles
  double s_start = 0.0, s_end = 0.0;  // equal for a point contact, m
  /// The whole reaction on the rod (line and point forces), N, world frame.
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  /// The line reaction λ on a segment, N/m (0 at a point contact).
  double max_line_force = 0.0;
  /// The concentrated reactions at the ends (the point contact's in `start_force`), N.
  double start_force = 0.0, end_force = 0.0;
  bool point() const { return s_start == s_end; }
};

struct ContactOptions {
  /// Contact-set updates at most (each a Newton solve).
  int max_active_set_iterations = 40;
  /// Newton iterations per contact set.
  int max_newton_iterations = 60;
  /// A node of a free span is clear when its gap is at least -gap_tolerance, m; contact gaps are
  /// solved to the shooting residual tolerance. 1e-8 m is above the dip of a Cosserat rod behind
  /// a lift-off's concentrated reaction P, about (P/GA)·√(EI/GA) (1e-9 m for the bundled cable):
  /// that dip is the model's, not a contact.
  double gap_tolerance = 1e-8;
  static constexpr int kMaxActiveSetIterations = 1000;
  static constexpr int kMaxNewtonIterations = 1000;
  /// Throws InputError naming the field.
  void validate() const;
};

struct ContactEquilibriumResult {
  /// The summary (Converged only for a consistent contact set whose residual and integration
  /// error are within tolerance), the base wrench and the configuration (no derivatives when a
  /// contact is active).
  ShootingResult shooting;
  std::vector<RodContact> contacts;
  /// The least gap over the touchable obstacles at the nodes and contact ends, m.
  double least_gap = 0.0;
  int active_set_iterations = 0;
  int newton_iterations = 0;
  /// "2 contacts, largest reaction 0.51 N".
  std::string brief() const;
};

/// Solves the equilibrium of `rod` with `tip` resting on the scene's touchable obstacles (the
/// others are not looked at: their clearance is the caller's). With no touchable obstacle, or when
/// the free equilibrium clears them all, it is solve_equilibrium()'s result, contacts empty.
/// Throws InputError for bad input (as solve_equilibrium, and a rod without a section and with a
/// scene.rod_radius of 0 touching an obstacle is its centreline touching it).
ContactEquilibriumResult solve_contact_equilibrium(const ClampedRod& rod,
                                                   const TipCondition& tip,
                                                   const Scene& scene,
                                                   const BaseWrench& guess = {},
                                                   const ShootingOptions& options = {},
                                                   const ContactOptions& contact = {});

/// The gap of the rod's surface to `obstacle` at a point of the rod, m: d(p) minus the section's
/// support distance along ∇d(p) (`radius` when the section is unknown).
double contact_gap(const Obstacle& obstacle,
                   const RodPoint& point,
                   const RodProperties& properties,
                   double radius);

}  // namespace rodshape
