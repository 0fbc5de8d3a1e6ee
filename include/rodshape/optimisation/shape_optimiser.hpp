// shape_optimiser.hpp: solve a ShapeProblem with IPOPT (interior point, as in the paper), exact
// first derivatives and a Hessian by differences of them (or IPOPT's limited-memory one), from one
// or several initial base wrenches. IPOPT stays behind this header: no IPOPT type appears in
// rodshape's public API.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "rodshape/core/rod_configuration.hpp"
#include "rodshape/core/wrench.hpp"
#include "rodshape/optimisation/shape_problem.hpp"
#include "rodshape/solvers/solve_status.hpp"
#include "rodshape/solvers/stability.hpp"

namespace rodshape {

struct ShapeOptimiserOptions {
  /// Upper bounds (docs/limits.md, "Sizes"): an IPOPT iteration integrates the rod with its
  /// derivatives; each start is a whole solve (about 20 ms per step for the 101-node band).
  static constexpr int kMaxIterations = 10'000;
  static constexpr int kMaxMultiStarts = 100;

  int max_iterations = 500;            // IPOPT max_iter, 0 … kMaxIterations
  double tolerance = 1e-8;             // IPOPT tol (scaled NLP error)
  double constraint_tolerance = 1e-9;  // IPOPT constr_viol_tol, in the constraints' units
  /// Extra starts besides the given guess: the guess with each bending moment component flipped,
  /// and so on; feasible optima are ranked by elastic energy (the paper's use of the energy term).
  int multi_starts = 0;  // 0 … kMaxMultiStarts
  int print_level = 0;   // IPOPT print_level (0: silent)
  /// The Hessian of the Lagrangian. FiniteDifference: forward differences of its exact gradient
  /// (6 more evaluations per iteration, Newton's convergence: the paper's experiment plans in 77
  /// iterations instead of 402). LimitedMemory: IPOPT's L-BFGS, cheaper iterations and more of
  /// them, but robust where constraints are active (with the differenced Hessian, strain-limited
  /// problems wandered off to the iteration limit). Automatic: FiniteDifference when the problem
  /// has no constraint rows or a moving base (12 unknowns, where L-BFGS with an active workspace
  /// and a released grasp ran out of iterations: examples/plan_base_arm.yaml), LimitedMemory
  /// otherwise.
  enum class Hessian { Automatic, FiniteDifference, LimitedMemory };
  Hessian hessian = Hessian::Automatic;
  bool assess_stability = true;  // run assess_stability() on the optimum
  /// Refuse to evaluate F beyond WrenchBounds::from_scale(rod) (widened to twice a start that lies
  /// outside): IPOPT then cuts such a step back, as after a failed evaluation. Unlike bounds given
  /// to IPOPT, this adds no barrier term, so an optimisation that stays in the box runs exactly as
  /// without it, while one that would wander to coiled shapes of |w| ~ 10³ cannot.
  bool confine_to_scale = true;
  /// Throws InputError naming the field.
  void validate() const;
};

/// IPOPT's own account of the solve, kept whole (not collapsed to a bool). A problem without
/// constraint rows or wrench bounds (with the differenced Hessian) is solved by the iteration IPOPT
/// would perform there, Newton's method with its inertia correction and line search, without
/// IPOPT's overhead: `solver` says "dense Newton", and the status, iterations and objective read
/// as IPOPT's would.
struct IpoptDetails {
  std::string solver = "IPOPT";         // or "dense Newton"
  int application_status = 0;           // Ipopt::ApplicationReturnStatus as an int
  std::string application_status_name;  // e.g. "Solve_Succeeded"
  int iterations = 0;
  double objective = 0.0;
  std::vector<double> constraint_multipliers;           // λ, one per row of g
  Vector6d lower_bound_multipliers = Vector6d::Zero();  // z_L for w
  Vector6d upper_bound_multipliers = Vector6d::Zero();  // z_U for w
  /// Stopped because steps kept reaching beyond WrenchBounds::from_scale (confine_to_scale).
  bool beyond_scale = false;
};

struct ShapeResult {
  SolveStatus status = SolveStatus::NotRun;
  std::string message = "optimise_shape() was not called";
  BaseWrench base_wrench;
  RodConfiguration configuration;  // at base_wrench, with all-node derivatives
  ShapeCostBreakdown cost;
  double max_constraint_violation = 0.0;
  std::optional<StabilityResult> stability;
  IpoptDetails ipopt;
  int starts_tried = 1;
  bool converged() const { return status == SolveStatus::Converged; }
  /// "converged: max distance 0.37 mm, energy 0.0025 J; <message>".
  std::string brief() const;
};

/// Optimises from `guess` (and the extra starts of the options). Throws InputError for bad options;
/// a solve that fails is reported in the status, never thrown.
ShapeResult optimise_shape(ShapeProblem& problem,
                           const BaseWrench& guess,
                           const ShapeOptimiserOptions& options = {});

/// Whether this build has IPOPT (always true today; kept for a build without it).
bool ipopt_available();

}  // namespace rodshape
