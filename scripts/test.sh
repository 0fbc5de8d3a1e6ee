#!/usr/bin/env bash
# Installs the Debian packages rodshape needs, builds the library, the command-line tool, the tests
# and the benchmarks (Release) into build/, and runs the tests with CTest.
# Usage: bash scripts/test.sh              (as root, or with sudo available)
# RODSHAPE_JOBS sets the number of parallel compile and test jobs (default 2).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

jobs="${RODSHAPE_JOBS:-2}"

bash scripts/install-deps.sh
# The test programs and the library in batches of 8 files (RODSHAPE_UNITY_TESTS,
# RODSHAPE_UNITY_LIBRARY): the tests' compile took 949 CPU-s file by file, about half of the build,
# and the library's 1003 CPU-s file by file against 480 in batches (the whole build 830 s -> 655 s
# on 2 cores; BENCHMARKS.md, "CI's compile"). A plain `cmake -S . -B build`, the developer's build,
# compiles file by file, which catches a file missing an #include before it is committed.
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DRODSHAPE_BUILD_TESTS=ON -DRODSHAPE_UNITY_TESTS=ON \
  -DRODSHAPE_UNITY_LIBRARY=ON
cmake --build build -j "$jobs"
ctest --test-dir build --output-on-failure -j "$jobs"
