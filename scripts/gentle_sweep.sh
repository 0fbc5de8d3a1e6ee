#!/usr/bin/env bash
# The full sweep of random stable targets (tests/trajectory/test_random_gentle.cpp, issue 25): 512
# seeded cases (the band and the nylon cable, with and without gravity, 3D bends of 90-170 degrees
# with twist and helices of 0.5-1.2 turns; each target the equilibrium a gentle continuation from
# rest reaches). >= 99 % must be planned complete, reach the points and be followed within
# 1.1 x the larger end energy (tracked and independently replayed); the others are printed with
# their ratios. Prints every case, the count, the median and the worst time. CI runs 8 cases in the
# suite.
# Usage: bash scripts/gentle_sweep.sh [cases [first]]     (after bash scripts/test.sh has built build/)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
RODSHAPE_GENTLE_CASES="${1:-512}" RODSHAPE_GENTLE_FIRST="${2:-0}" build/tests/rodshape_tests_trajectory \
  --gtest_filter='RandomGentleTargets.*' 2>&1 | grep -vE "^\[ (RUN|       OK) |^\[-|^\[=|^Note|^Running"
