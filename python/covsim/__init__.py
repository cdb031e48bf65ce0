"""covsim from Python: scenarios, step-by-step simulations with numpy arrays, cells, sweeps,
run folders, and planners and coverage laws written in Python. See docs/python.md.

    import covsim
    s = covsim.Scenario.from_file("scenarios/u_shape.json")
    sim = covsim.Simulation(s, seed=1)
    sim.run()
    sim.positions          # (n, 2) numpy array, metres
"""
import csv
import gzip
import json
import os
import tempfile

import numpy as np

from ._covsim import (
    Environment,
    Knowledge,
    Partition,
    Robot,
    Scenario,
    ScenarioError,
    SensorReading,
    Simulation,
    __version__,
    components,
    measures,
    register_law,
    register_planner,
)
from . import _covsim

__all__ = [
    "Cells", "Environment", "Knowledge", "Partition", "Robot", "Scenario", "ScenarioError",
    "SensorReading", "Simulation", "cells", "components", "draw_environment", "environment",
    "load_run",
    "measures", "register_law",
    "register_planner", "sweep", "__version__",
]


def environment(scenario):
    """The environment Ω of a scenario (a Scenario, or a dict with "environment" and
    "density")."""
    return _covsim._environment(_as_scenario(scenario))


class Cells(_covsim._Cells):
    """Ω and φ parsed once, with the integrator over them: cells = Cells(environment, density),
    then cells(generators) for each set of generators ((n, 2) array, metres) returns a
    Partition: .mass (n,), .centroid (n, 2), .cost (n,) as arrays, .cell(i), .pieces(i), and
    .to_list(), the dicts covsim.cells gives. A call costs what the partition costs in C++.
    environment: a scenario's "environment" object (dict), an Environment, or a whole scenario
    (a Scenario, a dict or a path), whose density is used when density is None. density: a
    scenario's "density" object; None: uniform (or the scenario's). Generators at one point
    split their cell into wedges."""

    def __init__(self, environment, density=None):
        if isinstance(environment, Environment):
            rings = environment.rings
            environment = {"outer": rings[0].tolist(), "holes": [r.tolist() for r in rings[1:]]}
        if isinstance(environment, dict) and "outer" in environment:
            scenario = {"environment": environment, "density": density or {"type": "uniform"}}
        else:
            scenario = _as_scenario(environment)
            if density is not None:
                scenario = Scenario.from_dict(dict(scenario.to_dict(), density=density))
        super().__init__(_as_scenario(scenario))


def cells(environment, density=None, generators=None):
    """The Voronoi partition of the generators ((n, 2) array, metres) restricted to Ω, without
    a run: per generator a dict with its cell, the convex pieces of cell ∩ Ω (arrays of
    vertices, metres), mass (∫φ, m² for a uniform density), centroid (metres) and cost
    (½∫|x - g|²φ, m⁴ φ). The arguments are Cells'; for many calls on one Ω keep a Cells."""
    if generators is None:
        raise ValueError("cells: give the generators, an (n, 2) array")
    return Cells(environment, density)(np.asarray(generators, dtype=float)).to_list()


def draw_environment(ax, environment, color="black", margin=0.02):
    """Draws what is not Ω on a matplotlib axes, filled: the holes, and the band between the
    outer ring and its bounding box (widened by `margin` of its size). Drawn last, it covers
    whatever was drawn outside Ω. environment: an Environment or anything environment()
    takes."""
    from matplotlib.patches import PathPatch
    from matplotlib.path import Path

    if not isinstance(environment, Environment):
        environment = globals()["environment"](environment)
    outer = environment.rings[0]
    lo, hi = outer.min(axis=0), outer.max(axis=0)
    pad = margin * (hi - lo)
    (x0, y0), (x1, y1) = lo - pad, hi + pad
    box = np.array([[x0, y0], [x1, y0], [x1, y1], [x0, y1]])
    rings = [box, outer[::-1]] + [ring for ring in environment.rings[1:]]
    vertices, codes = [], []
    for ring in rings:
        vertices += list(ring) + [ring[0]]
        codes += [Path.MOVETO] + [Path.LINETO] * (len(ring) - 1) + [Path.CLOSEPOLY]
    ax.add_patch(PathPatch(Path(np.array(vertices), codes), facecolor=color, edgecolor="none"))
    ax.set_xlim(x0, x1)
    ax.set_ylim(y0, y1)
    ax.set_aspect("equal")


