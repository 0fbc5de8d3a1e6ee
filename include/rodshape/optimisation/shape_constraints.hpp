// shape_constraints.hpp: what the optimal shape must respect besides the workspace: the grasp's
// wrench constraints at the tip (paper: "n_x = 0 or m_x = 0 if the grasp does not enable forces or
// moments along x"), bounds on the base wrench, and limits on the object's strain for fragile
// objects (curvature |u - ũ| and axial strain v_z - ṽ_z at every node).
#pragma once

#include <Eigen/Core>
#include <array>
#include <limits>
#include <optional>

#include "rodshape/core/clamped_rod.hpp"
#include "rodshape/core/pose.hpp"
#include "rodshape/core/wrench.hpp"

namespace rodshape {

/// How the robot holds the tip. Components of the tip wrench n(L), m(L), in the grasp frame (the
/// tip's frame R(L)), that the grasp cannot transmit are zero: order force x, y, z, moment x, y, z.
struct Grasp {
  std::array<bool, 6> released{};
  Pose tip_to_end_effector;  // tip_T_ee: the end-effector pose is world_T_tip · tip_T_ee
};

struct StrainLimits {
  std::optional<double> max_curvature;     // |u - ũ| ≤ κ_max at every node, 1/m
  std::optional<double> max_axial_strain;  // |v_z - ṽ_z| ≤ ε_max at every node (Cosserat only)
  /// Throws InputError naming "limits.max_curvature" / "limits.max_axial_strain" (must be > 0).
  void validate() const;
};

struct WrenchBounds {
  Vector6d lower = Vector6d::Constant(-std::numeric_limits<double>::infinity());
  Vector6d upper = Vector6d::Constant(std::numeric_limits<double>::infinity());

  /// Bounds from the rod's scale, |n_i(0)| ≤ F and |m_i(0)| ≤ M with
  ///   M = 4π max(EIx, EIy, GJ) / L + |f| L² / 2,  F = ½ max(K_tra) + |f| L:
  /// a base moment of M bends (or twists) the rod at the clamp by two full turns over its length,
  /// and a force of F strains it by 50 % (the model's validity limit), both plus what the
  /// distributed load f can add. Every shape the model can say anything about lies well inside;
  /// a bad start cannot wander to coiled shapes of |w| ~ 10³.
  static WrenchBounds from_scale(const ClampedRod& rod);
  /// These bounds where they are finite, `fallback`'s where they are infinite.
  WrenchBounds or_else(const WrenchBounds& fallback) const;
};

}  // namespace rodshape
