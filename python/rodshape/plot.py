"""rodshape.plot: figures with matplotlib (Debian's python3-matplotlib).

    plan_steps(plan)                   the rod at every step of a plan in 3D, with its objective
                                       points (a rodshape.Plan or PlanResult, or a plan.json dict)
    joint_trajectory(plan)             joint positions and velocities of a rodshape.Plan with an
                                       arm, as fractions of the arm's limits
    validation_errors(validation)      the paper's errors over time of a rodshape.Validation
    plan_directory_figures(outdir)     PNGs of a `rodshape plan` output directory: joint positions
                                       and velocities against their URDF limits, the wrist against
                                       the reach shell, the end-effector path

Each function returns the figure (or the files written); nothing is shown. scripts/plot_plan.py is
the command-line face of plan_directory_figures.
"""
import io
import json
import os
import secrets
import xml.etree.ElementTree as ET
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

DPI = 150
# The bundled Panda, when this file is run from a source tree.
DEFAULT_URDF = Path(__file__).resolve().parents[2] / "data" / "robots" / "panda.urdf"


try:
    # The package's one exception for bad input, and the CLI's own file writer.
    from ._rodshape import InputError, write_file_atomically
except ImportError:  # this file loaded on its own (scripts/plot_plan.py), without the module
    write_file_atomically = None

    class InputError(ValueError):
        """A plan directory that cannot be drawn (the message says why)."""


def read_csv(path):
    """(header names, rows as a 2-D array) of a CSV with one header line."""
    try:
        with open(path) as f:
            header = f.readline().strip().split(",")
        rows = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    except (OSError, ValueError) as e:
        raise InputError(f"cannot read {path}: {e}") from None
    if rows.shape[1] != len(header):
        raise InputError(f"{path}: {rows.shape[1]} columns but {len(header)} names in the header")
    return header, rows


def numbers(values):
    """A JSON list of numbers (null for not finite) as a float array."""
    return np.array([np.nan if v is None else v for v in values], dtype=float)


def waypoint_indices(plan, path):
    """Row of trajectory.csv at which each waypoint is reached (each arrival is a sample)."""
    positions, quaternions = path[:, 1:4], path[:, 4:8]
    indices, start = [], 0
    for waypoint in plan["end_effector_path"]["waypoints"]:
        p, q = np.array(waypoint["position"]), np.array(waypoint["rotation"])
        # The CSV keeps consecutive quaternions in one hemisphere, the JSON has w >= 0: either sign.
        error = np.linalg.norm(positions[start:] - p, axis=1) + np.minimum(
            np.linalg.norm(quaternions[start:] - q, axis=1),
            np.linalg.norm(quaternions[start:] + q, axis=1))
        matches = np.flatnonzero(error < 1e-7)
        if matches.size == 0:
            print(f"note: waypoint {len(indices) + 1} is not a sample of trajectory.csv; "
                  "waypoint times not marked")
            return []
        start += matches[0]
        indices.append(start)
    return indices


def mark_waypoints(ax, times):
    """Thin grey vertical lines at the waypoint arrivals, numbered by step along the top."""
    for step, t in enumerate(times, 1):
        ax.axvline(t, color="0.6", linewidth=0.6, zorder=0,
                   label="waypoint arrival" if step == 1 else None)
        ax.text(t, 1.0, str(step), transform=ax.get_xaxis_transform(), ha="center",
                va="bottom", fontsize=7, color="0.4")


def joint_limits(urdf, names):
    """{name: (lower, upper, velocity)} from the URDF's <limit> tags (None where missing)."""
    try:
        root = ET.parse(urdf).getroot()
    except (OSError, ET.ParseError) as e:
        raise InputError(f"cannot read the URDF {urdf}: {e}") from None
    joints = {joint.get("name"): joint.find("limit") for joint in root.iter("joint")}
    limits = {}
    for name in names:
        if name not in joints:
            raise InputError(f"{urdf} has no joint '{name}' (of joint_trajectory.csv): "
                             "give the robot's URDF with --urdf")
        limit = joints[name]
        get = (lambda key: float(limit.get(key)) if limit is not None and limit.get(key) else None)
        limits[name] = (get("lower"), get("upper"), get("velocity"))
    return limits