def _as_scenario(s):
    if isinstance(s, Scenario):
        return s
    if isinstance(s, dict):
        return Scenario.from_dict(s)
    return Scenario.from_file(os.fspath(s))


def sweep(spec, jobs=1, out=None, keep_series=False):
    """Runs a sweep (docs/sweeps.md) on `jobs` C++ threads, the GIL released. spec: a sweep
    file's path, or its object (a "scenario" given by path is relative to the current
    folder). out: the output folder (runs/, runs.csv, summary.csv); a temporary one if None.
    keep_series: keep each run's metrics as out/runs/<index>.metrics.csv (give out).
    Returns the rows of runs.csv: a pandas DataFrame when pandas can be imported, else a list
    of dicts. Every setting is validated before anything runs (a ScenarioError naming the
    value). Results do not depend on jobs. A rerun into the same out reuses every finished run
    (docs/sweeps.md), as `covsim sweep` does: a spec object is kept as out/spec.json, so that
    the sweep file of both calls is the same."""
    with tempfile.TemporaryDirectory(prefix="covsim-sweep-") as scratch:
        if isinstance(spec, dict):
            spec = dict(spec)
            if isinstance(spec.get("scenario"), str):
                spec["scenario"] = os.path.abspath(spec["scenario"])
            folder = scratch
            if out is not None:
                folder = os.path.abspath(os.fspath(out))
                os.makedirs(folder, exist_ok=True)
            path = os.path.join(folder, "spec.json" if out is not None else "sweep.json")
            with open(path, "w") as f:
                json.dump(spec, f)
        else:
            path = os.fspath(spec)
        rows = _covsim._sweep(path, os.fspath(out) if out is not None else
                              os.path.join(scratch, "out"), int(jobs), bool(keep_series))
    try:
        import pandas
    except ImportError:
        return rows
    return pandas.DataFrame(rows)


class Run:
    """A run folder read back (covsim run --out DIR): final (dict, as final.json), scenario
    (dict), trajectory and metrics (dicts of numpy arrays by column, as in trajectory.csv (or
    trajectory.csv.gz) and metrics.csv; docs/outputs.md)."""

    def __init__(self, final, scenario, trajectory, metrics):
        self.final = final
        self.scenario = scenario
        self.trajectory = trajectory
        self.metrics = metrics

    @property
    def robots(self):
        return len(self.final["robots"])

    def path(self, robot):
        """Robot's positions over time, an (m, 2) array [m]."""
        rows = self.trajectory["robot"] == robot
        return np.column_stack([self.trajectory["x"][rows], self.trajectory["y"][rows]])

    def virtual_path(self, robot):
        rows = self.trajectory["robot"] == robot
        return np.column_stack([self.trajectory["vx"][rows], self.trajectory["vy"][rows]])


def _columns(path):
    opener = gzip.open if path.endswith(".gz") else open
    with opener(path, "rt", newline="") as f:
        reader = csv.reader(f)
        header = next(reader)
        rows = [[float(v) for v in row] for row in reader]
    data = np.array(rows, dtype=float).reshape(len(rows), len(header))
    out = {}
    for k, name in enumerate(header):
        column = data[:, k]
        out[name] = column.astype(np.int64) if name == "robot" else column
    return out


def _trajectory_file(folder):
    """The trajectory file of a run folder: trajectory.csv, or trajectory.csv.gz when the run
    was compressed (pandas.read_csv and numpy.loadtxt read either)."""
    folder = os.fspath(folder)
    plain = os.path.join(folder, "trajectory.csv")
    compressed = plain + ".gz"
    if os.path.exists(compressed):
        if os.path.exists(plain):
            raise ValueError(f"{folder}: holds both trajectory.csv and trajectory.csv.gz; "
                             "remove the one not of this run")
        return compressed
    return plain


def load_run(folder):
    """Reads a run folder (final.json, scenario.json, trajectory.csv or trajectory.csv.gz,
    metrics.csv)."""
    folder = os.fspath(folder)
    with open(os.path.join(folder, "final.json")) as f:
        final = json.load(f)
    with open(os.path.join(folder, "scenario.json")) as f:
        scenario = json.load(f)
    return Run(final, scenario, _columns(_trajectory_file(folder)),
               _columns(os.path.join(folder, "metrics.csv")))
