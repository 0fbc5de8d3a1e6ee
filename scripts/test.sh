#!/usr/bin/env bash
# Installs the Debian packages rodshape needs, builds the library, the command-line tool, the tests
# and the benchmarks (Release) into build/, and runs the tests with CTest.
# Usage: bash scripts/test.sh              (as root, or with sudo available)
# RODSHAPE_JOBS sets the number of parallel compile and test jobs (default 2).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

jobs="${RODSHAPE_JOBS:-2}"

bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DRODSHAPE_BUILD_TESTS=ON
cmake --build build -j "$jobs"
ctest --test-dir build --output-on-failure -j "$jobs"
