#!/usr/bin/python3
"""Compares the planners: regenerates docs/planners.md's tables, or writes them for your scenarios.

Every registered planner under every coverage law that computes its own targets (`covsim
list planners --names`, `covsim list laws --names --autonomous`: the registry is the one
list of names), or those named by --planners and --laws.

Usage: python3 studies/compare_planners.py [--jobs N]
  the paper's scenarios and 20 random environments (`covsim random-env --seed k`, k =
  1..20), one seed each (their runs are deterministic); rewrites docs/planners.md's tables
  and docs/planners/*.svg, then the paper's Fig. 2 section (studies/fig2_baselines.py).
Usage: python3 studies/compare_planners.py SCENARIO... --out DIR [--seeds N] [--planners A,B]
       [--laws A,B] [--jobs N]
  your scenarios, each with seeds 1..N (draw their starts per seed for N > 1:
  docs/sweeps.md, "Seeds that differ"): DIR/report.md (a table per scenario, a summary over
  them), DIR/*.svg and DIR/all.csv; the docs are left alone.
Results are the same for any N of --jobs. The sweeps resume: a rerun into the same folder
reuses every run already there. The text around the generated sections of docs/planners.md
is written from traced runs, not here.
"""
import argparse
import math
import os
import sys
from pathlib import Path

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


def run_sweeps(jobs, scenarios, work, seeds, planners, laws):
    """One sweep per scenario (name -> file) into work/<name>; returns every run in one
    table (COLUMNS, the scenario and the seed), in the sweeps' order."""
    tables = []
    for s, scenario in scenarios.items():
        grid = {"controller.type": laws, "planner.type": planners}
        if s == "office":
            # A coarser geodesic lattice (0.2 m) keeps geodesic_lloyd's 30 robots affordable.
            grid["controller.geodesic_lloyd.resolution"] = [0.2]
        study.sweep(study.write_sweep(work / f"{s}.json", scenario, grid, seeds=seeds),
                    work / s, jobs)
        runs = study.read_runs(work / s)
        tables.append(runs[list(COLUMNS)].rename(columns=COLUMNS)
                      .assign(scenario=s, seed=runs["seed"].astype(int)))
    table = pd.concat(tables, ignore_index=True)
    return table[["scenario", "seed"] + list(COLUMNS.values())]


def docs_scenarios():
    """The paper's scenarios and the 20 random environments (written into WORK/envs)."""
    (WORK / "envs").mkdir(parents=True, exist_ok=True)
    for s in RANDOM:
        study.covsim_cli("random-env", "--seed", s.split("_")[1], "--out",
                         WORK / "envs" / f"{s}.json", quiet=True)
    out = {s: study.ROOT / "scenarios" / f"{s}.json" for s in PAPER}
    out.update({s: WORK / "envs" / f"{s}.json" for s in RANDOM})
    return out


def with_path_ratio(table):
    """Adds path_ratio: the path relative to the visibility-graph planner's under the same
    controller in the same environment and seed (NaN where that path is not positive or
    the visibility graph was not compared)."""
    reference = (table[table["planner"] == REFERENCE_PLANNER]
                 .set_index(["scenario", "controller", "seed"])["path"])
    ref = pd.Series([reference.get((s, c, k), math.nan) for s, c, k in
                     zip(table["scenario"], table["controller"], table["seed"])],
                    index=table.index)
    return table.assign(path_ratio=(table["path"] / ref).where(ref > 0))


def scenario_table(table, scenario):
    """A row per run of the scenario; with several seeds, a column says which."""
    runs = table[table["scenario"] == scenario]
    seeded = runs["seed"].nunique() > 1
    rows = []
    for _, r in runs.iterrows():
        rows.append(([f"{r['seed']}"] if seeded else []) + [
            r["controller"], r["planner"], r["stop"], f"{r['time']:.1f}",
            f"{r['path_ratio']:.2f}", f"{r['cost']:.5g}", f"{r['outside']:.0f}",
            f"{r['stalled']:.1f}", f"{r['step_us']:.2f}"])
    return study.markdown_table(
        (["seed"] if seeded else []) +
        ["controller", "planner", "outcome", "time [s]", "path / visibility graph",
         "final cost H", "target outside Ω [steps]", "stalled [s]", "planner step [µs]"],
        rows, [True] * seeded + [False] * 3 + [True] * 6)


def summary(table, scenarios):
    """Per (controller, planner), over the runs of `scenarios`: runs, converged, stuck, the
    mean time of the converged runs, the mean path ratio, the mean final cost relative to
    the paper's controller with the visibility-graph planner (same scenario and seed), the
    mean planner step."""
    runs = table[table["scenario"].isin(scenarios)]
    reference = runs[(runs["controller"] == REFERENCE_LAW) &
                     (runs["planner"] == REFERENCE_PLANNER)].set_index(["scenario", "seed"])["cost"]
    ref = pd.Series([reference.get((s, k), math.nan)
                     for s, k in zip(runs["scenario"], runs["seed"])], index=runs.index)
    runs = runs.assign(cost_ratio=(runs["cost"] / ref).where(ref > 0))
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