def joint_velocities(outdir, t, q):
    """The velocities of joint_trajectory.json if it matches the CSV, else central differences."""
    try:
        with open(outdir / "joint_trajectory.json") as f:
            velocities = np.array([point["velocities"] for point in json.load(f)["points"]], float)
        if velocities.shape == q.shape:
            return velocities
    except (OSError, ValueError, KeyError, TypeError):
        pass
    print("note: joint velocities by central differences of joint_trajectory.csv")
    v = np.empty_like(q)
    v[1:-1] = (q[2:] - q[:-2]) / (t[2:] - t[:-2])[:, None]
    v[0] = (q[1] - q[0]) / (t[1] - t[0])
    v[-1] = (q[-1] - q[-2]) / (t[-1] - t[-2])
    return v


def plot_joints(outdir, urdf, waypoint_rows, path_samples):
    """Joint positions and velocities as fractions of their limits, over time."""
    header, rows = read_csv(outdir / "joint_trajectory.csv")
    names, t, q = header[1:], rows[:, 0], rows[:, 1:]
    if len(t) < 2:
        raise InputError("joint_trajectory.csv has fewer than two samples")
    if Path(urdf) == DEFAULT_URDF and names and names[0].startswith("fr3_"):
        urdf = DEFAULT_URDF.with_name("fr3.urdf")  # the bundled FR3's joints
    limits = joint_limits(urdf, names)
    v = joint_velocities(outdir, t, q)
    # The rows of trajectory.csv and joint_trajectory.csv are the same samples (the joints' times
    # stretched where the arm was slowed), so the waypoints arrive at the same rows.
    times = t[waypoint_rows] if len(t) == path_samples else []

    # Constrained layout keeps the legends beside the axes inside the figure.
    fig, (ax_q, ax_v) = plt.subplots(2, 1, figsize=(10, 7.5), sharex=True, layout="constrained")
    # (margin to a limit, joint) and (|q̇| / limit, joint) at the worst sample
    closest, fastest = (np.inf, None), (0.0, None)
    for j, name in enumerate(names):
        lower, upper, velocity = limits[name]
        color = f"C{j}"
        if lower is not None and upper is not None and upper > lower:
            position = (q[:, j] - lower) / (upper - lower)
            ax_q.plot(t, position, color=color, label=name)
            closest = min(closest, (min(position.min(), 1 - position.max()), name))
        else:
            print(f"note: {name} has no position limits in {urdf}; left out of the position plot")
        if velocity:
            speed = v[:, j] / velocity
            ax_v.plot(t, speed, color=color, label=name)
            fastest = max(fastest, (np.abs(speed).max(), name))
        else:
            print(f"note: {name} has no velocity limit in {urdf}; left out of the velocity plot")
    for ax, levels in ((ax_q, (0, 1)), (ax_v, (-1, 1))):
        for level in levels:
            ax.axhline(level, color="k", linestyle="--", linewidth=0.9)
        mark_waypoints(ax, times)
        ax.grid(axis="y", alpha=0.3)
    ax_q.set_ylim(-0.05, 1.05)
    ax_q.set_ylabel("(q − lower) / (upper − lower)")
    ax_q.set_title("Joint positions within their limits (dashed: the limits)" + (
        f"; closest: {closest[1]}, {closest[0]:.1%} of its range from a limit"
        if closest[1] else ""), pad=14)
    ax_q.legend(loc="center left", bbox_to_anchor=(1.01, 0.5), fontsize=8)
    ax_v.set_ylabel("q̇ / velocity limit")
    ax_v.set_xlabel("time (s)")
    ax_v.set_title("Joint velocities within their limits (dashed: ±limit)" + (
        f"; fastest: {fastest[1]}, {fastest[0]:.1%} of its limit" if fastest[1] else ""), pad=14)
    ax_v.legend(loc="center left", bbox_to_anchor=(1.01, 0.5), fontsize=8)
    return fig


