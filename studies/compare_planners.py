#!/usr/bin/python3
"""Regenerates the tables of docs/planners.md and docs/planners/*.svg.

Every registered planner under every coverage law that computes its own targets (`covsim
list planners --names`, `covsim list laws --names --autonomous`: the registry is the one
list of names) on the paper's scenarios and on 20 random environments (`covsim random-env
--seed k`, k = 1..20), one sweep of one seed per environment (runs are deterministic). Then
the paper's Fig. 2 section (studies/fig2_baselines.py).

Usage: python3 studies/compare_planners.py [--jobs N]   (results are the same for any N)
The sweeps resume: a rerun into out/compare-planners/ reuses every run already there; all
runs in one table go to out/compare-planners/all.csv. The text around the generated
sections of docs/planners.md is written from traced runs, not here.
"""
import argparse
import math
import os
import sys

import pandas as pd

import fig2_baselines
import study

WORK = study.ROOT / "out" / "compare-planners"
FIGURES = study.DOCS / "planners"
PAPER = ["l_shape", "u_shape", "two_obstacles", "fig2b", "fig2c", "fig2d", "office"]
RANDOM = [f"random_{k}" for k in range(1, 21)]
REFERENCE_PLANNER = "visibility_graph"
REFERENCE_LAW = "virtual_generators"

# runs.csv's columns in the joint table, by their short names there.
COLUMNS = {"controller.type": "controller", "planner.type": "planner", "stop_reason": "stop",
           "converged": "converged", "sim_time": "time", "cost_real": "cost",
           "path_length": "path", "planner_step_time": "step_us",
           "target_outside_steps": "outside", "stalled_time": "stalled"}


def names(*args):
    return study.covsim_cli("list", *args, "--names").split()


def run_sweeps(jobs):
    """One sweep per environment; returns every run in one table (COLUMNS, and the
    scenario), in the sweeps' order."""
    planners = names("planners")
    laws = names("laws", "--autonomous")
    (WORK / "envs").mkdir(parents=True, exist_ok=True)
    for s in RANDOM:
        study.covsim_cli("random-env", "--seed", s.split("_")[1], "--out",
                         WORK / "envs" / f"{s}.json", quiet=True)
    tables = []
    for s in PAPER + RANDOM:
        scenario = study.ROOT / "scenarios" / f"{s}.json"
        if not scenario.exists():
            scenario = WORK / "envs" / f"{s}.json"
        grid = {"controller.type": laws, "planner.type": planners}
        if s == "office":
            # A coarser geodesic lattice (0.2 m) keeps geodesic_lloyd's 30 robots affordable.
            grid["controller.geodesic_lloyd.resolution"] = [0.2]
        study.sweep(study.write_sweep(WORK / f"{s}.json", scenario, grid, seeds=[1]),
                    WORK / s, jobs)
        runs = study.read_runs(WORK / s)
        tables.append(runs[list(COLUMNS)].rename(columns=COLUMNS).assign(scenario=s))
    table = pd.concat(tables, ignore_index=True)
    return table[["scenario"] + list(COLUMNS.values())]


def with_path_ratio(table):
    """Adds path_ratio: the path relative to the visibility-graph planner's under the same
    controller in the same environment (NaN where that path is not positive)."""
    reference = (table[table["planner"] == REFERENCE_PLANNER]
                 .set_index(["scenario", "controller"])["path"])
    ref = pd.Series([reference.get((s, c), math.nan)
                     for s, c in zip(table["scenario"], table["controller"])], index=table.index)
    return table.assign(path_ratio=(table["path"] / ref).where(ref > 0))


def scenario_table(table, scenario):
    rows = []
    for _, r in table[table["scenario"] == scenario].iterrows():
        rows.append([r["controller"], r["planner"], r["stop"], f"{r['time']:.1f}",
                     f"{r['path_ratio']:.2f}", f"{r['cost']:.5g}", f"{r['outside']:.0f}",
                     f"{r['stalled']:.1f}", f"{r['step_us']:.2f}"])
    return study.markdown_table(
        ["controller", "planner", "outcome", "time [s]", "path / visibility graph",
         "final cost H", "target outside Ω [steps]", "stalled [s]", "planner step [µs]"],
        rows, [False] * 3 + [True] * 6)


