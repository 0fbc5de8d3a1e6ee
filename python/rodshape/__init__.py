"""rodshape: plan how a robot bends a deformable linear object (a static Cosserat rod) gently into
a wanted shape, and check the plan in simulation.

    import rodshape
    task = rodshape.load_task("examples/plan_c_arc.yaml")
    plan = rodshape.plan(task)              # as `rodshape plan`
    print(plan.brief(), plan.steps[-1].configuration.positions.shape)
    plan.write("out/c_arc")                 # plan.json, trajectory.csv, plan.svg

Arrays are numpy float64 in SI units: positions (N+1, 3), rotations (N+1, 3, 3), wrenches (3,).
Bad input raises rodshape.InputError (a ValueError) with the library's one-line message.
"""
import re

from ._rodshape import *  # noqa: F401,F403
from ._rodshape import (InputError, __version__, read_equilibrium_task,  # noqa: F401
                        read_plan_task)

_TASK_CAP = 1 << 20  # bytes: the task reader's cap (docs/limits.md); it says so beyond


def load_task(path):
    """An equilibrium task or a plan task (one with a top-level `target`) read from a YAML file,
    with the same checks and messages as the command line."""
    try:
        with open(path, "rb") as f:
            head = f.read(_TASK_CAP + 1).decode("utf-8", errors="replace")
    except OSError:
        return read_equilibrium_task(str(path))  # the reader says what is wrong, in its words
    if re.search(r"^target\s*:", head, re.MULTILINE):
        return read_plan_task(str(path))
    return read_equilibrium_task(str(path))
