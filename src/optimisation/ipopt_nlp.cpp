#include "optimisation/ipopt_nlp.hpp"
#include "optimisation/ipopt_derivative_test.hpp"

#include <Eigen/Cholesky>
#include <IpJournalist.hpp>
#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <sstream>

namespace rodshape::detail {

namespace {

constexpr int kUnknowns = 6;               // w = (n(0), m(0))
constexpr int kLimitedMemoryHistory = 20;  // limited_memory_max_history (see apply_options)

}  // namespace

// ---- options -----------------------------------------------------------------------------------

bool uses_finite_difference_hessian(const ShapeOptimiserOptions& options,
                                    const ShapeProblem& problem) {
  using Hessian = ShapeOptimiserOptions::Hessian;
  return options.hessian == Hessian::FiniteDifference ||
         (options.hessian == Hessian::Automatic &&
          (problem.constraint_count() == 0 || problem.base_moves()));
}

void apply_options(Ipopt::OptionsList& ipopt_options,
                   const ShapeOptimiserOptions& options,
                   bool finite_difference_hessian) {
  bool ok = true;
  const auto set_string = [&](const char* name, const char* value) {
    ok = ipopt_options.SetStringValue(name, value) && ok;
  };
  const auto set_number = [&](const char* name, double value) {
    ok = ipopt_options.SetNumericValue(name, value) && ok;
  };
  const auto set_integer = [&](const char* name, int value) {
    ok = ipopt_options.SetIntegerValue(name, value) && ok;
  };

  // Output. print_level 0 prints nothing; "sb" (suppress banner) = yes also silences the
  // "This program contains Ipopt ... Eclipse Public License" banner IPOPT prints once per process.
  set_integer("print_level", options.print_level);
  set_string("sb", "yes");

  // Termination. tol bounds IPOPT's scaled NLP error (max of dual infeasibility, complementarity
  // and constraint violation, the first two divided by a measure of the multipliers' size);
  // constr_viol_tol bounds the unscaled constraint violation, in the units of g (m for workspace
  // rows, N or N·m for grasp rows, 1/m for strain rows); max_iter caps the iterations per start.
  set_number("tol", options.tolerance);
  set_number("constr_viol_tol", options.constraint_tolerance);
  set_integer("max_iter", options.max_iterations);
  // IPOPT may also stop at an "acceptable" point (15 iterations within acceptable_tol = 1e-6,
  // its default). Its feasibility test is made as strict as the main one (default 1e-2), so an
  // acceptable point never violates a constraint by more than constraint_tolerance.
  set_number("acceptable_constr_viol_tol", options.constraint_tolerance);
  // IPOPT relaxes every bound by bound_relax_factor·max(1, |bound|) (default 1e-8) to keep the
  // interior non-empty. Relax by a tenth of the constraint tolerance at most, so that a point that
  // satisfies the relaxed bound satisfies ours to constraint_tolerance (bounds are of order 1 in
  // SI).
  set_number("bound_relax_factor", std::min(1e-8, 0.1 * options.constraint_tolerance));
  // The final w is projected back inside the original (unrelaxed) bounds w_lower ≤ w ≤ w_upper.
  set_string("honor_original_bounds", "yes");
  // No bound is infinite to IPOPT; ShapeNlp maps ±inf to ±kIpoptInfinity (IPOPT's default value,
  // stated here because the adapter depends on it).
  set_number("nlp_lower_bound_inf", -kIpoptInfinity);
  set_number("nlp_upper_bound_inf", kIpoptInfinity);

  // Derivatives. F and g come with exact first derivatives (the integrator's variational
  // equations); the Hessian of the Lagrangian is either forward differences of its exact gradient
  // (eval_h) or IPOPT's limited-memory BFGS approximation. With 6 unknowns a long L-BFGS history
  // is free, and IPOPT's default of 6 pairs forgets curvature too fast on this non-convex problem.
  // On the rubber band
  // with the target of tests/optimisation/test_shape_optimiser.cpp, from a zero guess, history 6
  // failed 2 of 4 cases (grasp m_x = 0: max_iter 500; half-space: Infeasible_Problem_Detected
  // after wandering to |w| ~ 1e3); history 20 solved all 4 in 26–79 iterations.
  set_string("hessian_approximation", finite_difference_hessian ? "exact" : "limited-memory");
  set_integer("limited_memory_max_history", kLimitedMemoryHistory);
  // With the limited-memory Hessian, the "extended" augmented system puts the low-rank update into
  // one KKT factorisation, instead of Sherman–Morrison with 2 × history back-solves per direction:
  // each MUMPS call carries a fixed cost (its save/restore bookkeeping), so on the paper's
  // experiment this is 47 → 19 ms for the same 22 iterations of one step.
  set_string("limited_memory_aug_solver", "extended");

  // Barrier parameter: the monotone Fiacco–McCormick strategy (IPOPT's default, stated). The
  // adaptive strategy was tried on the same 4 cases from 4 or 5 starts each: it needed more
  // iterations in most and, in one, converged to a coiled rod of 300 times the energy; with
  // limited_memory_initialization scalar2 as well it failed one case. Monotone solved all 20 to the
  // low-energy optimum.
  set_string("mu_strategy", "monotone");

  // Scaling: IPOPT's gradient-based scaling (its default, stated): F and each row of g are scaled
  // down when their gradient at the start exceeds 100 in the max-norm. Rows mix m, N and 1/m.
  set_string("nlp_scaling_method", "gradient-based");

  // Linear solver for the KKT systems: MUMPS, which Debian's coinor-libipopt is built with, for
  // large systems; IpoptSession switches a solve to "ma27", the dense solver of
  // dense_kkt_solver.hpp (no HSL), when its KKT system is small. That solver asks for exactly the
  // storage it uses, so IPOPT's 5-fold margin is not needed, and no MC19 scaling (HSL) is wanted.
  set_string("linear_solver", "mumps");
  set_number("ma27_la_init_factor", 1.0);
  set_number("ma27_liw_init_factor", 1.0);
  set_string("linear_system_scaling", "none");

  assert(ok && "an IPOPT option was rejected: check its name and range");
  (void)ok;
}

// ---- the NLP ------------------------------------------------------------------------------------

int ShapeNlp::kkt_dimension() const {
  const Eigen::VectorXd& lower = problem_.constraint_lower();
  const Eigen::VectorXd& upper = problem_.constraint_upper();
  int inequalities = 0;
  for (int i = 0; i < rows_; ++i)
    if (lower(i) != upper(i)) ++inequalities;
  const int low_rank = finite_difference_hessian_ ? 0 : 2 * kLimitedMemoryHistory;
  return n_ + rows_ + inequalities + low_rank;
}

ShapeNlp::ShapeNlp(ShapeProblem& problem,
                   const Vector6d& start,
                   bool finite_difference_hessian,
                   const std::optional<WrenchBounds>& admissible)
    : problem_(problem),
      start_(start),
      rows_(problem.constraint_count()),
      finite_difference_hessian_(finite_difference_hessian),
      admissible_(admissible) {
  outcome_.w = start;
  outcome_.constraint_multipliers.assign(static_cast<std::size_t>(rows_), 0.0);
}

ShapeNlp::ShapeNlp(ShapeProblem& problem,
                   const Vector12d& start,
                   bool finite_difference_hessian,
                   const std::optional<WrenchBounds>& admissible)
    : problem_(problem),
      n_(12),
      start_(start.head<6>()),
      start_x_(start),
      rows_(problem.constraint_count()),
      finite_difference_hessian_(finite_difference_hessian),
      admissible_(admissible) {
  // IPOPT sees x̃ = x / D: the wrench in its bending units, δt in rod lengths, δφ in radians, so
  // that its regularisation and barrier treat the 12 unknowns alike.
  scale_ << problem.rod().properties.bending_wrench_units(),
      Eigen::Vector3d::Constant(problem.rod().properties.length), Eigen::Vector3d::Ones();
  projected_ = rows_ == 0 && problem.rigid_alignment_applies();
  xi_ = start.tail<6>();
  outcome_.x = start;
  outcome_.w = problem.world_wrench(start).to_vector();
  outcome_.constraint_multipliers.assign(static_cast<std::size_t>(rows_), 0.0);
}

bool ShapeNlp::get_nlp_info(Ipopt::Index& n,
                            Ipopt::Index& m,
                            Ipopt::Index& nnz_jac_g,
                            Ipopt::Index& nnz_h_lag,
                            IndexStyleEnum& index_style) {
  n = unknowns();
  m = rows_;
  nnz_jac_g = n * rows_;  // dg/dw is dense: every row depends on every component of w
  // The lower triangle of the dense n × n Hessian, or nothing for the limited-memory one.
  nnz_h_lag = finite_difference_hessian_ ? n * (n + 1) / 2 : 0;
  index_style = C_STYLE;
  return true;
}

bool ShapeNlp::get_bounds_info(Ipopt::Index n,
                               Ipopt::Number* x_l,
                               Ipopt::Number* x_u,
                               Ipopt::Index m,
                               Ipopt::Number* g_l,
                               Ipopt::Number* g_u) {
  assert(n == unknowns() && m == rows_);
  (void)n;
  // ±inf → ±kIpoptInfinity, which IPOPT reads as "no bound".
  if (n_ == 12) {
    const Vector12d lower = problem_.variable_lower(), upper = problem_.variable_upper();
    for (int j = 0; j < unknowns(); ++j) {
      x_l[j] = std::clamp(lower(j) / scale_(j), -kIpoptInfinity, kIpoptInfinity);
      x_u[j] = std::clamp(upper(j) / scale_(j), -kIpoptInfinity, kIpoptInfinity);
    }
  } else {
    const WrenchBounds& bounds = problem_.wrench_bounds();
    for (int j = 0; j < kUnknowns; ++j) {
      x_l[j] = std::clamp(bounds.lower(j), -kIpoptInfinity, kIpoptInfinity);
      x_u[j] = std::clamp(bounds.upper(j), -kIpoptInfinity, kIpoptInfinity);
    }
  }
  const Eigen::VectorXd& lower = problem_.constraint_lower();
  const Eigen::VectorXd& upper = problem_.constraint_upper();
  for (Ipopt::Index i = 0; i < m; ++i) {
    g_l[i] = std::clamp(lower(i), -kIpoptInfinity, kIpoptInfinity);
    g_u[i] = std::clamp(upper(i), -kIpoptInfinity, kIpoptInfinity);
  }
  return true;
}

bool ShapeNlp::get_starting_point(Ipopt::Index n,
                                  bool init_x,
                                  Ipopt::Number* x,
                                  bool init_z,
                                  Ipopt::Number* /*z_L*/,
                                  Ipopt::Number* /*z_U*/,
                                  Ipopt::Index /*m*/,
                                  bool init_lambda,
                                  Ipopt::Number* /*lambda*/) {
  assert(n == unknowns());
  (void)n;
  // Only a primal start is given (warm_start_init_point stays "no"); IPOPT then initialises the
  // multipliers itself and never asks for them.
  if (!init_x || init_z || init_lambda) return false;
  for (int j = 0; j < unknowns(); ++j) x[j] = n_ == 12 ? start_x_(j) / scale_(j) : start_(j);
  return true;
}

bool ShapeNlp::admissible(const Vector6d& w) const {
  if (!admissible_) return true;
  return (w.array() >= admissible_->lower.array()).all() &&
         (w.array() <= admissible_->upper.array()).all();
}

bool ShapeNlp::evaluate_at(const Ipopt::Number* x) {
  // IPOPT's new_x says whether x changed since the last call; ShapeProblem::evaluate() is a no-op
  // at the last w anyway, so it is called every time: one 6-vector comparison buys independence
  // from the hint (the derivative checker, for one, moves x between calls).
  if (projected_) {
    const Vector6d w_b = Eigen::Map<const Vector6d>(x).cwiseProduct(scale_.head<6>());
    if (!admissible(w_b)) {
      ++outcome_.refusals;
      return false;
    }
    if (w_b != aligned_at_) {
      if (!problem_.align_base(w_b, xi_)) return false;
      aligned_at_ = w_b;
    }
    Vector12d at;
    at << w_b, xi_;
    problem_.evaluate_with_base(at);
    return std::isfinite(problem_.cost()) && problem_.variable_gradient().allFinite();
  }
  if (n_ == 12) {
    const Vector12d at = Eigen::Map<const Vector12d>(x).cwiseProduct(scale_);
    if (!admissible(at.head<6>())) {
      ++outcome_.refusals;
      return false;
    }
    problem_.evaluate_with_base(at);
    return std::isfinite(problem_.cost()) && problem_.variable_gradient().allFinite() &&
           problem_.constraints().allFinite() && problem_.variable_jacobian().allFinite();
  }
  const Vector6d w = Eigen::Map<const Vector6d>(x);
  if (!admissible(w)) {
    ++outcome_.refusals;
    return false;
  }
  problem_.evaluate(w);
  return std::isfinite(problem_.cost()) && problem_.cost_gradient().allFinite() &&
         problem_.constraints().allFinite() && problem_.constraint_jacobian().allFinite();
}

bool ShapeNlp::eval_f(Ipopt::Index n,
                      const Ipopt::Number* x,
                      bool /*new_x*/,
                      Ipopt::Number& obj_value) {
  assert(n == unknowns());
  (void)n;
  if (!evaluate_at(x)) return false;
  obj_value = problem_.cost();
  return true;
}

bool ShapeNlp::eval_grad_f(Ipopt::Index n,
                           const Ipopt::Number* x,
                           bool /*new_x*/,
                           Ipopt::Number* grad_f) {
  assert(n == unknowns());
  (void)n;
  if (!evaluate_at(x)) return false;
  if (projected_) {  // ∂F/∂w_b at ξ*(w_b): ∂F/∂ξ = 0 there
    Eigen::Map<Vector6d> gradient(grad_f);
    gradient = problem_.variable_gradient().head<6>().cwiseProduct(scale_.head<6>());
    return true;
  }
  if (n_ == 12) {
    Eigen::Map<Vector12d> gradient(grad_f);
    gradient = problem_.variable_gradient().cwiseProduct(scale_);
    return true;
  }
  Eigen::Map<Vector6d> gradient(grad_f);
  gradient = problem_.cost_gradient();
  return true;
}

bool ShapeNlp::eval_g(
    Ipopt::Index n, const Ipopt::Number* x, bool /*new_x*/, Ipopt::Index m, Ipopt::Number* g) {
  assert(n == unknowns() && m == rows_);
  (void)n;
  if (m == 0) return true;
  if (!evaluate_at(x)) return false;
  Eigen::Map<Eigen::VectorXd>(g, m) = problem_.constraints();
  return true;
}

bool ShapeNlp::eval_h(Ipopt::Index n,
                      const Ipopt::Number* x,
                      bool /*new_x*/,
                      Ipopt::Number obj_factor,
                      Ipopt::Index m,
                      const Ipopt::Number* lambda,
                      bool /*new_lambda*/,
                      Ipopt::Index nele_hess,
                      Ipopt::Index* iRow,
                      Ipopt::Index* jCol,
                      Ipopt::Number* values) {
  assert(n == unknowns() && m == rows_ && nele_hess == n * (n + 1) / 2);
  (void)n;
  (void)nele_hess;
  if (values == nullptr) {
    Ipopt::Index k = 0;  // the lower triangle, row by row
    for (Ipopt::Index i = 0; i < unknowns(); ++i) {
      for (Ipopt::Index j = 0; j <= i; ++j, ++k) {
        iRow[k] = i;
        jCol[k] = j;
      }
    }
    assert(k == nele_hess && "the Hessian structure does not match nnz_h_lag");
    return true;
  }
  if (projected_) return projected_hessian(x, obj_factor, values);
  const Eigen::Map<const Eigen::VectorXd> multipliers(lambda, m);
  const Vector6d units = problem_.rod().properties.bending_wrench_units();
  if (n_ == 12) {
    // In the scaled unknowns x̃ (units 1).
    return differenced_hessian<Vector12d, Eigen::Matrix<double, 12, 12>>(x, obj_factor, multipliers,
                                                                         Vector12d::Ones(), values);
  }
  return differenced_hessian<Vector6d, Matrix6d>(x, obj_factor, multipliers, units, values);
}

bool ShapeNlp::projected_hessian(const Ipopt::Number* x, double obj_factor, Ipopt::Number* values) {
  if (!evaluate_at(x)) return false;  // ξ*(w_b)
  using Matrix12 = Eigen::Matrix<double, 12, 12>;
  Vector12d at;  // x̃ = (w̃_b, ξ̃*)
  at << Eigen::Map<const Vector6d>(x), xi_.cwiseQuotient(scale_.tail<6>());
  const Eigen::Map<const Eigen::VectorXd> none(nullptr, 0);
  Vector12d at_x;
  if (!lagrangian_gradient(at, obj_factor, none, at_x)) return false;
  Matrix12 H;
  for (int j = 0; j < 12; ++j) {
    const double h =
        std::sqrt(std::numeric_limits<double>::epsilon()) * std::max(std::abs(at[j]), 1.0);
    Vector12d shifted = at, at_shifted;
    shifted[j] += h;
    if (!lagrangian_gradient(shifted, obj_factor, none, at_shifted)) return false;
    H.col(j) = (at_shifted - at_x) / h;
  }
  H = 0.5 * (H + H.transpose()).eval();
  // ξ* minimises F at every w_b, so dξ*/dw_b = -H_ξξ⁻¹ H_ξw and ∇²_w F(w_b, ξ*(w_b)) is the Schur
  // complement.
  const Eigen::LDLT<Matrix6d> ldlt(H.bottomRightCorner<6, 6>());
  const Matrix6d reduced =
      H.topLeftCorner<6, 6>() - H.topRightCorner<6, 6>() * ldlt.solve(H.bottomLeftCorner<6, 6>());
  if (!reduced.allFinite()) return false;
  Ipopt::Index k = 0;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j <= i; ++j) values[k++] = reduced(i, j);
  return true;
}

