#include "rodshape/solvers/tip_stiffness.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>
#include <limits>

namespace rodshape {

namespace {

/// The tip compliance of the unloaded straight rod of length L in its clamp frame, d(p(L), θ(L)) /
/// d(F, M) for a tip force F and moment M about the tip (symmetric, Maxwell–Betti):
///   p_x: L³/(3 EIy) + L/GA on F_x, L²/(2 EIy) on M_y;  p_y: L³/(3 EIx) + L/GA on F_y,
///   -L²/(2 EIx) on M_x;  p_z: L/EA;  θ_x: L/EIx, θ_y: L/EIy, θ_z: L/GJ.
Matrix6d straight_tip_compliance(const RodProperties& props) {
  const double L = props.length, L2 = L * L, L3 = L2 * L;
  const Eigen::Vector3d b = props.K_rot.cwiseInverse();
  Eigen::Vector3d c = props.K_tra.cwiseInverse();
  // The axial compliance is at least that of bending, L³ (1/EIx + 1/EIy)/6: a bent rod answers an
  // axial tip force through bending, and against EA/L alone its margin would be O(EI/(EA L²)),
  // below round-off for a thin wire. (A Kirchhoff rod has no axial compliance of its own.)
  const double bending_axial = L2 * (b.x() + b.y()) / 6.0;
  if (props.model == ConstitutiveModel::Kirchhoff) c << 0.0, 0.0, bending_axial;
  c.z() = std::max(c.z(), bending_axial);
  Matrix6d C = Matrix6d::Zero();
  C(0, 0) = L3 * b.y() / 3.0 + L * c.x();
  C(1, 1) = L3 * b.x() / 3.0 + L * c.y();
  C(2, 2) = L * c.z();
  C(0, 4) = C(4, 0) = L2 * b.y() / 2.0;
  C(1, 3) = C(3, 1) = -L2 * b.x() / 2.0;
  C(3, 3) = L * b.x();
  C(4, 4) = L * b.y();
  C(5, 5) = L * b.z();
  return C;
}

/// The rows and columns of `A` where `free` is set.
Eigen::MatrixXd free_block(const Matrix6d& A, const std::array<bool, 6>& free) {
  std::vector<int> index;
  for (int i = 0; i < 6; ++i)
    if (free[i]) index.push_back(i);
  Eigen::MatrixXd block(index.size(), index.size());
  for (std::size_t i = 0; i < index.size(); ++i)
    for (std::size_t j = 0; j < index.size(); ++j) block(i, j) = A(index[i], index[j]);
  return block;
}

}  // namespace

double tip_stiffness_eigenvalue(const ClampedRod& rod,
                                const RodConfiguration& c,
                                const Eigen::Matrix3d& grasp,
                                const std::array<bool, 6>& free) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  // X and Λ in the clamp frame (columns: the base wrench, in any basis: it cancels in Λ X⁻¹).
  const Eigen::Matrix3d R0t = c.R.front().transpose();
  Matrix6d X, Lambda;
  X << R0t * c.tip_dp_dw, R0t * c.R.back() * c.tip_dtheta_dw;
  Lambda << R0t * c.tip_dn_dw, R0t * c.tip_dm_dw;
  const Eigen::FullPivLU<Matrix6d> lu(X);
  if (!X.allFinite() || !Lambda.allFinite() || !lu.isInvertible()) return kNaN;
  const Matrix6d K = Lambda * lu.inverse();
  const Matrix6d K0 = straight_tip_compliance(rod.properties).inverse();

  // Both in the grasp frame: vectors there map to the clamp frame by R0ᵀ R_d.
  Matrix6d M = Matrix6d::Zero();
  M.topLeftCorner<3, 3>() = M.bottomRightCorner<3, 3>() = R0t * grasp;
  const Matrix6d K_grasp = M.transpose() * K * M;
  const Matrix6d K0_grasp = M.transpose() * K0 * M;
  const Eigen::MatrixXd S = free_block(0.5 * (K_grasp + K_grasp.transpose()), free);
  const Eigen::MatrixXd S0 = free_block(0.5 * (K0_grasp + K0_grasp.transpose()), free);
  if (S.size() == 0) return kNaN;
  // S x = λ S0 x with S0 = L Lᵀ: the eigenvalues of L⁻¹ S L⁻ᵀ.
  const Eigen::LLT<Eigen::MatrixXd> llt(S0);
  const Eigen::MatrixXd L_inv =
      llt.matrixL().solve(Eigen::MatrixXd::Identity(S0.rows(), S0.cols()));
  const Eigen::MatrixXd W = L_inv * S * L_inv.transpose();
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(0.5 * (W + W.transpose()))
      .eigenvalues()
      .minCoeff();
}

}  // namespace rodshape