def plot_reach(plan):
    """The wrist's distance from the shoulder in the reach shell, and the largest distance to the
    objective points, per step."""
    reach = plan["robot"]["reach"]
    wrist = numbers(reach["wrist_distances"])
    steps = plan["steps"]
    fig, (ax_w, ax_d) = plt.subplots(2, 1, figsize=(8, 7), sharex=True)
    ax_w.plot(range(len(wrist)), wrist, "o-", color="C0", label="wrist distance |w − c|")
    ax_w.axhline(reach["outer_radius"], color="C3", label="shell outer radius")
    ax_w.axhline(reach["inner_radius"], color="C2", label="shell inner radius")
    low, high = numbers(reach["wrist_range"])
    ax_w.axhline(high, color="C3", linestyle="--", linewidth=0.9, label="sampled wrist range")
    ax_w.axhline(low, color="C2", linestyle="--", linewidth=0.9)
    ax_w.set_ylabel("distance from the shoulder (m)")
    gap = np.fmin(reach["outer_radius"] - wrist, wrist - reach["inner_radius"])
    nearest = int(np.nanargmin(gap))
    ax_w.set_title(f"The arm's wrist in its reach shell (margin {reach['margin']:g} m)\n"
                   f"nearest the shell: step {nearest}, {1e3 * gap[nearest]:.1f} mm inside")
    ax_w.legend(fontsize=8, loc="best")
    ax_w.grid(alpha=0.3)

    index = [s["step"] for s in steps]
    max_mm = 1e3 * numbers([s["max_distance"] for s in steps])
    ax_d.plot(index, max_mm, "o-", color="C1", label="largest distance to the objective points")
    inserted = [i for i, s in enumerate(steps) if s.get("inserted")]
    if inserted:
        ax_d.plot([index[i] for i in inserted], max_mm[inserted], "s", mfc="none", ms=10,
                  color="k", label="inserted step")
    ax_d.set_ylim(bottom=0)
    ax_d.set_xlabel("step (0: the initial pose)")
    ax_d.set_ylabel("max distance (mm)")
    ax_d.set_title("Largest distance from the rod to the step's objective points")
    ax_d.legend(fontsize=8, loc="best")
    ax_d.grid(alpha=0.3)
    ax_d.xaxis.get_major_locator().set_params(integer=True)
    return fig


def plot_path(path, waypoint_rows):
    """The end effector's x, y, z over time (with a moving base, the base gripper's too, dashed:
    trajectory.csv's columns bx, by, bz)."""
    t = path[:, 0]
    fig, ax = plt.subplots(figsize=(9, 5))
    for k, axis in enumerate("xyz"):
        ax.plot(t, path[:, 1 + k], color=f"C{k}", label=axis)
    if path.shape[1] >= 15:
        for k, axis in enumerate("xyz"):
            ax.plot(t, path[:, 8 + k], "--", color=f"C{k}", label=f"base gripper {axis}")
    mark_waypoints(ax, t[waypoint_rows])
    ax.set_xlabel("time (s)")
    ax.set_ylabel("end-effector position (m, world frame)")
    ax.set_title("End-effector path (trajectory.csv)", pad=14)
    ax.legend(fontsize=8, loc="best")
    ax.grid(axis="y", alpha=0.3)
    return fig


def save(fig, path):
    """Writes fig to path whole or not at all, with the package's write_file_atomically (as the
    CLI writes its files) or, loaded on its own, a temporary file in the same directory created as
    open() would (mode 0666 less the umask, which the system applies: the process's umask is
    neither read nor changed), renamed."""
    if not fig.get_constrained_layout():
        fig.tight_layout()
    if write_file_atomically is not None:
        png = io.BytesIO()
        try:
            fig.savefig(png, format="png", dpi=DPI)
        finally:
            plt.close(fig)
        write_file_atomically(str(path), png.getvalue())
        return path
    temporary = path.parent / f".{path.name}.{secrets.token_hex(6)}.tmp"
    fd = os.open(temporary, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o666)
    try:
        with os.fdopen(fd, "wb") as f:
            fig.savefig(f, format="png", dpi=DPI)
        os.replace(temporary, path)
    except BaseException:
        os.unlink(temporary)
        raise
    finally:
        plt.close(fig)
    return path


