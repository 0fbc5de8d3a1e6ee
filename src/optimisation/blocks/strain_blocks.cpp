// strain_blocks.cpp: the strain limits of a fragile object, one row per node.
//  curvature:    |u_i - ũ|² ≤ κ², with u - ũ = K_rot⁻¹ m̄, m̄ = Rᵀm (computed from m̄, without
//                cancellation against ũ), d/dw = 2 (u - ũ)ᵀ K_rot⁻¹ (m̄ × θ + Rᵀ δm);
//  axial strain: v_z - ṽ_z = (K_tra⁻¹ n̄)_z ∈ [-ε, ε], d/dw = e_zᵀ K_tra⁻¹ (n̄ × θ + Rᵀ δn).
#include <limits>

#include "optimisation/blocks/constraint_blocks.hpp"
#include "rodshape/core/so3.hpp"

namespace rodshape::blocks {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

class CurvatureBlock final : public ConstraintBlock {
 public:
  CurvatureBlock(const RodProperties& properties, int nodes, double max_curvature)
      : C_rot_(properties.K_rot.cwiseInverse()), nodes_(nodes), kappa_(max_curvature) {}

  std::string name() const override { return "curvature"; }
  int rows() const override { return nodes_; }
  void bounds(Eigen::Ref<Eigen::VectorXd> lower, Eigen::Ref<Eigen::VectorXd> upper) const override {
    lower.setConstant(-kInf);
    upper.setConstant(kappa_ * kappa_);
  }
  void evaluate(const RodConfiguration& c,
                Eigen::Ref<Eigen::VectorXd> g,
                Eigen::Ref<Eigen::MatrixXd> dg_dw) override {
    for (int i = 0; i < nodes_; ++i) {
      const Eigen::Matrix3d& R = c.R[i];
      const Eigen::Vector3d m_body = R.transpose() * c.m[i];
      const Eigen::Vector3d du = C_rot_.cwiseProduct(m_body);
      const Matrix36d dm_body = hat(m_body) * c.dtheta_dw[i] + R.transpose() * c.dm_dw[i];
      g(i) = du.squaredNorm();
      dg_dw.row(i) = 2.0 * du.cwiseProduct(C_rot_).transpose() * dm_body;
    }
  }

 private:
  Eigen::Vector3d C_rot_;  // K_rot⁻¹
  int nodes_;
  double kappa_;
};

class AxialStrainBlock final : public ConstraintBlock {
 public:
  AxialStrainBlock(const RodProperties& properties, int nodes, double max_axial_strain)
      : c_axial_(1.0 / properties.K_tra.z()), nodes_(nodes), epsilon_(max_axial_strain) {}

  std::string name() const override { return "axial_strain"; }
  int rows() const override { return nodes_; }
  void bounds(Eigen::Ref<Eigen::VectorXd> lower, Eigen::Ref<Eigen::VectorXd> upper) const override {
    lower.setConstant(-epsilon_);
    upper.setConstant(epsilon_);
  }
  void evaluate(const RodConfiguration& c,
                Eigen::Ref<Eigen::VectorXd> g,
                Eigen::Ref<Eigen::MatrixXd> dg_dw) override {
    for (int i = 0; i < nodes_; ++i) {
      const Eigen::Matrix3d& R = c.R[i];
      const Eigen::Vector3d n_body = R.transpose() * c.n[i];
      const Matrix36d dn_body = hat(n_body) * c.dtheta_dw[i] + R.transpose() * c.dn_dw[i];
      g(i) = c_axial_ * n_body.z();  // v_z - ṽ_z, without the cancellation against ṽ_z ≈ 1
      dg_dw.row(i) = c_axial_ * dn_body.row(2);
    }
  }

 private:
  double c_axial_;  // 1 / EA
  int nodes_;
  double epsilon_;
};

}  // namespace

std::unique_ptr<ConstraintBlock> curvature(const RodProperties& properties,
                                           int nodes,
                                           double max_curvature) {
  return std::make_unique<CurvatureBlock>(properties, nodes, max_curvature);
}

std::unique_ptr<ConstraintBlock> axial_strain(const RodProperties& properties,
                                              int nodes,
                                              double max_axial_strain) {
  return std::make_unique<AxialStrainBlock>(properties, nodes, max_axial_strain);
}

}  // namespace rodshape::blocks
