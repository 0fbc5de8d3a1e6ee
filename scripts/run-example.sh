#!/usr/bin/env bash
# Installs the Debian packages rodshape needs, builds it (Release) into build/ and runs the bundled
# examples of the paper's rubber band: its equilibrium clamped at both ends
# (examples/rubber_band.yaml → out/rubber_band.json), then the main job, a plan that bends it into an
# S in seven optimal steps (examples/plan_s_curve.yaml → out/plan_s_curve/: plan.json,
# trajectory.csv, plan.svg, plan.html). One summary line each.
# Usage: bash scripts/run-example.sh       (as root, or with sudo available)
# RODSHAPE_JOBS sets the number of parallel compile jobs (default 2).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

jobs="${RODSHAPE_JOBS:-2}"

bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j "$jobs" --target rodshape_cli

mkdir -p out
status=0
build/rodshape equilibrium examples/rubber_band.yaml -o out/rubber_band.json || status=$?

# Exit code 3 (not converged) still writes the whole result; 2 (bad input) writes nothing.
if [ "$status" -eq 0 ] || [ "$status" -eq 3 ]; then
  python3 - out/rubber_band.json <<'PY'
import json, sys
with open(sys.argv[1]) as f:
    r = json.load(f)
stable = {True: "true", False: "false", None: "n/a"}[r["stable"]]
residual = "n/a" if r["residual"] is None else f"{r['residual']:.3g}"
energy = "n/a" if r["energy"] is None else f"{r['energy']:.6g} J"
print(f"rubber_band: status={r['status']} residual={residual} energy={energy} stable={stable} "
      f"(full result: {sys.argv[1]})")
PY
fi
[ "$status" -eq 0 ] || exit "$status"

build/rodshape plan examples/plan_s_curve.yaml -o out/plan_s_curve
