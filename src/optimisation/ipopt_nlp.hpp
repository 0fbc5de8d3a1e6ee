// ipopt_nlp.hpp (private): the ShapeProblem seen by IPOPT, as its TNLP. This header is included
// only by ipopt_nlp.cpp and ipopt_adapter.cpp, the only places that include IPOPT; the rest of
// rodshape uses ipopt_adapter.hpp, which names no IPOPT type. rodshape links IPOPT PRIVATE.
//
// The NLP (paper, "Model-based optimization under constraints"):
//   min_{w ∈ R^6} F(w)   s.t.   g_L ≤ g(w) ≤ g_U,   w_L ≤ w ≤ w_U,
// with w = (n(0), m(0)) the base wrench, F the shape cost and g the workspace, grasp and strain
// rows of ShapeProblem. First derivatives are exact (one integration with all-node derivatives);
// the Hessian of the Lagrangian is forward differences of its exact gradient (eval_h), or IPOPT's
// limited-memory (L-BFGS) approximation when ShapeOptimiserOptions::hessian says so.
#pragma once

#include <limits>
#include <optional>

#include <IpIpoptApplication.hpp>
#include <IpTNLP.hpp>
#include <string>
#include <vector>

#include "optimisation/ipopt_adapter.hpp"
#include "rodshape/core/wrench.hpp"
#include "rodshape/optimisation/shape_optimiser.hpp"
#include "rodshape/optimisation/shape_problem.hpp"

namespace rodshape::detail {

/// IPOPT's "infinity": a bound at or beyond ±kIpoptInfinity is no bound
/// (nlp_lower/upper_bound_inf).
inline constexpr double kIpoptInfinity = 1e19;

/// Every IPOPT option rodshape sets, in one place, each with its reason (see the .cpp). Call before
/// IpoptApplication::Initialize(""), which applies print_level to the console journal.
void apply_options(Ipopt::OptionsList& ipopt_options,
                   const ShapeOptimiserOptions& options,
                   bool finite_difference_hessian);

/// What IPOPT left in finalize_solution() and intermediate_callback().
struct NlpOutcome {
  bool finalized = false;  // finalize_solution() was called
  Ipopt::SolverReturn solver_return = Ipopt::UNASSIGNED;
  Vector6d w = Vector6d::Zero();    // the final iterate (with a moving base: its world wrench)
  Vector12d x = Vector12d::Zero();  // with a moving base: the final iterate (w_b, ξ)
  double objective = 0.0;
  /// λ, one per row of g. IPOPT's sign convention (Lagrangian F + gᵀλ): λ ≥ 0 where g presses on
  /// its upper bound, λ ≤ 0 where it presses on its lower bound, 0 where inactive.
  std::vector<double> constraint_multipliers;
  Vector6d lower_bound_multipliers = Vector6d::Zero();  // z_L ≥ 0
  Vector6d upper_bound_multipliers = Vector6d::Zero();  // z_U ≥ 0
  int iterations = 0;  // last iteration number reported by intermediate_callback()
  /// Trial points refused for lying outside the admissible box; at kMaxRefusals IPOPT is asked to
  /// stop (User_Requested_Stop): the optimum lies beyond the rod's scale.
  int refusals = 0;
  static constexpr int kMaxRefusals = 20;
  bool stopped_beyond_scale() const { return refusals >= kMaxRefusals; }
};

class ShapeNlp final : public Ipopt::TNLP {
 public:
  /// Infinite bounds are given to IPOPT as ±kIpoptInfinity (apply_options sets its
  /// nlp_lower/upper_bound_inf to that).
  /// With `admissible`, F is not evaluated outside it (eval_* return false: IPOPT cuts the step
  /// back); `start` must lie inside.
  ShapeNlp(ShapeProblem& problem,
           const Vector6d& start,
           bool finite_difference_hessian,
           const std::optional<WrenchBounds>& admissible = std::nullopt);
  /// With a moving base (problem.base_moves()): the 12 unknowns x = (w_b, ξ) from `start`; the
  /// admissible box bounds w_b. Without constraint rows, where ShapeProblem::
  /// rigid_alignment_applies(), IPOPT sees w_b alone and ξ is eliminated: at every w_b it is the
  /// best rigid placement of the shape, ξ*(w_b) = argmin_ξ F (ShapeProblem::align_base), and the
  /// Hessian is the reduced one (the Schur complement of the differenced 12 × 12 Hessian).
  ShapeNlp(ShapeProblem& problem,
           const Vector12d& start,
           bool finite_difference_hessian,
           const std::optional<WrenchBounds>& admissible = std::nullopt);

  const NlpOutcome& outcome() const { return outcome_; }
  /// The dimension of IPOPT's KKT systems for this NLP: n + m unknowns and multipliers, a slack per
  /// inequality row (g_L < g_U), and with the limited-memory Hessian the 2 × history rows of its
  /// low-rank update ("extended" augmented system). Variable bounds add none.
  int kkt_dimension() const;

