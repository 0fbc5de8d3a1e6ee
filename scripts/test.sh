#!/usr/bin/env bash
# Installs the Debian packages rodshape needs, builds the library, the command-line tool, the tests
# and the benchmarks (Release) into build/, and runs the tests with CTest.
# Usage: bash scripts/test.sh              (as root, or with sudo available)
# RODSHAPE_JOBS sets the number of parallel compile and test jobs (default 2).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

jobs="${RODSHAPE_JOBS:-2}"

bash scripts/install-deps.sh
# The test programs in batches of 8 files (RODSHAPE_UNITY_TESTS): their compile took 949 CPU-s
# file by file, about half of the build (BENCHMARKS.md, "CI's compile", 2026-11-27). A plain
# `cmake -S . -B build` builds them file by file, which also catches a test file missing an #include.
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DRODSHAPE_BUILD_TESTS=ON -DRODSHAPE_UNITY_TESTS=ON
cmake --build build -j "$jobs"
ctest --test-dir build --output-on-failure -j "$jobs"
