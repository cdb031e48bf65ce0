#!/usr/bin/python3
"""Runs the unknown-environment study (mapping while covering) and prints its tables.

office (30 robots) and maze (40 robots) with Ω not known beforehand (`environment.known`:
"boundary", the outer ring known and the holes found by sensing, or "none", only the
bounding box known), across the range sensor's range (0.5 m, 2 m, unlimited) and Bernoulli
loss on every link (p = 0, 0.3, 0.6), each on seeds 1..3. Every run is decentralized: the
Bernoulli model is set at p = 0 too, which makes each robot keep its own map and share it in
its broadcasts (the scenario files as they stand have no `network` section and run on the
ideal network, one shared map). Those shared-map runs are run as well, as a reference
(loss "shared" in the tables). Each run also runs the scenario with Ω known from the same
starts and seed (`mapping.compare_known`), which gives `mapping.cost_ratio`.

Per setting: runs converged; time from which the real cost stays within 1% of its final
value (convergence.time_to_1_percent); the final real cost over the Ω-known run's
(mapping.cost_ratio); when the robots' maps together first held 90% and 100% of Ω's free
area; the least fraction one robot's map held at the end; the disagreement between the
robots' maps at the end; the map bytes broadcast; the planners' discoveries of obstacles not
yet mapped. Mean ± standard deviation over the seeds.

Usage: python3 studies/mapping.py [--covsim PATH] [--jobs N] [--seeds N] [--markdown FILE]
Runs are cached in out/study-mapping/ (one covsim output folder each, trajectory.csv.gz
included); a rerun reuses them. The tables go to standard output (and to --markdown), the
figure to docs/studies/mapping-sweeps.svg.
"""
import argparse
import json
import math
import os
import shutil
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor

import numpy as np

import study

WORK = study.ROOT / "out" / "study-mapping"
FIGURE = study.DOCS / "studies" / "mapping-sweeps.svg"
SCENARIOS = ["office", "maze"]
KNOWN = ["boundary", "none"]
RANGES = [0.5, 2, None]  # m; None: unlimited
LOSSES = [0.0, 0.3, 0.6]  # Bernoulli p, decentralized
SHARED = "shared"  # the scenario's own ideal network: one map, no messages
SEEDS = 3


def range_text(r):
    return "∞" if r is None else f"{r:g}"


def loss_text(p):
    return p if p == SHARED else f"{p:g}"


def settings(references=True):
    """(scenario, known, range, loss) of every setting, in table order."""
    losses = LOSSES + ([SHARED] if references else [])
    return [(s, k, r, p) for s in SCENARIOS for k in KNOWN for r in RANGES for p in losses]


def name(scenario, known, rng, loss, seed):
    r = "inf" if rng is None else f"{rng:g}"
    p = loss if loss == SHARED else f"{loss:g}"
    return f"{scenario}-{known}-r{r}-p{p}-s{seed}"


def overrides(known, rng, loss):
    sets = [f"environment.known={known}",
            f"sensor.range={'null' if rng is None else f'{rng:g}'}"]
    if loss != SHARED:
        sets += ["network.loss.model=bernoulli", f"network.loss.p={loss:g}"]
    return sets


