#!/usr/bin/python3
"""Runs the unknown-environment study (mapping while covering) and writes its tables.

office (30 robots) and maze (40 robots) with Ω not known beforehand (`environment.known`:
"boundary", the outer ring known and the holes found by sensing, or "none", only the
bounding box known), across the range sensor's range (0.5 m, 2 m, unlimited) and Bernoulli
loss on every link (p = 0, 0.3, 0.6), each on seeds 1..3, from the scenarios' own starts.
Every such run is decentralized: the Bernoulli model is set at p = 0 too, which makes each
robot keep its own map and share it in its broadcasts (the scenario files as they stand have
no `network` section and run on the ideal network, one shared map). Two references per
range: those shared-map runs (loss "shared" in the tables), and the same runs with Ω known
("full"). Each unknown-Ω run also runs the scenario with Ω known from the same starts and
seed (`mapping.compare_known`), which gives `mapping.cost_ratio`; the study checks that this
cost is the "full" run's final cost.

Per setting: distinct runs among the seeds (without loss nothing random is left: the seeds
give one run); runs converged; time from which the real cost stays within 1% of its final
value (convergence.time_to_1_percent); the final real cost over the Ω-known run's
(mapping.cost_ratio); when the robots' maps together first held 90% and 100% of Ω's free
area; the least fraction one robot's map held at the end; the obstacles the least-informed
robot knew whole; the disagreement between the robots' maps at the end; the map bytes
broadcast; the planners' discoveries of obstacles not yet mapped. Mean ± standard deviation
over the seeds. Where "boundary" and "none" give the same runs (an outer ring that is its
bounding box, as on both scenarios) they share one row.

Usage: python3 studies/mapping.py [--covsim PATH] [--jobs N] [--seeds N] [--markdown FILE]
Runs are cached in out/study-mapping/ (one covsim output folder each, trajectory.csv.gz
included); a rerun reuses those the same build wrote and reruns the others. The tables go
to docs/studies.md's generated section "mapping" (and to --markdown), the figure to
docs/studies/mapping-sweeps.svg.
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
# "boundary" runs once per range (seed 1, the shared map): on a scenario whose outer ring is
# its bounding box it is the "none" run, fingerprint for fingerprint.
BOUNDARY_LOSSES = ["shared"]
FULL = "full"  # the reference: Ω known
RANGES = [0.5, 2, None]  # m; None: unlimited
LOSSES = [0.0, 0.3, 0.6]  # Bernoulli p, decentralized
SHARED = "shared"  # the scenario's own ideal network: one map, no messages
SEEDS = 3


def range_text(r):
    return "∞" if r is None else f"{r:g}"


def loss_text(p):
    return p if p == SHARED else f"{p:g}"


def jobs_of(seeds):
    """(scenario, known, range, loss, seed) of every run."""
    out = []
    for s in SCENARIOS:
        for r in RANGES:
            for p in LOSSES + [SHARED]:
                out += [(s, k, r, p, seed) for k in [FULL, "none"] for seed in seeds]
            out += [(s, "boundary", r, p, seeds[0]) for p in BOUNDARY_LOSSES]
    return out


def name(scenario, known, rng, loss, seed):
    r = "inf" if rng is None else f"{rng:g}"
    return f"{scenario}-{known}-r{r}-p{loss_text(loss)}-s{seed}"


def overrides(known, rng, loss):
    # The ratio to the Ω-known run comes from the study's own "full" runs.
    sets = [f"environment.known={known}",
            f"sensor.range={'null' if rng is None else f'{rng:g}'}"]
    if known != FULL:
        sets += ["mapping.compare_known=false"]
    if loss != SHARED:
        sets += ["network.loss.model=bernoulli", f"network.loss.p={loss:g}"]
    return sets


BUILD = None  # set by main(): the build a cached run must come from to be reused


def run(covsim, job):
    """One run into WORK/<name>/ (written as <name>.partial and renamed when done); its
    final.json."""
    scenario, known, rng, loss, seed = job
    folder = WORK / name(*job)
    final = folder / "final.json"
    if not study.made_by(final, BUILD):
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
    # The largest disagreement between the maps over the run (metrics.csv).
    out["disagreement_max"] = max_column(folder / "metrics.csv", "map_disagreement")
    if out["network"]["decentralized"] != (loss != SHARED):
        raise study.StudyError(f"{folder.name}: network.decentralized is "
                               f"{out['network']['decentralized']}")
    if out["mapping"]["known"] != known:
        raise study.StudyError(f"{folder.name}: mapping.known is {out['mapping']['known']}")
    return out


def max_column(path, column):
    with open(path) as f:
        header = f.readline().strip().split(",")
        k = header.index(column)
        return max(float(line.split(",")[k]) for line in f if line.strip())


def with_ratios(results):
    """mapping.cost_ratio of each unknown-Ω run: its final cost over the "full" run's of the
    same setting and seed."""
    for (s, k, r, p, seed), out in results.items():
        if k != FULL:
            full = results[(s, FULL, r, p, seed)]["cost"]["real"]
            out["mapping"]["cost_known"] = full
            out["mapping"]["cost_ratio"] = out["cost"]["real"] / full


# ---------------------------------------------------------------------------------------
# Cells


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
    return text if len(got) == len(v) else f"{text} ({len(got)}/{len(v)}, else never)"


def fraction_cell(v):
    v = np.asarray(v, dtype=float)
    if np.all(v == 1.0):
        return "1"
    if np.all(v == v[0]):
        return f"{v[0]:.4f}"
    return f"{v.mean():.4f} (min {v.min():.4f})"


COLUMNS = [
    ("known", False), ("range [m]", True), ("loss p", True), ("distinct runs", True),
    ("converged", True), ("time to 1% [s]", True), ("cost / Ω known", True),
    ("mapped 90% [s]", True), ("mapped 100% [s]", True), ("least map [fraction]", True),
    ("obstacles, least map", True), ("largest disagreement", True),
    ("map MB sent (new)", True), ("discoveries", True)]


def row(label, rng, loss, runs):
    m = [r["mapping"] for r in runs]
    known = [x["obstacles_known_min"] for x in m]
    mapped = runs[0]["mapping"]["known"] != FULL
    return [label, range_text(rng), loss_text(loss),
            f"{len({r['fingerprint'] for r in runs})}",
            f"{sum(r['converged'] for r in runs)}/{len(runs)}",
            mean_sd([r["convergence"]["time_to_1_percent"] for r in runs], "%.0f"),
            mean_sd([x["cost_ratio"] for x in m], "%.3f") if mapped else "(1)",
            reached([x["time_to_90_percent"] for x in m], "%.0f") if mapped else "–",
            reached([x["time_to_100_percent"] for x in m], "%.0f") if mapped else "–",
            fraction_cell([x["known_fraction_min"] for x in m]) if mapped else "–",
            (f"{min(known)}" if min(known) == max(known) else f"{min(known)}–{max(known)}")
            + f" of {m[0]['obstacles']}" if mapped else "–",
            mean_sd([r["disagreement_max"] for r in runs], "%.3g") if mapped else "–",
            (mean_sd([x["bytes"] / 1e6 for x in m], "%.0f") + " ("
             + mean_sd([x["bytes_new"] / 1e6 for x in m], "%.1f") + ")") if mapped else "–",
            mean_sd([x["discoveries"] for x in m], "%.1f") if mapped else "–"]


def same_runs(results, scenario, seeds):
    """Whether "boundary" and "none" gave the same run (fingerprint) wherever both ran."""
    return all(results[(scenario, "boundary", r, p, seeds[0])]["fingerprint"]
               == results[(scenario, "none", r, p, seeds[0])]["fingerprint"]
               for r in RANGES for p in BOUNDARY_LOSSES)


def known_groups(results, scenario, seeds):
    """(label, known value whose runs the rows show) for a scenario's tables and figure."""
    if not same_runs(results, scenario, seeds):
        raise study.StudyError(f"{scenario}: \"boundary\" and \"none\" differ; the study runs "
                               f"\"boundary\" once per range only")
    return [("boundary = none", "none")]


