// rod_configuration.hpp: the rod sampled at its nodes s_i = i L / N, i = 0..N, as the integrator
// leaves it, with (optionally) the derivatives of every quantity with respect to the base wrench.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "rodshape/core/pose.hpp"
#include "rodshape/core/wrench.hpp"

namespace rodshape {

/// Which derivatives with respect to the base wrench w = (n(0), m(0)) the integrator computes.
enum class Derivatives {
  None,      // the shape only
  Tip,       // d(tip pose, tip wrench, energy)/dw: what the shooting solvers need
  AllNodes,  // also dp_i/dw, dθ_i/dw, dn_i/dw, dm_i/dw at every node (stability, shape cost)
};

/// Which values integrate() stores. The Runge–Kutta steps are the same, so the tip, the tip
/// wrench and the tip derivatives are bitwise those of Output::Full; a caller that reads only the
/// tip (a shooting solver's inner iterations) saves the per-node stores and the energy.
enum class Output {
  Full,  // s, p, R, n, m, v, u at every node, and the energy (with its derivative)
  Tip,   // nodes() == 2: the base (s = 0) and the tip (s = L); energy and denergy_dw NaN (not
         // integrated). Derivatives::AllNodes ignores it (every node is stored).
};

struct RodConfiguration {
  // Node values, world frame except u and v (body frame, as in the paper).
  std::vector<double> s;
  std::vector<Eigen::Vector3d> p;  // position
  std::vector<Eigen::Matrix3d> R;  // orientation (exactly orthonormal)
  std::vector<Eigen::Vector3d> n;  // internal force
  std::vector<Eigen::Vector3d> m;  // internal moment
  std::vector<Eigen::Vector3d> v;  // v = K_tra⁻¹ Rᵀ n + ṽ
  std::vector<Eigen::Vector3d> u;  // u = K_rot⁻¹ Rᵀ m + ũ
  double energy = 0.0;  // E = ∫ ½ΔvᵀK_traΔv + ½ΔuᵀK_rotΔu ds, J (NaN with Output::Tip)
  Output output = Output::Full;  // what was stored (Output::Tip: two nodes, no energy)

  // Derivatives with respect to w (6 columns: n(0) then m(0)). A rotation's derivative is the
  // body-frame angle: δR = R θ̂ with θ = dθ_dw δw.
  Derivatives derivatives = Derivatives::None;
  std::vector<Matrix36d> dp_dw;             // size nodes() with AllNodes, else empty
  std::vector<Matrix36d> dtheta_dw;         // "
  std::vector<Matrix36d> dn_dw;             // "
  std::vector<Matrix36d> dm_dw;             // "
  Matrix36d tip_dp_dw = Matrix36d::Zero();  // with Tip or AllNodes
  Matrix36d tip_dtheta_dw = Matrix36d::Zero();
  Matrix36d tip_dn_dw = Matrix36d::Zero();
  Matrix36d tip_dm_dw = Matrix36d::Zero();
  Eigen::Matrix<double, 1, 6> denergy_dw = Eigen::Matrix<double, 1, 6>::Zero();

  int nodes() const { return static_cast<int>(s.size()); }
  double length() const { return s.empty() ? 0.0 : s.back(); }
  Pose tip() const { return {p.back(), R.back()}; }
  Pose node_pose(int i) const { return {p[i], R[i]}; }
  /// n(L), m(L): the wrench the gripper applies to the rod at s = L.
  Wrench tip_wrench() const { return {n.back(), m.back()}; }
  /// n(0), m(0).
  BaseWrench base_wrench() const { return {n.front(), m.front()}; }

  /// Every node value (s, p, R, n, m, v, u) and the energy (unless Output::Tip) are finite; the
  /// derivatives are not looked at. One pass over the nodes: for the end of a solve, not its inner
  /// loop.
  bool finite() const;

  /// Sizes every array for `nodes` nodes; allocates only when the size changes.
  void resize(int nodes, Derivatives derivatives, Output stored = Output::Full);
};

}  // namespace rodshape