def run(covsim, job):
    """One run into WORK/<name>/ (written as <name>.partial and renamed when done); its
    final.json."""
    scenario, known, rng, loss, seed = job
    folder = WORK / name(*job)
    final = folder / "final.json"
    if final.exists():
        return json.loads(final.read_text())
    partial = folder.with_name(folder.name + ".partial")
    shutil.rmtree(partial, ignore_errors=True)
    args = [str(covsim), "run", str(study.ROOT / "scenarios" / f"{scenario}.json"),
            "--seed", str(seed), "--out", str(partial), "--compress"]
    for s in overrides(known, rng, loss):
        args += ["--set", s]
    print(f"run {folder.name}", file=sys.stderr, flush=True)
    result = subprocess.run(args, text=True, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    if result.returncode != 0:
        raise study.StudyError(f"{folder.name}: covsim failed with exit code "
                               f"{result.returncode}: {result.stderr.strip()[-2000:]}")
    (partial / "covsim.log").write_text(result.stdout + result.stderr)
    shutil.rmtree(folder, ignore_errors=True)
    partial.replace(folder)
    out = json.loads(final.read_text())
    if out["network"]["decentralized"] != (loss != SHARED):
        raise study.StudyError(f"{folder.name}: network.decentralized is "
                               f"{out['network']['decentralized']}")
    return out


# ---------------------------------------------------------------------------------------
# Cells


def values(runs, get):
    return [get(r) for r in runs]


def mean_sd(v, fmt):
    """Mean ± sample standard deviation; '–' without values."""
    v = np.asarray([x for x in v if x is not None], dtype=float)
    if len(v) == 0:
        return "–"
    if len(v) == 1 or np.all(v == v[0]):
        return fmt % v.mean()
    return f"{fmt % v.mean()} ± {fmt % v.std(ddof=1)}"


def reached(v, fmt):
    """A time that may never come (null): mean ± sd of the runs that reached it, and how
    many did, or 'never'."""
    got = [x for x in v if x is not None]
    if not got:
        return "never"
    text = mean_sd(got, fmt)
    return text if len(got) == len(v) else f"{text} ({len(got)}/{len(v)}; never {len(v) - len(got)})"


def fraction_cell(v):
    v = np.asarray(v, dtype=float)
    if np.all(v == 1.0):
        return "1"
    return f"{v.mean():.3f} (min {v.min():.3f})"


COLUMNS = [
    ("known", False), ("range [m]", True), ("loss p", True), ("distinct runs", True),
    ("converged", True),
    ("time to 1% [s]", True), ("cost / Ω known", True), ("mapped 90% [s]", True),
    ("mapped 100% [s]", True), ("least map [fraction]", True), ("obstacles, least map", True),
    ("disagreement", True), ("map MB sent", True), ("discoveries", True)]


def row(known, rng, loss, runs):
    m = [r["mapping"] for r in runs]
    return [known, range_text(rng), loss_text(loss),
            f"{len({r['fingerprint'] for r in runs})}",
            f"{sum(r['converged'] for r in runs)}/{len(runs)}",
            mean_sd(values(runs, lambda r: r["convergence"]["time_to_1_percent"]), "%.0f"),
            mean_sd([x["cost_ratio"] for x in m], "%.3f"),
            reached([x["time_to_90_percent"] for x in m], "%.0f"),
            reached([x["time_to_100_percent"] for x in m], "%.0f"),
            fraction_cell([x["known_fraction_min"] for x in m]),
            f"{min(x['obstacles_known_min'] for x in m)}–{max(x['obstacles_known_min'] for x in m)}"
            f" of {m[0]['obstacles']}",
            mean_sd([x["disagreement"] for x in m], "%.3f"),
            mean_sd([x["bytes"] / 1e6 for x in m], "%.0f"),
            mean_sd([x["discoveries"] for x in m], "%.1f")]


def tables(results, seeds):
    lines = []
    for scenario in SCENARIOS:
        lines += [f"### {scenario}", ""]
        rows = []
        for (s, k, r, p) in settings():
            if s == scenario:
                rows.append(row(k, r, p, [results[(s, k, r, p, seed)] for seed in seeds]))
        lines += study.markdown_table([c for c, _ in COLUMNS], rows, [a for _, a in COLUMNS])
        lines.append("")
    return lines


# ---------------------------------------------------------------------------------------
# Figure


def plot(results, seeds, file):
    """Per scenario (columns): time to 1% of the final cost, time to map 90% of Ω, and the
    cost over the Ω-known run's, against the sensor range; a line per loss, solid for known
    boundary and dashed for none; points are means over the seeds, a run that never mapped
    90% left out (an open marker where some were)."""
    plt = study.pyplot("covsim-study-mapping")
    measures = [("time to 1% of the final cost [s]",
                 lambda r: r["convergence"]["time_to_1_percent"]),
                ("maps together hold 90% of Ω [s]",
                 lambda r: r["mapping"]["time_to_90_percent"]),
                ("final cost / cost with Ω known", lambda r: r["mapping"]["cost_ratio"])]
    fig, axes = plt.subplots(len(measures), len(SCENARIOS), figsize=(9.6, 8.4),
                             constrained_layout=True, sharex=True)
    x = np.arange(len(RANGES))
    colours = {0.0: "C0", 0.3: "C1", 0.6: "C3", SHARED: "0.4"}
    for col, scenario in enumerate(SCENARIOS):
        for row_, (label, get) in enumerate(measures):
            ax = axes[row_][col]
            for known, style in [("boundary", "-"), ("none", "--")]:
                for loss in LOSSES + [SHARED]:
                    ys, partial = [], []
                    for rng in RANGES:
                        v = [get(results[(scenario, known, rng, loss, s)]) for s in seeds]
                        got = [y for y in v if y is not None]
                        ys.append(np.mean(got) if got else math.nan)
                        partial.append(0 < len(got) < len(v))
                    ys = np.asarray(ys)
                    ax.plot(x, ys, color=colours[loss], linestyle=style, marker="o",
                            markersize=4, linewidth=1.2 if loss != SHARED else 0.8,
                            label=f"{known}, p={loss_text(loss)}")
                    for xi, yi, p in zip(x, ys, partial):
                        if p:
                            ax.plot([xi], [yi], marker="o", markersize=8, color=colours[loss],
                                    fillstyle="none", linestyle="none")
            if row_ == 2:
                ax.axhline(1.0, color="k", linewidth=0.6)
            ax.set_xticks(x, [range_text(r) for r in RANGES])
            ax.grid(True, linewidth=0.4, alpha=0.5)
            if row_ == len(measures) - 1:
                ax.set_xlabel("sensor range [m]")
            if col == 0:
                ax.set_ylabel(label)
            if row_ == 0:
                ax.set_title(scenario, fontsize=10)
    axes[0][1].legend(fontsize=7, ncol=2)
    fig.suptitle(f"Unknown Ω: solid known boundary, dashed none; loss p per colour (shared: "
                 f"one map); means over {len(seeds)} seeds", fontsize=9)
    study.save_svg(fig, file)


# ---------------------------------------------------------------------------------------


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--covsim", help="the covsim program (default: the build's, built if "
                    "missing)")
    ap.add_argument("--jobs", type=int, default=os.cpu_count())
    ap.add_argument("--seeds", type=int, default=SEEDS)
    ap.add_argument("--markdown", help="also write the tables to this file")
    args = ap.parse_args()
    covsim = args.covsim or study.program()
    if not os.access(covsim, os.X_OK):
        raise study.StudyError(f"--covsim: {covsim} is not an executable")
    seeds = list(range(1, args.seeds + 1))
    jobs = [(*setting, seed) for setting in settings() for seed in seeds]
    WORK.mkdir(parents=True, exist_ok=True)
    with ThreadPoolExecutor(max_workers=args.jobs) as pool:
        results = dict(zip(jobs, pool.map(lambda j: run(covsim, j), jobs)))
    lines = [f"{len(seeds)} seeds per setting, {len(jobs)} runs (each with its Ω-known "
             f"comparison run). Mean ± sd over the seeds; a time that never came is "
             f"'never' (with how many runs reached it where some did).", ""]
    lines += tables(results, seeds)
    plot(results, seeds, FIGURE)
    lines += ["![Unknown environments: time to 1% of the final cost, time to map 90% of Ω "
              "and the cost over Ω known, against the sensor range](studies/mapping-sweeps.svg)",
              ""]
    text = "\n".join(lines) + "\n"
    print(text, end="")
    if args.markdown:
        with open(args.markdown, "w") as f:
            f.write(text)
    print(f"wrote {FIGURE}", file=sys.stderr)


if __name__ == "__main__":
    study.run(main)