template <class Vector>
bool ShapeNlp::lagrangian_gradient(const Vector& x,
                                   double obj_factor,
                                   const Eigen::Map<const Eigen::VectorXd>& multipliers,
                                   Vector& gradient) {
  if constexpr (Vector::SizeAtCompileTime == 12) {  // x is x̃: ∇_x̃ L = D ∇_x L
    problem_.evaluate_with_base(x.cwiseProduct(scale_));
    gradient = obj_factor * problem_.variable_gradient();
    if (multipliers.size() > 0)
      gradient.noalias() += problem_.variable_jacobian().transpose() * multipliers;
    gradient.array() *= scale_.array();
  } else {
    problem_.evaluate(x);
    gradient = obj_factor * problem_.cost_gradient();
    if (multipliers.size() > 0)
      gradient.noalias() += problem_.constraint_jacobian().transpose() * multipliers;
  }
  return gradient.allFinite();
}

template <class Vector, class Matrix>
bool ShapeNlp::differenced_hessian(const Ipopt::Number* x,
                                   double obj_factor,
                                   const Eigen::Map<const Eigen::VectorXd>& multipliers,
                                   const Vector& units,
                                   Ipopt::Number* values) {
  constexpr int kN = Vector::SizeAtCompileTime;
  const Vector w = Eigen::Map<const Vector>(x);
  Vector at_w;
  if (!lagrangian_gradient(w, obj_factor, multipliers, at_w)) return false;
  Matrix H;
  for (int j = 0; j < kN; ++j) {
    const double h =
        std::sqrt(std::numeric_limits<double>::epsilon()) * std::max(std::abs(w[j]), units[j]);
    Vector shifted = w, at_shifted;
    shifted[j] += h;
    if (!lagrangian_gradient(shifted, obj_factor, multipliers, at_shifted)) return false;
    H.col(j) = (at_shifted - at_w) / h;
  }
  H = 0.5 * (H + H.transpose()).eval();
  Ipopt::Index k = 0;
  for (int i = 0; i < kN; ++i)
    for (int j = 0; j <= i; ++j) values[k++] = H(i, j);
  return true;
}

