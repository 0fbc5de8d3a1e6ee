// pose_continuation.hpp (private): the plan of ObjectiveInterpolation::Pose. The target's optimum
// comes from a plan by objective sets (its last step); the held rod is then followed along the end
// effector's straight path from the initial pose to that optimum's, and the equilibria at the
// fractions i / n of the path are the steps (the last one the optimum itself). A straight tip-pose
// continuation rarely bends the rod beyond its end shapes: where the sets' optima coil the rod on
// the way (a helix wound from straight), it stays at its end energies.
#pragma once

#include <array>
#include <numbers>
#include <optional>
#include <string>

#include "detour_search.hpp"
#include "plan_stages.hpp"
#include "rodshape/trajectory/plan.hpp"

namespace rodshape::pose_continuation {

/// Why the path was not taken: SnapThrough (the rod lost, unstable, or arriving on another
/// equilibrium than the optimum) or Collision (nearer to an obstacle than it requires).
struct Refusal {
  PlanStatus status = PlanStatus::SnapThrough;
  std::string why;
};

/// Re-optimisations of the goal per plan: where the path arrives at the goal's pose on another
/// stable equilibrium, the goal's step optimised from there (a local optimum of the same points on
/// the branch the rod reaches) and the path followed again to it.
inline constexpr int kMaxReoptimisations = 2;

/// Extra turns of the end effector about the rod's tangent at the tip, spread evenly along the
/// path, tried in turn where the straight path (0) and the wrench line (Way) are refused or not
/// gentle: the target's points fix the centreline, not the twist, and its optimum is the least
/// twisted equilibrium through them; the straight path to its pose may then wind the rod onto
/// another equilibrium there, where a path turning the tip by an eighth to three quarters of a
/// turn more (and back) keeps the branch (the sweep's helices needed 30° to 165°). The
/// gentlest followed plan is kept; the first within PlanOptions::kGentleRatio ends the tries.
inline constexpr double kEighthTurn = std::numbers::pi / 4;
inline constexpr std::array<double, 11> kTwists = {0.0,
                                                   kEighthTurn,
                                                   -kEighthTurn,
                                                   2 * kEighthTurn,
                                                   -2 * kEighthTurn,
                                                   3 * kEighthTurn,
                                                   -3 * kEighthTurn,
                                                   4 * kEighthTurn,
                                                   -4 * kEighthTurn,
                                                   6 * kEighthTurn,
                                                   -6 * kEighthTurn};

/// A way from the initial pose to the goal's: straight (the default), turned `twist` (rad) more
/// about the rod's tangent at the tip along the way (kTwists), or through the tip poses of the
/// equilibria whose base wrenches lie on the straight line from the initial equilibrium's to the
/// goal's (`wrench_line`): where the sets' optima and the straight pose path bend the rod beyond
/// its end shapes on the way (a bend whose chord shortens faster than its arc), the equilibria on
/// the wrench line grow steadily from one end's energy to the other's (on the sweep's bends they
/// peak at the goal).
struct Way {
  double twist = 0.0;
  bool wrench_line = false;
  bool straight() const { return twist == 0.0 && !wrench_line; }
  /// The path's name in messages ("the end effector's straight path", …).
  const char* path_name() const {
    if (wrench_line) return "the wrench line's path";
    return straight() ? "the end effector's straight path" : "the end effector's twisted path";
  }
};

/// The plan along the end effector's straight path from the initial equilibrium to `reference`'s
/// last step (a plan by objective sets that reached the target, tracked or not), or to that step
/// optimised again by `reoptimise` (may be empty) from where the path arrives instead; nullopt,
/// with `refusal`, when the rod cannot be followed there.
std::optional<PlanResult> plan(const PlanProblem& problem,
                               const PlanOptions& options,
                               const plan_stages::InitialEquilibrium& initial,
                               const PlanResult& reference,
                               const detour::Reoptimise& reoptimise,
                               Refusal& refusal);

}  // namespace rodshape::pose_continuation
