"""Assignments through nested properties take effect (issue 43, round 3): a part of a bound object
(a struct, an Eigen vector, a released-axes array, the obstacle list) is the owner's own member,
never a copy that an assignment silently changes."""
import os
from pathlib import Path

import numpy as np
import pytest

import rodshape

SOURCE = Path(os.environ.get("RODSHAPE_SOURCE_DIR", Path(__file__).resolve().parents[2]))
EXAMPLES = SOURCE / "examples"
PANDA = SOURCE / "data" / "robots" / "panda.urdf"

MOVING_BASE_TASK = """rod:
  length: 0.29
  nodes: 21
  stiffness: {EA: 1280, GA: 427, EIx: 0.04, EIy: 0.04, GJ: 0.028}
base:
  position: [0, 0, 0]
  moving: true
  motion_weight: 0.02
base_grasp:
  base_to_end_effector: {position: [0, 0, -0.03]}
target:
  points: [[0.01, 0, 0.1], [0.05, 0, 0.2], [0.1, 0, 0.25]]
trajectory:
  steps: 3
  base_end_effector: {max_linear_speed: 0.05}
"""


def c_arc():
    return rodshape.load_task(str(EXAMPLES / "plan_c_arc.yaml"))


def ball_and_table():
    return [rodshape.Obstacle(rodshape.SphereObstacle([0.12, 0.0, 0.2], 0.02), "ball"),
            rodshape.Obstacle(rodshape.HalfSpaceObstacle([0.0, 0.0, -1.0], 0.03), "table")]


def test_task_rod_intervals():
    task = c_arc()
    task.rod.intervals = 40
    assert task.rod.intervals == 40 and task.problem.rod.intervals == 40
    plan = rodshape.plan(task)
    assert plan.status == "complete", plan.result.message
    assert plan.steps[-1].configuration.nodes == 41


def test_scene_obstacles_append():
    task = c_arc()
    scene = task.problem.scene
    scene.rod_radius = 0.5 * np.hypot(0.02, 0.02)
    scene.clearance = 0.005
    scene.obstacles.append(ball_and_table()[0])
    assert [o.name for o in task.problem.scene.obstacles] == ["ball"]
    plan = rodshape.plan(task)
    assert plan.status == "complete", plan.result.message
    assert plan.scene is not None and plan.scene.obstacle_label == "'ball'"
    assert plan.scene.min_gap >= 0.005 - 1e-9


def test_scene_obstacles_del():
    scene = rodshape.Scene()
    scene.obstacles = ball_and_table()
    problem = c_arc().problem
    problem.scene = scene
    del problem.scene.obstacles[1]
    assert [o.name for o in problem.scene.obstacles] == ["ball"]
    # The clamp at the origin is inside a table put at z > -0.03: only without it is the problem
    # good input.
    problem.scene.obstacles.append(
        rodshape.Obstacle(rodshape.HalfSpaceObstacle([0.0, 0.0, 1.0], -0.01), "floor"))
    with pytest.raises(rodshape.InputError, match="floor"):
        problem.validate()
    del problem.scene.obstacles[1]
    problem.validate()
    assert len(problem.scene.obstacles) == 1


def test_world_T_base_position():
    task = rodshape.load_task(str(EXAMPLES / "plan_panda_s_curve.yaml"))
    task.problem.world_T_base.position = [-5.0, 0.0, -0.2]
    assert np.allclose(task.problem.world_T_base.position, [-5.0, 0.0, -0.2])
    task.problem.world_T_base.position[1] = 0.5
    assert np.allclose(task.problem.world_T_base.position, [-5.0, 0.5, -0.2])
    with pytest.raises(rodshape.InputError, match=r"arm's wrist would be 5\.0\d* m from its"):
        rodshape.plan(task)  # the arm 5 m away: the new placement is the plan's
    # Without an arm there is no placement to change: said, not a copy.
    with pytest.raises(rodshape.InputError, match="set PlanProblem.arm first"):
        c_arc().problem.world_T_base.position = [1.0, 0.0, 0.0]


def test_base_world_T_base_position(tmp_path):
    path = tmp_path / "moving.yaml"
    path.write_text(MOVING_BASE_TASK +
                    f"base_robot:\n  urdf: {PANDA}\n  base: {{position: [-0.5, 0, 0]}}\n")
    task = rodshape.read_plan_task(str(path))
    task.problem.base_world_T_base.position = [-5.0, 0.0, 0.0]
    assert np.allclose(task.problem.base_world_T_base.position, [-5.0, 0.0, 0.0])
    with pytest.raises(rodshape.InputError, match=r"base arm's wrist would be 5\.0\d* m from"):
        rodshape.plan(task)  # the base arm 5 m away: the new placement is the plan's
    with pytest.raises(rodshape.InputError, match="set PlanProblem.base_arm first"):
        c_arc().problem.base_world_T_base.position = [1.0, 0.0, 0.0]


