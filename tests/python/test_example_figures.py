"""examples/README.md's figures, checked against what the documented commands print today, so that
the README stays true (issue 43).

Each test runs the README's commands (`rodshape plan examples/X.yaml -o DIR`, `rodshape
equilibrium`, `rodshape estimate`, `rodshape validate`) into a temporary folder, reads their JSON
and renders each figure the README quotes at the precision it writes it ("0.52 mm" is
f"{1e3 * x:.2f} mm"); the rendered phrase must appear in the README (whitespace folded, so that a
line break does not matter). A drifted figure fails with the phrase the README should have.
Wall times are not checked: the README points to BENCHMARKS.md for them. About 15 s of CPU in
Release.

Environment: RODSHAPE_CLI is the rodshape executable (python/CMakeLists.txt sets it for ctest;
else build/rodshape of the source tree), RODSHAPE_SOURCE_DIR the source tree.
"""
import csv
import json
import math
import os
import re
import subprocess
from pathlib import Path

import pytest

SOURCE = Path(os.environ.get("RODSHAPE_SOURCE_DIR", Path(__file__).resolve().parents[2])).resolve()
CLI = os.environ.get("RODSHAPE_CLI", str(SOURCE / "build" / "rodshape"))
EXAMPLES = SOURCE / "examples"

pytestmark = pytest.mark.skipif(not Path(CLI).is_file(), reason=f"no rodshape executable at {CLI}")

# The plans of the README's results table without a scene, in its order.
TABLE_PLANS = ["plan_c_arc", "plan_s_curve", "plan_twisted_3d", "plan_lifted_bend", "plan_tip_bend",
               "plan_square_beam", "plan_partial_hook"]


def folded(text):
    return " ".join(text.split())


class Readme:
    """The README's text; `says(template, *values)` records the phrase the values render to when
    the README does not contain it, `check()` fails with every such phrase."""

    def __init__(self):
        self.text = folded((EXAMPLES / "README.md").read_text())
        self.missing = []
        self.checked = False

    def says(self, template, *values):
        phrase = folded(template.format(*values))
        if phrase not in self.text:
            self.missing.append(phrase)

    def check(self):
        self.checked = True
        assert not self.missing, ("examples/README.md does not say what the commands print; "
                                  "it should say:\n  " + "\n  ".join(self.missing))


@pytest.fixture
def readme():
    r = Readme()
    yield r
    if not r.checked:  # each test checks at its end; this catches one that does not
        r.check()


class Runs:
    """The commands, each run once for the whole module (cwd: the source tree, as the README's
    commands are written; -q where the command has it)."""

    def __init__(self, root):
        self.root = root
        self.cache = {}

    def _run(self, key, args):
        if key not in self.cache:
            done = subprocess.run([CLI, *args], cwd=SOURCE, capture_output=True, text=True,
                                  timeout=300)
            assert done.returncode == 0, f"rodshape {' '.join(args)}: exit {done.returncode}\n{done.stderr}"
            self.cache[key] = True

    def plan(self, name, task=None):
        out = self.root / name
        self._run(("plan", name), ["plan", str(task or EXAMPLES / f"{name}.yaml"), "-o", str(out),
                                   "--no-html", "-q"])
        return json.loads((out / "plan.json").read_text()), out

    def equilibrium(self, name):
        out = self.root / f"{name}.json"
        self._run(("equilibrium", name), ["equilibrium", f"examples/{name}.yaml", "-o", str(out), "-q"])
        return json.loads(out.read_text())

    def estimate(self, name):
        out = self.root / f"{name}.json"
        self._run(("estimate", name), ["estimate", f"examples/{name}.yaml", "--cloud",
                                       f"examples/clouds/{name}.ply", "-o", str(out)])
        return json.loads(out.read_text())

    def validate(self, name, *flags):
        out = self.root / ("validate_" + name + "".join(flags).replace("-", "_"))
        self._run(("validate", name, flags), ["validate", f"examples/{name}.yaml", "-o", str(out),
                                              "--no-html", "-q", *flags])
        return json.loads((out / "validation.json").read_text())


@pytest.fixture(scope="module")
def runs(tmp_path_factory):
    return Runs(tmp_path_factory.mktemp("example_figures"))


def mm(x):
    return 1e3 * x


