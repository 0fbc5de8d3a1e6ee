// clearance_block.cpp: the rod kept clear of the scene. One row per obstacle j and segment
// [p_i, p_{i+1}] (i = 0 … N-1): the gap of the chord to the obstacle,
//   g = d_j([p_i, p_{i+1}]) - r ≥ required_j,
//   dg/dw = ∂d/∂aᵀ dp_i/dw + ∂d/∂bᵀ dp_{i+1}/dw   (∂d/∂a = (1 - t*) ∇d(p*), ∂d/∂b = t* ∇d(p*)),
// so a thin obstacle cannot slip between two nodes. The obstacles are those the planner chose for
// the step (a fixed number of rows); the cost is linear in N and in the obstacles.
#include <limits>

#include "optimisation/blocks/constraint_blocks.hpp"

namespace rodshape::blocks {

namespace {

class ClearanceBlock final : public ConstraintBlock {
 public:
  ClearanceBlock(const Clearance& clearance, int intervals)
      : clearance_(clearance), intervals_(intervals) {}

  std::string name() const override { return "clearance"; }
  int rows() const override {
    return static_cast<int>(clearance_.scene.obstacles.size()) * intervals_;
  }
  void bounds(Eigen::Ref<Eigen::VectorXd> lower, Eigen::Ref<Eigen::VectorXd> upper) const override {
    for (std::size_t j = 0; j < clearance_.scene.obstacles.size(); ++j)
      lower.segment(static_cast<Eigen::Index>(j) * intervals_, intervals_)
          .setConstant(clearance_.required[j]);
    upper.setConstant(std::numeric_limits<double>::infinity());
  }
  void evaluate(const RodConfiguration& c,
                Eigen::Ref<Eigen::VectorXd> g,
                Eigen::Ref<Eigen::MatrixXd> dg_dw) override {
    const double r = clearance_.scene.rod_radius;
    Eigen::Index row = 0;
    for (const Obstacle& obstacle : clearance_.scene.obstacles) {
      for (int i = 0; i < intervals_; ++i, ++row) {
        const SegmentDistance d = obstacle.distance(c.p[i], c.p[i + 1]);
        g(row) = d.distance - r;
        dg_dw.row(row) =
            d.dd_da().transpose() * c.dp_dw[i] + d.dd_db().transpose() * c.dp_dw[i + 1];
      }
    }
  }

 private:
  Clearance clearance_;
  int intervals_;
};

}  // namespace

std::unique_ptr<ConstraintBlock> clearance(const Clearance& clearance, int intervals) {
  return std::make_unique<ClearanceBlock>(clearance, intervals);
}

}  // namespace rodshape::blocks
