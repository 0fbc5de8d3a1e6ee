#!/usr/bin/env bash
# The full sweep of random reachable targets for two arms (tests/trajectory/test_random_two_arm.cpp,
# issue 21's goal): 1000 seeded cases in the cell of examples/plan_two_pandas.yaml (the rubber band
# held from above at both ends by two Pandas facing each other 0.8 m apart; the file's problem and
# options, 7 steps). Case k (std::mt19937 seeded 21000 + k) draws a stable equilibrium of the band:
# its base moved up to 5 cm and turned up to 0.3 rad from the initial pose, bent by 30-150 degrees
# with twist by a random base wrench, both end-effector poses with an IK solution for their arm;
# its objective points are 6-10 points of it at equal arc lengths, both ends among them.
# Goal: both arms have IK at every sample (ArmPlanStatus reachable) in >= 99.5 % of the plans; the
# test fails when the failures reject that at the 5 % level (binomial: at most 9 of 1000). Prints
# every case (seed, plan status, both arms' status, samples, reach, time), then the counts (IK at
# every sample, complete), the 95 % upper bound on the failure rate, the median and worst time, and
# every plan without IK at every sample or not complete with its plan's and both arms' messages.
# CI runs 16 cases in the suite (RODSHAPE_TWO_ARM_CASES unset).
# Usage: bash scripts/two_arm_sweep.sh [cases [first]]   (after bash scripts/test.sh has built build/)
#   e.g. nice bash scripts/two_arm_sweep.sh 1000 > two_arm_sweep.log 2>&1 &   (about 1 s a case)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
RODSHAPE_TWO_ARM_CASES="${1:-1000}" RODSHAPE_TWO_ARM_FIRST="${2:-0}" build/tests/rodshape_tests_trajectory \
  --gtest_filter='RandomTwoArmTargets.*' 2>&1 | grep -vE "^\[ +(RUN|OK) |^\[-|^\[=|^Note|^Running"
