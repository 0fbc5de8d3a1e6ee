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
#include "validation.hpp"

namespace rodshape::detour {

namespace {

constexpr double kGoalBias = 0.2;
// Gentleness: an edge's peak energy at most EnergyCaps::first times the larger of the start's
// and the goal's (the closed loop's guard against coiled re-plans uses 1.5) for the first
// kGentleEdges edges; when they find no way, the rest allow EnergyCaps::wider (the plan's tracked
// peak energy reports what was used: the path taken, shortened, is often below the first cap).
constexpr double kMaxTurn = 0.25 * 3.141592653589793;  // rad: a sample's turn off the slerp
constexpr double kBranchTolerance = 1e-3;  // m, arrival on the planned shape (as the tracking)
constexpr int kMaxReoptimisations = 3;     // goals optimised again from another branch, per search
constexpr int kFoldCheckResolution = 16;   // substeps per search substep, verifying the path
constexpr double kSpike = 4.0;             // a substep's motion over the largest before it: a snap
/// The longest edge towards a sample, in pose_distance.
constexpr double kSteerLength(double rod_length) { return rod_length / 6.0; }

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
       const Reoptimise& reoptimise,
       const EnergyCaps& caps)
      : problem_(problem),
        options_(options),
        required_(required),
        goal_(goal),
        reoptimise_(reoptimise),
        rng_(20261125),
        caps_(caps) {}