def random_summary(table):
    """Per (controller, planner), over the random environments: runs, converged, stuck, the
    mean time of the converged runs, the mean path ratio, the mean final cost relative to
    the paper's controller with the visibility-graph planner, the mean planner step."""
    runs = table[table["scenario"].isin(RANDOM)]
    reference = runs[(runs["controller"] == REFERENCE_LAW) &
                     (runs["planner"] == REFERENCE_PLANNER)].set_index("scenario")["cost"]
    runs = runs.assign(cost_ratio=runs["cost"] / runs["scenario"].map(reference))
    runs = runs.assign(cost_ratio=runs["cost_ratio"].where(runs["scenario"].map(reference) > 0))
    rows = []
    for (controller, planner), g in runs.groupby(["controller", "planner"], sort=False):
        converged = g[g["converged"] == 1]
        rows.append({
            "controller": controller, "planner": planner, "runs": len(g),
            "converged": int(g["converged"].sum()), "stuck": int((g["stop"] == "stuck").sum()),
            "time": converged["time"].mean() if len(converged) else math.nan,
            "path_ratio": g["path_ratio"].mean(), "cost_ratio": g["cost_ratio"].mean(),
            "step_us": g["step_us"].mean()})
    return pd.DataFrame(rows)


def random_table(summary):
    def fixed(v, digits, missing):
        return missing if math.isnan(v) else f"{v:.{digits}f}"

    rows = [[r["controller"], r["planner"], f"{r['converged']}/{r['runs']}", f"{r['stuck']}",
             fixed(r["time"], 1, "-"), fixed(r["path_ratio"], 2, "0.00"),
             fixed(r["cost_ratio"], 3, "0.000"), f"{r['step_us']:.2f}"]
            for _, r in summary.iterrows()]
    return study.markdown_table(
        ["controller", "planner", "converged", "stuck", "mean time to converge [s]",
         "path / visibility graph", "final cost / paper + visibility graph",
         "planner step [µs]"], rows, [False] * 2 + [True] * 6)


def bar_chart(plt, table, value, title, label, file):
    """A group per planner, a bar per controller: the value's mean over the random
    environments (runs where it is undefined left out)."""
    runs = table[table["scenario"].isin(RANDOM)]
    means = runs.groupby(["planner", "controller"], sort=False)[value].mean()
    planners = list(dict.fromkeys(runs["planner"]))
    controllers = list(dict.fromkeys(runs["controller"]))
    width = 0.8 / len(controllers)
    fig, ax = plt.subplots(figsize=(7.2, 4.0), constrained_layout=True)
    for k, c in enumerate(controllers):
        ax.bar([i + (k - (len(controllers) - 1) / 2) * width for i in range(len(planners))],
               [means.get((p, c), math.nan) for p in planners], width, label=c)
    ax.set_xticks(range(len(planners)), planners, fontsize=8)
    ax.set_ylabel(label)
    ax.set_title(title, fontsize=10)
    ax.grid(True, axis="y", linewidth=0.4, alpha=0.5)
    ax.set_axisbelow(True)
    ax.legend(fontsize=8)
    study.save_svg(fig, file)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--jobs", type=int, default=os.cpu_count())
    args = ap.parse_args()
    plt = study.pyplot("covsim-compare-planners")
    table = with_path_ratio(run_sweeps(args.jobs))
    table.to_csv(WORK / "all.csv", index=False)

    bar_chart(plt, table, "converged", "Converged, share of the 20 random environments",
              "convergence rate", FIGURES / "convergence.svg")
    bar_chart(plt, table, "path_ratio",
              "Total path length / visibility-graph planner's (random environments)",
              "path ratio", FIGURES / "path-ratio.svg")
    bar_chart(plt, table, "step_us", "Planner compute time per step (random environments)",
              "microseconds", FIGURES / "step-time.svg")

    section = ["## The paper's scenarios", ""]
    for s in PAPER:
        section += [f"### {s}", ""] + scenario_table(table, s) + [""]
    study.replace_section(study.DOCS / "planners.md", "planners-paper", section)
    section = [
        "## 20 random environments",
        "",
        "`covsim random-env --seed k` for k = 1..20: star-shaped outer rings of 14 vertices in",
        "a 4 m square, up to 3 convex holes, 6 robots. Final cost is relative to the paper's",
        "controller with the visibility-graph planner in the same environment.",
        "",
        *random_table(random_summary(table)),
        "",
        "![convergence rate](planners/convergence.svg)",
        "",
        "![path length ratio](planners/path-ratio.svg)",
        "",
        "![planner step time](planners/step-time.svg)",
    ]
    study.replace_section(study.DOCS / "planners.md", "planners-random", section)
    fig2_baselines.main()
    print(f"wrote {study.DOCS / 'planners.md'}", file=sys.stderr)


if __name__ == "__main__":
    study.run(main)
