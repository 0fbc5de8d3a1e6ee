// workspace.hpp: Ws, the set the tip must stay in (paper: p(s = L) ⊂ Ws), as an intersection of
// simple smooth sets, each giving IPOPT inequality constraints g with bounds and derivatives. The
// box, balls and half-spaces bound the tip's position p(L); the reach shell bounds a point fixed in
// the tip's frame (an arm's wrist), so it depends on the tip's orientation R(L) as well.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <optional>
#include <vector>

#include "rodshape/core/pose.hpp"

namespace rodshape {

struct Workspace {
  struct Box {
    Eigen::Vector3d lower, upper;  // lower ≤ p ≤ upper
  };
  struct Ball {
    Eigen::Vector3d center;
    double radius;
  };
  struct HalfSpace {
    Eigen::Vector3d normal;  // nᵀ p ≤ offset
    double offset;
  };

  /// An arm's reach seen from the rod's tip: the point q = p(L) + R(L) t, fixed in the tip's frame
  /// (the arm's wrist point when the hand holds the tip; see ArmReach), lies in a spherical shell
  /// around `center` (the arm's shoulder): inner_radius ≤ |q - c| ≤ outer_radius.
  struct ReachShell {
    Eigen::Vector3d center = Eigen::Vector3d::Zero();
    double inner_radius = 0.0;  // 0: no lower bound
    double outer_radius = 0.0;
    Eigen::Vector3d tip_point = Eigen::Vector3d::Zero();  // t, in the tip frame
    /// q for a tip pose.
    Eigen::Vector3d point(const Pose& tip) const { return tip.position + tip.rotation * tip_point; }
    /// |q - c| for a tip pose.
    double distance(const Pose& tip) const { return (point(tip) - center).norm(); }
  };

  /// Upper bound on each of inside, outside and half_spaces (docs/limits.md, "Sizes"): each is a
  /// row of g, evaluated with its derivatives at every iteration of every step.
  static constexpr std::size_t kMaxSets = 100;

  std::optional<Box> box;
  // Rows of g, in this order: box (3: p itself), inside balls, outside balls, half-spaces, reach
  // (one row, two-sided).
  std::vector<Ball> inside;   // |p - c|² ≤ r²
  std::vector<Ball> outside;  // |p - c|² ≥ r²
  std::vector<HalfSpace> half_spaces;
  std::optional<ReachShell> reach;  // r_in² ≤ |q - c|² ≤ r_out² (no lower bound when r_in = 0)

  bool unbounded() const {
    return !box && inside.empty() && outside.empty() && half_spaces.empty() && !reach;
  }
  /// Number of rows of g: 3 for the box (two-sided), one per ball and half-space, one for the
  /// reach shell (two-sided).
  int constraint_count() const;
  /// The tip pose is within `tolerance` (a distance, m) of every set.
  bool contains(const Pose& tip, double tolerance = 0.0) const;
  /// g at the tip pose into `g` (size constraint_count()), dg/dp into `dg_dp` and dg/dθ into
  /// `dg_dtheta` (count × 3 each), θ being the tip's rotation increment in its own frame
  /// (δR = R θ̂; only the reach row depends on it). Allocates nothing.
  void evaluate(const Pose& tip,
                Eigen::Ref<Eigen::VectorXd> g,
                Eigen::Ref<Eigen::MatrixXd> dg_dp,
                Eigen::Ref<Eigen::MatrixXd> dg_dtheta) const;
  /// lower ≤ g(p) ≤ upper (±inf where one-sided).
  void bounds(Eigen::Ref<Eigen::VectorXd> lower, Eigen::Ref<Eigen::VectorXd> upper) const;
  /// Throws InputError naming the field ("workspace.box", "workspace.inside[1].radius",
  /// "workspace.reach.outer_radius", ...).
  void validate() const;
};

}  // namespace rodshape
