"""A misspelt attribute is not taken, and a plan's task is read-only (issue 43): `task.optionz = 3`
was silently stored on the task (its classes take dynamic attributes) and changed nothing.

Environment as test_rodshape.py: PYTHONPATH holds build/python, RODSHAPE_SOURCE_DIR the source
tree."""
import os
from pathlib import Path

import numpy as np
import pytest

import rodshape

SOURCE = Path(os.environ.get("RODSHAPE_SOURCE_DIR", Path(__file__).resolve().parents[2]))
EXAMPLES = SOURCE / "examples"


def test_a_misspelt_attribute_names_the_nearest():
    task = rodshape.load_task(str(EXAMPLES / "plan_c_arc.yaml"))
    with pytest.raises(AttributeError,
                       match=r"^PlanTask has no attribute 'optionz': did you mean 'options'\?$"):
        task.optionz = task.options
    with pytest.raises(AttributeError,
                       match=r"^ClampedRod has no attribute 'intervalls': did you mean "
                             r"'intervals'\?$"):
        task.rod.intervalls = 5
    equilibrium = rodshape.load_task(str(EXAMPLES / "rubber_band.yaml"))
    with pytest.raises(AttributeError, match=r"^EquilibriumTask has no attribute 'rood'"):
        equilibrium.rood = equilibrium.rod
    with pytest.raises(AttributeError, match=r"its attributes are .*\brod\b"):
        equilibrium.zzzzzzzz = 1
    assert not hasattr(task, "optionz") and not hasattr(equilibrium, "rood")
    # The right names still work, and so does the package's mark of a task changed in code.
    task.rod.intervals = 40
    assert task.problem.rod.intervals == 40
    assert task._changed_in_code


def test_a_plans_task_is_a_read_only_copy():
    task = rodshape.load_task(str(EXAMPLES / "plan_c_arc.yaml"))
    task.options.steps = 1
    plan = rodshape.plan(task)
    with pytest.raises(AttributeError, match=r"^Plan.task is read-only: .*rodshape.plan\(task\)"):
        plan.task = task
    with pytest.raises(AttributeError, match=r"^plan.task.options: plan.task is a read-only copy"):
        plan.task.options = task.options
    copy = plan.task
    copy.problem.rod.intervals = 7  # the copy's: the plan's task is unchanged
    assert plan.task.problem.rod.intervals == task.problem.rod.intervals
    assert plan.task.source == task.source


def test_a_setters_type_error_is_one_line():
    rod = rodshape.rubber_band(intervals=20)
    with pytest.raises(TypeError) as raised:
        rod.intervals = np.zeros((4, 4))
    assert "\n" not in str(raised.value), str(raised.value)
    assert str(raised.value).startswith("ClampedRod.intervals = array([[0., 0., 0., 0.], [0.")
