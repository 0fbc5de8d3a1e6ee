// Benchmarks of the rod model and the equilibrium solvers on the paper's rubber band (L = 0.29 m,
// EIx = EIy = 0.04 N·m², GJ = 0.028 N·m², 0.02 × 0.02 m section, E = 3.2 MPa, ν = 0.5), at N = 50,
// 100 and 200 intervals. Names are stable so that figures compare from one change to the next.
// BM_PlainRk4Kernel is a plain RK4 of the same ODE, written for comparison; the cases of the
// integrator and the solvers report their CPU time over its at the same N (counter x_kernel).
#include <benchmark/benchmark.h>

#include <Eigen/Geometry>
#include <ctime>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "rodshape/core/base_pose_derivatives.hpp"
#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/samples/rubber_band.hpp"
#include "rodshape/solvers/shooting_solver.hpp"

namespace {

using namespace rodshape;

ClampedRod rubber_band(int intervals) {
  return samples::rubber_band(ConstitutiveModel::Cosserat, intervals);
}

using samples::bent_tip;

/// A generic 3D wrench: bending about both axes, torsion, shear and tension.
BaseWrench generic_wrench() { return {{0.3, -0.2, 0.5}, {0.02, -0.03, 0.01}}; }

/// A plain fixed-step RK4 of the same static Cosserat ODE, written for comparison (no quaternion,
/// no energy, no derivatives): state (p, R, n, m), all nodes stored,
///   v = K_tra⁻¹ Rᵀ n + ṽ,  u = K_rot⁻¹ Rᵀ m + ũ,
///   p' = R v,  R' = R û,  n' = -f,  m' = -p' × n - l.
/// R drifts from orthonormal by O(h⁴) per step; the integrator proper keeps it exact.
class PlainRk4Kernel {
 public:
  explicit PlainRk4Kernel(const ClampedRod& rod)
      : C_tra_(rod.properties.K_tra.cwiseInverse()),
        C_rot_(rod.properties.K_rot.cwiseInverse()),
        v_rest_(rod.properties.v_rest),
        u_rest_(rod.properties.u_rest),
        f_(rod.load.force),
        l_(rod.load.moment),
        p0_(rod.clamp.position),
        R0_(rod.clamp.rotation),
        h_(rod.step()),
        p_(rod.nodes()),
        R_(rod.nodes()) {}

  void run(const BaseWrench& w) {
    State y{p0_, R0_, w.force, w.moment};
    p_[0] = y.p;
    R_[0] = y.R;
    for (std::size_t i = 1; i < p_.size(); ++i) {
      const State k1 = derivative(y);
      const State k2 = derivative(add(y, k1, 0.5 * h_));
      const State k3 = derivative(add(y, k2, 0.5 * h_));
      const State k4 = derivative(add(y, k3, h_));
      y.p += h_ / 6.0 * (k1.p + 2.0 * k2.p + 2.0 * k3.p + k4.p);
      y.R += h_ / 6.0 * (k1.R + 2.0 * k2.R + 2.0 * k3.R + k4.R);
      y.n += h_ / 6.0 * (k1.n + 2.0 * k2.n + 2.0 * k3.n + k4.n);
      y.m += h_ / 6.0 * (k1.m + 2.0 * k2.m + 2.0 * k3.m + k4.m);
      p_[i] = y.p;
      R_[i] = y.R;
    }
  }
  const Eigen::Vector3d& tip() const { return p_.back(); }

 private:
  struct State {
    Eigen::Vector3d p;
    Eigen::Matrix3d R;
    Eigen::Vector3d n, m;
  };

  static State add(const State& y, const State& k, double a) {
    return {y.p + a * k.p, y.R + a * k.R, y.n + a * k.n, y.m + a * k.m};
  }

  static Eigen::Matrix3d hat(const Eigen::Vector3d& u) {
    Eigen::Matrix3d U;
    U << 0.0, -u.z(), u.y(), u.z(), 0.0, -u.x(), -u.y(), u.x(), 0.0;
    return U;
  }

  State derivative(const State& y) const {
    const Eigen::Vector3d v = C_tra_.cwiseProduct(y.R.transpose() * y.n) + v_rest_;
    const Eigen::Vector3d u = C_rot_.cwiseProduct(y.R.transpose() * y.m) + u_rest_;
    const Eigen::Vector3d p_prime = y.R * v;
    return {p_prime, y.R * hat(u), -f_, -p_prime.cross(y.n) - l_};
  }