bool ShapeNlp::eval_jac_g(Ipopt::Index n,
                          const Ipopt::Number* x,
                          bool /*new_x*/,
                          Ipopt::Index m,
                          Ipopt::Index nele_jac,
                          Ipopt::Index* iRow,
                          Ipopt::Index* jCol,
                          Ipopt::Number* values) {
  assert(n == unknowns() && m == rows_ && nele_jac == n_ * rows_);
  (void)n;
  (void)nele_jac;
  if (values == nullptr) {
    // The structure, declared once: the dense m × n Jacobian in row-major order, entry k = n i + j.
    Ipopt::Index k = 0;
    for (Ipopt::Index i = 0; i < m; ++i) {
      for (Ipopt::Index j = 0; j < n_; ++j, ++k) {
        iRow[k] = i;
        jCol[k] = j;
      }
    }
    assert(k == nele_jac && "the Jacobian structure does not match nnz_jac_g");
    return true;
  }
  if (m == 0) return true;
  if (!evaluate_at(x)) return false;
  if (n_ == 12) {
    Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, 12, Eigen::RowMajor>>(values, m, 12) =
        problem_.variable_jacobian() * scale_.asDiagonal();
    return true;
  }
  // Same row-major order as the structure; dg/dw is stored column-major in Eigen.
  Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, kUnknowns, Eigen::RowMajor>>(
      values, m, kUnknowns) = problem_.constraint_jacobian();
  return true;
}

