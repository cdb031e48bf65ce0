"""covsim from Python: scenarios, step-by-step simulations with numpy arrays, cells, sweeps,
run folders, and planners and coverage laws written in Python. See docs/python.md.

    import covsim
    s = covsim.Scenario.from_file("scenarios/u_shape.json")
    sim = covsim.Simulation(s, seed=1)
    sim.run()
    sim.positions          # (n, 2) numpy array, metres
"""
import csv as _csv
import gzip as _gzip
import json as _json
import operator as _operator
import os as _os
import sys as _sys
import tempfile as _tempfile

from . import _build


def _wrong_python(error):
    import sys

    return ImportError(
        f"covsim was built for {_build.python} (Python {_build.version}); this is "
        f"{sys.executable} (Python {sys.version.split()[0]}), where it cannot load ({error}). "
        f"Run it with {_build.python}, or build covsim for this Python: "
        f"cmake -DPython_EXECUTABLE={sys.executable} ...")


try:
    import numpy as _np
    from . import _covsim
except ImportError as error:
    raise _wrong_python(error) from error

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
    (½∫|x - g|²φ, m⁴·φ). The arguments are Cells'; for many calls on one Ω keep a Cells."""
    if generators is None:
        raise ValueError("cells: give the generators, an (n, 2) array")
    return Cells(environment, density)(_np.asarray(generators, dtype=float)).to_list()


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
    box = _np.array([[x0, y0], [x1, y0], [x1, y1], [x0, y1]])
    rings = [box, outer[::-1]] + [ring for ring in environment.rings[1:]]
    vertices, codes = [], []
    for ring in rings:
        vertices += list(ring) + [ring[0]]
        codes += [Path.MOVETO] + [Path.LINETO] * (len(ring) - 1) + [Path.CLOSEPOLY]
    ax.add_patch(PathPatch(Path(_np.array(vertices), codes), facecolor=color, edgecolor="none"))
    ax.set_xlim(x0, x1)
    ax.set_ylim(y0, y1)
    ax.set_aspect("equal")


def _renamed(error, file, name):
    """A ScenarioError like error, with `file` in its message and attribute read as name."""
    renamed = ScenarioError(str(error).replace(file, name))
    renamed.file = name if error.file == file else error.file
    renamed.path = error.path
    return renamed


def _as_scenario(s):
    if isinstance(s, Scenario):
        return s
    if isinstance(s, dict):
        return Scenario.from_dict(s)
    return Scenario.from_file(_os.fspath(s))


def _progress_reporter(progress):
    """The callback for sweep(progress=...): a callable as given; True: a tqdm bar where
    tqdm is installed, else a line per run on stderr, as `covsim sweep` writes off a
    terminal; None or False: none."""
    if progress is None or progress is False:
        return None
    if callable(progress):
        return progress
    if progress is not True:
        raise ValueError(f"sweep(progress={progress!r}): expected None, True or a callable "
                         "(done, failed, total)")
    try:
        from tqdm import tqdm
    except ImportError:
        def line(done, failed, total):
            if done > 0:
                print(f"sweep: {done}/{total} runs done, {failed} failed", file=_sys.stderr,
                      flush=True)
        return line
    bar = {}

    def update(done, failed, total):
        if "bar" not in bar:
            bar["bar"] = tqdm(total=total, initial=done, unit="run", desc="sweep")
        b = bar["bar"]
        b.set_postfix(failed=failed, refresh=False)
        b.update(done - b.n)
        if done == total:
            b.close()
    return update


