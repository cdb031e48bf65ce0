#!/usr/bin/python3
"""Regenerates the fidelity section of docs/studies.md and its heat maps (docs/studies/).

A factorial study of the question covsim exists for: how the Lloyd/planner frequency ratio
and the sensor range affect convergence. On u_shape, office and dead_ends (a comb whose
teeth make deep dead ends between the robots and half of Ω), 20 random deployments per
cell, the paper's controller centralized with an ideal network:

- the loop schedule: loop-2 periods 0.1 and 0.2 s, each with the classic loop 1 and with a
  periodic loop 1 at 1, 5 and 20 times the loop-2 period;
- the sensor range: 0 (contact), 0.5 m, 2 m and infinite (TangentBug; grid_astar knows the
  map and reads no range, so it runs once per schedule);
- the planner: tangent_bug and grid_astar;
- the projection policy: discover (the paper's) and known.

Times are measured where coverage is won: the time to 1% of the final cost, beside the time
to converge, with the tolerance a fraction (1%) of the robots' spacing so that they compare
across scenarios (docs/scenario-format.md, convergence.spacing_tolerance). Each cell is
summarised by its median and interquartile range, and by its two modes where the runs split
into early and late ones (docs/sweeps.md); means would describe runs that never happened.

A second section puts the map planners on what their robots sense (planner.map "sensed":
grid_astar, potential_field and visibility_graph at 0.5 m, 2 m and infinite range) beside
TangentBug at every range and grid_astar on the given map (the lower bound), for every loop
schedule and both projection policies; its seeds per scenario are --sensed-seeds (20 each by
default; office's runs with 30 sensing robots take one to two seconds each).

Usage: python3 studies/fidelity.py [--jobs N] [--seeds N] [--scenarios a,b]
                                   [--sensed-seeds u_shape=20,office=20,...]
The sweeps resume: a rerun into out/study-fidelity/ reuses every run already there. A sweep
with a failed run fails the study. The prose findings live in docs/studies.md, outside the
generated section, and are written from traced runs.
"""
import argparse
import json
import math
import os

import pandas as pd

import study

WORK = study.ROOT / "out" / "study-fidelity"
FIGURES = study.DOCS / "studies"
LOOP2 = [0.1, 0.2]
RATIOS = [1, 5, 20]
RANGES = [0.0, 0.5, 2.0, None]
PROJECTIONS = ["discover", "known"]
SPACING_TOLERANCE = 0.01
SENSED_PLANNERS = ["grid_astar", "potential_field", "visibility_graph"]
SENSED_RANGES = [0.5, 2.0, None]


def loop_settings():
    out = []
    for l2 in LOOP2:
        out.append({"mode": "classic", "loop2_period": l2})
        for r in RATIOS:
            out.append({"mode": "periodic", "loop2_period": l2, "loop1_period": round(r * l2, 6)})
    return out


SENSED_LOOPS = loop_settings()


def loop_label(loops):
    if loops["mode"] == "classic":
        return f"classic, Δ2 {loops['loop2_period']:g} s"
    ratio = loops["loop1_period"] / loops["loop2_period"]
    return f"ratio {ratio:g} (Δ1 {loops['loop1_period']:g} s, Δ2 {loops['loop2_period']:g} s)"


def range_label(r):
    return "∞" if r is None or (isinstance(r, float) and math.isinf(r)) else f"{r:g} m"


def run_sweep(name, scenario, grid, seeds, jobs):
    """Runs one sweep into WORK/name; returns its summary.csv, the loop schedules as dicts."""
    out = WORK / name
    study.sweep(study.write_sweep(WORK / f"{name}.json", scenario, grid, seeds), out, jobs)
    summary = study.read_summary(out)
    summary["loops"] = summary["loops"].map(json.loads)
    return summary


def column_key(row):
    """The heat map's column: TangentBug at each range, or grid_astar."""
    if row["planner.type"] == "grid_astar":
        return "grid_astar"
    r = row["sensor.range"]
    return f"tangent_bug {range_label(None if r in ('', 'null') else float(r))}"


def columns():
    return [f"tangent_bug {range_label(r)}" for r in RANGES] + ["grid_astar"]