bool ShapeNlp::intermediate_callback(Ipopt::AlgorithmMode /*mode*/,
                                     Ipopt::Index iter,
                                     Ipopt::Number /*obj_value*/,
                                     Ipopt::Number /*inf_pr*/,
                                     Ipopt::Number /*inf_du*/,
                                     Ipopt::Number /*mu*/,
                                     Ipopt::Number /*d_norm*/,
                                     Ipopt::Number /*regularization_size*/,
                                     Ipopt::Number /*alpha_du*/,
                                     Ipopt::Number /*alpha_pr*/,
                                     Ipopt::Index /*ls_trials*/,
                                     const Ipopt::IpoptData* /*ip_data*/,
                                     Ipopt::IpoptCalculatedQuantities* /*ip_cq*/) {
  outcome_.iterations = iter;
  // Steps cut back at the admissible box again and again: the optimum lies beyond it, and IPOPT
  // would spend its iteration limit creeping towards the box's face.
  return !outcome_.stopped_beyond_scale();
}

void ShapeNlp::finalize_solution(Ipopt::SolverReturn status,
                                 Ipopt::Index n,
                                 const Ipopt::Number* x,
                                 const Ipopt::Number* z_L,
                                 const Ipopt::Number* z_U,
                                 Ipopt::Index m,
                                 const Ipopt::Number* /*g*/,
                                 const Ipopt::Number* lambda,
                                 Ipopt::Number obj_value,
                                 const Ipopt::IpoptData* /*ip_data*/,
                                 Ipopt::IpoptCalculatedQuantities* /*ip_cq*/) {
  assert(n == unknowns() && m == rows_);
  (void)n;
  outcome_.finalized = true;
  outcome_.solver_return = status;
  outcome_.objective = obj_value;
  if (x != nullptr && projected_) {
    evaluate_at(x);  // ξ*(w_b)
    outcome_.x << Eigen::Map<const Vector6d>(x).cwiseProduct(scale_.head<6>()), xi_;
    outcome_.w = problem_.world_wrench(outcome_.x).to_vector();
  } else if (x != nullptr && n_ == 12) {
    outcome_.x = Eigen::Map<const Vector12d>(x).cwiseProduct(scale_);
    outcome_.w = problem_.world_wrench(outcome_.x).to_vector();
  } else if (x != nullptr) {
    outcome_.w = Eigen::Map<const Vector6d>(x);
  }
  if (z_L != nullptr) outcome_.lower_bound_multipliers = Eigen::Map<const Vector6d>(z_L);
  if (z_U != nullptr) outcome_.upper_bound_multipliers = Eigen::Map<const Vector6d>(z_U);
  if (n_ == 12) {  // the multipliers of x̃'s bounds, back in x's units (w_b's)
    outcome_.lower_bound_multipliers.array() /= scale_.head<6>().array();
    outcome_.upper_bound_multipliers.array() /= scale_.head<6>().array();
  }
  if (lambda != nullptr) outcome_.constraint_multipliers.assign(lambda, lambda + m);
}

