"""pytest suite of the rodshape Python package (run by ctest as python.pytest).

Environment: PYTHONPATH holds build/python; RODSHAPE_CLI is the rodshape executable and
RODSHAPE_SOURCE_DIR the source tree (for the bundled examples)."""
import concurrent.futures
import glob
import json
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

import rodshape

SOURCE = Path(os.environ.get("RODSHAPE_SOURCE_DIR", Path(__file__).resolve().parents[2]))
CLI = os.environ.get("RODSHAPE_CLI", str(SOURCE / "build" / "rodshape"))
EXAMPLES = SOURCE / "examples"


def test_integrate_gives_arrays_of_the_documented_shapes():
    rod = rodshape.rubber_band(intervals=50)
    c = rodshape.integrate(rod, rodshape.Wrench(moment=[0.0, 0.05, 0.0]))
    assert c.positions.shape == (51, 3) and c.positions.dtype == np.float64
    assert c.rotations.shape == (51, 3, 3)
    assert c.s.shape == (51,) and c.s[-1] == pytest.approx(0.29, abs=1e-15)
    assert c.forces.shape == c.moments.shape == c.u.shape == c.v.shape == (51, 3)
    # Every rotation is orthonormal.
    for R in c.rotations:
        assert np.allclose(R.T @ R, np.eye(3), atol=1e-12)


def test_an_end_moment_bends_the_rod_into_an_arc():
    # Analytical oracle: a moment M about y on a Kirchhoff rod gives a circular arc of curvature
    # M / EI; the tip is at (R (1 - cos θ), 0, R sin θ), θ = L / R. RK4 at N = 100: error ~1e-10.
    rod = rodshape.rubber_band(rodshape.ConstitutiveModel.Kirchhoff, 100)
    M, EI, L = 0.05, 0.04, 0.29
    c = rodshape.integrate(rod, rodshape.Wrench(moment=[0.0, M, 0.0]))
    R = EI / M
    theta = L / R
    expected = [R * (1 - np.cos(theta)), 0.0, R * np.sin(theta)]
    assert np.allclose(c.tip.position, expected, atol=1e-9)
    assert c.energy == pytest.approx(0.5 * M * M / EI * L, rel=1e-9)


def test_solve_equilibrium_holds_the_tip_where_asked():
    rod = rodshape.rubber_band()
    pose = rodshape.Pose(position=[0.12, 0.0, 0.22],
                         rotation=[[0, 0, 1], [0, 1, 0], [-1, 0, 0]])
    result = rodshape.solve_equilibrium(rod, rodshape.ClampedTip(pose))
    assert result.converged(), result.brief()
    assert np.allclose(result.configuration.tip.position, [0.12, 0.0, 0.22], atol=1e-9)


def test_bad_input_raises_input_error_with_the_clis_message(tmp_path):
    text = (EXAMPLES / "rubber_band.yaml").read_text().replace("length: 0.29", "lenght: 0.29")
    task = tmp_path / "bad.yaml"
    task.write_text(text)
    with pytest.raises(rodshape.InputError) as raised:
        rodshape.load_task(str(task))
    assert isinstance(raised.value, ValueError)
    cli = subprocess.run([CLI, "equilibrium", str(task)], capture_output=True, text=True)
    assert cli.returncode == 2
    assert cli.stderr.strip() == f"error: {raised.value}"
    assert "rod.lenght: unknown key; did you mean 'length'?" in str(raised.value)


def test_a_non_finite_number_names_its_field(tmp_path):
    text = (EXAMPLES / "rubber_band.yaml").read_text().replace("young_modulus: 3.2e6",
                                                               "young_modulus: .nan")
    task = tmp_path / "nan.yaml"
    task.write_text(text)
    with pytest.raises(rodshape.InputError, match="rod.material.young_modulus"):
        rodshape.load_task(str(task))


def equilibrium_examples():
    return [p for p in sorted(glob.glob(str(EXAMPLES / "*.yaml")))
            if not Path(p).name.startswith(("plan_", "validate_", "estimate_"))]


def plan_examples():
    """The plan tasks: plan_*.yaml, and validate_*.yaml (plan tasks made to be validated)."""
    return sorted(glob.glob(str(EXAMPLES / "plan_*.yaml")) +
                  glob.glob(str(EXAMPLES / "validate_*.yaml")))


