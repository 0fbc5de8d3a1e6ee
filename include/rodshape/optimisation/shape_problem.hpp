// shape_problem.hpp: the paper's optimisation over the base wrench w = (n(0), m(0)):
//   min_w F(w) = W1/(2L) ∫ (Δvᵀ K_tra Δv + Δuᵀ K_rot Δu) ds + W2 Σᵢ dist(Γ, p_obj,i)
//   s.t. (p(L), R(L)) ∈ Ws, grasp wrench components = 0, strain limits, clearance to the scene,
//        w_lower ≤ w ≤ w_upper,
// with F, g and their exact first derivatives from one integration with all-node derivatives.
// g is a stack of named constraint blocks (constraint_block.hpp), one per kind of constraint.
// Note W1/(2L) ∫ (…) ds = W1 E / L with E the elastic energy.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "rodshape/core/clamped_rod.hpp"
#include "rodshape/core/rod_configuration.hpp"
#include "rodshape/core/scene.hpp"
#include "rodshape/optimisation/constraint_block.hpp"
#include "rodshape/optimisation/curve_distance.hpp"
#include "rodshape/optimisation/shape_constraints.hpp"
#include "rodshape/optimisation/shape_target.hpp"
#include "rodshape/optimisation/workspace.hpp"

namespace rodshape {

/// The terms of F at one w.
struct ShapeCostBreakdown {
  double cost = 0.0;              // F
  double energy = 0.0;            // E, J
  double energy_term = 0.0;       // W1 E / L
  double distance_term = 0.0;     // W2 Σ dist (or dist²)
  std::vector<double> distances;  // dist(Γ, p_obj,i), m
  double max_distance = 0.0;
};

/// The obstacles a shape keeps its rod clear of (for a plan's step: those near its rod, chosen
/// once, so that the rows stay fixed) and the gap each one requires (Scene::required_gaps, or
/// more).
struct Clearance {
  Scene scene;
  std::vector<double> required;  // one per scene obstacle, m
  std::vector<int> indices;      // optional: each obstacle's index in a larger scene (messages)
  bool empty() const { return scene.empty(); }
  /// Throws InputError naming "Clearance.required" when the sizes differ or a gap is not finite.
  void validate() const;
};

class ShapeProblem {
 public:
  /// Validates everything (InputError naming the field) and sizes every buffer once.
  ShapeProblem(ClampedRod rod,
               ShapeTarget target,
               Workspace workspace = {},
               Grasp grasp = {},
               StrainLimits limits = {},
               WrenchBounds wrench_bounds = {},
               Clearance clearance = {});
  // Move-only: each block keeps its own scratch.
  ShapeProblem(const ShapeProblem&) = delete;
  ShapeProblem& operator=(const ShapeProblem&) = delete;
  ShapeProblem(ShapeProblem&&) noexcept = default;
  ~ShapeProblem();

  /// How many rows of g each block has; the blocks follow each other in this order:
  /// workspace (on the tip pose), grasp (one per released entry), curvature (one per node), axial
  /// strain (one per node, Cosserat only), clearance (one per obstacle and segment).
  struct RowBlocks {
    int workspace = 0, grasp = 0, curvature = 0, axial = 0, clearance = 0;
  };

  int constraint_count() const { return constraint_count_; }
  const RowBlocks& row_blocks() const { return rows_; }
  const StrainLimits& limits() const { return limits_; }
  const ClampedRod& rod() const { return rod_; }
  const ShapeTarget& target() const { return target_; }
  const Workspace& workspace() const { return workspace_; }
  const Grasp& grasp() const { return grasp_; }
  const WrenchBounds& wrench_bounds() const { return wrench_bounds_; }
  const Clearance& clearance() const { return clearance_; }
  /// lower ≤ g(w) ≤ upper.
  const Eigen::VectorXd& constraint_lower() const { return g_lower_; }
  const Eigen::VectorXd& constraint_upper() const { return g_upper_; }

  /// Integrates at w (with all-node derivatives) and evaluates F, ∇F, g and dg/dw; a call at the
  /// same w as the last one does nothing. Does not allocate after construction.
  /// With Σ dist (not squared), ∇ dist is undefined where dist = 0 (an objective point exactly on
  /// Γ); the subgradient 0 is used there. Curvature and axial rows are computed from m̄ = Rᵀm and
  /// n̄ = Rᵀn (u - ũ = K_rot⁻¹ m̄, v_z - ṽ_z = n̄_z / EA), without cancellation against ũ, ṽ.
  void evaluate(const Vector6d& w);

  // Results of the last evaluate().
  double cost() const { return breakdown_.cost; }
  const Vector6d& cost_gradient() const { return cost_gradient_; }
  const Eigen::VectorXd& constraints() const { return g_; }
  const Eigen::MatrixXd& constraint_jacobian() const { return dg_dw_; }  // count × 6
  const ShapeCostBreakdown& breakdown() const { return breakdown_; }
  /// max(0, g - g_upper, g_lower - g, w - w_upper, w_lower - w) over every row and bound (+inf
  /// when g is not finite).
  double constraint_violation() const;
  const RodConfiguration& configuration() const { return configuration_; }
  const std::vector<CurveProjection>& projections() const { return projections_; }

 private:
  ClampedRod rod_;
  ShapeTarget target_;
  Workspace workspace_;
  Grasp grasp_;
  StrainLimits limits_;
  WrenchBounds wrench_bounds_;
  Clearance clearance_;
  std::vector<std::unique_ptr<ConstraintBlock>> blocks_;
  RowBlocks rows_;
  int constraint_count_ = 0;
  Eigen::VectorXd g_lower_, g_upper_;

  bool evaluated_ = false;
  Vector6d w_ = Vector6d::Zero();
  RodConfiguration configuration_;
  std::vector<CurveProjection> projections_;
  std::vector<IntervalBall> balls_;  // of the current configuration
  ShapeCostBreakdown breakdown_;
  Vector6d cost_gradient_ = Vector6d::Zero();
  Eigen::VectorXd g_;
  Eigen::MatrixXd dg_dw_;
  void evaluate_cost();
  void evaluate_constraints();
};

}  // namespace rodshape