def tables(results, seeds):
    lines = []
    for scenario in SCENARIOS:
        lines += [f"### {scenario}", ""]
        rows = []
        for label, known in [(FULL + " (Ω known)", FULL)] + known_groups(results, scenario,
                                                                           seeds):
            for r in RANGES:
                for p in LOSSES + [SHARED]:
                    rows.append(row(label, r, p, [results[(scenario, known, r, p, s)]
                                                  for s in seeds]))
        lines += study.markdown_table([c for c, _ in COLUMNS], rows, [a for _, a in COLUMNS])
        lines.append("")
    return lines


# ---------------------------------------------------------------------------------------
# The paper's scenarios: obstacles as large as the cells, notches of the outer ring


PAPER = ["u_shape", "l_shape", "two_obstacles", "fig2b", "fig2c", "fig2d", "dead_ends"]
PAPER_RANGES = [0.0, 0.1, 0.5, None]


def paper_jobs():
    return [(s, r) for s in PAPER for r in PAPER_RANGES]


def run_paper(covsim, job):
    """One run of a paper scenario with only the bounding box known (the ideal network, its
    own seed), compared by covsim with the Ω-known run (mapping.compare_known)."""
    scenario, rng = job
    folder = WORK / f"paper-{scenario}-r{'inf' if rng is None else f'{rng:g}'}"
    final = folder / "final.json"
    if not study.made_by(final, BUILD):
        partial = folder.with_name(folder.name + ".partial")
        shutil.rmtree(partial, ignore_errors=True)
        args = [str(covsim), "run", str(study.ROOT / "scenarios" / f"{scenario}.json"),
                "--out", str(partial), "--set", "environment.known=none",
                "--set", f"sensor.range={'null' if rng is None else f'{rng:g}'}"]
        print(f"run {folder.name}", file=sys.stderr, flush=True)
        result = subprocess.run(args, text=True, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
        if result.returncode != 0:
            raise study.StudyError(f"{folder.name}: covsim failed with exit code "
                                   f"{result.returncode}: {result.stderr.strip()[-2000:]}")
        shutil.rmtree(folder, ignore_errors=True)
        partial.replace(folder)
    return json.loads(final.read_text())


def paper_table(results):
    lines = ["### The paper's scenarios, only the bounding box known", ""]
    rows = []
    for (scenario, rng), out in results.items():
        m = out["mapping"]
        rows.append([scenario, range_text(rng), out["stop_reason"], f"{out['sim_time']:.1f}",
                     f"{m['cost_ratio']:.4f}", f"{m['known_fraction']:.3f}",
                     f"{m['obstacles_known_min']} of {m['obstacles']}", f"{m['discoveries']}"])
    lines += study.markdown_table(
        ["scenario", "range [m]", "stop", "time [s]", "cost / Ω known", "mapped [fraction]",
         "obstacles known", "discoveries"], rows,
        [False, True, False, True, True, True, True, True])
    return lines + [""]


# ---------------------------------------------------------------------------------------
# Figure


def plot(results, seeds, file):
    """Per scenario (columns): time to 1% of the final cost, time to map 90% of Ω, and the
    cost over the Ω-known run's, against the sensor range; a colour per loss, solid with Ω
    unknown and dotted with Ω known (top row); means over the seeds with bars of ± one
    standard deviation, the losses side by side. A run that never mapped 90% is left out
    (an open ring where some did not; 'never' where none did)."""
    plt = study.pyplot("covsim-study-mapping")
    from matplotlib.lines import Line2D

    measures = [("time to 1% of the final cost [s]",
                 lambda r: r["convergence"]["time_to_1_percent"]),
                ("maps together hold 90% of Ω [s]",
                 lambda r: r["mapping"]["time_to_90_percent"]),
                ("final cost / cost with Ω known", lambda r: r["mapping"]["cost_ratio"])]
    fig, axes = plt.subplots(len(measures), len(SCENARIOS), figsize=(9.6, 8.4),
                             constrained_layout=True, sharex=True)
    x = np.arange(len(RANGES))
    losses = LOSSES + [SHARED]
    colours = {0.0: "C0", 0.3: "C1", 0.6: "C3", SHARED: "0.35"}
    shift = {p: 0.06 * (i - (len(losses) - 1) / 2) for i, p in enumerate(losses)}
    for col, scenario in enumerate(SCENARIOS):
        groups = known_groups(results, scenario, seeds)
        for row_, (label, get) in enumerate(measures):
            ax = axes[row_][col]
            lines = [(k, p, ["-", "--"][i], "o") for i, (_g, k) in enumerate(groups)
                     for p in losses]
            if row_ == 0:
                lines += [(FULL, p, ":", "s") for p in losses]
            for known, loss, style, marker in lines:
                mid, sd, partial, never = [], [], [], []
                for rng in RANGES:
                    v = [get(results[(scenario, known, rng, loss, s)]) for s in seeds]
                    got = np.asarray([y for y in v if y is not None], dtype=float)
                    mid.append(got.mean() if len(got) else math.nan)
                    sd.append(got.std(ddof=1) if len(got) > 1 else 0.0)
                    partial.append(0 < len(got) < len(v))
                    never.append(len(got) == 0)
                xs = x + shift[loss]
                ax.errorbar(xs, mid, yerr=sd, color=colours[loss], linestyle=style,
                            marker=marker, markersize=3.5, linewidth=1.1, elinewidth=0.7,
                            capsize=1.5)
                for xi, yi, p in zip(xs, mid, partial):
                    if p:
                        ax.plot([xi], [yi], marker="o", markersize=8, color=colours[loss],
                                fillstyle="none", linestyle="none")
                if row_ == 1 and all(never[:1]) and loss == losses[0]:
                    ax.annotate("never\n(every run)", (x[0], 0.5), xycoords=("data", "axes fraction"),
                                ha="center", va="center", fontsize=8, color="0.3")
            if row_ == 2:
                ax.axhline(1.0, color="k", linewidth=0.6)
            ax.set_xticks(x, [range_text(r) for r in RANGES])
            ax.grid(True, linewidth=0.4, alpha=0.5)
            if row_ == len(measures) - 1:
                ax.set_xlabel("sensor range [m]")
            if col == 0:
                ax.set_ylabel(label)
            if row_ == 0:
                ax.set_title(f"{scenario}: 1 run per point without loss, 3 with", fontsize=9)
    handles = [Line2D([], [], color=colours[p], marker="o", markersize=3.5,
                      label=f"p = {loss_text(p)}" if p != SHARED else "shared map (ideal network)")
               for p in losses]
    unknown = " = ".join(g for g, _k in known_groups(results, SCENARIOS[0], seeds))
    handles += [Line2D([], [], color="k", linestyle="-", marker="o", markersize=3.5,
                       label=f"Ω unknown ({unknown})"),
                Line2D([], [], color="k", linestyle=":", marker="s", markersize=3.5,
                       label="Ω known")]
    axes[0][-1].legend(handles=handles, loc="lower left", ncol=2, fontsize=6.5)
    fig.suptitle(f"Mapping while covering: means ± sd over {len(seeds)} seeds (without loss "
                 f"the seeds give one run)", fontsize=9)
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
    global BUILD
    BUILD = study.build_of(covsim)
    seeds = list(range(1, args.seeds + 1))
    jobs = jobs_of(seeds)
    paper = paper_jobs()
    WORK.mkdir(parents=True, exist_ok=True)
    with ThreadPoolExecutor(max_workers=args.jobs) as pool:
        results = dict(zip(jobs, pool.map(lambda j: run(covsim, j), jobs)))
        paper_results = dict(zip(paper, pool.map(lambda j: run_paper(covsim, j), paper)))
    with_ratios(results)
    mapped = len([j for j in jobs if j[1] != FULL])
    lines = [f"{len(seeds)} seeds per setting, {len(jobs)} runs ({mapped} with Ω unknown). "
             f"Mean ± sd over the seeds; a time that never came is 'never'. Least map and "
             f"obstacles: at the end of the run; disagreement: the largest over the run's "
             f"metrics samples.", ""]
    lines += tables(results, seeds)
    lines += paper_table(paper_results)
    plot(results, seeds, FIGURE)
    lines += ["![Unknown environments: time to 1% of the final cost, time to map 90% of Ω "
              "and the cost over Ω known, against the sensor range](studies/mapping-sweeps.svg)",
              ""]
    text = "\n".join(lines) + "\n"
    study.replace_section(study.DOCS / "studies.md", "mapping", lines)
    if args.markdown:
        with open(args.markdown, "w") as f:
            f.write(text)
    print(f"wrote {FIGURE}", file=sys.stderr)


if __name__ == "__main__":
    study.run(main)