@pytest.mark.parametrize("path", equilibrium_examples(), ids=lambda p: Path(p).stem)
def test_solve_writes_the_clis_json(path):
    ours = json.loads(rodshape.solve(rodshape.load_task(path)).to_json())
    cli = subprocess.run([CLI, "equilibrium", path], capture_output=True, text=True, check=True)
    assert_same_numbers(ours, json.loads(cli.stdout))


@pytest.mark.parametrize("path", plan_examples(), ids=lambda p: Path(p).stem)
def test_plan_writes_the_clis_json(path, tmp_path):
    ours = json.loads(rodshape.plan(rodshape.load_task(path)).to_json())
    subprocess.run([CLI, "plan", path, "-o", str(tmp_path), "-q"], check=True)
    assert_same_numbers(ours, json.loads((tmp_path / "plan.json").read_text()))


def assert_same_numbers(a, b, where="$"):
    """Equal structure, strings and booleans; numbers within 1e-12 (relative to max(1, |x|))."""
    assert type(a) is type(b) or (isinstance(a, (int, float)) and isinstance(b, (int, float))), where
    if isinstance(a, dict):
        assert a.keys() == b.keys(), where
        for k in a:
            assert_same_numbers(a[k], b[k], f"{where}.{k}")
    elif isinstance(a, list):
        assert len(a) == len(b), where
        for i, (x, y) in enumerate(zip(a, b)):
            assert_same_numbers(x, y, f"{where}[{i}]")
    elif isinstance(a, float) or isinstance(b, float):
        assert abs(a - b) <= 1e-12 * max(1.0, abs(a)), f"{where}: {a} != {b}"
    else:
        assert a == b, where


def test_plans_in_threads_equal_plans_in_series():
    tasks = [rodshape.load_task(str(EXAMPLES / f"plan_{n}.yaml"))
             for n in ("c_arc", "s_curve", "tip_bend", "partial_hook")]
    serial = [rodshape.plan(t).to_json() for t in tasks]
    with concurrent.futures.ThreadPoolExecutor(max_workers=4) as pool:
        parallel = list(pool.map(lambda t: rodshape.plan(t).to_json(), tasks))
    assert parallel == serial


def test_one_arm_task_planned_from_threads_equals_the_serial_plan():
    # Issue 24 item 1: the threads share the task's arm model (copies of one KDL description); each
    # evaluation must work on its own chain, or results differ (the reach shell off by centimetres).
    task = rodshape.load_task(str(EXAMPLES / "plan_panda_s_curve.yaml"))
    serial = rodshape.plan(task).to_json()
    with concurrent.futures.ThreadPoolExecutor(max_workers=3) as pool:
        parallel = list(pool.map(lambda _: rodshape.plan(task).to_json(), range(6)))
    for result in parallel:
        assert result == serial


def test_plan_result_arrays():
    plan = rodshape.plan(rodshape.load_task(str(EXAMPLES / "plan_c_arc.yaml")))
    assert plan.status == "complete"
    assert len(plan.steps) == 7
    last = plan.steps[-1]
    assert last.configuration.positions.shape == (101, 3)
    assert last.objective_points.shape == (10, 3)
    path = plan.result.end_effector_path
    assert path["positions"].shape == (len(path["t"]), 3)
    assert path["rotations"].shape == (len(path["t"]), 3, 3)
    assert np.all(np.diff(path["t"]) > 0)


def test_the_helix_is_planned_by_the_gentlest_scheme_and_says_so():
    task = rodshape.load_task(str(EXAMPLES / "plan_cable_helix.yaml"))
    assert task.options.interpolation == "auto"
    plan = rodshape.plan(task)
    assert plan.status == "complete"
    used = plan.result.interpolation
    assert used["used"] == "pose"
    assert [t["scheme"] for t in used["tried"]][:2] == ["shape", "pose"]
    assert used["tried"][0]["peak_ratio"] > 1.1 >= used["tried"][1]["peak_ratio"]
    options = task.options
    options.interpolation = "shape"
    assert options.interpolation == "shape"
    with pytest.raises(rodshape.InputError, match="PlanOptions.interpolation"):
        options.interpolation = "spline"


