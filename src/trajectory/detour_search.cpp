// detour_search.cpp: the RRT of detour_search.hpp, in named stages: sample, nearest, steer,
// follow_edge (the quasi-static rod along one edge), grow, shorten.
#include "detour_search.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <optional>
#include <random>

#include "rodshape/solvers/stability.hpp"

#include "plan_stages.hpp"
#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/solvers/follow_equilibrium.hpp"
#include "scene_stages.hpp"

namespace rodshape::detour {

namespace {

constexpr double kGoalBias = 0.2;
/// Gentleness: an edge's peak energy at most this times the larger of the start's and the goal's
/// (the closed loop's guard against coiled re-plans uses the same ratio) for the first half of the
/// edges; when that finds no way, the second half allows kWiderEnergyRatio (the plan's tracked peak
/// energy reports what was used).
constexpr double kMaxEnergyRatio = 1.5;
constexpr double kWiderEnergyRatio = 3.0;
constexpr double kMaxTurn = 0.25 * 3.141592653589793;  // rad: a sample's turn off the slerp
constexpr double kBranchTolerance = 1e-3;
constexpr int kMaxReoptimisations = 3;  // goals optimised again from another branch, per search  //
                                        // m, arrival on the planned shape (as the tracking)

struct Node {
  Waypoint state;
  int parent = -1;
};

/// The distance between two end-effector poses: m, with rotations weighed by the rod's length.
double pose_distance(const Pose& a, const Pose& b, double length) {
  const double angle = Eigen::AngleAxisd(a.rotation.transpose() * b.rotation).angle();
  return (a.position - b.position).norm() + 0.5 * length * angle;
}

class Tree {
 public:
  Tree(const PlanProblem& problem,
       const PlanOptions& options,
       const std::vector<double>& required,
       const PlanStep& goal,
       const Reoptimise& reoptimise)
      : problem_(problem),
        options_(options),
        required_(required),
        goal_(goal),
        reoptimise_(reoptimise),
        rng_(20261125) {}

  /// The rod followed along the straight interpolation from `start` to `to`; nullopt when it is
  /// lost, jumps, comes too near an obstacle, or (with `expected`) arrives elsewhere; then, with
  /// `elsewhere`, a stable equilibrium it arrived on instead.
  std::optional<Waypoint> follow_edge(const Waypoint& start,
                                      const Pose& to,
                                      const RodConfiguration* expected,
                                      std::optional<Waypoint>* elsewhere = nullptr) {
    ++edges_;
    FollowOptions follow;
    follow.substeps = options_.tracking_substeps;
    follow.final_derivatives = Derivatives::AllNodes;
    follow.arrival_stability = true;
    const double L = problem_.rod.properties.length;
    const double jump = std::max(
        4.0 * pose_distance(start.end_effector, to, L) / options_.tracking_substeps, 0.02 * L);
    Waypoint end;
    bool blocked = false;
    std::vector<Eigen::Vector3d> previous = start.configuration.p;
    scene_stages::SweptGap swept(problem_.scene, required_, start.configuration.p);
    // Every substep: clear of the scene (with the motion since the last), no node moving like a
    // snap, below the energy cap; the first that is not stops the edge.
    follow.observer = [&](double, const RodConfiguration& c) {
      const SceneGap gap = swept.add(c.p);
      if (gap.margin < end.gap.margin) end.gap = gap;
      if (!gap.clear()) blocked = ++stops_.scene > 0;
      if (!blocked && c.energy > energy_cap_) blocked = ++stops_.energy > 0;
      for (std::size_t i = 0; i < c.p.size() && !blocked; ++i)
        if ((c.p[i] - previous[i]).norm() > jump) blocked = ++stops_.snap > 0;
      previous = c.p;
      return !blocked;
    };
    const FollowResult followed = follow_equilibrium(
        problem_.rod, plan_stages::commanded_segment(problem_, start.end_effector, to),
        start.wrench, follow, expected, kBranchTolerance);
    if (blocked) return std::nullopt;
    const bool other_branch = followed.event == FollowEvent::OtherBranch;
    if (!followed.followed() && !other_branch) {  // the observer saw every substep
      ++stops_.lost;
      return std::nullopt;
    }
    for (const FollowedState& state : followed.states) {
      end.peak_energy = std::max(end.peak_energy, state.energy);
      end.peak_curvature = std::max(end.peak_curvature, state.max_curvature);
    }
    end.end_effector = to;
    end.stability = followed.arrival_stability;
    end.wrench = followed.base_wrench;
    end.configuration = followed.configuration;
    if (!other_branch) return end;
    ++stops_.elsewhere;
    if (elsewhere) {  // follow_equilibrium stops at the branch test: the stability test here
      end.stability = assess_stability(
          problem_.rod, end.configuration,
          plan_stages::commanded_segment(problem_, start.end_effector, to).tip_at(1.0));
      if (end.stability->stable) *elsewhere = std::move(end);
    }
    return std::nullopt;
  }

