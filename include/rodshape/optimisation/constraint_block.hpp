// constraint_block.hpp: one named kind of constraint of the shape optimisation, a block of rows of
// g(w) with their bounds and exact derivatives, evaluated on the configuration the integrator left
// at w (all-node derivatives). ShapeProblem stacks its blocks in order; a new kind of constraint
// is a new block (a class here and its .cpp), not an edit of the problem, the NLP or the planner.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <string>

#include "rodshape/core/rod_configuration.hpp"

namespace rodshape {

class ConstraintBlock {
 public:
  virtual ~ConstraintBlock() = default;
  /// "workspace", "grasp", "curvature", "axial_strain", "clearance".
  virtual std::string name() const = 0;
  /// Rows of g, fixed at construction.
  virtual int rows() const = 0;
  /// lower ≤ g ≤ upper (±inf where one-sided), rows() entries each.
  virtual void bounds(Eigen::Ref<Eigen::VectorXd> lower,
                      Eigen::Ref<Eigen::VectorXd> upper) const = 0;
  /// g (rows() entries) and dg/dw (rows() × 6) at the configuration `c`, which has all-node
  /// derivatives. Allocates nothing.
  virtual void evaluate(const RodConfiguration& c,
                        Eigen::Ref<Eigen::VectorXd> g,
                        Eigen::Ref<Eigen::MatrixXd> dg_dw) = 0;
};

}  // namespace rodshape