def test_validate_repeats_bit_for_bit_and_writes_the_clis_files(tmp_path):
    task = rodshape.load_task(str(EXAMPLES / "plan_c_arc.yaml"))
    a = rodshape.validate(task, runs=2, seed=5)
    b = rodshape.validate(task, runs=2, seed=5)
    assert a.status == "complete"
    assert not a.driven_by_joints  # no arm: the end-effector path
    assert np.array_equal(a.runs[1].error_3d, b.runs[1].error_3d)
    assert a.runs[0].final.true_error < 1e-3
    names = a.write(str(tmp_path))
    assert "validation.json" in names and "plan.json" in names
    if rodshape.html_unavailable() == "":  # libjs-three installed: the 3D pages too
        assert "plan.html" in names and "validation.html" in names
    names = a.write(str(tmp_path), html=False)
    assert "plan.html" not in names and not (tmp_path / "plan.html").exists()
    assert json.loads((tmp_path / "validation.json").read_text()) == json.loads(a.to_json())


def test_one_gravity_acts_on_the_plant(tmp_path):
    # Issue 24: the plant's gravity was added to the task's, and under the task's gravity the
    # plant's mass per length changed nothing.
    text = (EXAMPLES / "plan_c_arc.yaml").read_text() + "gravity: [0, 0, -9.81]\n"
    path = tmp_path / "heavy.yaml"
    path.write_text(text)
    task = rodshape.load_task(str(path))
    assert np.allclose(task.plant.planner_gravity, [0.0, 0.0, -9.81])
    assert task.plant.gravity is None  # the task's
    weight = task.rod.properties.mass_per_length * np.array([0.0, 0.0, -9.81])
    assert np.allclose(task.plant.real_rod(task.rod).load.force, weight)
    task.plant.gravity = [0.0, 0.0, -9.81]  # given as well: once, not twice
    assert np.allclose(task.plant.real_rod(task.rod).load.force, weight)
    task.plant.mass_per_length = 0.0
    assert np.allclose(task.plant.real_rod(task.rod).load.force, [0.0, 0.0, 0.0])


def test_a_seed_whose_runs_would_wrap_is_bad_input():
    task = rodshape.load_task(str(EXAMPLES / "plan_c_arc.yaml"))
    with pytest.raises(rodshape.InputError, match="would wrap"):
        rodshape.validate(task, runs=2, seed=2**64 - 1)


def test_plot_figures(tmp_path):
    import matplotlib
    matplotlib.use("Agg")
    from rodshape import plot
    plan = rodshape.plan(rodshape.load_task(str(EXAMPLES / "plan_s_curve.yaml")))
    fig = plot.plan_steps(plan)
    assert len(fig.axes) == 1
    fig.savefig(tmp_path / "steps.png")
    validation = rodshape.validate(rodshape.load_task(str(EXAMPLES / "plan_c_arc.yaml")))
    plot.validation_errors(validation).savefig(tmp_path / "errors.png")
    assert (tmp_path / "steps.png").stat().st_size > 1000
    # One scale on the three axes: the planar S-curve keeps a flat axis as wide as the others
    # (autoscaled, y spanned ±3e-14 m and the steps looked like loops).
    ax = fig.axes[0]
    spans = [np.ptp(limits) for limits in (ax.get_xlim(), ax.get_ylim(), ax.get_zlim())]
    assert spans == pytest.approx([spans[0]] * 3) and spans[0] > 0.1


def test_plot_imports_cleanly(monkeypatch):
    # Importing rodshape.plot neither reads nor changes the umask (os.umask(0) then back was a
    # moment of umask 0 for every thread), and saving gives a file open() would.
    import importlib
    import sys
    import matplotlib
    matplotlib.use("Agg")
    sys.modules.pop("rodshape.plot", None)

    def no_umask(mask):
        raise AssertionError("os.umask called")
    monkeypatch.setattr(os, "umask", no_umask)
    plot = importlib.import_module("rodshape.plot")
    assert plot.InputError is rodshape.InputError
    for unused in ("argparse", "sys", "tempfile"):
        assert not hasattr(plot, unused), unused