def heat_map(plt, table, scenario, measure, label, fmt, file):
    """One panel per projection policy: rows the loop schedules, columns the planners at
    each range; colour the median, text the median and the converged share."""
    rows = [loop_label(l) for l in loop_settings()]
    cols = columns()
    fig, axes = plt.subplots(1, len(PROJECTIONS), figsize=(6.8, 3.9), sharey=True,
                             constrained_layout=True)
    values = {}
    for p in PROJECTIONS:
        grid = [[float("nan")] * len(cols) for _ in rows]
        for _, row in table[table["controller.projection"] == p].iterrows():
            i = rows.index(loop_label(row["loops"]))
            j = cols.index(column_key(row))
            grid[i][j] = row[f"{measure}_median"]
        values[p] = grid
    finite = [v for g in values.values() for line in g for v in line if not math.isnan(v)]
    vmin, vmax = (min(finite), max(finite)) if finite else (0.0, 1.0)
    for ax, p in zip(axes, PROJECTIONS):
        image = ax.imshow(values[p], cmap="viridis_r", vmin=vmin, vmax=vmax, aspect="auto")
        for i in range(len(rows)):
            for j in range(len(cols)):
                v = values[p][i][j]
                if not math.isnan(v):
                    ax.text(j, i, fmt % v, ha="center", va="center", fontsize=6.5,
                            color="white" if v > (vmin + vmax) / 2 else "black")
        ax.set_xticks(range(len(cols)), [c.replace("tangent_bug ", "TB ") for c in cols],
                      rotation=40, ha="right", fontsize=7)
        ax.set_yticks(range(len(rows)), rows, fontsize=7)
        ax.set_title(f"projection {p}", fontsize=8)
    bar = fig.colorbar(image, ax=axes, shrink=0.85)
    bar.set_label(label, fontsize=7)
    bar.ax.tick_params(labelsize=7)
    fig.suptitle(f"{scenario}: median {label} ({len(finite)} cells)", fontsize=9)
    study.save_svg(fig, file)


def markdown(table, scenario):
    lines = [f"### {scenario}", ""]
    lines.append(f"![time to 1% of the final cost](studies/fidelity-{scenario}-time_to_1_percent.svg)")
    lines.append(f"![final cost](studies/fidelity-{scenario}-cost_real.svg)")
    lines.append("")
    lines.append("| schedule | planner | projection | converged | time to 1% of the final cost [s] "
                 "| time to converge [s] | final cost H | path, all robots [m] |")
    lines.append("|---|---|---|---:|---:|---:|---:|---:|")
    order = {loop_label(l): k for k, l in enumerate(loop_settings())}
    col_order = {c: k for k, c in enumerate(columns())}
    table = table.assign(_row=table["loops"].map(lambda l: order[loop_label(l)]),
                         _col=table.apply(column_key, axis=1))
    table = table.assign(_c=table["_col"].map(col_order)).sort_values(
        ["_row", "controller.projection", "_c"])
    for _, row in table.iterrows():
        lines.append(
            f"| {loop_label(row['loops'])} | {row['_col']} | {row['controller.projection']} | "
            f"{study.percent(row, 'converged_rate')} | "
            f"{study.median_iqr(row, 'time_to_1_percent', '%.1f')} | "
            f"{study.median_iqr(row, 'sim_time', '%.1f')} | "
            f"{study.median_iqr(row, 'cost_real', '%.4g')} | "
            f"{study.median_iqr(row, 'path_length', '%.3g')} |")
    lines.append("")
    return lines


def sensed_key(row):
    """The sensed section's column: a planner at a range, on its map."""
    r = row["sensor.range"]
    rng = range_label(None if r in ("", "null") or (isinstance(r, float) and math.isnan(r))
                      else float(r))
    if row["planner.type"] == "tangent_bug":
        return f"TB {rng}"
    short = {"grid_astar": "A*", "potential_field": "PF", "visibility_graph": "VG"}[row["planner.type"]]
    return f"{short} given" if row.get("planner.map", "given") == "given" else f"{short} {rng}"


def sensed_columns():
    cols = [f"TB {range_label(r)}" for r in RANGES] + ["A* given"]
    for short in ["A*", "PF", "VG"]:
        cols += [f"{short} {range_label(r)}" for r in SENSED_RANGES]
    return cols


def sensed_rows():
    return [(loop_label(l), p) for l in SENSED_LOOPS for p in PROJECTIONS]


