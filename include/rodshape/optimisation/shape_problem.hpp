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
#include <optional>
#include <string>
#include <vector>

#include "rodshape/core/clamped_rod.hpp"
#include "rodshape/core/rod_configuration.hpp"
#include "rodshape/core/scene.hpp"
#include "rodshape/optimisation/base_motion.hpp"
#include "rodshape/optimisation/constraint_block.hpp"
#include "rodshape/optimisation/curve_distance.hpp"
#include "rodshape/optimisation/shape_constraints.hpp"
#include "rodshape/optimisation/shape_target.hpp"
#include "rodshape/optimisation/workspace.hpp"

namespace rodshape {

using Vector12d = Eigen::Matrix<double, 12, 1>;

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
    int workspace = 0, grasp = 0, curvature = 0, axial = 0, clearance = 0, base = 0;
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
  /// How many integrations the evaluations have done (evaluate() at a new w; with a moving base,
  /// evaluate_with_base() at a new x and the eliminated evaluation's shape in the base's frame),
  /// the measure of a solver's cost on this problem.
  int integrations() const { return integrations_; }

  // ---- A moving base (issue 21, base_motion.hpp): the variables x = (w_b, ξ) ----------------
  /// Makes the base pose a variable (12 unknowns; the rod's clamp is then the base pose at the
  /// last evaluation). Adds the base workspace's rows after the others (RowBlocks::base). Throws
  /// InputError for bad input.
  void move_base(BaseMotion motion);
  bool base_moves() const { return base_motion_.has_value(); }
  const std::optional<BaseMotion>& base_motion() const { return base_motion_; }
  /// Starts ξ at a new reference pose (the next step's: the base pose of the last optimum).
  void set_base_reference(const Pose& reference);
  /// 6, or 12 with a moving base.
  int variables() const { return base_motion_ ? 12 : 6; }
  /// The base pose at x (ξ about the reference) and the world wrench (R(0) n_b, R(0) m_b).
  Pose base_pose(const Vector12d& x) const;
  BaseWrench world_wrench(const Vector12d& x) const;
  /// x for a world wrench w at the reference pose (ξ = 0).
  Vector12d variables_at_reference(const BaseWrench& w) const;
  /// Integrates at x with the derivatives of both the wrench and the base pose, and evaluates F,
  /// ∇F, g and dg/dx; a call at the same x does nothing. Does not allocate after the first call.
  void evaluate_with_base(const Vector12d& x);
  const Eigen::VectorXd& variable_gradient() const { return gradient_x_; }  // ∇_x F, 12
  const Eigen::MatrixXd& variable_jacobian() const { return dg_dx_; }       // count × 12
  /// Bounds of x: w_b within the base's wrench bounds (released components at 0), δt free, each
  /// |δφ_i| ≤ BaseMotion::kMaxTurn.
  Vector12d variable_lower() const;
  Vector12d variable_upper() const;
  /// Whether the base pose can be aligned without integrating (align_base): a moving base, no
  /// distributed load (the shape in the base's frame then depends on w_b alone), a smooth distance
  /// term (distance_smoothing > 0 or squared distances) and W2 > 0.
  bool rigid_alignment_applies() const;
  /// ξ minimising F(w_b, ξ) for the base-frame wrench w_b (the best rigid placement of its shape,
  /// the motion term included): Newton steps from `xi`, which returns the minimiser. The shape is
  /// integrated once in the base's frame and moved rigidly; evaluate_with_base()'s state is left as
  /// it was. False when no descent is found or a value is not finite.
  bool align_base(const Vector6d& w_b, Vector6d& xi);
  /// What align_base() minimises, at ξ about the reference for the base-frame wrench w_b: F less
  /// the energy term (constant in ξ), every point projected onto the whole curve, with its
  /// gradient and Newton Hessian in ξ̃ = (δt / L, δφ) (either may be null), and with `mixed` the
  /// gradient's derivative in w_b, ∂²F/∂ξ̃∂w_b (with the gradient). Integrates once.
  double alignment_cost(const Vector6d& w_b,
                        const Vector6d& xi,
                        Vector6d* gradient,
                        Matrix6d* hessian,
                        Matrix6d* mixed = nullptr);
  /// dξ̃*/dw_b = -(∂²F/∂ξ̃²)⁻¹ ∂²F/∂ξ̃∂w_b at the last align_base()'s minimiser (the implicit
  /// function theorem on ∂F/∂ξ̃ = 0), or nothing when that Hessian is not positive definite. The
  /// eliminated evaluation starts each alignment from ξ̃* + (dξ̃*/dw_b) δw_b.
  std::optional<Matrix6d> alignment_sensitivity() const {
    return predictor_ready_ ? std::optional<Matrix6d>(xi_sensitivity_) : std::nullopt;
  }
  /// The base pose eliminated (rigid_alignment_applies(), no constraint rows): evaluate(w̃) takes
  /// w̃ = w_b / D (D the bending wrench units, as ShapeNlp scales w_b), places the shape of the
  /// base-frame wrench w_b at ξ*(w_b) = argmin_ξ F (align_base, from the last ξ*, ξ = 0 at the
  /// start) and evaluates at (w_b, ξ*); cost() is F(w_b, ξ*(w_b)), cost_gradient() D ∂F/∂w_b
  /// there, which is the total derivative of the reduced F (∂F/∂ξ = 0 at ξ*), so its derivative is
  /// the reduced Hessian. A failed alignment leaves a NaN cost. For the dense Newton over w̃ alone
  /// (shape_optimiser.cpp); off again with false.
  void eliminate_base_pose(bool eliminated);
  bool base_pose_eliminated() const { return eliminated_; }
  /// x = (w_b, ξ*) of the last evaluation with the pose eliminated.
  const Vector12d& evaluated_variables() const { return x_; }

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
  int integrations_ = 0;
  Vector6d w_ = Vector6d::Zero();
  RodConfiguration configuration_;
  std::vector<CurveProjection> projections_;
  std::vector<IntervalBall> balls_;  // of the current configuration
  ShapeCostBreakdown breakdown_;
  Vector6d cost_gradient_ = Vector6d::Zero();
  Eigen::VectorXd g_;
  Eigen::MatrixXd dg_dw_;
  /// F and ∇_w F at configuration_, each point projected onto the whole curve.
  void evaluate_cost() { evaluate_cost(configuration_, target_.points, nullptr); }
  /// F and ∇_w F at configuration `c` for `points` (in c's frame), into breakdown_, cost_gradient_
  /// and projections_; given `near_intervals` (one per point), each point projected locally from
  /// its interval (project_from_interval), else onto the whole curve.
  void evaluate_cost(const RodConfiguration& c,
                     const std::vector<Eigen::Vector3d>& points,
                     const std::vector<int>* near_intervals);
  void evaluate_constraints();
  /// ρ(d) of the distance term (plain, pseudo-Huber or squared), and W2 ρ'(d).
  double distance_penalty(double d) const;
  double distance_term_slope(double d) const;