// ---- status names -------------------------------------------------------------------------------

std::string application_status_name(Ipopt::ApplicationReturnStatus status) {
  switch (status) {
    case Ipopt::Solve_Succeeded:
      return "Solve_Succeeded";
    case Ipopt::Solved_To_Acceptable_Level:
      return "Solved_To_Acceptable_Level";
    case Ipopt::Infeasible_Problem_Detected:
      return "Infeasible_Problem_Detected";
    case Ipopt::Search_Direction_Becomes_Too_Small:
      return "Search_Direction_Becomes_Too_Small";
    case Ipopt::Diverging_Iterates:
      return "Diverging_Iterates";
    case Ipopt::User_Requested_Stop:
      return "User_Requested_Stop";
    case Ipopt::Feasible_Point_Found:
      return "Feasible_Point_Found";
    case Ipopt::Maximum_Iterations_Exceeded:
      return "Maximum_Iterations_Exceeded";
    case Ipopt::Restoration_Failed:
      return "Restoration_Failed";
    case Ipopt::Error_In_Step_Computation:
      return "Error_In_Step_Computation";
    case Ipopt::Maximum_CpuTime_Exceeded:
      return "Maximum_CpuTime_Exceeded";
    case Ipopt::Not_Enough_Degrees_Of_Freedom:
      return "Not_Enough_Degrees_Of_Freedom";
    case Ipopt::Invalid_Problem_Definition:
      return "Invalid_Problem_Definition";
    case Ipopt::Invalid_Option:
      return "Invalid_Option";
    case Ipopt::Invalid_Number_Detected:
      return "Invalid_Number_Detected";
    case Ipopt::Unrecoverable_Exception:
      return "Unrecoverable_Exception";
    case Ipopt::NonIpopt_Exception_Thrown:
      return "NonIpopt_Exception_Thrown";
    case Ipopt::Insufficient_Memory:
      return "Insufficient_Memory";
    case Ipopt::Internal_Error:
      return "Internal_Error";
  }
  return "Unknown_Status_" + std::to_string(static_cast<int>(status));
}