def plan_directory_figures(outdir, output_dir=None, urdf=DEFAULT_URDF, report=print):
    """Writes PNGs of the `rodshape plan` output directory `outdir` into `output_dir` (default
    outdir): end_effector_path.png, joint_positions.png (with a robot) and reach.png (with a reach
    shell); a figure whose data the plan lacks is skipped with a note. Returns the paths written.
    Raises InputError when plan.json cannot be read."""
    outdir = Path(outdir)
    figdir = Path(output_dir) if output_dir else outdir
    try:
        with open(outdir / "plan.json") as f:
            plan = json.load(f)
    except OSError as e:
        raise InputError(f"cannot read {outdir / 'plan.json'}: {e.strerror}") from None
    except ValueError as e:
        raise InputError(f"{outdir / 'plan.json'} is not JSON: {e}") from None
    if not isinstance(plan, dict) or "steps" not in plan:
        raise InputError(f"{outdir / 'plan.json'} is not a plan of `rodshape plan` (no steps)")
    # Every figure is drawn before any is written, so bad input leaves FIGDIR as it was.
    figures, path = {}, np.empty((0, 8))
    if (outdir / "trajectory.csv").exists():
        path = read_csv(outdir / "trajectory.csv")[1]
        waypoint_rows = waypoint_indices(plan, path)
        figures["end_effector_path.png"] = plot_path(path, waypoint_rows)
    else:
        waypoint_rows = []
        report(f"note: no trajectory.csv (plan {plan.get('status')}); skipped end_effector_path.png")

    if (outdir / "joint_trajectory.csv").exists():
        figures["joint_positions.png"] = plot_joints(outdir, Path(urdf), waypoint_rows, len(path))
    else:
        report("note: no joint_trajectory.csv (no robot, or a pose out of its reach); "
               "skipped joint_positions.png")

    if (plan.get("robot") or {}).get("reach"):
        figures["reach.png"] = plot_reach(plan)
    else:
        report("note: plan.json has no robot reach shell; skipped reach.png")

    figdir.mkdir(parents=True, exist_ok=True)
    return [save(figure, figdir / name) for name, figure in figures.items()]


def _steps_of(plan):
    """(initial positions, [(positions, objective points)], target points) of a rodshape.Plan, a
    rodshape.PlanResult or a plan.json dict."""
    if isinstance(plan, dict):
        initial = np.array(plan["initial"]["nodes"]["position"]) if plan.get("initial") else None
        steps = [(np.array(s["configuration"]["nodes"]["position"]),
                  np.array(s["objective_points"])) for s in plan["steps"]]
        return initial, steps, np.array(plan["target"]["points"])
    result = getattr(plan, "result", plan)  # a Plan (of a task) holds its PlanResult
    initial = result.initial_configuration.positions
    steps = [(s.configuration.positions, s.objective_points) for s in result.steps]
    return initial, steps, steps[-1][1] if steps else np.empty((0, 3))


def set_equal_scales(ax, points):
    """One scale on the three axes of a 3-D `ax`, a cube around `points` (n × 3): a planar plan
    keeps a flat axis of the rod's size instead of an autoscaled ±1e-14 m."""
    points = np.asarray(points, float).reshape(-1, 3)
    points = points[np.isfinite(points).all(axis=1)]
    if not len(points):
        return
    low, high = points.min(axis=0), points.max(axis=0)
    centre, half = 0.5 * (low + high), 0.55 * max((high - low).max(), 1e-3)
    ax.set_xlim(centre[0] - half, centre[0] + half)
    ax.set_ylim(centre[1] - half, centre[1] + half)
    ax.set_zlim(centre[2] - half, centre[2] + half)
    ax.set_box_aspect((1, 1, 1))


