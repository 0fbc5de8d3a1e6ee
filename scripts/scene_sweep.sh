#!/usr/bin/env bash
# The full sweep of random scenes (tests/trajectory/test_random_scenes.cpp): 200 seeded cases, half
# with obstacles beside the way a plan without them takes (a plan must exist), half with one
# across it; >= 99 % of all must complete, the others be reported; every complete plan is re-solved
# independently and kept clear. Prints the counts, the median and the worst time. CI runs 8 cases in the suite.
# Usage: bash scripts/scene_sweep.sh [cases [first]]     (after bash scripts/test.sh has built build/)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
RODSHAPE_SCENE_CASES="${1:-200}" RODSHAPE_SCENE_FIRST="${2:-0}" build/tests/rodshape_tests_trajectory \
  --gtest_filter='RandomScenes.*' 2>&1 | grep -vE "^\[ (RUN|       OK) |^\[-|^\[=|^Note|^Running"