  /// The rod followed along the straight interpolation from `start` to `to`; nullopt when it is
  /// lost, jumps, comes too near an obstacle, or (with `expected`) arrives elsewhere; then, with
  /// `elsewhere`, a stable equilibrium it arrived on instead.
  std::optional<Waypoint> follow_edge(const Waypoint& start,
                                      const Pose& to,
                                      const RodConfiguration* expected,
                                      std::optional<Waypoint>* elsewhere = nullptr,
                                      int resolution = 1) {
    ++edges_;
    FollowOptions follow;
    const double L = problem_.rod.properties.length;
    const double distance = pose_distance(start.end_effector, to, L);
    // One resolution along every edge: tracking_substeps per sixth of the rod's length (a steered
    // edge's), more on the long edges to the goal, so that no fold is stepped over.
    follow.substeps = std::clamp(
        resolution *
            static_cast<int>(std::ceil(options_.tracking_substeps * distance / kSteerLength(L))),
        resolution * options_.tracking_substeps, FollowOptions::kMaxSubsteps);
    follow.final_derivatives = Derivatives::AllNodes;
    follow.arrival_stability = true;
    const double jump = std::max(4.0 * distance / follow.substeps, 0.02 * L);
    Waypoint end;
    bool blocked = false;
    std::vector<Eigen::Vector3d> previous = start.configuration.p;
    double largest = 0.0;  // the largest node displacement of a substep so far
    scene_stages::SweptGap swept(problem_.scene, required_, start.configuration.p);
    // Every substep: clear of the scene (with the motion since the last), no node moving like a
    // snap, below the energy cap; the first that is not stops the edge.
    follow.observer = [&](double, const RodConfiguration& c) {
      const SceneGap gap = swept.add(c.p);
      if (gap.margin < end.gap.margin) end.gap = gap;
      if (!gap.clear()) blocked = ++stops_.scene > 0;
      if (!blocked && c.energy > energy_cap_) blocked = ++stops_.energy > 0;
      double moved = 0.0;
      for (std::size_t i = 0; i < c.p.size(); ++i)
        moved = std::max(moved, (c.p[i] - previous[i]).norm());
      // A snap: a node moving farther than `jump`, or, when following finely (resolution > 1), a
      // substep moving kSpike times farther than any before it (smooth motion changes gradually).
      const bool spike = resolution > 1 && largest > 0.0 && moved > kSpike * largest;
      if (!blocked && (moved > jump || spike)) blocked = ++stops_.snap > 0;
      largest = std::max(largest, moved);
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
    const double step = kSteerLength(L);
    return d <= step ? to : interpolate(from, to, step / d);
  }

  Search grow(const Waypoint& root) {
    const double larger = std::max(root.configuration.energy, goal_.solution.configuration.energy);
    energy_cap_ = caps_.first * larger;
    nodes_.push_back({root, -1});
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    while (edges_ < kMaxEdges && static_cast<int>(nodes_.size()) < kMaxNodes) {
      if (edges_ >= kGentleEdges) energy_cap_ = caps_.wider * larger;
      const Pose target = unit(rng_) < kGoalBias ? goal_.end_effector
                                                 : sample(root.end_effector, goal_.end_effector);
      const int from = nearest(target);
      const Pose next = steer(nodes_[from].state.end_effector, target);
      std::optional<Waypoint> reached = follow_edge(nodes_[from].state, next, nullptr);
      if (!reached) continue;
      nodes_.push_back({std::move(*reached), from});
      const int added = static_cast<int>(nodes_.size()) - 1;
      std::optional<Waypoint> elsewhere;
      if (follow_edge(nodes_[added].state, goal_.end_effector, &goal_.solution.configuration,
                      &elsewhere)) {
        if (std::optional<Search> search = found(added)) return std::move(*search);
        continue;
      }
      if (elsewhere && reoptimise_ && reoptimised_ < kMaxReoptimisations) {
        if (auto search = goal_from(added, std::move(*elsewhere))) return std::move(*search);
      }
    }
    Search search;
    search.edges = edges_;
    search.nodes = static_cast<int>(nodes_.size());
    search.message = "no detour found in " + std::to_string(edges_) + " edges (" +
                     std::to_string(nodes_.size()) + " equilibria; " + stops_text() + ")";
    return search;
  }

 private:
  /// Why edges stopped, for the search's message.
  std::string stops_text() const {
    return "edges stopped by the scene " + std::to_string(stops_.scene) + ", by the energy cap (" +
           detail::format_value(caps_.first) +
           (caps_.wider != caps_.first ? ", then " + detail::format_value(caps_.wider)
                                       : std::string()) +
           " x the larger end energy) " + std::to_string(stops_.energy) + ", by a snap " +
           std::to_string(stops_.snap) + ", rod lost or unstable " + std::to_string(stops_.lost) +
           ", arrived off the planned shape " + std::to_string(stops_.elsewhere);
  }

  /// The rod arrived at the goal's pose on another equilibrium `other` than the planned one: the
  /// goal's step optimised again from there (a local optimum of the same objective set, on the
  /// branch the rod can reach), and followed to from `other`.
  std::optional<Search> goal_from(int added, Waypoint other) {
    ++reoptimised_;
    std::optional<PlanStep> step = reoptimise_(other.wrench);
    if (!step) return std::nullopt;
    if (!follow_edge(other, step->end_effector, &step->solution.configuration)) return std::nullopt;
    nodes_.push_back({std::move(other), added});
    goal_ = std::move(*step);
    goal_replaced_ = true;
    return found(static_cast<int>(nodes_.size()) - 1);
  }

  /// An edge of the path taken, followed kFoldCheckResolution times as finely as the search's
  /// (a fold stepped over by the coarse edge shows there as a spike, or as the rod lost or
  /// arriving elsewhere), arriving on `expected`.
  std::optional<Waypoint> verified(const Waypoint& at,
                                   const Pose& to,
                                   const RodConfiguration& expected) {
    return follow_edge(at, to, &expected, nullptr, kFoldCheckResolution);
  }

  /// The path root → … → node `last` → goal, shortened: from each waypoint, the farthest later
  /// one (or the goal) reached directly; every edge taken verified. nullopt when an edge of the
  /// tree fails its verification (the search goes on).
  std::optional<Search> found(int last) {
    std::vector<Waypoint> chain;
    for (int k = last; k >= 0; k = nodes_[k].parent) chain.push_back(nodes_[k].state);
    std::reverse(chain.begin(), chain.end());  // chain[0] is the root
    Search search;
    Waypoint at = chain.front();
    for (std::size_t i = 0;;) {
      const RodConfiguration& goal = goal_.solution.configuration;
      const bool last_node = i == chain.size() - 1;
      if (last_node || follow_edge(at, goal_.end_effector, &goal)) {
        std::optional<Waypoint> direct = verified(at, goal_.end_effector, goal);
        if (direct) {
          search.goal = std::move(*direct);
          break;
        }
        if (last_node) return std::nullopt;
      }
      std::size_t j = chain.size() - 1;
      std::optional<Waypoint> hop;
      for (; j > i + 1 && !hop; --j) {
        if (std::optional<Waypoint> coarse = follow_edge(at, chain[j].end_effector, nullptr))
          hop = verified(at, chain[j].end_effector, coarse->configuration);
        if (hop) break;
      }
      if (!hop) {  // the tree's own edge
        j = i + 1;
        hop = verified(at, chain[j].end_effector, chain[j].configuration);
        if (!hop) return std::nullopt;
      }
      search.via.push_back(*hop);
      at = std::move(*hop);
      i = j;
    }
    search.found = true;
    search.edges = edges_;
    search.nodes = static_cast<int>(nodes_.size());
    if (goal_replaced_) search.goal_step = goal_;
    search.message = "detour of " + std::to_string(search.via.size()) + " waypoints (" +
                     std::to_string(edges_) + " edges tried, " + std::to_string(nodes_.size()) +
                     " equilibria; " + stops_text() + ")" +
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
  EnergyCaps caps_;
  double energy_cap_ = 0.0;  // J
};

}  // namespace

Search search(const PlanProblem& problem,
              const PlanOptions& options,
              const std::vector<double>& required,
              const Pose& from,
              const BaseWrench& w,
              const PlanStep& goal,
              const Reoptimise& reoptimise,
              const EnergyCaps& caps) {
  Waypoint root;
  root.end_effector = from;
  root.wrench = w;
  root.configuration = integrate(problem.rod, w, Derivatives::AllNodes);
  Tree tree(problem, options, required, goal, reoptimise, caps);
  return tree.grow(root);
}

}  // namespace rodshape::detour
