// workspace_block.cpp: the tip pose (p(L), R(L)) in the workspace Ws:
//   g_ws, dg/dw = dg_ws/dp · tip_dp_dw + dg_ws/dθ · tip_dtheta_dw
// (only the reach shell depends on R(L)); or, for a moving base, the base pose (p(0), R(0)) in
// the base's workspace, with node 0's derivatives (zero with respect to the wrench; those of the
// base pose's variables in the configuration of base_pose_derivatives).
#include "optimisation/blocks/constraint_blocks.hpp"

namespace rodshape::blocks {

namespace {

class WorkspaceBlock final : public ConstraintBlock {
 public:
  WorkspaceBlock(const Workspace& workspace, bool base)
      : workspace_(workspace),
        base_(base),
        rows_(workspace.constraint_count()),
        dg_dp_(Eigen::MatrixXd::Zero(rows_, 3)),
        dg_dtheta_(Eigen::MatrixXd::Zero(rows_, 3)) {}

  std::string name() const override { return base_ ? "base_workspace" : "workspace"; }
  int rows() const override { return rows_; }
  void bounds(Eigen::Ref<Eigen::VectorXd> lower, Eigen::Ref<Eigen::VectorXd> upper) const override {
    workspace_.bounds(lower, upper);
  }
  void evaluate(const RodConfiguration& c,
                Eigen::Ref<Eigen::VectorXd> g,
                Eigen::Ref<Eigen::MatrixXd> dg_dw) override {
    if (base_) {
      workspace_.evaluate(Pose{c.p[0], c.R[0]}, g, dg_dp_, dg_dtheta_);
      dg_dw = dg_dp_.lazyProduct(c.dp_dw[0]);
      if (workspace_.reach) dg_dw += dg_dtheta_.lazyProduct(c.dtheta_dw[0]);
      return;
    }
    const int N = c.nodes() - 1;
    workspace_.evaluate(Pose{c.p[N], c.R[N]}, g, dg_dp_, dg_dtheta_);
    dg_dw = dg_dp_.lazyProduct(c.tip_dp_dw);  // lazy: no GEMM buffers
    if (workspace_.reach) dg_dw += dg_dtheta_.lazyProduct(c.tip_dtheta_dw);
  }

 private:
  Workspace workspace_;
  bool base_;
  int rows_;
  Eigen::MatrixXd dg_dp_, dg_dtheta_;  // scratch
};

}  // namespace

std::unique_ptr<ConstraintBlock> workspace(const Workspace& workspace) {
  return std::make_unique<WorkspaceBlock>(workspace, false);
}

std::unique_ptr<ConstraintBlock> base_workspace(const Workspace& workspace) {
  return std::make_unique<WorkspaceBlock>(workspace, true);
}

}  // namespace rodshape::blocks