def bar_chart(plt, table, scenarios, value, title, label, file):
    """A group per planner, a bar per controller: the value's mean over the runs of
    `scenarios` (runs where it is undefined left out)."""
    runs = table[table["scenario"].isin(scenarios)]
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


def charts(plt, table, scenarios, where, folder):
    bar_chart(plt, table, scenarios, "converged", f"Converged, share of the runs ({where})",
              "convergence rate", folder / "convergence.svg")
    bar_chart(plt, table, scenarios, "path_ratio",
              f"Total path length / visibility-graph planner's ({where})",
              "path ratio", folder / "path-ratio.svg")
    bar_chart(plt, table, scenarios, "step_us", f"Planner compute time per step ({where})",
              "microseconds", folder / "step-time.svg")


def names_option(value, registered, option):
    """A comma-separated --planners or --laws value, each name checked against the
    registry's."""
    if value is None:
        return registered
    chosen = [v for v in value.split(",") if v]
    for v in chosen:
        if v not in registered:
            raise study.StudyError(f"{option}: \"{v}\" is not one of {', '.join(registered)}")
    return chosen


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("scenarios", nargs="*", metavar="SCENARIO",
                    help="scenario files to compare on (default: the docs' own set)")
    ap.add_argument("--out", help="output folder, with SCENARIO... (required then)")
    ap.add_argument("--seeds", type=int, default=1, help="seeds 1..N per scenario")
    ap.add_argument("--planners", help="comma-separated planners (default: every one)")
    ap.add_argument("--laws", help="comma-separated autonomous laws (default: every one)")
    ap.add_argument("--jobs", type=int, default=os.cpu_count())
    args = ap.parse_args()
    planners = names_option(args.planners, names("planners"), "--planners")
    laws = names_option(args.laws, names("laws", "--autonomous"), "--laws")
    if args.scenarios:
        if args.out is None:
            raise study.StudyError("SCENARIO... needs --out DIR (the docs are left alone)")
        if args.seeds < 1:
            raise study.StudyError(f"--seeds: expected at least 1, found {args.seeds}")
        return compare_own(args, planners, laws)
    if args.out is not None or args.seeds != 1 or args.planners or args.laws:
        raise study.StudyError("--out, --seeds, --planners and --laws go with SCENARIO...: "
                               "the docs' tables compare every planner and law, one seed each")
    plt = study.pyplot("covsim-compare-planners")
    table = with_path_ratio(run_sweeps(args.jobs, docs_scenarios(), WORK, [1], planners, laws))
    table.to_csv(WORK / "all.csv", index=False)
    charts(plt, table, RANDOM, "random environments", FIGURES)

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
        *random_table(summary(table, RANDOM)),
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


def compare_own(args, planners, laws):
    """The comparison on the user's scenarios, into args.out: report.md, the charts and
    all.csv."""
    out = Path(args.out).resolve()
    scenarios = {}
    for f in args.scenarios:
        path = Path(f).resolve()
        if not path.is_file():
            raise study.StudyError(f"{f}: no such scenario file")
        name = path.stem
        while name in scenarios:
            name += "_"
        scenarios[name] = path
    seeds = list(range(1, args.seeds + 1))
    table = with_path_ratio(run_sweeps(args.jobs, scenarios, out / "sweeps", seeds, planners,
                                       laws))
    table.to_csv(out / "all.csv", index=False)
    plt = study.pyplot("covsim-compare-planners-own")
    charts(plt, table, list(scenarios), "your scenarios", out)
    lines = ["# Planner comparison", "",
             f"Scenarios: {', '.join(f'{n} ({p})' for n, p in scenarios.items())}; "
             f"seeds 1 to {args.seeds}; planners {', '.join(planners)}; laws {', '.join(laws)}.",
             ""]
    for s in scenarios:
        lines += [f"## {s}", ""] + scenario_table(table, s) + [""]
    lines += ["## Over all of them", "",
              "Final cost relative to the paper's controller with the visibility-graph planner "
              "on the same scenario and seed (empty where those were not compared).", "",
              *random_table(summary(table, list(scenarios))), "",
              "![convergence rate](convergence.svg)", "",
              "![path length ratio](path-ratio.svg)", "",
              "![planner step time](step-time.svg)", ""]
    (out / "report.md").write_text("\n".join(lines))
    print(f"wrote {out / 'report.md'}", file=sys.stderr)


if __name__ == "__main__":
    study.run(main)
