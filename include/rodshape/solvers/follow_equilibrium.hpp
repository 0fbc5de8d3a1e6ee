// follow_equilibrium.hpp: the held rod followed along a path of boundary conditions, σ ∈ [0, 1]
// (continuation). At each substep the equilibrium is solved directly (Levenberg–Marquardt, no
// continuation of its own) from the last one, so the rod stays on the branch it starts on, as a
// quasi-static rod does while the gripper moves slowly. Used by solve_equilibrium()'s continuation
// (adaptive steps from the unloaded rod), the planner's tracking between waypoints (fixed steps),
// and a simulated plant driven by a commanded path.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "rodshape/core/clamped_rod.hpp"
#include "rodshape/core/pose.hpp"
#include "rodshape/core/rod_configuration.hpp"
#include "rodshape/enum_names.hpp"
#include "rodshape/solvers/shooting_solver.hpp"
#include "rodshape/solvers/stability.hpp"
#include "rodshape/solvers/tip_condition.hpp"

namespace rodshape {

/// A one-parameter family of boundary-value problems: the tip condition at σ ∈ [0, 1] and, with
/// ramp_loads, the rod's distributed load scaled by σ (a continuation from the unloaded rod).
/// σ = 0 is where the start wrench is an equilibrium.
struct EquilibriumPath {
  std::function<TipCondition(double sigma)> tip_at;
  bool ramp_loads = false;
  /// The base end held by a moving gripper (issue 21): the clamp pose at σ (empty: the rod's
  /// own clamp throughout). Each substep's solve starts from the last base wrench turned with
  /// the clamp (the same wrench in the base's frame).
  std::function<Pose(double sigma)> clamp_at = {};
};

/// The tip held (ClampedTip, or GraspedTip where `released` has a component) at the poses
/// interpolated between `from` and `to` (position on the line, rotation by slerp).
EquilibriumPath held_tip_path(const Pose& from,
                              const Pose& to,
                              const std::array<bool, 6>& released = {});

/// The tip held at each pose of `samples` in turn: σ_k = k / (K - 1) for K samples (the first is
/// where the rod starts), each reached in one substep (use FollowOptions::substeps = K - 1).
EquilibriumPath sampled_tip_path(std::vector<TipCondition> samples);

struct FollowOptions {
  /// Upper bound of substeps and max_substeps (docs/limits.md, "Sizes"): a substep is one solve.
  static constexpr int kMaxSubsteps = 4096;

  /// Each substep's direct solve (its `continuation` is not used; `output_derivatives` is the
  /// derivatives of the last substep's configuration, see final_derivatives).
  ShootingOptions shooting;
  /// Fixed schedule: σ_j = j / substeps, j = 1 … substeps; the first failed substep ends the
  /// path. Used when `adaptive` is false. Without a moving clamp or ramped loads, each substep
  /// after the first starts from a predictor along the path's tangent (-B⁻¹ r from the last
  /// root's Jacobian estimate, second order from the third substep on) where it is closer.
  int substeps = 10;
  /// Adaptive schedule: the first step is initial_step, a step is doubled after it converges and
  /// halved after it fails, down to 1 / max_substeps; a secant predictor extrapolates the last
  /// two solutions. Substeps that failed are counted in the summary but not recorded as states.
  bool adaptive = false;
  double initial_step = 0.125;
  int max_substeps = 256;
  /// The derivatives stored in the returned (last) configuration.
  Derivatives final_derivatives = Derivatives::AllNodes;
  /// Assess the stability of every substep's equilibrium (an unstable one ends the path with the
  /// event Unstable); false: none is assessed (see arrival_stability).
  bool stability_every_substep = false;
  /// Assess the stability of the last configuration (needs final_derivatives = AllNodes).
  bool arrival_stability = false;
  /// Called with every accepted substep's σ and equilibrium (e.g. to measure its gap to a scene);
  /// returning false stops the path there (the event Stopped). Empty: nothing is called.
  std::function<bool(double sigma, const RodConfiguration&)> observer;
  /// Throws InputError naming the field ("FollowOptions.substeps = 0 must be >= 1").
  void validate() const;
};

/// One substep's equilibrium, as followed.
struct FollowedState {
  double sigma = 0.0;
  BaseWrench base_wrench;
  Pose tip;                                  // the rod's tip pose
  Wrench tip_wrench;                         // n(L), m(L)
  double energy = 0.0;                       // J
  double max_curvature = 0.0;                // max over nodes of |(u_x, u_y)|, 1/m
  ShootingSummary solve;                     // this substep's direct solve
  std::optional<StabilityResult> stability;  // when stability_every_substep
};

enum class FollowEvent {
  None,         // the path was followed to σ = 1
  Lost,         // a substep's solve failed: the equilibrium cannot be followed further
  Unstable,     // a followed equilibrium (every substep, or on arrival) is unstable
  OtherBranch,  // on arrival the rod is not the expected equilibrium (follow_equilibrium's
                // `expected`): it went over to another branch on the way (snap-through)
  Stopped,      // FollowOptions::observer returned false at a substep
};
/// The names of FollowEvent, in its order (to_string).
inline constexpr EnumNames<FollowEvent, 5> kFollowEventNames = {{
    {FollowEvent::None, "none"},
    {FollowEvent::Lost, "lost"},
    {FollowEvent::Unstable, "unstable"},
    {FollowEvent::OtherBranch, "other_branch"},
    {FollowEvent::Stopped, "stopped"},
}};
/// "none", "lost", "unstable", "other_branch", "stopped"
std::string to_string(FollowEvent event);

struct FollowResult {
  FollowEvent event = FollowEvent::None;
  std::string message = "follow_equilibrium() was not called";
  double sigma = 0.0;        // how far the path was followed (1 when it was followed to the end)
  double event_sigma = 0.0;  // where the event happened (Lost: the σ whose solve failed)
  ShootingSummary failed_solve;       // Lost: the solve that failed
  std::vector<FollowedState> states;  // every accepted substep, σ increasing
  BaseWrench base_wrench;             // the last followed equilibrium's (the start if none)
  RodConfiguration configuration;     // the last followed equilibrium, with final_derivatives
  ShootingSummary total;              // the work of every substep added up; its status is the
                                      // last substep's (Converged when followed to the end)
  std::optional<StabilityResult> arrival_stability;  // with arrival_stability
  double arrival_deviation = 0.0;  // with `expected`: max over nodes |p_i - p_expected,i|, m
  bool followed() const { return event == FollowEvent::None; }
  /// One line: "followed to the end in 10 substeps (…)" or the event and where it happened.
  std::string brief() const;
};

/// Follows the equilibrium of `rod` along `path` from `start` (an equilibrium at σ = 0). With
/// `expected` (a configuration of the same rod), the arrival is compared with it: farther than
/// branch_tolerance (m, at any node) is the event OtherBranch. Throws InputError for bad input;
/// an equilibrium that cannot be followed is an event, never thrown.
FollowResult follow_equilibrium(const ClampedRod& rod,
                                const EquilibriumPath& path,
                                const BaseWrench& start,
                                const FollowOptions& options = {},
                                const RodConfiguration* expected = nullptr,
                                double branch_tolerance = 1e-3);

/// Largest distance between corresponding nodes of two configurations of the same rod, m.
double node_deviation(const RodConfiguration& a, const RodConfiguration& b);

}  // namespace rodshape