// ---- derivative test ----------------------------------------------------------------------------

namespace {

/// A journal that keeps what IPOPT prints in a string.
class StringJournal final : public Ipopt::Journal {
 public:
  explicit StringJournal(Ipopt::EJournalLevel level) : Ipopt::Journal("rodshape_capture", level) {}
  const std::string& text() const { return text_; }

 protected:
  void PrintImpl(Ipopt::EJournalCategory /*category*/,
                 Ipopt::EJournalLevel /*level*/,
                 const char* str) override {
    text_ += str;
  }
  void PrintfImpl(Ipopt::EJournalCategory /*category*/,
                  Ipopt::EJournalLevel /*level*/,
                  const char* format,
                  va_list args) override {
    va_list copy;
    va_copy(copy, args);
    const int size = std::vsnprintf(nullptr, 0, format, copy);
    va_end(copy);
    if (size <= 0) return;
    std::string buffer(static_cast<std::size_t>(size) + 1, '\0');
    std::vsnprintf(buffer.data(), buffer.size(), format, args);
    buffer.resize(static_cast<std::size_t>(size));
    text_ += buffer;
  }
  void FlushBufferImpl() override {}

 private:
  std::string text_;
};

}  // namespace

DerivativeTestReport run_derivative_test(ShapeProblem& problem,
                                         const Vector6d& w,
                                         double tolerance,
                                         double perturbation) {
  Ipopt::SmartPtr<Ipopt::IpoptApplication> app = IpoptApplicationFactory();
  ShapeOptimiserOptions options;
  options.max_iterations = 0;  // check at the start, do not optimise
  const bool differenced = uses_finite_difference_hessian(options, problem);
  apply_options(*app->Options(), options, differenced);
  bool ok = app->Options()->SetStringValue("derivative_test", "first-order");
  ok = app->Options()->SetNumericValue("derivative_test_tol", tolerance) && ok;
  ok = app->Options()->SetNumericValue("derivative_test_perturbation", perturbation) && ok;
  ok = app->Options()->SetStringValue("derivative_test_print_all", "yes") && ok;
  // IPOPT moves the test point randomly by up to point_perturbation_radius (default 10) before
  // checking; for a wrench in N and N·m that is a different, wildly coiled rod. Check at w itself.
  ok = app->Options()->SetNumericValue("point_perturbation_radius", 0.0) && ok;
  assert(ok);
  (void)ok;

  DerivativeTestReport report;
  if (app->Initialize("") != Ipopt::Solve_Succeeded) {
    report.error_count = -1;
    report.log = "IpoptApplication::Initialize failed";
    return report;
  }
  Ipopt::SmartPtr<StringJournal> journal = new StringJournal(Ipopt::J_WARNING);
  app->Jnlst()->AddJournal(Ipopt::GetRawPtr(journal));
  Ipopt::SmartPtr<Ipopt::TNLP> nlp = new ShapeNlp(problem, w, differenced);
  app->OptimizeTNLP(nlp);

  report.log = journal->text();
  std::istringstream lines(report.log);
  for (std::string line; std::getline(lines, line);) {
    const auto first = line.find_first_not_of(' ');
    if (first != std::string::npos && line[first] == '*') ++report.error_count;
    if (line.find("No errors detected by derivative checker") != std::string::npos)
      report.no_errors_line = true;
  }
  return report;
}

}  // namespace rodshape::detail