def sensed_heat_map(plt, table, scenario, file):
    rows, cols = sensed_rows(), sensed_columns()
    grid = [[float("nan")] * len(cols) for _ in rows]
    share = [[""] * len(cols) for _ in rows]
    for _, row in table.iterrows():
        i = rows.index((loop_label(row["loops"]), row["controller.projection"]))
        j = cols.index(sensed_key(row))
        share[i][j] = study.percent(row, "converged_rate")
        # A time to 1% of a final cost no run reached (none converged) is not comparable.
        if row["converged_rate"] > 0:
            grid[i][j] = row["time_to_1_percent_median"]
    finite = [v for line in grid for v in line if not math.isnan(v)]
    vmin, vmax = (min(finite), max(finite)) if finite else (0.0, 1.0)
    fig, ax = plt.subplots(figsize=(8.4, 1.6 + 0.36 * len(rows)), constrained_layout=True)
    image = ax.imshow(grid, cmap="viridis_r", vmin=vmin, vmax=vmax, aspect="auto")
    for i in range(len(rows)):
        for j in range(len(cols)):
            v = grid[i][j]
            if not math.isnan(v):
                ax.text(j, i, f"{v:.0f}\n{share[i][j]}", ha="center", va="center", fontsize=5.5,
                        color="white" if v > (vmin + vmax) / 2 else "black")
            elif share[i][j]:
                ax.text(j, i, f"stuck\n{share[i][j]}", ha="center", va="center", fontsize=5.5,
                        color="black")
    ax.set_xticks(range(len(cols)), cols, rotation=40, ha="right", fontsize=7)
    ax.set_yticks(range(len(rows)), [f"{l}, {p}" for l, p in rows], fontsize=7)
    bar = fig.colorbar(image, ax=ax, shrink=0.85)
    bar.set_label("time to 1% of final cost [s]", fontsize=7)
    bar.ax.tick_params(labelsize=7)
    fig.suptitle(f"{scenario}: median time to 1% of the final cost, converged share "
                 "(blank: no run converged)", fontsize=9)
    study.save_svg(fig, file)


def sensed_markdown(table, scenario, seeds):
    lines = [f"### {scenario} ({seeds} deployments per cell)", "",
             f"![sensed planners](studies/fidelity-sensed-{scenario}.svg)", "",
             "| schedule | projection | planner | converged | time to 1% of the final cost [s] "
             "| time to converge [s] | final cost H | path, all robots [m] |",
             "|---|---|---|---:|---:|---:|---:|---:|"]
    rows = {r: k for k, r in enumerate(sensed_rows())}
    cols = {c: k for k, c in enumerate(sensed_columns())}
    table = table.assign(
        _r=table.apply(lambda r: rows[(loop_label(r["loops"]), r["controller.projection"])], axis=1),
        _c=table.apply(lambda r: cols[sensed_key(r)], axis=1)).sort_values(["_r", "_c"])
    for _, row in table.iterrows():
        lines.append(
            f"| {loop_label(row['loops'])} | {row['controller.projection']} | {sensed_key(row)} | "
            f"{study.percent(row, 'converged_rate')} | "
            f"{study.median_iqr(row, 'time_to_1_percent', '%.1f')} | "
            f"{study.median_iqr(row, 'sim_time', '%.1f')} | "
            f"{study.median_iqr(row, 'cost_real', '%.4g')} | "
            f"{study.median_iqr(row, 'path_length', '%.3g')} |")
    lines.append("")
    return lines


