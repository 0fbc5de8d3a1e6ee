"""rodshape.estimate(task, points): the bundled band's cloud as an (n, 3) array gives what
`rodshape estimate` writes; bad arrays are InputErrors naming `points`."""
import json
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

import rodshape

SOURCE = Path(os.environ.get("RODSHAPE_SOURCE_DIR", Path(__file__).resolve().parents[2]))
CLI = os.environ.get("RODSHAPE_CLI", str(SOURCE / "build" / "rodshape"))
TASK = SOURCE / "examples" / "estimate_band.yaml"
CLOUD = SOURCE / "examples" / "clouds" / "estimate_band.ply"


def ply_points(path):
    lines = path.read_text().splitlines()
    body = lines[lines.index("end_header") + 1:]
    return np.array([[float(v) for v in line.split()] for line in body])


def test_estimate_is_the_command_lines():
    task = rodshape.load_task(TASK)
    assert task.kind == "estimate"
    points = ply_points(CLOUD)
    assert points.shape == (500, 3)
    result = rodshape.estimate(task, points)
    assert result.explained, result.unexplained
    e = result.estimate
    assert e.status == "converged" and e.points == 500 and 30 <= e.outliers <= 60
    assert e.configuration.positions.shape == (51, 3)
    ours = json.loads(result.to_json())
    theirs = json.loads(subprocess.run([CLI, "estimate", str(TASK), "--cloud", str(CLOUD)],
                                       check=True, capture_output=True, text=True).stdout)
    assert ours == theirs


def test_bad_points_name_the_field():
    task = rodshape.load_task(TASK)
    with pytest.raises(rodshape.InputError, match="points: expected an"):
        rodshape.estimate(task, np.zeros((4, 2)))
    bad = np.zeros((3, 3))
    bad[1, 2] = np.nan
    with pytest.raises(rodshape.InputError, match=r"points\[1\] is not finite"):
        rodshape.estimate(task, bad)


def test_an_empty_cloud_is_not_explained():
    result = rodshape.estimate(rodshape.load_task(TASK), np.zeros((0, 3)))
    assert not result.explained
    assert result.estimate.status == "not_run"
    assert "nothing was measured" in result.unexplained