def plan_steps(plan, ax=None):
    """The rod at every step of `plan` (a Plan, PlanResult or plan.json dict) in 3D (grey: the
    initial rod; a colour ramp from the first step to the last), each step's objective points as
    dots and the target's as red crosses, at one scale on the three axes."""
    if ax is None:
        fig = plt.figure(figsize=(6, 6))
        ax = fig.add_subplot(projection="3d")
    initial, steps, target = _steps_of(plan)
    if initial is not None and len(initial):
        ax.plot(initial[:, 0], initial[:, 1], initial[:, 2], color="0.6", label="initial")
    for k, (positions, points) in enumerate(steps):
        colour = plt.cm.viridis(k / max(len(steps) - 1, 1))
        ax.plot(positions[:, 0], positions[:, 1], positions[:, 2], color=colour,
                lw=2.0 if k == len(steps) - 1 else 1.0)
        if len(points):
            ax.scatter(points[:, 0], points[:, 1], points[:, 2], color=colour, s=6)
    if len(target):
        ax.scatter(target[:, 0], target[:, 1], target[:, 2], color="#d62728", marker="x",
                   label="target")
    drawn = [p for p in [initial, target] + [s for step in steps for s in step]
             if p is not None and len(p)]
    if drawn:
        set_equal_scales(ax, np.concatenate([np.asarray(p, float).reshape(-1, 3) for p in drawn]))
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_zlabel("z (m)")
    ax.legend()
    return ax.figure


def validation_errors(validation, ax=None):
    """The paper's errors over time (mm) of every run of a rodshape.Validation: 3D and 2D
    measured, and the true error."""
    if ax is None:
        _, ax = plt.subplots(figsize=(8, 4))
    for k, run in enumerate(validation.runs):
        label = k == 0
        ax.plot(run.time, 1e3 * run.error_3d, color="C0", lw=0.8, label="3D" if label else None)
        ax.plot(run.time, 1e3 * run.error_2d, color="C1", lw=0.8, label="2D" if label else None)
        ax.plot(run.time, 1e3 * run.true_error, color="C2", lw=1.2,
                label="true" if label else None)
    ax.set_xlabel("time (s)")
    ax.set_ylabel("error (mm)")
    ax.legend()
    return ax.figure


def joint_trajectory(plan, axes=None):
    """The joint positions and velocities of a rodshape.Plan with an arm, as fractions of the
    arm's limits (dashed: the limits), over time. Raises ValueError for a plan without an arm."""
    joints, arm = plan.result.joints, plan.task.arm
    if joints is None or arm is None:
        raise ValueError("the plan has no arm (no robot section), so no joint trajectory")
    if axes is None:  # constrained layout keeps the legend beside the axes inside the figure
        _, axes = plt.subplots(2, 1, figsize=(10, 7.5), sharex=True, layout="constrained")
    ax_q, ax_v = axes
    lower, upper, velocity = arm.lower_limits, arm.upper_limits, arm.velocity_limits
    t, q, qdot = joints.t, joints.q, joints.qdot
    for j, name in enumerate(joints.joint_names):
        if np.isfinite(lower[j]) and np.isfinite(upper[j]) and upper[j] > lower[j]:
            ax_q.plot(t, (q[:, j] - lower[j]) / (upper[j] - lower[j]), color=f"C{j}", label=name)
        if len(qdot) and np.isfinite(velocity[j]) and velocity[j] > 0:
            ax_v.plot(t, qdot[:, j] / velocity[j], color=f"C{j}", label=name)
    for ax, levels in ((ax_q, (0, 1)), (ax_v, (-1, 1))):
        for level in levels:
            ax.axhline(level, color="k", linestyle="--", linewidth=0.9)
    ax_q.set_ylabel("(q − lower) / (upper − lower)")
    ax_v.set_ylabel("q̇ / velocity limit")
    ax_v.set_xlabel("time (s)")
    ax_q.legend(loc="center left", bbox_to_anchor=(1.01, 0.5), fontsize=8)
    return ax_q.figure