def same_loops(table):
    """The rows of a summary whose loop schedule is one of SENSED_LOOPS."""
    keep = [json.dumps(l, sort_keys=True) for l in SENSED_LOOPS]
    return table[table["loops"].map(lambda l: json.dumps(l, sort_keys=True) in keep)]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--jobs", type=int, default=os.cpu_count())
    ap.add_argument("--seeds", type=int, default=20)
    ap.add_argument("--scenarios", default="u_shape,office,dead_ends")
    ap.add_argument("--sensed-seeds", default="u_shape=20,office=20,dead_ends=20",
                    help="deployments per cell of the sensed-map section, per scenario")
    args = ap.parse_args()
    scenarios = args.scenarios.split(",")
    sensed_seeds = {}
    for item in args.sensed_seeds.split(","):
        name, _, count = item.partition("=")
        if not count.isdigit() or int(count) < 1:
            ap.error(f"--sensed-seeds: expected scenario=count, found {item!r}")
        sensed_seeds[name] = int(count)
    for s in scenarios:
        if s not in study.DEPLOY:
            ap.error(f"--scenarios: unknown scenario {s!r} (one of {', '.join(study.DEPLOY)})")
    plt = study.pyplot("covsim-study-fidelity")
    # A scenario's own tolerances (office sets 5 cm) give way to the fraction of the spacing.
    common = {"convergence.spacing_tolerance": [SPACING_TOLERANCE],
              "convergence.position_tolerance": [None], "convergence.virtual_tolerance": [None],
              "loops": loop_settings()}
    section = [
        "## Fidelity: Lloyd/planner ratio, sensor range, planner and projection policy",
        "",
        "Generated by `studies/fidelity.py` (sweep files in `out/study-fidelity/`): the",
        "paper's controller, centralized with an ideal network, on u_shape, office and",
        f"dead_ends, {args.seeds} random deployments per cell (seed k draws the start of run k),",
        "every loop schedule (loop-2 period Δ2 of 0.1 and 0.2 s, the classic loop 1 and a",
        f"periodic one at {', '.join(str(r) for r in RATIOS)} times Δ2) × TangentBug at each sensor range",
        "(0, 0.5 m, 2 m, ∞) × the projection policy (discover, known), and grid_astar (which",
        "knows the map and plans to the closest point of Ω under either policy: its rows repeat",
        f"one sweep). Tolerances are {SPACING_TOLERANCE:g} of the robots' spacing √(area / N).",
        "Cells give the median [first quartile, third quartile]; where the runs split into two",
        "modes (docs/sweeps.md), the share of runs and the median of each.",
        "",
    ]
    sensed_section = [
        "## Planners on what they sensed: range for every planner",
        "",
        "Generated by `studies/fidelity.py` (sweeps `out/study-fidelity/*-sensed`): the map",
        "planners on the walls their robots sensed (`planner.map` \"sensed\", one map shared by",
        "the team, as the centralized run shares everything) at 0.5 m, 2 m and infinite range,",
        "beside TangentBug at those ranges and with contact alone (0 m), and grid_astar on the",
        "given map (the lower bound: from the section above, its deployments), for every loop",
        "schedule above, under both projection policies. Tolerances as above. A*: grid_astar, PF:",
        "potential_field, VG: visibility_graph, TB: tangent_bug. Cells: median [quartiles].",
        "",
    ]
    for scenario in scenarios:
        deploy = {"robots": [study.DEPLOY[scenario]]}
        tangent_bug = run_sweep(f"{scenario}-tangent_bug", scenario, {
            **common, **deploy, "planner.type": ["tangent_bug"],
            "controller.projection": PROJECTIONS, "sensor.range": RANGES}, args.seeds, args.jobs)
        # grid_astar plans to the closest point of Ω itself: both policies give the same runs.
        grid = run_sweep(f"{scenario}-grid_astar", scenario, {
            **common, **deploy, "planner.type": ["grid_astar"]}, args.seeds, args.jobs)
        grid = grid.assign(**{"sensor.range": ""})
        table = pd.concat([tangent_bug] +
                          [grid.assign(**{"controller.projection": p}) for p in PROJECTIONS],
                          ignore_index=True)
        for measure, label, fmt in [("time_to_1_percent", "time to 1% of final cost [s]", "%.0f"),
                                    ("cost_real", "final cost H", "%.3g")]:
            heat_map(plt, table, scenario, measure, label, fmt,
                     FIGURES / f"fidelity-{scenario}-{measure}.svg")
        section += markdown(table, scenario)
        seeds = sensed_seeds.get(scenario, args.seeds)
        sensed = run_sweep(f"{scenario}-sensed", scenario, {
            **common, **deploy, "loops": SENSED_LOOPS, "planner.type": SENSED_PLANNERS,
            "planner.map": ["sensed"], "controller.projection": PROJECTIONS,
            "sensor.range": SENSED_RANGES}, seeds, args.jobs).assign(**{"planner.map": "sensed"})
        # TangentBug and the given grid at the same schedules, from the sweeps above (their
        # seeds: --seeds).
        given = [same_loops(tangent_bug), same_loops(grid.assign(**{"planner.map": "given"}))]
        both = pd.concat([given[0]] + [given[1].assign(**{"controller.projection": p})
                                       for p in PROJECTIONS] + [sensed], ignore_index=True)
        sensed_heat_map(plt, both, scenario, FIGURES / f"fidelity-sensed-{scenario}.svg")
        sensed_section += sensed_markdown(both, scenario, seeds)
    # Each scenario's lines end with an empty one; the section does not.
    study.replace_section(study.DOCS / "studies.md", "fidelity", section[:-1])
    study.replace_section(study.DOCS / "studies.md", "fidelity-sensed", sensed_section[:-1])


if __name__ == "__main__":
    study.run(main)
