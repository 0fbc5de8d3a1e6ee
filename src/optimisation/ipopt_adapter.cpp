// ipopt_adapter.cpp: IpoptSession, and IPOPT's return status in rodshape's vocabulary.
#include "optimisation/ipopt_adapter.hpp"

#include <IpIpoptApplication.hpp>
#include <IpSolveStatistics.hpp>

#include "optimisation/dense_kkt_solver.hpp"
#include "optimisation/ipopt_nlp.hpp"
#include "optimisation/mumps_lock.hpp"

#include <atomic>
#include <memory>
#include <mutex>
#include <optional>

namespace rodshape::detail {

namespace {

/// IPOPT's ApplicationReturnStatus → SolveStatus. The raw status is kept in IpoptDetails.
///   Solve_Succeeded, Solved_To_Acceptable_Level    → Converged (then checked against our own
///   Feasible_Point_Found (square problems only)       constraint violation by optimise_shape)
///   Maximum_Iterations_Exceeded, _CpuTime_Exceeded → IterationLimit
///   Diverging_Iterates                             → Diverged  (|w| grew without bound)
///   Invalid_Number_Detected                        → Diverged  (F, g or a derivative non-finite)
///   Infeasible_Problem_Detected                    → Infeasible (a stationary point of the
///                                                    constraint violation: no step reduces it)
///   Restoration_Failed                             → Infeasible (the feasibility restoration
///                                                    found no step that reduces the violation)
///   Error_In_Step_Computation                      → Singular  (the KKT matrix stayed singular
///                                                    despite IPOPT's regularisation)
///   Search_Direction_Becomes_Too_Small             → Singular  (no step changes w any more
///                                                    although the tolerances are not met)
///   Not_Enough_Degrees_Of_Freedom                  → Singular  (more equality rows than the 6
///                                                    unknowns: dg/dw cannot have full row rank)
///   User_Requested_Stop, Invalid_Problem_Definition, Invalid_Option, Unrecoverable_Exception,
///   NonIpopt_Exception_Thrown, Insufficient_Memory, Internal_Error
///                                                  → Diverged  (the solve broke down; the
///                                                    message names IPOPT's status)
SolveStatus map_status(Ipopt::ApplicationReturnStatus status) {
  switch (status) {
    case Ipopt::Solve_Succeeded:
    case Ipopt::Solved_To_Acceptable_Level:
    case Ipopt::Feasible_Point_Found:
      return SolveStatus::Converged;
    case Ipopt::Maximum_Iterations_Exceeded:
    case Ipopt::Maximum_CpuTime_Exceeded:
      return SolveStatus::IterationLimit;
    case Ipopt::Infeasible_Problem_Detected:
    case Ipopt::Restoration_Failed:
      return SolveStatus::Infeasible;
    case Ipopt::Error_In_Step_Computation:
    case Ipopt::Search_Direction_Becomes_Too_Small:
    case Ipopt::Not_Enough_Degrees_Of_Freedom:
      return SolveStatus::Singular;
    case Ipopt::Diverging_Iterates:
    case Ipopt::Invalid_Number_Detected:
    case Ipopt::User_Requested_Stop:
    case Ipopt::Invalid_Problem_Definition:
    case Ipopt::Invalid_Option:
    case Ipopt::Unrecoverable_Exception:
    case Ipopt::NonIpopt_Exception_Thrown:
    case Ipopt::Insufficient_Memory:
    case Ipopt::Internal_Error:
      return SolveStatus::Diverged;
  }
  return SolveStatus::Diverged;
}

IpoptRun with_status(Ipopt::ApplicationReturnStatus status) {
  IpoptRun run;
  run.status = map_status(status);
  run.details.application_status = static_cast<int>(status);
  run.details.application_status_name = application_status_name(status);
  return run;
}

}  // namespace

IpoptRun run_ended(IpoptEnd end) {
  switch (end) {
    case IpoptEnd::SolveSucceeded:
      return with_status(Ipopt::Solve_Succeeded);
    case IpoptEnd::SolvedToAcceptableLevel:
      return with_status(Ipopt::Solved_To_Acceptable_Level);
    case IpoptEnd::MaximumIterationsExceeded:
      return with_status(Ipopt::Maximum_Iterations_Exceeded);
    case IpoptEnd::UserRequestedStop:
      return with_status(Ipopt::User_Requested_Stop);
    case IpoptEnd::DivergingIterates:
      return with_status(Ipopt::Diverging_Iterates);
    case IpoptEnd::InvalidNumberDetected:
      return with_status(Ipopt::Invalid_Number_Detected);
    case IpoptEnd::ErrorInStepComputation:
      return with_status(Ipopt::Error_In_Step_Computation);
    case IpoptEnd::SearchDirectionBecomesTooSmall:
      return with_status(Ipopt::Search_Direction_Becomes_Too_Small);
  }
  return with_status(Ipopt::Internal_Error);
}

struct IpoptSession::Application {
  Ipopt::SmartPtr<Ipopt::IpoptApplication> app = IpoptApplicationFactory();
};

IpoptSession::IpoptSession(const ShapeOptimiserOptions& options, bool finite_difference_hessian)
    : application_(std::make_unique<Application>()),
      finite_difference_hessian_(finite_difference_hessian) {
  Ipopt::IpoptApplication& app = *application_->app;
  apply_options(*app.Options(), options, finite_difference_hessian);
  // "" skips IPOPT's options file: an ipopt.opt in the working directory must not change results.
  const Ipopt::ApplicationReturnStatus init = app.Initialize("");
  if (init != Ipopt::Solve_Succeeded) {
    failure_ = with_status(init);
    failure_->status = SolveStatus::Diverged;
  }
}

IpoptSession::~IpoptSession() = default;

IpoptSession& IpoptSession::for_this_thread(const ShapeOptimiserOptions& options,
                                            bool finite_difference_hessian) {
  struct Cached {
    ShapeOptimiserOptions options;
    bool finite_difference_hessian;
    std::unique_ptr<IpoptSession> session;
  };
  thread_local std::optional<Cached> cached;
  // What apply_options() reads.
  const auto same = [&](const Cached& c) {
    return c.finite_difference_hessian == finite_difference_hessian &&
           c.options.max_iterations == options.max_iterations &&
           c.options.tolerance == options.tolerance &&
           c.options.constraint_tolerance == options.constraint_tolerance &&
           c.options.print_level == options.print_level;
  };
  if (!cached || !same(*cached))
    cached = Cached{options, finite_difference_hessian,
                    std::make_unique<IpoptSession>(options, finite_difference_hessian)};
  return *cached->session;
}

IpoptRun IpoptSession::run(ShapeProblem& problem,
                           const Vector6d& start,
                           const std::optional<WrenchBounds>& admissible) {
  return solve(new ShapeNlp(problem, start, finite_difference_hessian_, admissible));
}

IpoptRun IpoptSession::run(ShapeProblem& problem,
                           const Vector12d& start,
                           const std::optional<WrenchBounds>& admissible) {
  return solve(new ShapeNlp(problem, start, finite_difference_hessian_, admissible));
}

IpoptRun IpoptSession::solve(ShapeNlp* nlp) {
  Ipopt::IpoptApplication& app = *application_->app;
  const Ipopt::SmartPtr<Ipopt::TNLP> owner = nlp;
  // Small KKT systems (every fixed-clamp step without many constraint rows) go to the dense solver
  // of dense_kkt_solver.hpp, as IPOPT's "ma27": it keeps no state outside IPOPT's arrays, so these
  // solves need no lock at all. OptimizeTNLP builds its algorithm afresh and reads linear_solver
  // each time, so one session serves both kinds.
  const bool dense = nlp->kkt_dimension() <= kDenseKktMaxDimension;
  if (dense) register_dense_kkt_solver();
  app.Options()->SetStringValue("linear_solver", dense ? "ma27" : "mumps");
  // MUMPS, for the larger ones, is not thread-safe: its calls go one at a time through the lock of
  // mumps_lock.cpp, and the rest of the solve runs in parallel. Until a MUMPS solve has shown that
  // IPOPT's calls are bound to that lock (they are unless another image defining dmumps_c came
  // first), whole MUMPS solves are serialised instead.
  static std::mutex whole_solves;
  static std::atomic<bool> mumps_behind_lock{false};
  // A dense solve may still end the MUMPS instance of this session's last solve (IPOPT keeps its
  // algorithm until the next OptimizeTNLP): it is serialised too while the lock is unproven.
  const bool calls_mumps = !dense || last_solve_used_mumps_;
  last_solve_used_mumps_ = !dense;
  IpoptRun run;
  if (!calls_mumps || mumps_behind_lock.load(std::memory_order_acquire)) {
    run = with_status(app.OptimizeTNLP(owner));
  } else {
    const std::lock_guard<std::mutex> lock(whole_solves);
    const long calls_before = mumps_calls_in_this_thread();
    run = with_status(app.OptimizeTNLP(owner));
    if (mumps_calls_in_this_thread() > calls_before)
      mumps_behind_lock.store(true, std::memory_order_release);
  }
  const NlpOutcome& outcome = nlp->outcome();
  const Ipopt::SmartPtr<Ipopt::SolveStatistics> statistics = app.Statistics();
  run.w = outcome.w;
  run.x = outcome.x;
  run.details.iterations =
      Ipopt::IsValid(statistics) ? statistics->IterationCount() : outcome.iterations;
  run.details.objective = outcome.objective;
  run.details.constraint_multipliers = outcome.constraint_multipliers;
  run.details.lower_bound_multipliers = outcome.lower_bound_multipliers;
  run.details.upper_bound_multipliers = outcome.upper_bound_multipliers;
  run.details.beyond_scale = outcome.stopped_beyond_scale();
  return run;
}

}  // namespace rodshape::detail