  // A moving base.
  std::optional<BaseMotion> base_motion_;
  Vector12d x_ = Vector12d::Zero();
  RodConfiguration pose_tangent_;  // the configuration with d/dξ in its derivative arrays
  Eigen::VectorXd gradient_x_;
  Eigen::MatrixXd dg_dx_, dg_dxi_;
  Vector6d gradient_xi_ = Vector6d::Zero();
  void set_clamp(const Vector12d& x);
  Vector6d distance_gradient_sum(const RodConfiguration& derivatives) const;
  void evaluate_moving_constraints();
  // The base pose eliminated: evaluate() aligns ξ* (from xi_star_) at the w_b it is given.
  bool eliminated_ = false;
  Vector6d xi_star_ = Vector6d::Zero();
  bool eliminated_evaluated_ = false;  // evaluate_eliminated() has run at x_.head<6>()
  /// The next alignment's start, ξ̃*(w_b) to first order about the last one (at x_.head<6>()):
  /// alignment_sensitivity(), set by align_base().
  Matrix6d xi_sensitivity_ = Matrix6d::Zero();
  bool predictor_ready_ = false;
  Vector6d predicted_xi(const Vector6d& w_b) const;
  void evaluate_eliminated(const Vector6d& w_b);
  /// What evaluate_eliminated() reads of evaluate_with_base() at x = (w_b, ξ*), F and ∂F/∂w_b, in
  /// the base's frame: F is invariant under the rigid placement ξ, so it is F of body_ (with its
  /// derivatives in w_b, from align_base) and the points seen from the base, each projected from
  /// the alignment's closest interval (its last projection was global). Neither ξ's derivatives
  /// (∂F/∂ξ = 0 at ξ*) nor rows; configuration_ and projections_ are not the world's until
  /// evaluate_with_base() evaluates anew.
  void evaluate_aligned(const Vector12d& x);
  std::vector<Eigen::Vector3d> body_points_;  // the target's points seen from the base
  /// The motion term W_b W2 (|δt|² + L² |δφ|²) / L at x.
  double motion_cost(const Vector12d& x) const;
  // align_base(): the shape in the base's frame, with its derivatives in w_b, and its balls
  // (integrate_body).
  RodConfiguration body_;
  std::vector<IntervalBall> body_balls_;
  void integrate_body(const Vector6d& w_b);
  // The interval of each point's closest point at the last accepted alignment step: the next
  // projections' warm start.
  std::vector<int> align_intervals_;
  std::vector<int> align_found_;  // align_base()'s new closest intervals (scratch)
  /// F(w_b, ξ) less the energy term (constant in ξ) on body_, with its gradient and Hessian in
  /// ξ̃ = (δt / L, δφ). With `global` each point's closest point on the whole curve, else the one
  /// found from align_intervals_ by project_from_interval; the intervals into `intervals`. With
  /// `mixed` (and `gradient`), also H_ξ̃w = ∂²F/∂ξ̃∂w_b, the gradient's change as the curve moves
  /// under the points (body_ carries its derivatives in w_b).
  double aligned_cost(const Vector6d& xi_scaled,
                      Vector6d* gradient,
                      Matrix6d* hessian,
                      bool global,
                      std::vector<int>& intervals,
                      Matrix6d* mixed = nullptr);
};

}  // namespace rodshape
