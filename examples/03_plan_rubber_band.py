"""03_plan_rubber_band: the paper's trajectory generation. The band, straight at rest, is to pass
through ten points of an S (examples/plan_s_curve.yaml's target); rodshape.plan_problem makes
n_inter = 7 optimal shapes from the initial one to the target, times the end-effector path through
their tip poses and follows the held rod along it to check that it does not jump. Same as
03_plan_rubber_band.cpp. Usage: 03_plan_rubber_band.py [OUTDIR]  (writes OUTDIR/path.csv and,
with matplotlib, OUTDIR/steps.png)"""
import sys
from pathlib import Path

import numpy as np

import rodshape

target = rodshape.ShapeTarget(
    [[0.004, 0.0, 0.027], [0.016, 0.0, 0.054], [0.032, 0.0, 0.078], [0.051, 0.0, 0.100],
     [0.071, 0.0, 0.121], [0.091, 0.0, 0.142], [0.111, 0.0, 0.163], [0.128, 0.0, 0.187],
     [0.142, 0.0, 0.212], [0.149, 0.0, 0.240]],
    energy_weight=1e-3,  # W1: the tie-breaker between shapes through the points
    distance_weight=1.0)  # W2
problem = rodshape.PlanProblem(rodshape.rubber_band(), target,
                               initial=rodshape.InitialState.rest())
options = rodshape.PlanOptions()
options.steps = 7

result = rodshape.plan_problem(problem, options)
print(result.brief())
for step in result.steps:
    print(f"  step at {step.fraction:.3f}: max distance {step.max_distance * 1e3:.3f} mm, "
          f"energy {step.energy:.4f} J")
if len(sys.argv) > 1:
    out = Path(sys.argv[1])
    path = result.end_effector_path
    np.savetxt(out / "path.csv", np.column_stack([path["t"], path["positions"]]),
               delimiter=",", header="t,x,y,z", comments="", fmt="%.17g")
    import matplotlib
    matplotlib.use("Agg")
    from rodshape import plot
    plot.plan_steps(result).savefig(out / "steps.png", dpi=100)
sys.exit(0 if result.complete() else 3)
