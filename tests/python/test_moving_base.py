"""A moving base in Python (issue 21): PlanProblem.moving_base and base_arm, the task file's
base keys read into them, and PlanResult's base_end_effector_path, base_joints and each step's
base_end_effector."""
import json
import os
from pathlib import Path

import numpy as np
import pytest

import rodshape

SOURCE = Path(os.environ.get("RODSHAPE_SOURCE_DIR", Path(__file__).resolve().parents[2]))
EXAMPLES = SOURCE / "examples"
PANDA = SOURCE / "data" / "robots" / "panda.urdf"

TASK = """rod:
  length: 0.29
  nodes: 21
  stiffness: {EA: 1280, GA: 427, EIx: 0.04, EIy: 0.04, GJ: 0.028}
base:
  position: [0, 0, 0]
  moving: true
  motion_weight: 0.02
base_grasp:
  zero_wrench: [mz]
  base_to_end_effector: {position: [0, 0, -0.03]}
  wrench_bounds:
    lower: {force: [-5, -5, -5]}
target:
  points: [[0.01, 0, 0.1], [0.05, 0, 0.2], [0.1, 0, 0.25]]
trajectory:
  steps: 3
  base_end_effector: {max_linear_speed: 0.05}
"""


def test_moving_base_defaults_and_fields():
    base = rodshape.MovingBase()
    assert base.motion_weight == pytest.approx(1e-3)
    assert list(base.released) == [False] * 6
    assert np.all(np.isinf(base.wrench_lower)) and np.all(base.wrench_lower < 0)
    assert np.all(np.isinf(base.wrench_upper)) and np.all(base.wrench_upper > 0)
    base.released = [False, False, False, False, False, True]
    base.base_to_end_effector = rodshape.Pose(position=[0, 0, -0.03])
    base.wrench_lower = [-1, -2, -3, -4, -5, -6]
    base.motion_weight = 0.5
    assert base.released[5] and not base.released[0]
    assert base.base_to_end_effector.position[2] == pytest.approx(-0.03)
    assert base.wrench_lower[3] == -4
    base.validate()
    base.motion_weight = -1
    with pytest.raises(rodshape.InputError, match="motion_weight"):
        base.validate()


def test_plan_problem_moving_base_and_base_arm():
    task = rodshape.read_plan_task(str(EXAMPLES / "plan_c_arc.yaml"))
    problem = task.problem
    assert problem.moving_base is None and not problem.base_moves()
    assert problem.base_arm is None
    base = rodshape.MovingBase()
    base.motion_weight = 0.1
    problem.moving_base = base
    assert problem.base_moves() and problem.moving_base.motion_weight == pytest.approx(0.1)
    with pytest.raises(rodshape.InputError, match="base_arm first"):
        problem.base_world_T_base = rodshape.Pose(position=[0.5, 0, 0])
    problem.base_arm = rodshape.panda()
    problem.base_world_T_base = rodshape.Pose(position=[-0.5, 0, 0])
    assert isinstance(problem.base_arm, rodshape.ArmModel)
    assert problem.base_world_T_base.position[0] == pytest.approx(-0.5)
    problem.validate()
    # A base arm without a moving base is refused, naming the field.
    problem.moving_base = None
    with pytest.raises(rodshape.InputError, match="base_arm"):
        problem.validate()
    problem.base_arm = None
    assert problem.base_arm is None
    problem.validate()


def test_the_task_files_base_keys(tmp_path):
    path = tmp_path / "moving.yaml"
    path.write_text(TASK + f"base_robot:\n  urdf: {PANDA}\n  base: {{position: [-0.5, 0, 0]}}\n")
    task = rodshape.read_plan_task(str(path))
    base = task.problem.moving_base
    assert base is not None
    assert base.motion_weight == pytest.approx(0.02)
    assert list(base.released) == [False] * 5 + [True]
    assert base.base_to_end_effector.position[2] == pytest.approx(-0.03)
    assert base.wrench_lower[0] == -5 and np.isinf(base.wrench_lower[3])
    assert task.problem.base_arm is not None
    assert isinstance(task.base_arm, rodshape.ArmModel) and task.arm is None
    assert task.problem.base_world_T_base.position[0] == pytest.approx(-0.5)
    assert task.options.base_max_linear_speed == pytest.approx(0.05)
    # Left out, the base gripper's limits are the tip's (here the defaults).
    assert task.options.base_max_angular_speed == pytest.approx(
        rodshape.PlanOptions().base_max_angular_speed)


def test_bad_base_keys_name_the_field(tmp_path):
    path = tmp_path / "bad.yaml"
    path.write_text(TASK.replace("motion_weight: 0.02", "motion_weight: -2"))
    with pytest.raises(rodshape.InputError, match=r"bad.yaml:8: base.motion_weight = -2"):
        rodshape.read_plan_task(str(path))
    path.write_text(TASK.replace("  moving: true\n", ""))
    with pytest.raises(rodshape.InputError, match=r"base.motion_weight needs a moving base"):
        rodshape.read_plan_task(str(path))
    path.write_text(TASK.replace("zero_wrench: [mz]", "zero_wrench: [mq]"))
    with pytest.raises(rodshape.InputError, match=r"bad.yaml:10: base_grasp.zero_wrench\[0\]"):
        rodshape.read_plan_task(str(path))


