// detour_search.hpp (private): a way around the scene's obstacles between two waypoints, when the
// straight motion of the end effector drags the rod through an obstacle (plan() stage 5b).
//
// A rapidly-exploring random tree (RRT, LaValle 1998) over end-effector poses, rooted at the
// tracked rod's waypoint, as avishais/rod_planner and DLO_planning_2 plan deformable objects: a
// node is an equilibrium of the held rod (its pose and base wrench, as the rod is path-dependent);
// an edge is the rod followed quasi-statically along the straight pose interpolation
// (follow_equilibrium), accepted when every substep keeps its required gap to every obstacle, the
// rod neither gets lost nor moves by more than a jump between substeps, and it is stable on
// arrival. Samples: the goal (a fifth of the time), else a tip pose near the two ends (positions
// in their box widened by half the rod, within its reach; rotations slerped between theirs and
// turned by up to 45°). From every new node the goal is tried; the edge to the goal must arrive on
// the planned shape, or on another stable equilibrium there from which the goal's step, optimised
// again, is reached (a few times per search). The path found is then shortened greedily (each node
// joined to the farthest later one it reaches directly). Seeded: the same problem gives the same
// detour.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "rodshape/trajectory/plan.hpp"

namespace rodshape::detour {

/// One equilibrium on the way.
struct Waypoint {
  Pose end_effector;
  BaseWrench wrench;
  RodConfiguration configuration;            // all-node derivatives (for the stability test)
  double peak_energy = 0.0;                  // of the edge that reached it, J
  double peak_curvature = 0.0;               // 1/m
  SceneGap gap;                              // the least gap of that edge
  std::optional<StabilityResult> stability;  // on arrival (an unstable one is no waypoint)
};

struct Search {
  bool found = false;
  std::vector<Waypoint> via;  // the detour's waypoints between the start and the goal
  Waypoint goal;              // the goal as reached (the planned shape's equilibrium)
  /// When the rod reached the goal's pose only on another equilibrium, the goal's step optimised
  /// again from there (Reoptimise): the step the detour arrives at instead of the planned one.
  std::optional<PlanStep> goal_step;
  int edges = 0;  // edges tried
  int nodes = 0;  // tree size
  std::string message;
};

/// Upper bounds (docs/limits.md): an edge is tracking_substeps solves.
inline constexpr int kMaxEdges = 600;
inline constexpr int kMaxNodes = 300;

/// The energy an edge may reach, over the larger of the start's and the goal's: `first` for the
/// first kGentleEdges edges, `wider` after them (the scene's detours: 1.5, then 3; a gentle path
/// with no obstacles in the way: PlanOptions::kGentleRatio throughout).
struct EnergyCaps {
  double first = 1.5;
  double wider = 3.0;
};
inline constexpr int kGentleEdges = 100;

/// The goal's step optimised from the base wrench of another equilibrium at its pose; nullopt
/// when that optimisation fails.
using Reoptimise = std::function<std::optional<PlanStep>(const BaseWrench&)>;

/// From the end-effector pose `from` (the rod's equilibrium `w` there) to the step `goal`'s
/// waypoint, arriving on its planned shape, clear of problem.scene by `required` (one per
/// obstacle).
Search search(const PlanProblem& problem,
              const PlanOptions& options,
              const std::vector<double>& required,
              const Pose& from,
              const BaseWrench& w,
              const PlanStep& goal,
              const Reoptimise& reoptimise = {},
              const EnergyCaps& caps = {});

}  // namespace rodshape::detour
