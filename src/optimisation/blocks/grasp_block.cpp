// grasp_block.cpp: one row per true entry of Grasp::released (force x, y, z, then moment x, y, z):
// the tip wrench in the tip frame, e_kᵀ R(L)ᵀ n(L) or e_kᵀ R(L)ᵀ m(L), bounds [0, 0];
// δ(Rᵀn) = (Rᵀn) × θ_L + Rᵀ δn (δR = R θ̂).
#include <algorithm>

#include "optimisation/blocks/constraint_blocks.hpp"
#include "rodshape/core/so3.hpp"

namespace rodshape::blocks {

namespace {

class GraspBlock final : public ConstraintBlock {
 public:
  explicit GraspBlock(const Grasp& grasp)
      : released_(grasp.released),
        rows_(static_cast<int>(std::count(released_.begin(), released_.end(), true))) {}

  std::string name() const override { return "grasp"; }
  int rows() const override { return rows_; }
  void bounds(Eigen::Ref<Eigen::VectorXd> lower, Eigen::Ref<Eigen::VectorXd> upper) const override {
    lower.setZero();
    upper.setZero();
  }
  void evaluate(const RodConfiguration& c,
                Eigen::Ref<Eigen::VectorXd> g,
                Eigen::Ref<Eigen::MatrixXd> dg_dw) override {
    const int N = c.nodes() - 1;
    const Eigen::Matrix3d& R = c.R[N];
    const Matrix36d& theta = c.tip_dtheta_dw;
    const Eigen::Vector3d n_body = R.transpose() * c.n[N];
    const Eigen::Vector3d m_body = R.transpose() * c.m[N];
    const Matrix36d dn_body = hat(n_body) * theta + R.transpose() * c.tip_dn_dw;
    const Matrix36d dm_body = hat(m_body) * theta + R.transpose() * c.tip_dm_dw;
    int row = 0;
    for (int k = 0; k < 6; ++k) {
      if (!released_[k]) continue;
      g(row) = k < 3 ? n_body(k) : m_body(k - 3);
      dg_dw.row(row) = k < 3 ? dn_body.row(k) : dm_body.row(k - 3);
      ++row;
    }
  }

 private:
  std::array<bool, 6> released_;
  int rows_;
};

}  // namespace

std::unique_ptr<ConstraintBlock> grasp(const Grasp& grasp) {
  return std::make_unique<GraspBlock>(grasp);
}

}  // namespace rodshape::blocks
