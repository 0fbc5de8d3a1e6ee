"""rodshape: plan how a robot bends a deformable linear object (a static Cosserat rod) gently into
a wanted shape, and check the plan in simulation.

    import rodshape
    task = rodshape.load_task("examples/plan_c_arc.yaml")
    plan = rodshape.plan(task)              # as `rodshape plan`
    print(plan.brief(), plan.steps[-1].configuration.positions.shape)
    plan.write("out/c_arc")                 # plan.json, trajectory.csv, plan.svg, plan.html

Arrays are numpy float64 in SI units: positions (N+1, 3), rotations (N+1, 3, 3), wrenches (3,).
Bad input raises rodshape.InputError (a ValueError) with the library's one-line message.
"""
import os
import re
import sys

# Built and tested with Debian's /usr/bin/python3 and its python3-numpy: another python3 first on
# PATH (pyenv, a virtual environment) may lack numpy or not load the compiled module; say so.
try:
    import numpy  # noqa: F401  (the module returns numpy arrays)
    from . import _rodshape
except ImportError as _error:
    raise ImportError(
        f"rodshape: {_error}; this interpreter is {sys.executable} (Python "
        f"{sys.version.split()[0]}). rodshape is built for Debian's /usr/bin/python3 with "
        f"python3-numpy: run /usr/bin/python3 (another python3 may come first on PATH)") from None
from ._rodshape import *  # noqa: F401,F403
from ._rodshape import (InputError, __version__, read_equilibrium_task,  # noqa: F401
                        read_estimate_task, read_plan_task)

_TASK_CAP = 1 << 20  # bytes: the task reader's cap (docs/limits.md); it says so beyond


def load_task(path):
    """An equilibrium task, a plan task (one with a top-level `target`) or an estimate task (an
    equilibrium task with a top-level `sensor`: rodshape.estimate) read from a YAML file, with the
    same checks and messages as the command line. `path` is a str, bytes or os.PathLike
    (else TypeError)."""
    if not isinstance(path, (str, bytes, os.PathLike)):
        raise TypeError(f"load_task: path must be a str, bytes or os.PathLike, "
                        f"not {type(path).__name__}")
    path = os.fsdecode(path)  # bytes as the file system decodes them, not "b'...'"
    try:
        with open(path, "rb") as f:
            head = f.read(_TASK_CAP + 1).decode("utf-8", errors="replace")
    except OSError:
        return read_equilibrium_task(path)  # the reader says what is wrong, in its words
    if re.search(r"^target\s*:", head, re.MULTILINE):
        return read_plan_task(path)
    if re.search(r"^sensor\s*:", head, re.MULTILINE):
        return read_estimate_task(path)
    return read_equilibrium_task(path)


# ---- errors that name the field -----------------------------------------------------------------

def _short_repr(value, limit=60):
    text = repr(value)
    return text if len(text) <= limit else text[:limit - 3] + "..."


def _named_setter(owner, name, fset):
    """fset, whose TypeError (pybind11's "incompatible function arguments") names the field."""
    def setter(self, value):
        try:
            fset(self, value)
        except TypeError as error:
            expected = re.search(r"arg0: (.*?)\) -> None", str(error))
            wanted = expected.group(1) if expected else "another type"
            raise TypeError(f"{owner}.{name} = {_short_repr(value)}: expected {wanted}, "
                            f"got {type(value).__name__}") from None
    return setter


def _name_setter_errors(module):
    """Every settable attribute of the compiled classes raises a TypeError naming it."""
    for owner in vars(module).values():
        if not isinstance(owner, type) or owner.__module__ != module.__name__:
            continue
        for name, attribute in list(vars(owner).items()):
            if isinstance(attribute, property) and attribute.fset is not None:
                setattr(owner, name, property(attribute.fget,
                                              _named_setter(owner.__name__, name, attribute.fset),
                                              attribute.fdel, attribute.__doc__))


_name_setter_errors(_rodshape)


# ---- a task changed in code ----------------------------------------------------------------------
# A task read from a file reports bad input at the file's line. Once a part of it has been taken to
# be changed in code (task.problem, task.options, ...), a bad value may not be the file's: its
# message then names the file without a line and says so.

_TASK_PARTS = {_rodshape.PlanTask: ("rod", "problem", "options", "plant", "sensor", "depth_sensor",
                                         "closed_loop"),
               _rodshape.EquilibriumTask: ("rod", "scene")}


def _marking_access(prop):
    def fget(self):
        self._changed_in_code = True
        return prop.fget(self)

    def fset(self, value):
        self._changed_in_code = True
        prop.fset(self, value)
    return property(fget, fset, prop.fdel, prop.__doc__)


for _owner, _names in _TASK_PARTS.items():
    for _name in _names:
        setattr(_owner, _name, _marking_access(vars(_owner)[_name]))


def _unlocated(error, task):
    """The message of `error` without the file's line when `task` was changed in code."""
    message = str(error)
    if not getattr(task, "_changed_in_code", False):
        return None
    prefix = re.match(re.escape(task.source) + r":\d+: ", message)
    if not prefix:
        return None
    return (f"{task.source}: {message[prefix.end():]} (in the task as changed in code after it "
            f"was read; the file's lines do not apply)")


def _task_call(call):
    def wrapped(task, *args, **kwargs):
        try:
            return call(task, *args, **kwargs)
        except InputError as error:
            message = _unlocated(error, task)
            if message is None:
                raise
            raise InputError(message) from None
    wrapped.__name__, wrapped.__doc__ = call.__name__, call.__doc__
    return wrapped


plan = _task_call(_rodshape.plan)
validate = _task_call(_rodshape.validate)
solve = _task_call(_rodshape.solve)
estimate = _task_call(_rodshape.estimate)