def median(values):
    v = sorted(values)
    n = len(v)
    return v[n // 2] if n % 2 else 0.5 * (v[n // 2 - 1] + v[n // 2])


def iterations(plan):
    return [s["solver"]["iterations"] for s in plan["steps"]]


def peak_ratio(plan):
    return plan["tracking"]["peak_energy"] / max(plan["initial"]["energy"], plan["final"]["energy"])


def follows(plan):
    t = plan["tracking"]
    return t["performed"] and not t["jump"] and t["note"].startswith("the rod follows the plan")


def rotate(q, v):
    w, x, y, z = q
    r = [[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
         [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
         [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]]
    return [sum(r[i][k] * v[k] for k in range(3)) for i in range(3)]


def panda_velocity_limits():
    urdf = (SOURCE / "data" / "robots" / "panda.urdf").read_text()
    joints = re.findall(r'<joint name="(\w+)" type="revolute">.*?<limit lower="([-\d.]+)" '
                        r'upper="([-\d.]+)" velocity="([\d.]+)"', urdf, re.S)
    return {name: (float(lo), float(hi), float(v)) for name, lo, hi, v in joints}


def joint_figures(out):
    """The fastest joint's speed over its limit (joint_trajectory.json's velocities), the least
    distance of a joint from its position limits, and the elbow's (joint 4's) place in its range at
    the end."""
    limits = panda_velocity_limits()
    traj = json.loads((out / "joint_trajectory.json").read_text())
    names = traj["joint_names"]
    fastest = max(abs(v) / limits[n][2] for p in traj["points"] for n, v in zip(names, p["velocities"]))
    margin = min(min(q - limits[n][0], limits[n][1] - q)
                 for p in traj["points"] for n, q in zip(names, p["positions"]))
    lo, hi, _ = limits["panda_joint4"]
    elbow = (traj["points"][-1]["positions"][names.index("panda_joint4")] - lo) / (hi - lo)
    return fastest, margin, elbow


# --- the task files: equilibrium and estimate -----------------------------------------------------


def test_equilibrium_examples(runs, readme):
    cantilever = runs.equilibrium("cantilever_gravity")
    assert cantilever["status"] == "converged" and cantilever["stable"]
    # A 1 m steel wire (r = 1 mm, E = 200 GPa, rho = 7850 kg/m^3) clamped at z = 1 m.
    weight = 7850 * 9.81 * math.pi * 1e-3 ** 2
    bending = 200e9 * math.pi * 1e-3 ** 4 / 4
    readme.says("Small-deflection beam theory predicts a tip drop of {:.3f} m", weight / (8 * bending))
    readme.says("the rod model, which follows the large rotations, gives {:.3f} m",
                1.0 - cantilever["tip"]["position"][2])

    compressed = runs.equilibrium("compressed_band")
    search = compressed["stable_search"]
    assert search["found"] and compressed["stable"]
    readme.says("The solve from rest finds the planar S ({:.2f} J), which is unstable", search["solved_energy"])
    readme.says("returns the out-of-plane one it finds ({:.2f} J, stable)", compressed["energy"])
    readme.check()


def test_estimate_example(runs, readme):
    fit = runs.estimate("estimate_band")["fit"]
    assert fit["explained"]
    readme.says("`--cloud clouds/estimate_band.ply` ({} points in the camera frame", fit["points"])
    readme.says("is explained: {} points rejected, residual {:.2f}.", fit["rejected"], fit["residual"])
    readme.check()


# --- the plans' table ---------------------------------------------------------------------------


def test_plan_table(runs, readme):
    energy_error = {}
    for name in TABLE_PLANS:
        plan, _ = runs.plan(name)
        f = plan["final"]
        assert follows(plan) and plan["tracking"]["refinements"] == 0, name
        assert not any(s["inserted"] for s in plan["steps"]), name
        assert plan["tracking"]["peak_energy"] <= f["energy"] * (1 + 1e-9), name
        its = iterations(plan)
        readme.says("| `{}` | {} | {} | {:.2f} | {:.2f} | {:.3g} | {} | {} ({}) | {:.1f} | follows the plan "
                    "| {:.3g} ({:.2f}) |", name, plan["status"], len(plan["steps"]),
                    mm(f["max_distance"]), mm(f["mean_distance"]), f["energy"],
                    "yes" if f["stable"] else "no", sum(its), ", ".join(map(str, its)),
                    plan["end_effector_path"]["duration"], plan["tracking"]["peak_energy"], peak_ratio(plan))
        if name != "plan_partial_hook":  # its points lie on an arc, not on a generating shape
            header = folded((EXAMPLES / f"{name}.yaml").read_text().replace("#", ""))
            generating = float(re.search(r"stable equilibrium with ([0-9.]+) J of elastic energy",
                                         header).group(1))
            energy_error[name] = f["energy"] / generating - 1
    worst = max(mm(runs.plan(n)[0]["final"]["max_distance"]) for n in TABLE_PLANS)
    readme.says("every final shape passes within {:.2f} mm of its points", worst)
    twisted = energy_error.pop("plan_twisted_3d")
    assert max(abs(e) for e in energy_error.values()) <= 0.03, energy_error
    readme.says("within 3 % of the generating shape's (the twisted curve's is {:.0f} % lower", -100 * twisted)
    readme.check()


def test_plan_around_post(runs, readme):
    plan, _ = runs.plan("plan_around_post")
    f, steps, scene = plan["final"], plan["steps"], plan["scene"]
    assert follows(plan) and scene["clear"]
    detours = sum(s["detour"] for s in steps)
    sets = [s for s in steps if not s["detour"]]
    assert sets[-1]["fraction"] == 1.0 and steps[-2]["detour"]
    its = iterations(plan)
    readme.says("| `plan_around_post` | {} | {} ({}, {} on a detour, the last set; {} sets skipped: their "
                "points lie in the post) | {:.2f} | {:.2f} | {:.3g} | {} | {} ({}: the detour's step is an "
                "equilibrium, not an optimisation) | {:.1f} | follows the plan; least gap to the scene {:.2f} mm "
                "(clearance {:.0f} mm) | {:.2f} ({:.2f}) |",
                plan["status"], len(steps), len(sets) - 1, detours, plan["steps_requested"] - len(sets),
                mm(f["max_distance"]), mm(f["mean_distance"]), f["energy"], "yes" if f["stable"] else "no",
                sum(its), ", ".join(map(str, its)), plan["end_effector_path"]["duration"],
                mm(scene["min_gap"]), mm(scene["clearance"]), plan["tracking"]["peak_energy"], peak_ratio(plan))
    readme.says("(steps with `\"detour\": true`; least gap {:.2f} mm)", mm(scene["min_gap"]))
    readme.check()


def test_plan_cable_helix(runs, readme, tmp_path):
    plan, _ = runs.plan("plan_cable_helix")
    f = plan["final"]
    assert follows(plan)
    tried = {t["scheme"]: t for t in plan["interpolation"]["tried"]}
    # The `shape` sets alone, for the steps they insert.
    task = (EXAMPLES / "plan_cable_helix.yaml").read_text()
    assert task.count("\ntrajectory:\n") == 1
    shaped_task = tmp_path / "plan_cable_helix_shape.yaml"
    shaped_task.write_text(task.replace("\ntrajectory:\n", "\ntrajectory:\n  interpolation: shape\n"))
    shaped, _ = runs.plan("plan_cable_helix_shape", shaped_task)
    inserted = sum(s["inserted"] for s in shaped["steps"])
    assert abs(peak_ratio(shaped) - tried["shape"]["peak_ratio"]) < 1e-9
    readme.says("| `plan_cable_helix` (`auto` → `{}`) | {} | {} | {:.2f} | {:.2f} | {:.3g} | {} | | {:.1f} | "
                "follows the plan (`shape`: {:.2f} ×, {} inserted) | {:.3g} ({:.2f}) |",
                plan["interpolation"]["used"], plan["status"], len(plan["steps"]), mm(f["max_distance"]),
                mm(f["mean_distance"]), f["energy"], "yes" if f["stable"] else "no",
                plan["end_effector_path"]["duration"], tried["shape"]["peak_ratio"], inserted,
                plan["tracking"]["peak_energy"], peak_ratio(plan))
    readme.says("the `shape` sets peak at {:.2f} × the final energy ({} steps inserted), so the end effector's "
                "straight path to the same optimum (`{}`) is planned too and kept: followed at {:.2f} ×",
                tried["shape"]["peak_ratio"], inserted, plan["interpolation"]["used"], peak_ratio(plan))
    readme.check()


# --- the arm ----------------------------------------------------------------------------------


def test_plan_panda_s_curve(runs, readme):
    plan, out = runs.plan("plan_panda_s_curve")
    plain, _ = runs.plan("plan_s_curve")
    assert abs(plan["final"]["max_distance"] - plain["final"]["max_distance"]) < 1e-9
    reach, jt = plan["robot"]["reach"], plan["joint_trajectory"]
    assert plan["robot"]["status"] == "reachable" and jt["status"] == "complete" and not jt["slowed"]
    assert jt["ik_restarts"] == 0 and max(jt["max_position_error"], jt["max_rotation_error"]) <= 1e-10
    fastest, margin, _ = joint_figures(out)
    readme.says("`plan_panda_s_curve` plans as `plan_s_curve` (the reach shell, {:.3f}–{:.3f} m, stays inactive: "
                "the wrist is {:.2f}–{:.2f} m from the shoulder); its joint trajectory has the path's {} samples "
                "over {:.2f} s, not slowed (the fastest joint runs at {:.1f} % of its velocity limit), every joint "
                "at least {:.2f} rad from its position limits, IK errors ≤ 1e-10 m and rad, no IK restart.",
                reach["inner_radius"], reach["outer_radius"], min(reach["wrist_distances"]),
                max(reach["wrist_distances"]), jt["samples"], jt["duration"], 100 * fastest, margin)
    readme.check()


def test_plan_panda_reach_limit(runs, readme):
    plan, out = runs.plan("plan_panda_reach_limit")
    assert plan["status"] == "complete" and follows(plan)
    reach, jt, steps = plan["robot"]["reach"], plan["joint_trajectory"], plan["steps"]
    on_shell = [abs(d - reach["outer_radius"]) < 1e-6 for d in reach["wrist_distances"]]
    assert on_shell[-2:] == [True, True] and not any(on_shell[:-2])  # the last two steps on the shell
    # The wrist the final S of plan_s_curve would need from this arm's shoulder.
    s_curve, _ = runs.plan("plan_s_curve")
    tip = s_curve["steps"][-1]["configuration"]["tip"]
    wrist = [p + d for p, d in zip(tip["position"], rotate(tip["rotation"], reach["tip_point"]))]
    readme.says("where the final S would need its wrist {:.3f} m from its shoulder, beyond its {:.3f} m reach: "
                "the reach shell (`robot.reach`) stops the last two steps on the shell, the last {:.1f} mm from "
                "the points (within its `trajectory.reach_tolerance` of {:.0f} mm, so the plan is `{}`)",
                math.dist(wrist, reach["center"]), reach["wrist_range"][1], mm(plan["final"]["max_distance"]),
                mm(plan["reach"]["tolerance"]), plan["status"])
    assert plan["reach"]["target_distance"] <= plan["reach"]["tolerance"]
    fastest, _, elbow = joint_figures(out)
    readme.says("`plan_panda_reach_limit` completes its {} steps with the last two on the shell: max distance "
                "{:.1f} mm ({:.2f} mm at step 6, {:.2f} mm at step 5), energy {:.3f} J; {} samples over {:.2f} s, "
                "the elbow at {:.0f} % of its range at the end, no joint above {:.1f} % of its velocity limit",
                len(steps), mm(plan["final"]["max_distance"]), mm(steps[5]["max_distance"]),
                mm(steps[4]["max_distance"]), plan["final"]["energy"], jt["samples"], jt["duration"],
                100 * elbow, 100 * fastest)
    readme.check()


def test_plan_panda_shelf(runs, readme):
    plan, _ = runs.plan("plan_panda_shelf")
    scene, jt = plan["scene"], plan["joint_trajectory"]
    assert plan["status"] == "complete" and scene["clear"] and scene["robot_clear"]
    assert jt["status"] == "complete" and not jt["slowed"] and jt["ik_restarts"] == 0
    assert max(jt["max_position_error"], jt["max_rotation_error"]) <= 1e-10
    at = scene["robot_min_gap_at"]
    readme.says("(the shelf is far from the band: least gap {:.0f} mm, to the {}); its joint trajectory has the "
                "path's {} samples over {:.2f} s, not slowed, no IK restart", mm(scene["min_gap"]),
                scene["min_gap_at"]["obstacle"], jt["samples"], jt["duration"])
    readme.says("the arm's links keep at least {:.0f} mm from everything (the forearm, `{}`, from the {} at t = "
                "{:.2f} s)", mm(scene["robot_min_gap"]), at["link"], at["obstacle"], at["t"])
    readme.says("are kept {:.0f} cm clear (`robot.links`)", 100 * scene["clearance"])
    readme.says("every link keeps {:.0f} cm (`scene.robot_min_gap` in `plan.json`)", 100 * scene["robot_min_gap"])
    readme.check()


def test_validate_panda_closed_loop(runs, readme):
    open_loop = runs.validate("plan_panda_closed_loop", "--runs", "8")
    closed = runs.validate("plan_panda_closed_loop", "--runs", "8", "--closed-loop")
    assert open_loop["status"] == closed["status"] == "complete"
    readme.says("Open loop it ends {:.1f} mm from the points (true error), closed loop about {:.1f} mm",
                mm(median(r["final"]["true_error"] for r in open_loop["runs"])),
                mm(median(r["final"]["true_error"] for r in closed["runs"])))
    readme.check()


# --- two arms ---------------------------------------------------------------------------------


def test_plan_two_pandas(runs, readme):
    plan, out = runs.plan("plan_two_pandas")
    f, jt = plan["final"], plan["joint_trajectory"]
    assert plan["status"] == "complete" and follows(plan)
    assert plan["robot"]["status"] == plan["base_robot"]["status"] == "reachable"
    assert jt["status"] == plan["base_joint_trajectory"]["status"] == "complete"
    with open(out / "trajectory.csv") as file:
        base = [[float(row[k]) for k in ("bx", "by", "bz")] for row in csv.DictReader(file)]
    readme.says("`plan_two_pandas` (2026-11-26, issue 21) completes its {} steps with both ends moving: final max "
                "distance {:.2f} mm, energy {:.3f} J, followed at {:.2f} × its final energy; both arms reach every "
                "pose and every one of the path's {} samples ({:.1f} s), their hands at least {:.0f} mm apart; the "
                "base gripper moves {:.1f} cm.", len(plan["steps"]), mm(f["max_distance"]), f["energy"],
                peak_ratio(plan), jt["samples"], jt["duration"], mm(plan["scene"]["robot_min_gap"]),
                100 * max(math.dist(base[0], p) for p in base))
    readme.says("minimiser (ninth session): {} iterations", ", ".join(map(str, iterations(plan))))
    closed = runs.validate("plan_two_pandas", "--runs", "2", "--closed-loop")
    open_loop = runs.validate("plan_two_pandas")
    readme.says("2 runs) the true final errors are {:.2f} and {:.2f} mm, open loop {:.2f} mm.",
                *(mm(r["final"]["true_error"]) for r in closed["runs"]),
                mm(open_loop["runs"][0]["final"]["true_error"]))
    readme.check()


def test_plan_base_arm(runs, readme):
    plan, _ = runs.plan("plan_base_arm")
    f = plan["final"]
    assert plan["status"] == "complete" and follows(plan) and plan["base_robot"]["status"] == "reachable"
    assert all(s["solver"]["message"].startswith("IPOPT") for s in plan["steps"])
    its = iterations(plan)
    header = folded((EXAMPLES / "plan_base_arm.yaml").read_text().replace("#", ""))
    generating = float(re.search(r"N·m; ([0-9.]+) J\)", header).group(1))
    box = re.search(r"box: \{lower: \[([^]]*)\], upper: \[([^]]*)\]\}", header)
    lower, upper = ([float(x) for x in box.group(k).split(",")] for k in (1, 2))
    for step in plan["steps"]:  # the tip in its fixture at every step
        tip = step["configuration"]["tip"]["position"]
        assert all(lo - 1e-9 <= x <= hi + 1e-9 for lo, x, hi in zip(lower, tip, upper)), step["step"]
    half_widths = {round(mm(hi - lo) / 2, 6) for lo, hi in zip(lower, upper)}
    assert len(half_widths) == 1
    readme.says("(its position held within ±{:.1f} mm by `workspace.box`", *half_widths)
    readme.says("`plan_base_arm` completes with the tip in its fixture (within the ±{:.1f} mm box at every step): "
                "final max distance {:.3f} mm, energy {:.2f} J (the generating equilibrium's {:.3f} J), {:.2f} ×, "
                "in {} IPOPT iterations ({}) for the 12 unknowns", *half_widths, mm(f["max_distance"]), f["energy"],
                generating, peak_ratio(plan), sum(its), ", ".join(map(str, its)))
    readme.check()
