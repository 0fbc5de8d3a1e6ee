"""Errors from Python name what is wrong, as the command line's do (issue 24, item 7).

Environment as test_rodshape.py: PYTHONPATH holds build/python, RODSHAPE_SOURCE_DIR the source
tree."""
import os
from pathlib import Path

import numpy as np
import pytest

import rodshape

SOURCE = Path(os.environ.get("RODSHAPE_SOURCE_DIR", Path(__file__).resolve().parents[2]))
EXAMPLES = SOURCE / "examples"


def test_a_bytes_path_is_said_as_a_path():
    missing = os.fsencode(str(SOURCE / "no_such_task.yaml"))
    with pytest.raises(rodshape.InputError) as raised:
        rodshape.load_task(missing)
    assert "b'" not in str(raised.value)
    assert str(raised.value).startswith(str(SOURCE / "no_such_task.yaml") + ": cannot read")
    task = rodshape.load_task(os.fsencode(str(EXAMPLES / "rubber_band.yaml")))
    assert task.source == str(EXAMPLES / "rubber_band.yaml")


def test_a_path_of_the_wrong_type_is_a_type_error():
    for wrong in (123, None, 1.5, ["examples/rubber_band.yaml"]):
        with pytest.raises(TypeError, match="path must be a str, bytes or os.PathLike"):
            rodshape.load_task(wrong)


def test_integrate_refuses_a_wrench_that_is_not_finite():
    rod = rodshape.rubber_band(intervals=20)
    with pytest.raises(rodshape.InputError, match=r"^base_wrench.force\[1\] = nan must be finite"):
        rodshape.integrate(rod, rodshape.Wrench(force=[0.0, float("nan"), 0.0]))
    with pytest.raises(rodshape.InputError, match=r"^base_wrench.moment"):
        rodshape.integrate(rod, rodshape.Wrench(moment=[float("inf"), 0.0, 0.0]))
    rod.intervals = 0
    with pytest.raises(rodshape.InputError, match="^ClampedRod.intervals"):
        rodshape.integrate(rod)


def test_a_setter_given_the_wrong_type_names_the_field():
    rod = rodshape.rubber_band(intervals=20)
    with pytest.raises(TypeError, match=r"^ClampedRod.intervals = 'ten': expected int, got str"):
        rod.intervals = "ten"
    options = rodshape.PlanOptions()
    with pytest.raises(TypeError, match=r"^PlanOptions.steps = \[1, 2\]: expected int, got list"):
        options.steps = [1, 2]
    plant = rodshape.load_task(str(EXAMPLES / "plan_c_arc.yaml")).plant
    with pytest.raises(TypeError, match=r"^PlantModel.stiffness_scale = 'x'"):
        plant.stiffness_scale = "x"
    rod.intervals = 30  # the right type still sets it
    assert rod.intervals == 30


def test_a_value_set_in_code_is_not_reported_against_the_files_line():
    path = str(EXAMPLES / "plan_c_arc.yaml")
    task = rodshape.load_task(path)
    task.options.steps = 0
    with pytest.raises(rodshape.InputError) as raised:
        rodshape.plan(task)
    message = str(raised.value)
    assert message.startswith(path + ": trajectory.steps = 0 must be >= 1"), message
    assert "changed in code" in message
    # A task not changed in code keeps the file's line (the CLI's message).
    untouched = rodshape.load_task(path)
    assert rodshape.plan(untouched).status == "complete"


def test_plot_input_error_is_the_packages():
    from rodshape import plot
    assert plot.InputError is rodshape.InputError
    with pytest.raises(rodshape.InputError, match="cannot read"):
        plot.plan_directory_figures(SOURCE / "no_such_directory")
