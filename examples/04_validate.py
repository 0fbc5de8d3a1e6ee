"""04_validate: the plan carried out in simulation, as the paper's experiment was on the robot. The
C-arc task (examples/plan_c_arc.yaml) is planned; the simulated band, 15 % softer than the
planner's, with its weight and a grasp 2 mm off, follows the end-effector path and ten markers are
seen by a noisy camera. Open loop, then closed loop (at each waypoint the state is estimated from
the markers and the rest re-planned). Same as 04_validate.cpp.
Usage: 04_validate.py [OUTDIR]  (run from the source tree; writes the closed loop's plan.json,
validation.json, ... into OUTDIR, as `rodshape validate` does)"""
import sys

import rodshape

task = rodshape.load_task("examples/plan_c_arc.yaml")
task.plant.stiffness_scale = 0.85
task.plant.gravity = [0.0, 0.0, -9.81]
offset = rodshape.Pose(position=[0.002, 0.0, 0.0])
task.plant.grasp_offset = offset

for closed_loop in (False, True):
    v = rodshape.validate(task, runs=2, seed=7, closed_loop=closed_loop)
    if closed_loop is False:
        print(v.plan.brief())
    print(f"{'closed' if closed_loop else 'open'} loop: {v.brief()}")
    for run in v.runs:
        print(f"  seed {run.seed}: final true error {run.final.true_error * 1e3:.3f} mm")
    if v.status != "complete":
        sys.exit(3)
    if closed_loop and len(sys.argv) > 1:
        v.write(sys.argv[1])
