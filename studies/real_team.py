#!/usr/bin/python3
"""Runs the real-team study (an unknown room, noisy pose and ranges, bodies and the radio)
and writes its table.

Robots that do not know Ω (`environment.known` "none", sensor range 2 m) on dead_ends (8
robots drawn per seed below the comb) and office (30 robots from the file's starts), with
what a real team brings, alone and together:

- localization: exact, or an overhead tracking system (`robots.localization` "tracking",
  10 Hz) with 5 mm or 2 cm of noise on each axis;
- range noise: none, or 1 cm (`sensor.noise.sigma`); with either of these uncertain readings
  the robots map on a log-odds occupancy grid (docs/scenario-format.md);
- planner: tangent_bug (the paper's), grid_astar, visibility_graph (the last two on the map
  their robot sensed, implied when Ω is unknown);
- the team: bodies of radius 0.05 m, ORCA between them, a differential drive, and Bernoulli
  loss of 10% on every link (decentralized: each robot its own map, shared as grid patches).

dead_ends runs every combination on seeds 1-5 (max_time 1500 s); office only exact and both
tracking noises with range noise on, tangent_bug and grid_astar, without the team (with it an
office run takes tens of minutes), on seeds 1-2 (max_time 3000 s), plus the exact,
noise-free reference of each planner. Every run also runs with Ω known from the same starts
and seed (`mapping.compare_known`), which gives mapping.cost_ratio. With bodies covsim draws
dead_ends' starts at least two radii apart and a radius from the walls (the study checks
both), so a team run starts from another draw than the point run of the same seed: each is
compared with the exact, noise-free run of its own team setting.

Per setting: runs converged; simulated time at the end (median [least, largest]); the final
real cost over the same seed's run with exact localization and no range noise (same planner
and team setting); mapping.cost_ratio; the occupancy grid's errors (mapping.false_occupied
and false_free, means); robot-seconds of body contact and motion steps with a body on a wall
(totals over the seeds); the localization error (mean). Below the table, every run that did
not converge and every run whose cost ratio (either) exceeds 1.05.

Usage: python3 studies/real_team.py [--covsim PATH] [--jobs N] [--keep-going] [--markdown FILE]
A run covsim cannot finish (a crash: no final.json) stops the study, or with --keep-going is
listed in the section and run again by the next study. A planner failure (exit code 1 with
final.json, stop_reason planner_failure) is a result: it counts as not converged.
Runs are cached in out/study-real-team/ (one covsim output folder each, trajectory.csv.gz
included); a rerun reuses those the same build wrote and reruns the others. The table goes
to docs/studies.md's generated section "real_team" (and to --markdown).
"""
import argparse
import json
import math
import os
import re
import shutil
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor

import numpy as np

import study

WORK = study.ROOT / "out" / "study-real-team"
RANGE = 2.0  # m
RADIUS = 0.05  # m
LOSS = 0.1

LOCALIZATIONS = {  # label -> robots.localization
    "exact": {"type": "exact"},
    "tracking 5 mm": {"type": "tracking", "noise": 0.005},
    "tracking 2 cm": {"type": "tracking", "noise": 0.02},
}
NOISES = [0.0, 0.01]  # m, sensor.noise.sigma (0: no noise)
TEAM = {"robots.radius": RADIUS, "robots.avoidance": {"type": "orca"},
        "robots.kinematics": {"type": "differential_drive"},
        "network.loss": {"model": "bernoulli", "p": LOSS}}


def settings_of(planners, locs, noises, teams):
    """(planner, localization, noise, team) of every setting: the grid given, and the
    exact, noise-free reference of each planner and team setting."""
    out = []
    for team in teams:
        for planner in planners:
            ref = (planner, "exact", 0.0, team)
            rows = [(planner, l, n, team) for l in locs for n in noises]
            out += ([] if ref in rows else [ref]) + rows
    return out


SCENARIOS = {
    "dead_ends": {"robots": 8, "max_time": 1500, "seeds": [1, 2, 3, 4, 5],
                  "settings": settings_of(["tangent_bug", "grid_astar", "visibility_graph"],
                                          list(LOCALIZATIONS), NOISES, [False, True])},
    "office": {"robots": 30, "max_time": 3000, "seeds": [1, 2],
               # Without the team: with it a run takes far longer than the study can afford
               # (docs/studies.md).
               "settings": settings_of(["tangent_bug", "grid_astar"], list(LOCALIZATIONS),
                                       [0.01], [False])},
}


def noise_text(n):
    return "none" if n == 0 else f"{100 * n:g} cm"