  /// A tip pose near the two ends (see detour_search.hpp), as an end-effector pose.
  Pose sample(const Pose& from, const Pose& to) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const Pose& tip_T_ee = problem_.grasp.tip_to_end_effector;
    const Pose a = compose(from, inverse(tip_T_ee)), b = compose(to, inverse(tip_T_ee));
    const double L = problem_.rod.properties.length;
    const Eigen::Vector3d lower = a.position.cwiseMin(b.position).array() - 0.5 * L;
    const Eigen::Vector3d upper = a.position.cwiseMax(b.position).array() + 0.5 * L;
    const Eigen::Vector3d clamp = problem_.rod.clamp.position;
    Eigen::Vector3d p;
    do {  // within 0.95 L of the clamp: a held rod's tip cannot be farther
      for (int i = 0; i < 3; ++i) p(i) = lower(i) + unit(rng_) * (upper(i) - lower(i));
    } while ((p - clamp).norm() > 0.95 * L);
    const Eigen::Quaterniond slerped =
        Eigen::Quaterniond(a.rotation).slerp(unit(rng_), Eigen::Quaterniond(b.rotation));
    const Eigen::Vector3d axis =
        Eigen::Vector3d(unit(rng_) - 0.5, unit(rng_) - 0.5, unit(rng_) - 0.5).normalized();
    const Eigen::Matrix3d turn = Eigen::AngleAxisd(kMaxTurn * unit(rng_), axis).toRotationMatrix();
    return compose(Pose{p, turn * slerped.toRotationMatrix()}, tip_T_ee);
  }

  int nearest(const Pose& pose) const {
    const double L = problem_.rod.properties.length;
    int best = 0;
    for (std::size_t k = 1; k < nodes_.size(); ++k)
      if (pose_distance(nodes_[k].state.end_effector, pose, L) <
          pose_distance(nodes_[best].state.end_effector, pose, L))
        best = static_cast<int>(k);
    return best;
  }

  /// At most a sixth of the rod's length (in pose_distance) from `from` towards `to`.
  Pose steer(const Pose& from, const Pose& to) const {
    const double L = problem_.rod.properties.length;
    const double d = pose_distance(from, to, L);
    const double step = L / 6.0;
    return d <= step ? to : interpolate(from, to, step / d);
  }

  Search grow(const Waypoint& root) {
    const double larger = std::max(root.configuration.energy, goal_.solution.configuration.energy);
    energy_cap_ = kMaxEnergyRatio * larger;
    nodes_.push_back({root, -1});
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    while (edges_ < kMaxEdges && static_cast<int>(nodes_.size()) < kMaxNodes) {
      if (edges_ >= kMaxEdges / 2) energy_cap_ = kWiderEnergyRatio * larger;
      const Pose target = unit(rng_) < kGoalBias ? goal_.end_effector
                                                 : sample(root.end_effector, goal_.end_effector);
      const int from = nearest(target);
      const Pose next = steer(nodes_[from].state.end_effector, target);
      std::optional<Waypoint> reached = follow_edge(nodes_[from].state, next, nullptr);
      if (!reached) continue;
      nodes_.push_back({std::move(*reached), from});
      const int added = static_cast<int>(nodes_.size()) - 1;
      std::optional<Waypoint> elsewhere;
      if (auto arrived = follow_edge(nodes_[added].state, goal_.end_effector,
                                     &goal_.solution.configuration, &elsewhere)) {
        return found(added, std::move(*arrived));
      }
      if (elsewhere && reoptimise_ && reoptimised_ < kMaxReoptimisations) {
        if (auto search = goal_from(added, std::move(*elsewhere))) return std::move(*search);
      }
    }
    Search search;
    search.edges = edges_;
    search.nodes = static_cast<int>(nodes_.size());
    search.message = "no detour found in " + std::to_string(edges_) + " edges (" +
                     std::to_string(nodes_.size()) + " equilibria; edges stopped by the scene " +
                     std::to_string(stops_.scene) +
                     ", by the energy cap (1.5, then 3 x the larger end energy) " +
                     std::to_string(stops_.energy) + ", by a snap " + std::to_string(stops_.snap) +
                     ", rod lost or unstable " + std::to_string(stops_.lost) +
                     ", arrived off the planned shape " + std::to_string(stops_.elsewhere) + ")";
    return search;
  }