def test_a_fixed_clamp_plan_has_its_clamp_as_base_end_effector(tmp_path):
    task = rodshape.load_task(str(EXAMPLES / "plan_c_arc.yaml"))
    task.options.steps = 2
    plan = rodshape.plan(task)
    path = plan.result.base_end_effector_path
    assert path["t"].shape == (0,)
    assert path["positions"].shape[0] == 0
    assert plan.result.base_joints is None and plan.result.base_arm_status is None
    for step in plan.steps:
        assert step.base_pose.position.shape == (3,)
        assert step.base_end_effector.position.shape == (3,)
    names = plan.write(str(tmp_path), html=False)
    assert not any(name.startswith("base_") for name in names)
    header = (tmp_path / "trajectory.csv").read_text().splitlines()[0]
    assert header == "t,x,y,z,qw,qx,qy,qz"


def test_the_path_figure_draws_the_base_gripper():
    pytest.importorskip("matplotlib")
    from rodshape import plot
    t = np.linspace(0.0, 1.0, 11)
    tip = np.column_stack([t, t, 0 * t, 0.29 + 0 * t, 1 + 0 * t, 0 * t, 0 * t, 0 * t])
    base = np.column_stack([0 * t, -t, 0 * t, 1 + 0 * t, 0 * t, 0 * t, 0 * t])
    figure = plot.plot_path(np.hstack([tip, base]), [0, 10])
    labels = [line.get_label() for line in figure.axes[0].get_lines()]
    assert "base gripper y" in labels and "x" in labels
    only_tip = plot.plot_path(tip, [0, 10])
    assert not any(label.startswith("base") for label in
                   [line.get_label() for line in only_tip.axes[0].get_lines()])


TWO_PANDAS = """rod:
  length: 0.29
  nodes: 51
  section: {shape: rectangle, width: 0.02, height: 0.02}
  material: {young_modulus: 3.2e6, poisson_ratio: 0.5, density: 1392}
  stiffness: {EIx: 0.04, EIy: 0.04, GJ: 0.028}
base:
  position: [-0.145, 0, 0.35]
  rotation: [[0, 0, 1], [0, 1, 0], [-1, 0, 0]]
  moving: true
base_grasp:
  base_to_end_effector: {position: [0, 0, 0.01], rotation: [[0, 0, 1], [0, -1, 0], [1, 0, 0]]}
grasp:
  tip_to_end_effector: {position: [0, 0, -0.01], rotation: [[0, 0, 1], [0, -1, 0], [1, 0, 0]]}
target:
  points: [[-0.09, 0, 0.37], [0.0, 0, 0.39], [0.09, 0, 0.37]]
trajectory:
  steps: 4
robot:
  urdf: PANDA
  base: {position: [0.4, 0, 0], rotation: [0, 0, 0, 1]}
  flange_to_end_effector: {position: [0, 0, 0.1034]}
base_robot:
  urdf: PANDA
  base: {position: [-0.4, 0, 0]}
  flange_to_end_effector: {position: [0, 0, 0.1034]}
"""


def test_two_pandas_plan_and_its_files(tmp_path):
    path = tmp_path / "two_pandas.yaml"
    path.write_text(TWO_PANDAS.replace("PANDA", str(PANDA)))
    plan = rodshape.plan(rodshape.load_task(str(path)))
    assert plan.status == "complete"
    result = plan.result
    tip, base = result.end_effector_path, result.base_end_effector_path
    assert base["positions"].shape == tip["positions"].shape
    assert np.array_equal(base["t"], tip["t"])  # one clock
    assert result.base_joints.complete() and result.base_arm_status.startswith("reachable")
    assert result.base_joints.q.shape == (len(base["t"]), 7)
    step = plan.steps[-1]
    # The base gripper is the rod's base pose composed with base_T_ee.
    offset = plan.task.problem.moving_base.base_to_end_effector
    expected = step.base_pose.position + step.base_pose.rotation @ offset.position
    assert np.allclose(step.base_end_effector.position, expected, atol=1e-12)
    names = plan.write(str(tmp_path / "out"), html=False)
    assert "base_joint_trajectory.csv" in names and "base_joint_trajectory.json" in names
    header = (tmp_path / "out" / "trajectory.csv").read_text().splitlines()[0]
    assert header == "t,x,y,z,qw,qx,qy,qz,bx,by,bz,bqw,bqx,bqy,bqz"
    document = json.loads(plan.to_json())
    assert document["base_joint_trajectory"]["file"] == "base_joint_trajectory.csv"
    assert document["base_robot"]["status"] == "reachable"
    # At the first sample the two hands are 131.46 mm apart (the initial poses' IK, before any
    # optimisation), so the least gap over the path, rod and other arm both checked, is no larger.
    # Which pair is least depends on the steps' optima in the moving base's flat valley (with the
    # dense KKT solver: the base arm's link 2 and the rod at step 4, 118.96 mm).
    scene = document["scene"]
    assert scene["robot_min_gap_at"]["obstacle"] in ("other_arm", "rod")
    assert scene["robot_clear"] and scene["robot_min_gap"] <= 0.13147


def test_two_pandas_validation_drives_the_base_by_its_arm(tmp_path):
    path = tmp_path / "two_pandas.yaml"
    path.write_text(TWO_PANDAS.replace("PANDA", str(PANDA)))
    validation = rodshape.validate(rodshape.load_task(str(path)))
    assert validation.driven_by_joints and validation.base_driven_by == "base_joint_trajectory"
    assert json.loads(validation.to_json())["base_driven_by"] == "base_joint_trajectory"
    fixed = rodshape.validate(rodshape.load_task(str(EXAMPLES / "plan_c_arc.yaml")))
    assert fixed.base_driven_by is None
    assert "base_driven_by" not in json.loads(fixed.to_json())