def test_plot_saves_like_open(tmp_path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from rodshape import plot
    import importlib.util
    assert plot.write_file_atomically is rodshape.write_file_atomically  # the CLI's writer
    # And loaded on its own (scripts/plot_plan.py), without the compiled module: its own writer.
    spec = importlib.util.spec_from_file_location("plot_alone", SOURCE / "python" / "rodshape" / "plot.py")
    alone = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(alone)
    assert alone.write_file_atomically is None
    for module, name in ((plot, "line.png"), (alone, "alone.png")):
        fig, ax = plt.subplots()
        ax.plot([0, 1], [0, 1])
        old = os.umask(0o027)
        try:
            module.save(fig, tmp_path / name)
        finally:
            os.umask(old)
        assert (tmp_path / name).stat().st_mode & 0o777 == 0o640
        assert (tmp_path / name).read_bytes().startswith(b"\x89PNG")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["alone.png", "line.png"]  # no temporary


def test_optimise_shape_passes_through_points_of_a_reachable_shape():
    # Oracle: points taken from an equilibrium the rod can take (a base wrench integrated) are
    # reached by the optimum of the distance term alone (W1 = 0): its distances are 0 up to the
    # smoothing δ = 1e-4 m and IPOPT's tolerance (Σ d²/(2δ) ≤ tol ⇒ d ≲ 1e-6 m).
    rod = rodshape.rubber_band()
    reference = rodshape.integrate(rod, rodshape.Wrench(force=[0.02, 0.0, 0.0],
                                                        moment=[0.0, 0.03, 0.0]))
    points = reference.positions[[25, 50, 75, 100]]
    target = rodshape.ShapeTarget(points, energy_weight=0.0, distance_weight=1.0)
    assert target.points.shape == (4, 3)
    assert rodshape.check_feasibility(target, rod).feasible
    result = rodshape.optimise_shape(rod, target)
    assert result.converged(), result.brief()
    assert result.cost.max_distance < 1e-5
    assert len(result.cost.distances) == 4
    assert result.configuration.positions.shape == (101, 3)


def test_optimise_shape_respects_the_curvature_limit():
    rod = rodshape.rubber_band()
    target = rodshape.ShapeTarget([[0.1, 0.0, 0.1]], energy_weight=1.0, distance_weight=10.0)
    free = rodshape.optimise_shape(rod, target)
    kappa = np.linalg.norm(free.configuration.u, axis=1).max()
    limited = rodshape.optimise_shape(rod, target, max_curvature=0.8 * kappa)
    assert limited.converged(), limited.brief()
    # The limit binds (the free optimum exceeds it) and holds at every node to IPOPT's
    # constraint tolerance (1e-9).
    assert np.linalg.norm(limited.configuration.u, axis=1).max() <= 0.8 * kappa + 1e-8
    with pytest.raises(rodshape.InputError, match="max_curvature"):
        rodshape.optimise_shape(rod, target, max_curvature=-1.0)


def test_arm_jacobian_matches_finite_differences_of_its_kinematics():
    arm = rodshape.panda()
    q = rodshape.panda_ready_pose() + 0.1
    J = arm.jacobian(q)
    assert J.shape == (6, 7)
    h = 1e-6  # central differences: truncation ~h², rounding ~1e-16/h
    for j in range(7):
        dq = np.zeros(7)
        dq[j] = h
        plus, minus = arm.forward_kinematics(q + dq), arm.forward_kinematics(q - dq)
        assert np.allclose((plus.position - minus.position) / (2 * h), J[:3, j], atol=1e-8)
        # ω from dR Rᵀ (skew-symmetric to first order)
        W = (plus.rotation - minus.rotation) / (2 * h) @ arm.forward_kinematics(q).rotation.T
        assert np.allclose([W[2, 1], W[0, 2], W[1, 0]], J[3:, j], atol=1e-8)


def test_the_bundled_fr3_carries_frankas_limits():
    fr3 = rodshape.fr3()
    assert fr3.robot_name == "fr3" and fr3.tip_link == "fr3_link8"
    assert fr3.joint_names == [f"fr3_joint{i}" for i in range(1, 8)]
    assert list(fr3.upper_limits) == [2.7437, 1.7837, 2.9007, -0.1518, 2.8065, 4.5169, 3.0159]
    assert list(fr3.acceleration_limits) == [10.0] * 7 and list(fr3.jerk_limits) == [5000.0] * 7
    assert list(rodshape.panda().jerk_limits) == [7500, 3750, 5000, 6250, 7500, 10000, 10000]
    assert np.isinf(rodshape.ArmModel.from_urdf_file(str(SOURCE / "data/robots/fr3.urdf"))
                    .acceleration_limits).all()  # a URDF holds none
    task = rodshape.load_task(str(EXAMPLES / "plan_fr3_s_curve.yaml"))  # urdf: fr3
    assert task is not None


def test_inverse_kinematics_returns_to_a_reachable_pose():
    arm = rodshape.panda()
    goal_q = rodshape.panda_ready_pose() + np.array([0.2, -0.1, 0.1, 0.2, -0.1, 0.1, 0.2])
    goal = arm.forward_kinematics(goal_q)
    result = rodshape.solve_ik(arm, goal)
    assert result.converged(), result.brief()
    reached = arm.forward_kinematics(result.q)
    assert np.linalg.norm(reached.position - goal.position) <= 1e-10
    assert np.all(result.q >= arm.lower_limits) and np.all(result.q <= arm.upper_limits)
    far = rodshape.Pose(position=[3.0, 0.0, 0.5])
    assert rodshape.solve_ik(arm, far).status == "out_of_reach"
    with pytest.raises(rodshape.InputError):
        arm.forward_kinematics(np.zeros(3))


def test_a_plan_with_an_arm_has_a_joint_trajectory_within_the_limits(tmp_path):
    import matplotlib
    matplotlib.use("Agg")
    from rodshape import plot
    plan = rodshape.plan(rodshape.load_task(str(EXAMPLES / "plan_panda_s_curve.yaml")))
    joints, arm = plan.result.joints, plan.task.arm
    assert joints.complete(), joints.brief()
    assert joints.q.shape == (len(joints.t), arm.joints) == joints.qdot.shape
    assert np.all(np.diff(joints.t) > 0)
    assert np.all(joints.q >= arm.lower_limits - 1e-12)
    assert np.all(joints.q <= arm.upper_limits + 1e-12)
    assert np.all(np.abs(joints.qdot) <= arm.velocity_limits * (1 + 1e-9))
    fig = plot.joint_trajectory(plan)
    fig.savefig(tmp_path / "joints.png")
    assert (tmp_path / "joints.png").stat().st_size > 1000
    # The legend beside the axes is inside the figure (it was cut off at its right edge).
    fig.canvas.draw()
    legend = fig.axes[0].get_legend().get_window_extent()
    assert legend.x1 <= fig.bbox.x1 + 1 and legend.x0 >= 0
    validation = rodshape.validate(rodshape.load_task(str(EXAMPLES / "plan_panda_s_curve.yaml")))
    assert validation.driven_by_joints
    assert all(run.driven_by_joints for run in validation.runs)
    assert json.loads(validation.to_json())["driven_by"] == "joint_trajectory"
    no_arm = rodshape.plan(rodshape.load_task(str(EXAMPLES / "plan_c_arc.yaml")))
    assert no_arm.result.joints is None
    with pytest.raises(ValueError):
        plot.joint_trajectory(no_arm)


def test_closed_loop_options_and_checkpoints():
    task = rodshape.load_task(str(EXAMPLES / "plan_c_arc.yaml"))
    task.plant.grasp_offset = rodshape.Pose(position=[0.002, 0.0, 0.0])
    assert task.closed_loop.horizon == 1 and task.closed_loop.significance == 3.0
    run = rodshape.validate(task, runs=1, seed=3, closed_loop=True).runs[0]
    assert len(run.checkpoints) == 6  # at every waypoint but the last of seven
    first = run.checkpoints[0]
    # A 2 mm grasp offset is far beyond the averaged markers' noise: the first estimate acts.
    assert first.significant and first.replanned, first.message
    assert first.estimate.status == "converged" and first.estimate.converged
    assert first.consistent and first.estimate.residual <= task.closed_loop.max_residual == 2.0
    assert task.closed_loop.max_energy_ratio == 1.5
    assert first.estimate.prior_chi2 - first.estimate.chi2 > 6 + 3 * np.sqrt(12)
    assert task.closed_loop.fuse
    cov = np.asarray(first.estimate.tip_covariance)
    assert cov.shape == (6, 6) and np.allclose(cov, cov.T) and np.all(np.linalg.eigvalsh(cov) > 0)
    # The tip is placed to a fraction of a millimetre (markers averaged over 15 frames).
    assert np.sqrt(np.trace(cov[:3, :3])) < 1e-3
    task.closed_loop.significance = 1e9  # never significant: nothing is corrected
    kept = rodshape.validate(task, runs=1, seed=3, closed_loop=True).runs[0]
    assert not any(c.significant or c.replanned for c in kept.checkpoints)
    task.closed_loop.horizon = -1
    with pytest.raises(rodshape.InputError, match="horizon"):
        rodshape.validate(task, closed_loop=True)
    task.closed_loop.horizon = 1
    task.closed_loop.max_energy_ratio = 0.5
    with pytest.raises(rodshape.InputError, match="max_energy_ratio"):
        rodshape.validate(task, closed_loop=True)


def test_validate_jobs_and_progress_callback():
    task = rodshape.load_task(str(EXAMPLES / "plan_c_arc.yaml"))
    serial = rodshape.validate(task, runs=2, seed=3, closed_loop=True)
    calls = []
    parallel = rodshape.validate(task, runs=2, seed=3, closed_loop=True, jobs=2,
                                 progress=lambda done, total: calls.append((done, total)))
    assert calls == [(1, 2), (2, 2)]
    for a, b in zip(parallel.runs, serial.runs):  # the same runs, whichever thread did them
        assert np.array_equal(a.error_3d, b.error_3d) and a.final.true_error == b.final.true_error
    assert not np.array_equal(serial.runs[0].error_3d, serial.runs[1].error_3d)
    frames = []
    open_loop = rodshape.validate(task, progress=lambda done, total: frames.append((done, total)))
    assert frames[-1] == (len(open_loop.runs[0].time),) * 2 and len(frames) <= 101

    def fail(done, total):
        raise RuntimeError("stop at %d of %d" % (done, total))

    with pytest.raises(RuntimeError, match="stop at 1 of 2"):
        rodshape.validate(task, runs=2, closed_loop=True, jobs=2, progress=fail)
    with pytest.raises(rodshape.InputError, match="jobs"):
        rodshape.validate(task, jobs=0)


def test_a_scene_built_in_python_is_kept_clear():
    task = rodshape.load_task(str(EXAMPLES / "plan_c_arc.yaml"))
    problem = task.problem
    scene = rodshape.Scene()
    scene.rod_radius = 0.5 * np.hypot(0.02, 0.02)
    scene.clearance = 0.005
    # A ball beside the C (its nearest target point is 4 cm away) and a table under the clamp.
    scene.obstacles = [
        rodshape.Obstacle(rodshape.SphereObstacle([0.12, 0.0, 0.2], 0.02), "ball"),
        rodshape.Obstacle(rodshape.HalfSpaceObstacle([0.0, 0.0, -1.0], 0.03), "table"),
    ]
    problem.scene = scene
    result = rodshape.plan_problem(problem, task.options)
    assert result.status == "complete", result.message
    assert result.scene is not None
    assert result.scene.min_gap >= scene.clearance - 1e-9
    assert result.scene.obstacle_label in ("'ball'", "'table'")
    d, gradient = scene.obstacles[0].distance([0.12, 0.0, 0.25])
    assert abs(d - 0.03) < 1e-15 and np.allclose(gradient, [0.0, 0.0, 1.0])


def test_the_bundled_post_is_passed_by_a_detour():
    plan = rodshape.plan(rodshape.load_task(str(EXAMPLES / "plan_around_post.yaml")))
    assert plan.status == "complete", plan.message
    assert any(step.detour for step in plan.steps)
    assert plan.scene.clear()


def test_the_shelf_plan_keeps_the_arms_links_clear():
    plan = rodshape.plan(rodshape.load_task(str(EXAMPLES / "plan_panda_shelf.yaml")))
    assert plan.status == "complete", plan.message
    robot = plan.scene.robot
    assert robot is not None and robot.clear()
    assert plan.scene.robot_min_gap == robot.min_gap >= 0.01
    assert robot.link == "panda_link5" and robot.obstacle_name == "board"
    assert plan.result.joints.clearance_steps > 0
    arm = rodshape.panda()
    assert len(arm.link_capsules) == 14 and arm.collision_notes == []
    assert arm.link_capsules[-1].label() == "panda_link8 (right_finger)"


def test_a_depth_task_has_its_depth_camera():
    depth = rodshape.load_task(str(EXAMPLES / "validate_depth_camera.yaml"))
    camera = depth.depth_sensor
    assert isinstance(camera, rodshape.DepthSensorModel)
    assert (camera.width, camera.height, camera.points) == (512, 424, 500)
    assert camera.noise.a0 == 0.0015 and camera.outliers == 0.02
    assert rodshape.load_task(str(EXAMPLES / "plan_c_arc.yaml")).depth_sensor is None