def sweep(spec, jobs=1, out=None, keep_series=False, progress=None):
    """Runs a sweep (docs/sweeps.md) on `jobs` C++ threads, the GIL released. spec: a sweep
    file's path, or its object (a "scenario" given by path is relative to the current
    folder). out: the output folder (runs/, runs.csv, summary.csv); a temporary one if None.
    keep_series: keep each run's metrics as out/runs/<index>.metrics.csv (give out).
    progress: a callable (done, failed, total), called before the first run and after each
    (one call at a time; an exception it raises ends the sweep once the runs under way
    end); True: a tqdm bar where tqdm is installed, else a line per run on stderr.
    Returns the rows of runs.csv: a pandas DataFrame when pandas can be imported, else a list
    of dicts. Every setting is validated before anything runs (a ScenarioError naming the
    value). Results do not depend on jobs. A rerun into the same out reuses every finished run
    (docs/sweeps.md), as `covsim sweep` does: a spec object is kept as out/spec.json, so that
    the sweep file of both calls is the same."""
    try:
        count = None if isinstance(jobs, bool) else _operator.index(jobs)
    except TypeError:
        count = None
    if count is None or not 1 <= count <= 1024:
        raise ValueError(f"sweep(jobs={jobs!r}): expected an integer from 1 to 1024, as "
                         "covsim sweep --jobs")
    jobs = count
    reporter = _progress_reporter(progress)
    with _tempfile.TemporaryDirectory(prefix="covsim-sweep-") as scratch:
        if isinstance(spec, dict):
            spec = dict(spec)
            if isinstance(spec.get("scenario"), str):
                spec["scenario"] = _os.path.abspath(spec["scenario"])
            folder = scratch
            if out is not None:
                folder = _os.path.abspath(_os.fspath(out))
                _os.makedirs(folder, exist_ok=True)
            path = _os.path.join(folder, "spec.json" if out is not None else "sweep.json")
            with open(path, "w") as f:
                _json.dump(spec, f)
        else:
            path = _os.fspath(spec)
        try:
            rows = _covsim._sweep(path, _os.fspath(out) if out is not None else
                                  _os.path.join(scratch, "out"), int(jobs), bool(keep_series),
                                  reporter)
        except ScenarioError as e:
            if path.startswith(scratch):
                # The spec object was written to a scratch file the user never saw: name the
                # call instead.
                raise _renamed(e, path, "sweep(spec)") from None
            raise
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
        return _np.column_stack([self.trajectory["x"][rows], self.trajectory["y"][rows]])

    def virtual_path(self, robot):
        rows = self.trajectory["robot"] == robot
        return _np.column_stack([self.trajectory["vx"][rows], self.trajectory["vy"][rows]])


def _columns(path):
    opener = _gzip.open if path.endswith(".gz") else open
    with opener(path, "rt", newline="") as f:
        reader = _csv.reader(f)
        header = next(reader)
        rows = [[float(v) for v in row] for row in reader]
    data = _np.array(rows, dtype=float).reshape(len(rows), len(header))
    out = {}
    for k, name in enumerate(header):
        column = data[:, k]
        out[name] = column.astype(_np.int64) if name == "robot" else column
    return out


def _trajectory_file(folder):
    """The trajectory file of a run folder: trajectory.csv, or trajectory.csv.gz when the run
    was compressed (pandas.read_csv and numpy.loadtxt read either)."""
    folder = _os.fspath(folder)
    plain = _os.path.join(folder, "trajectory.csv")
    compressed = plain + ".gz"
    if _os.path.exists(compressed):
        if _os.path.exists(plain):
            raise ValueError(f"{folder}: holds both trajectory.csv and trajectory.csv.gz; "
                             "remove the one not of this run")
        return compressed
    return plain


def load_run(folder):
    """Reads a run folder (final.json, scenario.json, trajectory.csv or trajectory.csv.gz,
    metrics.csv)."""
    folder = _os.fspath(folder)
    with open(_os.path.join(folder, "final.json")) as f:
        final = _json.load(f)
    with open(_os.path.join(folder, "scenario.json")) as f:
        scenario = _json.load(f)
    return Run(final, scenario, _columns(_trajectory_file(folder)),
               _columns(_os.path.join(folder, "metrics.csv")))