def test_released_axis():
    # A grasp's released axes: the tip held twisted by 0.5 rad about its axis carries a twisting
    # moment, none once m_z is released.
    rod = rodshape.rubber_band(intervals=50)
    turn = np.array([[np.cos(0.5), -np.sin(0.5), 0.0], [np.sin(0.5), np.cos(0.5), 0.0],
                     [0.0, 0.0, 1.0]])
    tip = rodshape.GraspedTip(rodshape.Pose([0.0, 0.0, 0.28], turn), [False] * 6)
    held = rodshape.solve_equilibrium(rod, tip)
    assert held.converged() and abs(held.configuration.moments[-1][2]) > 1e-3
    tip.released[5] = True
    assert list(tip.released) == [False] * 5 + [True]
    free = rodshape.solve_equilibrium(rod, tip)
    assert free.converged() and abs(free.configuration.moments[-1][2]) < 1e-9
    problem = c_arc().problem
    problem.released[5] = True
    assert list(problem.released) == [False] * 5 + [True]
    base = rodshape.MovingBase()
    base.released[5] = True
    problem.moving_base = base
    problem.moving_base.released[4] = True
    assert list(problem.moving_base.released) == [False] * 4 + [True, True]


def test_moving_base_base_to_end_effector_position(tmp_path):
    path = tmp_path / "moving.yaml"
    path.write_text(MOVING_BASE_TASK)
    task = rodshape.read_plan_task(str(path))
    task.problem.moving_base.base_to_end_effector.position = [0.0, 0.0, -0.05]
    assert np.allclose(task.problem.moving_base.base_to_end_effector.position, [0.0, 0.0, -0.05])
    plan = rodshape.plan(task)
    assert plan.status == "complete", plan.result.message
    for step in plan.steps:  # the base gripper's pose is world_T_base · base_T_ee
        base = step.base_pose
        offset = step.base_end_effector.position - base.position
        assert np.allclose(base.rotation.T @ offset, [0.0, 0.0, -0.05], atol=1e-12)


def closed_loop_task():
    task = c_arc()
    task.plant.stiffness_scale = 0.85
    task.plant.gravity = [0.0, 0.0, -9.81]
    return task


def test_closed_loop_gravity():
    task = closed_loop_task()
    assert task.closed_loop.gravity is None
    task.closed_loop.gravity = [0.0, 0.0, -9.81]
    assert np.allclose(task.closed_loop.gravity, [0.0, 0.0, -9.81])
    task.closed_loop.gravity[2] = -9.8
    assert task.closed_loop.gravity[2] == -9.8
    run = rodshape.validate(task, closed_loop=True).runs[0]
    assert run.checkpoints and all(c.estimate.load_factor_sigma > 0 for c in run.checkpoints)
    task.closed_loop.gravity = None
    run = rodshape.validate(task, closed_loop=True).runs[0]
    assert all(c.estimate.load_factor_sigma == 0 for c in run.checkpoints)


def test_closed_loop_estimate_stiffness():
    task = closed_loop_task()
    assert task.closed_loop.estimate_stiffness is False
    task.closed_loop.estimate_stiffness = True
    assert task.closed_loop.estimate_stiffness is True
    run = rodshape.validate(task, closed_loop=True).runs[0]
    assert run.checkpoints and all(c.estimate.stiffness_sigma > 0 for c in run.checkpoints)


def test_the_other_parts_are_the_owners_too():
    # The same design everywhere: an Eigen member is a writable view, a struct a reference.
    rod = rodshape.rubber_band(intervals=20)
    rod.clamp.position[0] = 0.01
    rod.properties.K_rot[1] = 0.08
    rod.load.force[2] = -0.1
    assert rod.clamp.position[0] == 0.01 and rod.properties.K_rot[1] == 0.08
    assert rod.load.force[2] == -0.1
    assert rodshape.integrate(rod).positions[0][0] == 0.01
    problem = c_arc().problem
    problem.moving_base = rodshape.MovingBase()
    problem.moving_base.wrench_lower[0] = -2.0
    assert problem.moving_base.wrench_lower[0] == -2.0
    scene = problem.scene
    scene.obstacles = ball_and_table()
    scene.obstacles[0].shape.center[0] = 0.5
    scene.obstacles[1].name = "floor"
    assert problem.scene.obstacles[0].shape.center[0] == 0.5
    assert problem.scene.obstacles[1].name == "floor"
    plant = c_arc().plant
    plant.rest_curvature = [0.0, 0.0, 0.0]
    plant.rest_curvature[0] = 0.5
    assert plant.rest_curvature[0] == 0.5
    # Copies are read-only, never silently changed: assign the whole array.
    target = problem.target
    with pytest.raises(ValueError, match="read-only"):
        target.points[0, 0] = 1.0
    with pytest.raises(ValueError, match="read-only"):
        c_arc().target_points[0, 0] = 1.0
    points = target.points.copy()
    points[0, 0] = 1.0
    target.points = points
    assert problem.target.points[0, 0] == 1.0