def name(scenario, planner, loc, noise, team, seed):
    loc = {"exact": "exact", "tracking 5 mm": "t0.005", "tracking 2 cm": "t0.02"}[loc]
    return f"{scenario}-{planner}-{loc}-n{noise:g}-{'team' if team else 'points'}-s{seed}"


def overrides(scenario, planner, loc, noise, team):
    sets = {"environment.known": "none", "sensor.range": RANGE,
            "mapping.compare_known": True,
            "convergence.max_time": SCENARIOS[scenario]["max_time"],
            "planner.type": planner, "robots.localization": LOCALIZATIONS[loc]}
    if noise > 0:
        sets["sensor.noise"] = {"sigma": noise}
    if team:
        sets.update(TEAM)
    return [f"{k}={json.dumps(v)}" for k, v in sets.items()]


# ---------------------------------------------------------------------------------------
# Runs


BUILD = None  # set by main(): the build a cached run must come from to be reused


KEEP_GOING = False  # set by main(): --keep-going


def command(scenario, planner, loc, noise, team, seed, out):
    """The covsim run of a job, as arguments."""
    args = ["covsim", "run", f"scenarios/{scenario}.json", "--seed", str(seed), "--out", out,
            "--compress"]
    for s in overrides(scenario, planner, loc, noise, team):
        args += ["--set", s]
    return args


def shell(args):
    return " ".join(a if re.fullmatch(r"[\w./=-]+", a) else "'" + a + "'" for a in args)