  bool get_nlp_info(Ipopt::Index& n,
                    Ipopt::Index& m,
                    Ipopt::Index& nnz_jac_g,
                    Ipopt::Index& nnz_h_lag,
                    IndexStyleEnum& index_style) override;
  bool get_bounds_info(Ipopt::Index n,
                       Ipopt::Number* x_l,
                       Ipopt::Number* x_u,
                       Ipopt::Index m,
                       Ipopt::Number* g_l,
                       Ipopt::Number* g_u) override;
  bool get_starting_point(Ipopt::Index n,
                          bool init_x,
                          Ipopt::Number* x,
                          bool init_z,
                          Ipopt::Number* z_L,
                          Ipopt::Number* z_U,
                          Ipopt::Index m,
                          bool init_lambda,
                          Ipopt::Number* lambda) override;
  bool eval_f(Ipopt::Index n,
              const Ipopt::Number* x,
              bool new_x,
              Ipopt::Number& obj_value) override;
  bool eval_grad_f(Ipopt::Index n,
                   const Ipopt::Number* x,
                   bool new_x,
                   Ipopt::Number* grad_f) override;
  bool eval_g(Ipopt::Index n,
              const Ipopt::Number* x,
              bool new_x,
              Ipopt::Index m,
              Ipopt::Number* g) override;
  bool eval_jac_g(Ipopt::Index n,
                  const Ipopt::Number* x,
                  bool new_x,
                  Ipopt::Index m,
                  Ipopt::Index nele_jac,
                  Ipopt::Index* iRow,
                  Ipopt::Index* jCol,
                  Ipopt::Number* values) override;
  /// ∇²L = obj_factor ∇²F + Σ λ_i ∇²g_i by forward differences of ∇L = obj_factor ∇F + Jᵀλ:
  /// column j = (∇L(w + h_j e_j) - ∇L(w)) / h_j with h_j = √ε max(|w_j|, s_j), s_j the bending
  /// scale of w_j (EI/L² for forces, EI/L for moments); error ≈ h_j |∇³L| / 2 + ε |∇L| / h_j, the
  /// optimum of the forward-difference model. Symmetrised; the lower triangle is given.
  bool eval_h(Ipopt::Index n,
              const Ipopt::Number* x,
              bool new_x,
              Ipopt::Number obj_factor,
              Ipopt::Index m,
              const Ipopt::Number* lambda,
              bool new_lambda,
              Ipopt::Index nele_hess,
              Ipopt::Index* iRow,
              Ipopt::Index* jCol,
              Ipopt::Number* values) override;
  bool intermediate_callback(Ipopt::AlgorithmMode mode,
                             Ipopt::Index iter,
                             Ipopt::Number obj_value,
                             Ipopt::Number inf_pr,
                             Ipopt::Number inf_du,
                             Ipopt::Number mu,
                             Ipopt::Number d_norm,
                             Ipopt::Number regularization_size,
                             Ipopt::Number alpha_du,
                             Ipopt::Number alpha_pr,
                             Ipopt::Index ls_trials,
                             const Ipopt::IpoptData* ip_data,
                             Ipopt::IpoptCalculatedQuantities* ip_cq) override;
  void finalize_solution(Ipopt::SolverReturn status,
                         Ipopt::Index n,
                         const Ipopt::Number* x,
                         const Ipopt::Number* z_L,
                         const Ipopt::Number* z_U,
                         Ipopt::Index m,
                         const Ipopt::Number* g,
                         const Ipopt::Number* lambda,
                         Ipopt::Number obj_value,
                         const Ipopt::IpoptData* ip_data,
                         Ipopt::IpoptCalculatedQuantities* ip_cq) override;

 private:
  /// Evaluates the problem at x; false when F, ∇F, g or dg/dw is not finite (IPOPT then cuts the
  /// step back instead of using the numbers).
  bool evaluate_at(const Ipopt::Number* x);
  /// Whether w lies in the admissible box (always, without one).
  bool admissible(const Vector6d& w) const;

  /// ∇L at x (n_ entries) into `gradient`; false when not finite.
  template <class Vector>
  bool lagrangian_gradient(const Vector& x,
                           double obj_factor,
                           const Eigen::Map<const Eigen::VectorXd>& multipliers,
                           Vector& gradient);
  /// The differenced ∇²F in x̃ at w̃ with ξ = ξ*(w_b), reduced to w̃: H_ww - H_wξ H_ξξ⁻¹ H_ξw.
  bool projected_hessian(const Ipopt::Number* x, double obj_factor, Ipopt::Number* values);
  /// The unknowns IPOPT sees: 6, or 12 with a moving base (6 when ξ is eliminated).
  int unknowns() const { return projected_ ? 6 : n_; }
  template <class Vector, class Matrix>
  bool differenced_hessian(const Ipopt::Number* x,
                           double obj_factor,
                           const Eigen::Map<const Eigen::VectorXd>& multipliers,
                           const Vector& units,
                           Ipopt::Number* values);

  ShapeProblem& problem_;
  int n_ = 6;  // 6, or 12 with a moving base
  Vector6d start_;
  Vector12d start_x_ = Vector12d::Zero();
  Vector12d scale_ = Vector12d::Ones();  // D: IPOPT's unknowns are x / D (moving base)
  int rows_;                             // m, fixed at construction
  bool finite_difference_hessian_;
  NlpOutcome outcome_;
  std::optional<WrenchBounds> admissible_;
  // ξ eliminated: ξ*(w_b) of the last w_b aligned at (the next alignment's start).
  bool projected_ = false;
  Vector6d xi_ = Vector6d::Zero();
  Vector6d aligned_at_ = Vector6d::Constant(std::numeric_limits<double>::quiet_NaN());
};

/// The name of an ApplicationReturnStatus, e.g. "Solve_Succeeded".
std::string application_status_name(Ipopt::ApplicationReturnStatus status);

}  // namespace rodshape::detail
