// workspace.hpp: Ws, the set the tip p(L) must stay in (paper: p(s = L) ⊂ Ws), as an intersection
// of simple smooth sets, each giving IPOPT inequality constraints g(p) with bounds and dg/dp.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

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

  std::optional<Box> box;
  // Rows of g, in this order: box (3: p itself), inside balls, outside balls, half-spaces.
  std::vector<Ball> inside;   // |p - c|² ≤ r²
  std::vector<Ball> outside;  // |p - c|² ≥ r² (e.g. around a robot's shoulder)
  std::vector<HalfSpace> half_spaces;

  bool unbounded() const {
    return !box && inside.empty() && outside.empty() && half_spaces.empty();
  }
  /// Number of rows of g: 3 for the box (two-sided), one per ball and half-space.
  int constraint_count() const;
  /// Within `tolerance` of every set.
  bool contains(const Eigen::Vector3d& p, double tolerance = 0.0) const;
  /// g(p) into `g` (size constraint_count()) and dg/dp into `dg_dp` (count × 3); pass an empty
  /// matrix (0 rows) as `dg_dp` to skip the Jacobian. Allocates nothing.
  void evaluate(const Eigen::Vector3d& p,
                Eigen::Ref<Eigen::VectorXd> g,
                Eigen::Ref<Eigen::MatrixXd> dg_dp) const;
  /// lower ≤ g(p) ≤ upper (±inf where one-sided).
  void bounds(Eigen::Ref<Eigen::VectorXd> lower, Eigen::Ref<Eigen::VectorXd> upper) const;
  /// Throws InputError naming the field ("workspace.box", "workspace.inside[1].radius", ...).
  void validate() const;
};

}  // namespace rodshape
