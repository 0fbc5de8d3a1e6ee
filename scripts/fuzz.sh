#!/usr/bin/env bash
# Builds the libFuzzer targets (fuzz/) with clang, AddressSanitizer and UndefinedBehaviorSanitizer
# into build-fuzz/ and runs each for a bounded time, all at once.
#   fuzz_task_reader   parse_equilibrium_task and parse_plan_task on arbitrary bytes
#   fuzz_equilibrium   parse, solve (capped iterations), stability, JSON
#   fuzz_cloud_reader  the PLY, PCD and CSV cloud readers on arbitrary bytes
# Usage: bash scripts/fuzz.sh [SECONDS]     (per target; default 60)
# Environment:
#   RODSHAPE_FUZZ_SECONDS  seconds per target when no argument is given (default 60)
#   RODSHAPE_FUZZ_STRICT=1 a converged solve with a non-finite configuration (or a residual above the
#                          tolerance) is a finding too (known numeric findings: fuzz/findings/)
#   RODSHAPE_JOBS          parallel compile jobs (default 2)
#   RODSHAPE_FUZZ_BUILD    the build directory (default build-fuzz). One already configured with
#                          clang and RODSHAPE_BUILD_FUZZ=ON is used as it is (its targets built, not
#                          configured again): .ci/run's sanitizer build, whose tests share the library
# Needs clang++ and libclang-rt-14-dev (libFuzzer). The corpus grows in build-fuzz/corpus/<target>/
# (seeded from examples/*.yaml and fuzz/regressions/; the cloud reader's from fuzz/seeds/cloud/); a finding's reproducer is written to build-fuzz/findings/<target>/
# and the script exits 1. Reproduce one with: (cd examples && ../build-fuzz/fuzz/<target> FILE)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
root="$PWD"

seconds="${1:-${RODSHAPE_FUZZ_SECONDS:-60}}"
jobs="${RODSHAPE_JOBS:-2}"
build="${RODSHAPE_FUZZ_BUILD:-$root/build-fuzz}"
case "$build" in /*) ;; *) build="$root/$build" ;; esac
targets=(fuzz_task_reader fuzz_equilibrium fuzz_cloud_reader)

# -O1 with line tables, as libFuzzer recommends; assertions on.
mkdir -p "$build"
if ! grep -qs '^RODSHAPE_BUILD_FUZZ:BOOL=ON' "$build/CMakeCache.txt"; then
  cmake -S . -B "$build" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only" \
    -DRODSHAPE_BUILD_FUZZ=ON -DRODSHAPE_BUILD_TESTS=OFF -DRODSHAPE_BUILD_BENCH=OFF \
    -DRODSHAPE_BUILD_CLI=OFF -DRODSHAPE_UNITY_LIBRARY=ON > "$build/configure.log" 2>&1 ||
    { cat "$build/configure.log"; exit 1; }
fi
cmake --build "$build" -j "$jobs" --target "${targets[@]}"

export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1"
export LSAN_OPTIONS="suppressions=$root/.ci/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"

pids=()
for target in "${targets[@]}"; do
  corpus="$build/corpus/$target"
  findings="$build/findings/$target"
  mkdir -p "$corpus" "$findings"
  if [ "$target" = fuzz_cloud_reader ]; then
    cp "$root"/fuzz/seeds/cloud/* "$corpus"/
  else
    cp "$root"/examples/*.yaml "$root"/fuzz/regressions/* "$corpus"/
  fi
  # In examples/, the seeds' relative robot.urdf paths lead to data/robots/. No standard input.
  (cd "$root/examples" && exec "$build/fuzz/$target" -max_total_time="$seconds" \
    -rss_limit_mb=2048 -timeout=10 -max_len=16384 -print_final_stats=1 \
    -artifact_prefix="$findings/" "$corpus" < /dev/null > "$build/$target.log" 2>&1) &
  pids+=($!)
done

status=0
for k in "${!targets[@]}"; do
  target="${targets[$k]}"
  rc=0
  wait "${pids[$k]}" || rc=$?
  echo "---- $target (exit $rc): $(grep -c . "$build/$target.log") lines of log in $build/$target.log"
  grep -E '^(stat::number_of_executed_units|stat::peak_rss_mb|note:|finding:)|Done [0-9]+ runs|ERROR|SUMMARY' \
    "$build/$target.log" | sort | uniq -c | sed 's/^ *//' || true
  if [ "$rc" -ne 0 ]; then
    echo "error: $target found a problem (reproducer in $build/findings/$target/):" >&2
    tail -n 40 "$build/$target.log" >&2
    status=1
  fi
done
exit "$status"