 private:
  /// The rod arrived at the goal's pose on another equilibrium `other` than the planned one: the
  /// goal's step optimised again from there (a local optimum of the same objective set, on the
  /// branch the rod can reach), and followed to from `other`.
  std::optional<Search> goal_from(int added, Waypoint other) {
    ++reoptimised_;
    std::optional<PlanStep> step = reoptimise_(other.wrench);
    if (!step) return std::nullopt;
    std::optional<Waypoint> on =
        follow_edge(other, step->end_effector, &step->solution.configuration);
    if (!on) return std::nullopt;
    nodes_.push_back({std::move(other), added});
    goal_ = std::move(*step);
    goal_replaced_ = true;
    return found(static_cast<int>(nodes_.size()) - 1, std::move(*on));
  }

  /// The path root → … → node `last` → goal, shortened: from each waypoint, the farthest later
  /// one (or the goal) reached directly.
  Search found(int last, Waypoint arrived) {
    std::vector<Waypoint> chain;
    for (int k = last; k >= 0; k = nodes_[k].parent) chain.push_back(nodes_[k].state);
    std::reverse(chain.begin(), chain.end());  // chain[0] is the root
    Search search;
    search.found = true;
    Waypoint at = chain.front();
    std::size_t i = 0;
    while (true) {
      if (auto direct = follow_edge(at, goal_.end_effector, &goal_.solution.configuration)) {
        search.goal = std::move(*direct);
        break;
      }
      std::size_t j = chain.size() - 1;
      std::optional<Waypoint> hop;
      for (; j > i + 1; --j)
        if ((hop = follow_edge(at, chain[j].end_effector, nullptr))) break;
      if (!hop) {  // the tree's own edge, as found
        j = i + 1;
        hop = chain[j];
      }
      search.via.push_back(*hop);
      at = std::move(*hop);
      i = j;
      if (i == chain.size() - 1) {
        search.goal = std::move(arrived);
        break;
      }
    }
    search.edges = edges_;
    search.nodes = static_cast<int>(nodes_.size());
    if (goal_replaced_) search.goal_step = goal_;
    search.message = "detour of " + std::to_string(search.via.size()) + " waypoints (" +
                     std::to_string(edges_) + " edges tried, " + std::to_string(nodes_.size()) +
                     " equilibria)" +
                     (goal_replaced_ ? "; the goal optimised again on the branch it reaches" : "");
    return search;
  }

  const PlanProblem& problem_;
  const PlanOptions& options_;
  const std::vector<double>& required_;
  PlanStep goal_;
  const Reoptimise& reoptimise_;
  bool goal_replaced_ = false;
  int reoptimised_ = 0;
  std::mt19937 rng_;
  std::vector<Node> nodes_;
  int edges_ = 0;
  struct Stops {  // why edges stopped
    int scene = 0, energy = 0, snap = 0, lost = 0, elsewhere = 0;
  } stops_;
  double energy_cap_ = 0.0;  // J
};

}  // namespace

Search search(const PlanProblem& problem,
              const PlanOptions& options,
              const std::vector<double>& required,
              const Pose& from,
              const BaseWrench& w,
              const PlanStep& goal,
              const Reoptimise& reoptimise) {
  Waypoint root;
  root.end_effector = from;
  root.wrench = w;
  root.configuration = integrate(problem.rod, w, Derivatives::AllNodes);
  Tree tree(problem, options, required, goal, reoptimise);
  return tree.grow(root);
}

}  // namespace rodshape::detour
