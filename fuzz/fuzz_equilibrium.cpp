// fuzz_equilibrium.cpp: libFuzzer target for the whole `rodshape equilibrium` path: parse the task,
// solve it (with few iterations and at most 200 intervals, so that one input stays fast), test the
// stability of a held tip, write the JSON. An InputError is the expected answer to bad input.
// Findings (abort()): anything else thrown, a crash, a sanitizer report, a timeout; and, with
// RODSHAPE_FUZZ_STRICT=1, a converged status whose configuration is not finite or whose residual is
// above the tolerance ("never garbage", issue 12; known findings are kept in fuzz/findings/).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <optional>
#include <string>
#include <variant>

#include "rodshape/error.hpp"
#include "rodshape/io/result_json.hpp"
#include "rodshape/io/task_reader.hpp"
#include "rodshape/solvers/shooting_solver.hpp"
#include "rodshape/solvers/stability.hpp"

namespace {

using namespace rodshape;

constexpr int kMaxIntervals = 200;
constexpr int kMaxIterations = 30;
constexpr int kMaxContinuationSteps = 16;

bool strict() {
  static const bool value = [] {
    const char* setting = std::getenv("RODSHAPE_FUZZ_STRICT");
    return setting != nullptr && std::string(setting) == "1";
  }();
  return value;
}

template <class Vectors>
bool all_finite(const Vectors& values) {
  for (const auto& value : values) {
    if (!value.allFinite()) return false;
  }
  return true;
}

bool finite(const RodConfiguration& c) {
  return all_finite(c.p) && all_finite(c.R) && all_finite(c.n) && all_finite(c.m) &&
         all_finite(c.v) && all_finite(c.u) && std::isfinite(c.energy);
}

/// A converged result that is not one: a finding with RODSHAPE_FUZZ_STRICT=1, else counted and
/// reported a few times.
void garbage(const char* what) {
  static int count = 0;
  if (strict()) {
    std::fprintf(stderr, "finding: converged, but %s\n", what);
    std::abort();
  }
  if (++count <= 3) {
    std::fprintf(stderr,
                 "note: converged, but %s (known; RODSHAPE_FUZZ_STRICT=1 makes it a finding)\n",
                 what);
  }
}

void run(const std::string& text) {
  EquilibriumTask task = parse_equilibrium_task(text, "fuzz.yaml");
  if (task.rod.intervals > kMaxIntervals) return;
  ShootingOptions options = task.options;
  options.max_iterations = std::min(options.max_iterations, kMaxIterations);
  options.max_continuation_steps = std::min(options.max_continuation_steps, kMaxContinuationSteps);
  const bool held = !std::holds_alternative<FreeTip>(task.tip);
  options.output_derivatives = held ? Derivatives::AllNodes : Derivatives::None;

  const ShootingResult solution =
      solve_equilibrium(task.rod, task.tip, task.initial_wrench, options);
  std::optional<StabilityResult> stability;
  if (solution.summary.converged()) {
    if (!finite(solution.configuration))
      garbage("the configuration is not finite");
    else if (!(solution.summary.residual_norm <= options.residual_tolerance))
      garbage("the residual is above the tolerance");
    if (held) stability = assess_stability(task.rod, solution.configuration);
  }
  (void)equilibrium_result_json(solution, stability, task.rod);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    run(std::string(reinterpret_cast<const char*>(data), size));
  } catch (const InputError&) {
    // bad input, said as such
  } catch (const std::exception& error) {
    std::fprintf(stderr, "finding: threw something else than InputError: %s\n", error.what());
    std::abort();
  }
  return 0;
}
