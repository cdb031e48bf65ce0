"""The composition matrix: every layer runs beside every other.

The layers (what the robots know of Ω, their localization, range noise, the planner, bodies
and their avoidance, kinematics, the coverage law and the channel) are combined as a
pairwise covering array (every pair of settings of two layers in some run), plus the full
stacks. Each combination runs and converges, or stops as `stuck` where its planner is
documented as incomplete, with bodies that never overlap and never come nearer a wall than
their radius (read back from trajectory.csv, or from every event of a Python run); or it is
refused, with an error docs/scenario-format.md lists under "Combinations refused".
"""
import itertools
import json
import os
import pathlib
import random
import subprocess

import numpy as np
import pytest

import covsim

SOURCE = pathlib.Path(os.environ.get("COVSIM_SOURCE_DIR", pathlib.Path(__file__).parents[2]))
COVSIM = os.environ.get("COVSIM_PROGRAM", str(SOURCE / "build" / "apps" / "covsim"))

LAYERS = {
    "known": ["full", "boundary", "none"],
    "localization": ["exact", "tracking", "odometry"],
    "noise": ["off", "on"],
    "planner": ["tangent_bug", "visibility_graph", "grid_astar", "potential_field",
                "straight_line", "py_sensing"],
    "bodies": ["none", "orca"],
    "kinematics": ["single_integrator", "unicycle", "differential_drive"],
    "law": ["virtual_generators", "euclidean_lloyd", "geodesic_lloyd"],
    "channel": ["abstract", "ns3_wifi"],
}
# Planners documented as incomplete (docs/planners.md): they may stall short of a target
# for good, and the run then stops as stuck.
INCOMPLETE = {"potential_field", "straight_line", "py_sensing"}
RADIUS = 0.02


def covering_array(layers, seed=1, candidates=30):
    """A pairwise covering array, built greedily: each row covers the most pairs not yet
    covered among `candidates` rows grown from an uncovered pair (AETG's scheme)."""
    names = list(layers)
    n = len(names)
    uncovered = {(a, x, b, y) for a, b in itertools.combinations(range(n), 2)
                 for x in layers[names[a]] for y in layers[names[b]]}

    def pairs(row):
        return {(a, row[a], b, row[b]) for a, b in itertools.combinations(range(n), 2)}

    rng = random.Random(seed)
    rows = []
    while uncovered:
        best, gain = None, -1
        for _ in range(candidates):
            a, x, b, y = sorted(uncovered)[rng.randrange(len(uncovered))]
            row = [None] * n
            row[a], row[b] = x, y
            order = [k for k in range(n) if row[k] is None]
            rng.shuffle(order)
            for k in order:
                def newly(v):
                    return sum((min(j, k), row[j] if j < k else v, max(j, k),
                                v if j < k else row[j]) in uncovered
                               for j in range(n) if row[j] is not None)
                values = layers[names[k]]
                row[k] = max(values, key=lambda v: (newly(v), -values.index(v)))
            g = len(pairs(row) & uncovered)
            if g > gain:
                best, gain = row, g
        rows.append(dict(zip(names, best)))
        uncovered -= pairs(best)
    return rows


ROWS = covering_array(LAYERS)
# The full stacks: Ω unknown, tracking, range noise, bodies with ORCA, a differential drive,
# grid A*, over the radio.
FULL = {"known": "none", "localization": "tracking", "noise": "on", "planner": "grid_astar",
        "bodies": "orca", "kinematics": "differential_drive", "law": "virtual_generators",
        "channel": "ns3_wifi"}
CASES = [(row, ["u_shape", "two_obstacles"][k % 2]) for k, row in enumerate(ROWS)]
CASES += [(FULL, "two_obstacles"), (FULL, "u_shape")]


def scenario_of(row, name):
    s = json.loads((SOURCE / "scenarios" / f"{name}.json").read_text())
    s["environment"]["known"] = row["known"]
    robots = s.setdefault("robots", {})
    robots["localization"] = {"exact": {"type": "exact"},
                              "tracking": {"type": "tracking", "noise": 0.005},
                              "odometry": {"type": "odometry"}}[row["localization"]]
    s["sensor"] = {"range": 0.5}
    if row["noise"] == "on":
        s["sensor"]["noise"] = {"sigma": 0.01}
    s["planner"] = {"type": row["planner"]}
    if row["planner"] == "potential_field":
        # Its stall window counts planner steps, and with kinematics a step in a local
        # minimum's oscillation can take a second (a body turning round); each stall gives a
        # robot one loop-1 update, so two stalled robots restart each other until their
        # virtual generators rest: 50 steps made the ns-3 row stuck only at 1663 s.
        s["planner"]["stall_window"] = 10
    if row["bodies"] == "orca":
        robots["radius"] = RADIUS
        robots["avoidance"] = {"type": "orca"}
    robots["kinematics"] = {"type": row["kinematics"]}
    s["controller"] = {"type": row["law"]}
    if row["channel"] == "ns3_wifi":
        s["network"] = {"channel": {"type": "ns3_wifi"}}
    else:  # decentralized: every robot keeps its own view and map
        s["network"] = {"loss": {"model": "bernoulli", "p": 0.1}}
    s["convergence"] = {"max_time": 1000}
    if row["known"] != "full":
        s["mapping"] = {"compare_known": False}
    return s