  Eigen::Vector3d C_tra_, C_rot_, v_rest_, u_rest_, f_, l_, p0_;
  Eigen::Matrix3d R0_;
  double h_;
  std::vector<Eigen::Vector3d> p_;
  std::vector<Eigen::Matrix3d> R_;
};

void BM_PlainRk4Kernel(benchmark::State& state) {
  PlainRk4Kernel kernel(rubber_band(static_cast<int>(state.range(0))));
  const BaseWrench w = generic_wrench();
  kernel.run(w);
  for (auto _ : state) {
    kernel.run(w);
    benchmark::DoNotOptimize(kernel.tip().data());
  }
  state.SetComplexityN(state.range(0));
}

/// This thread's CPU time, s: the ratios below compare CPU times, which other work on the machine
/// disturbs less than wall times.
double thread_seconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

/// The plain kernel's CPU time per run at `intervals`, s: the mean over at least `seconds` of CPU
/// time, measured where it is asked for (so that a case's ratio compares with this moment's
/// machine). The caller passes its own loop's CPU time, so that both sides of the ratio average
/// over as long a stretch as the CPU column does: one 10 ms sample (1000 runs, as before) read 1.0
/// to 1.9 times the kernel's median right after a case's loop (0.67 printed where the medians gave
/// 1.26; BENCHMARKS.md).
double kernel_seconds(int intervals, double seconds) {
  PlainRk4Kernel kernel(rubber_band(intervals));
  const BaseWrench w = generic_wrench();
  kernel.run(w);
  constexpr int kBatch = 20;
  long runs = 0;
  const double start = thread_seconds();
  double elapsed = 0.0;
  do {
    for (int i = 0; i < kBatch; ++i) {
      kernel.run(w);
      benchmark::DoNotOptimize(kernel.tip().data());
    }
    runs += kBatch;
    elapsed = thread_seconds() - start;
  } while (elapsed < seconds);
  return elapsed / static_cast<double>(runs);
}

/// Reports counter "x_kernel": the case's CPU time per iteration since `start` (thread_seconds()
/// just before its loop) over the plain kernel's at the same N, measured right after the loop for
/// as long (at least 10 ms): the ratio of the two CPU columns, repetition by repetition.
void report_kernel_ratio(benchmark::State& state, int intervals, double start) {
  const double elapsed = thread_seconds() - start;
  if (state.iterations() == 0) return;
  const double per_iteration = elapsed / static_cast<double>(state.iterations());
  state.counters["x_kernel"] = per_iteration / kernel_seconds(intervals, std::max(elapsed, 0.01));
}

void BM_Forward(benchmark::State& state) {
  const ClampedRod rod = rubber_band(static_cast<int>(state.range(0)));
  RodConfiguration out;
  const BaseWrench w = generic_wrench();
  integrate(rod, w, out);
  const double start = thread_seconds();
  for (auto _ : state) {
    integrate(rod, w, out);
    benchmark::DoNotOptimize(out.p.back().data());
  }
  report_kernel_ratio(state, static_cast<int>(state.range(0)), start);
  state.SetComplexityN(state.range(0));
}

void BM_ForwardWithDerivatives(benchmark::State& state) {
  const ClampedRod rod = rubber_band(static_cast<int>(state.range(0)));
  RodConfiguration out;
  const BaseWrench w = generic_wrench();
  integrate(rod, w, out, Derivatives::Tip);
  const double start = thread_seconds();
  for (auto _ : state) {
    integrate(rod, w, out, Derivatives::Tip);
    benchmark::DoNotOptimize(out.tip_dp_dw.data());
  }
  report_kernel_ratio(state, static_cast<int>(state.range(0)), start);
  state.SetComplexityN(state.range(0));
}

/// BM_Forward's integration storing only the base and the tip, without the energy (Output::Tip):
/// what a shooting solver's residual needs.
void BM_ForwardTip(benchmark::State& state) {
  const ClampedRod rod = rubber_band(static_cast<int>(state.range(0)));
  RodConfiguration out;
  const BaseWrench w = generic_wrench();
  integrate(rod, w, out, Derivatives::None, Output::Tip);
  const double start = thread_seconds();
  for (auto _ : state) {
    integrate(rod, w, out, Derivatives::None, Output::Tip);
    benchmark::DoNotOptimize(out.p.back().data());
  }
  report_kernel_ratio(state, static_cast<int>(state.range(0)), start);
}

/// BM_ForwardWithDerivatives with Output::Tip: a shooting solver's Jacobian.
void BM_ForwardWithDerivativesTip(benchmark::State& state) {
  const ClampedRod rod = rubber_band(static_cast<int>(state.range(0)));
  RodConfiguration out;
  const BaseWrench w = generic_wrench();
  integrate(rod, w, out, Derivatives::Tip, Output::Tip);
  const double start = thread_seconds();
  for (auto _ : state) {
    integrate(rod, w, out, Derivatives::Tip, Output::Tip);
    benchmark::DoNotOptimize(out.tip_dp_dw.data());
  }
  report_kernel_ratio(state, static_cast<int>(state.range(0)), start);
}

void BM_ForwardWithAllNodeDerivatives(benchmark::State& state) {
  const ClampedRod rod = rubber_band(static_cast<int>(state.range(0)));
  RodConfiguration out;
  const BaseWrench w = generic_wrench();
  integrate(rod, w, out, Derivatives::AllNodes);
  const double start = thread_seconds();
  for (auto _ : state) {
    integrate(rod, w, out, Derivatives::AllNodes);
    benchmark::DoNotOptimize(out.dp_dw.back().data());
  }
  report_kernel_ratio(state, static_cast<int>(state.range(0)), start);
}

/// The clamp-pose derivatives of every node (issue 21) from an all-node configuration, with gravity
/// (so that the load tangent is integrated): compare with BM_ForwardWithAllNodeDerivatives.
void BM_BasePoseDerivatives(benchmark::State& state) {
  ClampedRod rod = rubber_band(static_cast<int>(state.range(0)));
  rod.load = DistributedLoad::gravity(rod.properties.mass_per_length, {0.0, 0.0, -9.81});
  const RodConfiguration c = integrate(rod, generic_wrench(), Derivatives::AllNodes);
  RodConfiguration out;
  base_pose_derivatives(rod, c, out);
  const double start = thread_seconds();
  for (auto _ : state) {
    base_pose_derivatives(rod, c, out);
    benchmark::DoNotOptimize(out.dp_dw.back().data());
  }
  report_kernel_ratio(state, static_cast<int>(state.range(0)), start);
}

ShootingOptions bench_options() {
  ShootingOptions options;
  options.residual_tolerance = 1e-10;
  options.output_derivatives = Derivatives::None;  // the solve, not the final report
  return options;
}

/// The solver's own counts, as benchmark counters.
void report(benchmark::State& state, const ShootingSummary& summary) {
  state.counters["lm_iterations"] = summary.iterations;
  state.counters["chord_steps"] = summary.chord_steps;
  state.counters["integrations"] = summary.integrations;
  state.counters["with_derivatives"] = summary.jacobian_evaluations;
}

void BM_SolveClampedClampedCold(benchmark::State& state) {
  const ClampedRod rod = rubber_band(static_cast<int>(state.range(0)));
  const TipCondition tip = ClampedTip{bent_tip()};
  const ShootingOptions options = bench_options();
  ShootingSummary summary;
  const double start = thread_seconds();
  for (auto _ : state) {
    const ShootingResult solution = solve_equilibrium(rod, tip, BaseWrench{}, options);
    if (!solution.summary.converged()) state.SkipWithError("cold solve did not converge");
    summary = solution.summary;
  }
  report_kernel_ratio(state, static_cast<int>(state.range(0)), start);
  report(state, summary);
}

void BM_SolveClampedClampedWarm(benchmark::State& state) {
  const ClampedRod rod = rubber_band(static_cast<int>(state.range(0)));
  const ShootingOptions options = bench_options();
  const ShootingResult solved = solve_equilibrium(rod, ClampedTip{bent_tip()}, {}, options);
  Pose moved = bent_tip();
  moved.position += Eigen::Vector3d(1e-3, 0.0, 0.0);  // the tip moved by 1 mm
  const TipCondition tip = ClampedTip{moved};
  ShootingSummary summary;
  const double start = thread_seconds();
  for (auto _ : state) {
    const ShootingResult solution = solve_equilibrium(rod, tip, solved.base_wrench, options);
    if (!solution.summary.converged()) state.SkipWithError("warm solve did not converge");
    summary = solution.summary;
  }
  report_kernel_ratio(state, static_cast<int>(state.range(0)), start);
  report(state, summary);
}

/// A solve that cannot converge: the free tip loaded with (1e4, 0, 1e4) N and (0, 1e4, 0) N·m at
/// 1000 intervals, default options (the direct solve, then the continuation from rest until its
/// steps fail): how long the solver takes to say no.
void BM_SolveFreeTipFarBeyondConvergence(benchmark::State& state) {
  const ClampedRod rod = rubber_band(static_cast<int>(state.range(0)));
  const TipCondition tip = FreeTip{{{1e4, 0.0, 1e4}, {0.0, 1e4, 0.0}}};
  ShootingOptions options;
  options.output_derivatives = Derivatives::None;
  ShootingSummary summary;
  for (auto _ : state) {
    const ShootingResult solution = solve_equilibrium(rod, tip, BaseWrench{}, options);
    if (solution.summary.converged()) state.SkipWithError("the solve converged");
    summary = solution.summary;
  }
  report(state, summary);
  state.counters["continuation_steps"] = summary.continuation_steps;
}

BENCHMARK(BM_PlainRk4Kernel)->Arg(50)->Arg(100)->Arg(200)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Forward)->Arg(50)->Arg(100)->Arg(200)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ForwardWithDerivatives)->Arg(50)->Arg(100)->Arg(200)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ForwardTip)->Arg(100)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ForwardWithDerivativesTip)->Arg(100)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ForwardWithAllNodeDerivatives)->Arg(100)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_BasePoseDerivatives)->Arg(100)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SolveClampedClampedCold)->Arg(50)->Arg(100)->Arg(200)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SolveClampedClampedWarm)->Arg(50)->Arg(100)->Arg(200)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SolveFreeTipFarBeyondConvergence)->Arg(1000)->Unit(benchmark::kMillisecond);

}  // namespace
