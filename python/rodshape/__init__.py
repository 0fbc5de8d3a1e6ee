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
import difflib
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
    text = " ".join(repr(value).split())  # one line: a numpy array's repr has several
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


# ---- misspelt attributes -------------------------------------------------------------------------
# The task classes take dynamic attributes (the package's own, such as _changed_in_code): without a
# check `task.optionz = ...` or `task.rod.intervalls = 5` would be taken and change nothing.

def _attribute_names(owner):
    return sorted(name for name in dir(owner) if not name.startswith("_"))


def _checked_setattr(owner):
    """owner.__setattr__, refusing a public name the class does not have: AttributeError naming the
    nearest attribute. Names starting with '_' are the package's own and pass."""
    assign = owner.__setattr__

    def __setattr__(self, name, value):
        if not name.startswith("_") and not hasattr(type(self), name):
            names = _attribute_names(type(self))
            nearest = difflib.get_close_matches(name, names, n=1, cutoff=0.6)
            hint = (f"did you mean '{nearest[0]}'?" if nearest else
                    "its attributes are " + ", ".join(names))
            raise AttributeError(f"{type(self).__name__} has no attribute '{name}': {hint}")
        assign(self, name, value)
    return __setattr__


def _refuse_misspelt_attributes(module):
    for owner in vars(module).values():
        if isinstance(owner, type) and owner.__module__ == module.__name__:
            owner.__setattr__ = _checked_setattr(owner)


_refuse_misspelt_attributes(_rodshape)


# ---- a plan's task -------------------------------------------------------------------------------
# plan.task is a copy of the task the plan answers, read-only: assigning it, or a part of it, would
# change neither the plan nor the task it was made from.

def _read_only_task(prop):
    def fget(self):
        task = prop.fget(self)  # a copy (bind_io.cpp)
        task._read_only = True
        return task

    def fset(self, value):
        raise AttributeError("Plan.task is read-only: it is a copy of the task the plan answers; "
                             "to plan another task, change your task and call "
                             "rodshape.plan(task) again")
    return property(fget, fset, None, prop.__doc__)


_rodshape.Plan.task = _read_only_task(vars(_rodshape.Plan)["task"])


def _refuse_on_read_only(owner):
    assign = owner.__setattr__

    def __setattr__(self, name, value):
        if not name.startswith("_") and getattr(self, "_read_only", False):
            raise AttributeError(f"plan.task.{name}: plan.task is a read-only copy of the task "
                                 f"the plan answers (changing it changes nothing); change your "
                                 f"task and call rodshape.plan(task) again")
        assign(self, name, value)
    owner.__setattr__ = __setattr__


_refuse_on_read_only(_rodshape.PlanTask)


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