def documented_refusals():
    """The errors docs/scenario-format.md's "Combinations refused" table quotes."""
    text = (SOURCE / "docs" / "scenario-format.md").read_text()
    section = text[text.index("| combination |", text.index("## Combinations refused")):]
    section = section[:section.index("\n\n")]
    phrases = []
    for line in section.splitlines()[2:]:
        cells = [c.strip() for c in line.strip("|").split("|")]
        phrases.append(cells[1].strip("`"))
    return phrases


class Feeler:
    """A planner in Python that senses: told nothing of Ω, straight at the goal, stalling
    where a wall it sees is in the way."""

    def __init__(self, environment, params):
        self.goal = None

    def set_goal(self, goal):
        self.goal = np.array(goal)

    def learn(self, walls):
        pass

    def step(self, reading, max_step):
        x = reading.position
        d = np.linalg.norm(self.goal - x)
        if d <= 1e-9:
            return self.goal, "reached"
        nxt = self.goal if d <= max_step else x + max_step * (self.goal - x) / d

        def side(p, q, r):
            return np.sign((q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]))

        for ax, ay, bx, by in reading.pieces:
            a, b = (ax, ay), (bx, by)
            if side(x, nxt, a) * side(x, nxt, b) <= 0 and side(a, b, x) * side(a, b, nxt) <= 0:
                return x, "stalled"
        return nxt, "moving"


if "py_sensing" not in [p["name"] for p in covsim.components("planners")]:
    covsim.register_planner("py_sensing", Feeler, "straight, on what it senses", senses=True)


def wall_distances(points, rings):
    """The distance from each point to the nearest edge of the rings."""
    a = np.concatenate([np.asarray(r, float) for r in rings])
    b = np.concatenate([np.roll(np.asarray(r, float), -1, axis=0) for r in rings])
    d = b - a
    t = np.clip(np.einsum("pmk,mk->pm", points[:, None, :] - a[None], d) /
                np.einsum("mk,mk->m", d, d), 0.0, 1.0)
    nearest = a[None] + t[..., None] * d[None]
    return np.linalg.norm(points[:, None, :] - nearest, axis=2).min(axis=1)


def check_bodies(frames, rings):
    """No two bodies overlap and none comes nearer a wall than its radius, in any frame."""
    for t, p in frames:
        gaps = np.linalg.norm(p[:, None, :] - p[None], axis=2) + np.eye(len(p)) * 1e9
        assert gaps.min() >= 2 * RADIUS - 1e-9, f"bodies overlap at t={t}: {gaps.min()}"
        walls = wall_distances(p, rings)
        assert walls.min() >= RADIUS - 1e-9, f"a body meets a wall at t={t}: {walls.min()}"


def rings_of(s):
    return [s["environment"]["outer"], *s["environment"].get("holes", [])]


def refused(message):
    assert any(p in message for p in documented_refusals()), (
        f"refused without a documented reason: {message}")


@pytest.mark.parametrize("row,name", CASES, ids=[
    f"{k}-{name}-" + "-".join(row.values()) for k, (row, name) in enumerate(CASES)])
def test_every_layer_composes(row, name, tmp_path):
    s = scenario_of(row, name)
    if row["planner"] == "py_sensing":
        try:
            scenario = covsim.Scenario.from_dict(s)
        except covsim.ScenarioError as e:
            return refused(str(e))
        sim = covsim.Simulation(scenario)
        frames = []
        try:
            while sim.step():
                if row["bodies"] == "orca":
                    frames.append((sim.now, np.array(sim.positions)))
        except RuntimeError as e:
            if "ns3_wifi channel is unavailable" in str(e):
                pytest.skip(str(e))
            raise
        out = sim.outcome()
    else:
        (tmp_path / "s.json").write_text(json.dumps(s))
        p = subprocess.run([COVSIM, "run", str(tmp_path / "s.json"), "--out", str(tmp_path / "o")],
                           capture_output=True, text=True)
        if p.returncode == 2:
            return refused(p.stderr)
        if "ns3_wifi channel is unavailable" in p.stderr:
            pytest.skip(p.stderr.strip())
        assert p.returncode == 0, p.stderr
        out = json.loads((tmp_path / "o" / "final.json").read_text())
        frames = []
        if row["bodies"] == "orca":
            rows = np.genfromtxt(tmp_path / "o" / "trajectory.csv", delimiter=",", names=True)
            # A robot's row may be thinned out: it stands where its last row put it.
            at = np.full((int(rows["robot"].max()) + 1, 2), np.nan)
            for k, r in enumerate(rows):
                at[int(r["robot"])] = (r["x"], r["y"])
                if (k + 1 == len(rows) or rows[k + 1]["t"] != r["t"]) and not np.isnan(at).any():
                    frames.append((r["t"], at.copy()))
    allowed = {"converged", "stuck"} if row["planner"] in INCOMPLETE else {"converged"}
    assert out["stop_reason"] in allowed, out["stop_reason"]
    assert out["bodies"]["contact_time"] == 0 and out["bodies"]["wall_contacts"] == 0
    check_bodies(frames, rings_of(s))


def test_the_covering_array_covers_every_pair():
    names = list(LAYERS)
    for a, b in itertools.combinations(names, 2):
        for x in LAYERS[a]:
            for y in LAYERS[b]:
                assert any(r[a] == x and r[b] == y for r in ROWS), (a, x, b, y)
    assert len(ROWS) <= 24  # the smallest is 18: planners × what the robots know
