// tip_condition.hpp: the boundary condition at s = L. At s = 0 the rod is clamped.
#pragma once

#include <array>
#include <variant>

#include "rodshape/core/pose.hpp"
#include "rodshape/core/wrench.hpp"

namespace rodshape {

/// Clamped–free: the tip carries a given wrench (world frame): n(L) = F, m(L) = M.
struct FreeTip {
  Wrench wrench;
};

/// Clamped–clamped: the robot holds the tip at a pose: p(L) = p_d, R(L) = R_d.
struct ClampedTip {
  Pose pose;
};

/// Partial grasp: the tip pose is held except along `released` axes of the grasp frame R_d, which
/// carry no wrench. Order: force x, y, z (translation free, n(L)·R_d e_i = 0), then moment x, y, z
/// (rotation free, m(L)·R_d e_i = 0). Releasing moment x only is the paper's "m_x = 0" grasp: the
/// tip may turn about the grasp's x axis, which stays aligned with R_d e_x. Releasing all six is
/// bad input (it holds nothing: that is a FreeTip).
struct GraspedTip {
  Pose pose;
  std::array<bool, 6> released{};
};

using TipCondition = std::variant<FreeTip, ClampedTip, GraspedTip>;

/// "free", "clamped" or "grasped".
const char* tip_condition_name(const TipCondition& condition);

}  // namespace rodshape