def run(covsim, job):
    """One run into WORK/<name>/ (written as <name>.partial, renamed when done); its
    final.json, with the run's wall time. A run covsim could not finish (it crashed: no
    final.json) stops the study, or with --keep-going is returned as {"crashed": ...} and run
    again by the next study."""
    folder = WORK / name(*job)
    final = folder / "final.json"
    if not study.made_by(final, BUILD):
        partial = folder.with_name(folder.name + ".partial")
        shutil.rmtree(partial, ignore_errors=True)
        args = command(*job, str(partial))
        args[0] = str(covsim)
        args[2] = str(study.ROOT / args[2])
        print(f"run {folder.name}", file=sys.stderr, flush=True)
        start = time.monotonic()
        result = subprocess.run(args, text=True, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
        wall = time.monotonic() - start
        (WORK / f".{partial.name}.lock").unlink(missing_ok=True)  # covsim's, left behind
        if result.returncode != 0 and not planner_failure(partial, result.returncode):
            message = (f"covsim failed with exit code {result.returncode}"
                       + (f" (signal {-result.returncode})" if result.returncode < 0 else "")
                       + (f": {result.stderr.strip()[-2000:]}" if result.stderr.strip() else ""))
            if not KEEP_GOING:
                raise study.StudyError(f"{folder.name}: {message}")
            shutil.rmtree(partial, ignore_errors=True)
            shutil.rmtree(partial.with_name(partial.name + ".partial"), ignore_errors=True)
            return {"crashed": message, "command": shell(command(*job, f"out/{folder.name}")),
                    "wall_time": wall}
        (partial / "covsim.log").write_text(result.stdout + result.stderr)
        (partial / "wall_time").write_text(f"{wall:.1f}\n")
        shutil.rmtree(folder, ignore_errors=True)
        partial.replace(folder)
    out = json.loads(final.read_text())
    wall = folder / "wall_time"
    out["wall_time"] = float(wall.read_text()) if wall.exists() else math.nan
    check(folder, out, job)
    return out


def planner_failure(folder, code):
    """Whether covsim's exit code 1 is a planner failure, a result it writes (docs/outputs.md,
    stop_reason): a planner declared a goal in Ω unreachable and the run stopped there."""
    final = folder / "final.json"
    return code == 1 and final.exists() and \
        json.loads(final.read_text())["stop_reason"] == "planner_failure"


def check(folder, out, job):
    """What the run must be: the map model its readings call for, decentralized with the
    team, and the bodies' starts apart and clear of the walls."""
    _scenario, _planner, loc, noise, team, _seed = job
    model = "polygons" if loc == "exact" and noise == 0 else "occupancy"
    if out["mapping"]["model"] != model:
        raise study.StudyError(f"{folder.name}: mapping.model is {out['mapping']['model']}, "
                               f"expected {model}")
    if out["network"]["decentralized"] != team:
        raise study.StudyError(f"{folder.name}: network.decentralized is "
                               f"{out['network']['decentralized']}")
    if team:
        s = json.loads((folder / "scenario.json").read_text())
        gap, wall = start_clearance(s)
        if gap < 2 * RADIUS or wall < RADIUS:
            raise study.StudyError(f"{folder.name}: starts {gap:.3f} m apart and {wall:.3f} m "
                                   f"from a wall, radius {RADIUS}")


def start_clearance(s):
    """The least distance between two starts and from a start to ∂Ω."""
    p = np.asarray(s["robots"]["positions"], dtype=float)
    d = np.linalg.norm(p[:, None, :] - p[None, :, :], axis=2)
    d[np.diag_indices(len(p))] = np.inf
    wall = np.inf
    for ring in [s["environment"]["outer"]] + s["environment"].get("holes", []):
        a = np.asarray(ring, dtype=float)
        b = np.roll(a, -1, axis=0)
        ab = b - a
        t = np.clip(((p[:, None, :] - a[None]) * ab[None]).sum(2) / (ab * ab).sum(1)[None], 0, 1)
        q = a[None] + t[..., None] * ab[None]
        wall = min(wall, float(np.linalg.norm(p[:, None, :] - q, axis=2).min()))
    return float(d.min()), wall


def jobs_of():
    return [(s, *setting, seed) for s, spec in SCENARIOS.items()
            for setting in spec["settings"] for seed in spec["seeds"]]


def with_reference(results):
    """Each run's final real cost over the same seed's exact, noise-free run (same scenario,
    planner and team setting); None where either stopped at a planner failure."""
    for (s, planner, loc, noise, team, seed), out in results.items():
        ref = results[(s, planner, "exact", 0.0, team, seed)]
        if "crashed" in out:
            continue
        failed = "crashed" in ref or "planner_failure" in (out["stop_reason"],
                                                           ref["stop_reason"])
        out["cost_to_reference"] = None if failed else out["cost"]["real"] / ref["cost"]["real"]


# ---------------------------------------------------------------------------------------
# Cells


def spread(v, fmt):
    """Median [least, largest]; '–' without values."""
    v = np.asarray([x for x in v if x is not None], dtype=float)
    if len(v) == 0:
        return "–"
    if np.all(v == v[0]):
        return fmt % v[0]
    return f"{fmt % np.median(v)} [{fmt % v.min()}, {fmt % v.max()}]"


def mean_percent(v):
    v = [x for x in v if x is not None]
    return "–" if not v else f"{100 * np.mean(v):.2f}%"


def total(v, fmt):
    return fmt % sum(v)


COLUMNS = [("planner", False), ("localization", False), ("range noise", False),
           ("team", False), ("converged", True), ("time [s]", True),
           ("cost / exact, no noise", True), ("cost / Ω known", True),
           ("false occupied", True), ("false free", True), ("contact [robot-s]", True),
           ("wall contacts", True), ("localization error [mm]", True)]


def row(setting, runs):
    planner, loc, noise, team = setting
    crashed = sum("crashed" in r for r in runs)
    runs = [r for r in runs if "crashed" not in r]
    failed = sum(r["stop_reason"] == "planner_failure" for r in runs)
    # A planner failure stops the run at once: its time and costs are of no configuration
    # the method reached, and are left out.
    runs = [r for r in runs if r["stop_reason"] != "planner_failure"]
    m = [r["mapping"] for r in runs]
    occupancy = loc != "exact" or noise > 0
    converged = f"{sum(r['converged'] for r in runs)}/{len(runs) + failed + crashed}"
    notes = [f"{n} {what}{'s' if n > 1 else ''}" for n, what in
             [(failed, "planner failure"), (crashed, "crash")] if n]
    if notes:
        converged += f" ({', '.join(notes)})"
    return [planner, loc, noise_text(noise), "yes" if team else "–", converged,
            spread([r["sim_time"] for r in runs], "%.0f"),
            "(1)" if loc == "exact" and noise == 0 else
            spread([r["cost_to_reference"] for r in runs], "%.3f"),
            spread([x["cost_ratio"] for x in m], "%.3f"),
            mean_percent([x["false_occupied"] for x in m]) if occupancy else "–",
            mean_percent([x["false_free"] for x in m]) if occupancy else "–",
            total([r["bodies"]["contact_time"] for r in runs], "%.1f") if team else "–",
            total([r["bodies"]["wall_contacts"] for r in runs], "%d") if team else "–",
            f"{1000 * np.mean([r['localization']['error_mean'] for r in runs]):.1f}"
            if runs else "–"]


def setting_text(s, planner, loc, noise, team):
    return (f"{s}, {planner}, {loc}, range noise {noise_text(noise)}"
            f"{', team' if team else ''}")


def exceptions(results):
    """The runs that did not converge, and those with a cost ratio above 1.05."""
    lines = []
    for (s, planner, loc, noise, team, seed), out in results.items():
        notes = []
        if "crashed" in out:
            lines.append(f"- {setting_text(s, planner, loc, noise, team)}, seed {seed}: "
                         f"{out['crashed']} (`{out['command']}`)")
            continue
        if not out["converged"]:
            notes.append(f"stopped `{out['stop_reason']}` at {out['sim_time']:.1f} s")
            failure = out["planner_failure"]
            if failure:
                notes.append(f"robot {failure['robot']} declared its goal "
                             f"({failure['goal'][0]:.3f}, {failure['goal'][1]:.3f}) unreachable "
                             f"at ({failure['position'][0]:.3f}, {failure['position'][1]:.3f})")
        ratios = [] if out["stop_reason"] == "planner_failure" else \
            [("cost / exact, no noise", out["cost_to_reference"]),
             ("cost / Ω known", out["mapping"]["cost_ratio"])]
        for label, value in ratios:
            if value is not None and value > 1.05:
                notes.append(f"{label} {value:.3f}")
        if notes:
            lines.append(f"- {setting_text(s, planner, loc, noise, team)}, seed {seed}: "
                         f"{'; '.join(notes)} (fingerprint {out['fingerprint']})")
    return lines


def tables(results):
    lines = []
    for s, spec in SCENARIOS.items():
        lines += [f"### {s} ({spec['robots']} robots, seeds {spec['seeds'][0]}-"
                  f"{spec['seeds'][-1]}, max_time {spec['max_time']} s)", ""]
        rows = [row(setting, [results[(s, *setting, seed)] for seed in spec["seeds"]])
                for setting in spec["settings"]]
        lines += study.markdown_table([c for c, _ in COLUMNS], rows, [a for _, a in COLUMNS])
        lines.append("")
    return lines


# ---------------------------------------------------------------------------------------


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--covsim", help="the covsim program (default: the build's, built if "
                    "missing)")
    ap.add_argument("--jobs", type=int, default=os.cpu_count())
    ap.add_argument("--markdown", help="also write the section to this file")
    ap.add_argument("--keep-going", action="store_true",
                    help="a run covsim cannot finish (a crash) is listed in the section "
                    "instead of stopping the study")
    args = ap.parse_args()
    global KEEP_GOING
    KEEP_GOING = args.keep_going
    covsim = args.covsim or study.program()
    if not os.access(covsim, os.X_OK):
        raise study.StudyError(f"--covsim: {covsim} is not an executable")
    global BUILD
    BUILD = study.build_of(covsim)
    jobs = jobs_of()
    WORK.mkdir(parents=True, exist_ok=True)
    with ThreadPoolExecutor(max_workers=args.jobs) as pool:
        results = dict(zip(jobs, pool.map(lambda j: run(covsim, j), jobs)))
    with_reference(results)
    wall = sum(r["wall_time"] for r in results.values())
    lines = [f"{len(jobs)} runs (each also run with Ω known, for the cost over Ω known), "
             f"{wall / 60:.0f} minutes of run time summed over the runs. Converged: runs converged of "
             f"the seeds; a run stopped by a planner failure (a goal in Ω declared unreachable) "
             f"or by a crash counts as not converged and is left out of the other columns. "
             f"Time: simulated time at the end, median [least, largest] over the seeds (a run "
             f"that did not converge counts with the time it stopped at). Cost / exact, no "
             f"noise: the final real cost over "
             f"the same seed's run with exact localization and no range noise, same planner "
             f"and team setting; cost / Ω known: mapping.cost_ratio; both median [least, "
             f"largest]. False occupied and false free: the occupancy grid's errors at the "
             f"end, means (– with exact readings: the polygon map). Contact and wall "
             f"contacts: totals over the seeds. Team: bodies of {RADIUS} m, ORCA, differential "
             f"drive, Bernoulli loss {LOSS:g} on every link.", ""]
    lines += tables(results)
    notes = exceptions(results)
    lines += ["Runs that did not converge or ended above 1.05 times a reference:", ""]
    lines += notes if notes else ["- none"]
    lines.append("")
    study.replace_section(study.DOCS / "studies.md", "real_team", lines)
    if args.markdown:
        with open(args.markdown, "w") as f:
            f.write("\n".join(lines) + "\n")
    print(f"wrote {study.DOCS / 'studies.md'}", file=sys.stderr)


if __name__ == "__main__":
    study.run(main)
