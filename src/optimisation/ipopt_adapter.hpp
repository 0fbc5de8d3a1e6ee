// ipopt_adapter.hpp (private): IPOPT as shape optimisation sees it, with no IPOPT type in sight.
// An IpoptSession is one configured IpoptApplication; run() optimises the base wrench from one
// start and says how it ended, IPOPT's return status mapped to SolveStatus (the raw one kept in
// IpoptDetails). The TNLP itself is in ipopt_nlp.hpp.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "rodshape/core/wrench.hpp"
#include "rodshape/optimisation/shape_optimiser.hpp"
#include "rodshape/optimisation/shape_problem.hpp"
#include "rodshape/solvers/solve_status.hpp"

namespace rodshape::detail {

/// Whether the Hessian is differenced (eval_h) for this problem, per
/// ShapeOptimiserOptions::hessian.
bool uses_finite_difference_hessian(const ShapeOptimiserOptions& options,
                                    const ShapeProblem& problem);

/// One IPOPT run from one start.
struct IpoptRun {
  SolveStatus status = SolveStatus::NotRun;  // IPOPT's return status, mapped (see the .cpp)
  IpoptDetails details;                      // the raw status, iterations, multipliers
  Vector6d w = Vector6d::Zero();             // the final iterate (its world wrench)
  Vector12d x = Vector12d::Zero();           // with a moving base: the final (w_b, ξ)
};

/// How a solve ended, named by IPOPT's return statuses: those unconstrained_newton.hpp reports.
enum class IpoptEnd {
  SolveSucceeded,
  SolvedToAcceptableLevel,
  MaximumIterationsExceeded,
  UserRequestedStop,
  DivergingIterates,
  InvalidNumberDetected,
  ErrorInStepComputation,
  SearchDirectionBecomesTooSmall,
};

/// A run that ended so: its SolveStatus, IPOPT's status number and name (as an IPOPT run's).
IpoptRun run_ended(IpoptEnd end);

class ShapeNlp;

class IpoptSession {
 public:
  /// Configures IPOPT with `options` (every option rodshape sets, apply_options).
  IpoptSession(const ShapeOptimiserOptions& options, bool finite_difference_hessian);
  ~IpoptSession();
  IpoptSession(const IpoptSession&) = delete;
  IpoptSession& operator=(const IpoptSession&) = delete;

  /// This thread's session for `options` (a plan's steps share one): made anew when the options
  /// IPOPT sees differ from the last call's. An IpoptApplication costs ~150 µs to make (it
  /// registers several hundred options), a tenth of a typical step; one run does not change what
  /// the next computes (OptimizeTNLP builds its algorithm afresh).
  static IpoptSession& for_this_thread(const ShapeOptimiserOptions& options,
                                       bool finite_difference_hessian);

  bool finite_difference_hessian() const { return finite_difference_hessian_; }
  /// Set when IPOPT could not be initialised (run() must not be called then): its status.
  const std::optional<IpoptRun>& initialisation_failure() const { return failure_; }

  /// Optimises `problem` from `start` (F not evaluated outside `admissible`, when given); the
  /// problem is left evaluated at some iterate. The KKT systems go to the dense solver
  /// (dense_kkt_solver.hpp) when their dimension is at most kDenseKktMaxDimension, to MUMPS above.
  /// Runs in different threads overlap; only their calls of MUMPS (not thread-safe) are serialised
  /// (mumps_lock.hpp).
  IpoptRun run(ShapeProblem& problem,
               const Vector6d& start,
               const std::optional<WrenchBounds>& admissible = std::nullopt);
  /// With a moving base: from x = (w_b, ξ) (the admissible box bounds w_b).
  IpoptRun run(ShapeProblem& problem,
               const Vector12d& start,
               const std::optional<WrenchBounds>& admissible = std::nullopt);

 private:
  IpoptRun solve(ShapeNlp* nlp);
  struct Application;
  std::unique_ptr<Application> application_;
  bool finite_difference_hessian_;
  bool last_solve_used_mumps_ = false;  // its algorithm, with a MUMPS instance, is still alive
  std::optional<IpoptRun> failure_;
};

}  // namespace rodshape::detail
