#!/usr/bin/python3
"""Regenerates the communication section of docs/studies.md and its plots (docs/studies/).

Convergence time and final cost on u_shape and office against the message loss rate, the
broadcast period and the loop-1/loop-2 ratio: decentralized runs, 20 seeds per setting, each
seed a random deployment (studies/study.py, DEPLOY). Loss: Bernoulli p from 0 to 0.9.
Broadcast period and ratio: with 10% Bernoulli loss; the ratio runs loop 1 periodically
every ratio x loop2_period (0.1 s). office's decentralized runs are the costly ones: fewer
loss values there (0.1 is the broadcast sweep's first setting), and no loop-1 period of
0.1 s (the costliest).

Usage: python3 studies/network.py [--jobs N]   (results are the same for any N)
The sweeps resume: a rerun into out/study-network/ reuses every run already there. The
prose findings live in docs/studies.md, outside the generated section.
"""
import argparse
import os
import sys

import study

WORK = study.ROOT / "out" / "study-network"
FIGURES = study.DOCS / "studies"
SCENARIOS = ["u_shape", "office"]
LOSSES = {"u_shape": [0.0, 0.1, 0.3, 0.5, 0.7, 0.9], "office": [0.0, 0.3, 0.6, 0.9]}
RATIOS = {"u_shape": [0.1, 0.5, 1.0, 2.0], "office": [0.5, 1.0, 2.0]}

# (kind, swept parameter, its label, the text before the table)
KINDS = [
    ("loss", "network.loss.p", "loss p",
     "Against the Bernoulli loss probability p of every message (decentralized, broadcast\n"
     "period 0.1 s, classic loop 1):"),
    ("broadcast", "network.broadcast_period", "broadcast period [s]",
     "Against the broadcast period (10% loss):"),
    ("ratio", "loops.loop1_period", "loop-1 period [s]",
     "Against the Lloyd/planner frequency ratio, loop 1 every ratio × 0.1 s (periodic mode,\n"
     "10% loss); ratio 1 is the quasi-continuous version:"),
]
COLUMNS = ["runs", "converged", "time_to_1_percent", "sim_time", "cost_real",
           "messages_delivered", "info_age_mean", "area_claimed_by_several", "connected"]
# The plotted measures: (column, name, unit, whether the axis starts at zero: times do,
# so that they compare; the cost's axis spans its values).
# The measures plotted: (column, axis name, axis from zero); units from covsim.measures().
PLOTS = [("sim_time", "time to converge", True),
         ("cost_real", "final cost H (real)", False)]


def grids(scenario):
    deploy = {"robots": [study.DEPLOY[scenario]], "network.loss.model": ["bernoulli"]}
    return {
        "loss": {**deploy, "network.loss.p": LOSSES[scenario]},
        "broadcast": {**deploy, "network.loss.p": [0.1],
                      "network.broadcast_period": [0.1, 0.5, 1.0, 2.0]},
        "ratio": {**deploy, "network.loss.p": [0.1], "loops.mode": ["periodic"],
                  "loops.loop1_period": RATIOS[scenario]},
    }


def numeric_values(values):
    """The distinct numeric values of a parameter column (text), None if any is not a
    number; `null` (unlimited) is left out."""
    out = set()
    for v in values:
        if v == "null":
            continue
        try:
            out.add(float(v))
        except ValueError:
            return None
    return out


def plotted_parameters(out):
    """The swept parameters that are numbers taking two or more values."""
    summary = study.read_summary(out)
    names = []
    for p in study.parameters(out):
        values = numeric_values(summary[p])
        if values is not None and len(values) >= 2:
            names.append(p)
    return names


def plot(plt, out, scenario, parameter, label, measure, file):
    """The measure's mean over the runs against the parameter, with its 95% confidence
    interval (summary.csv) and the runs as faint dots (runs.csv)."""
    summary = study.read_summary(out)
    runs = study.read_runs(out)
    summary = summary[summary[parameter] != "null"].assign(
        _x=lambda t: t[parameter].map(float)).sort_values("_x")
    runs = runs[runs[parameter] != "null"].assign(_x=lambda t: t[parameter].map(float))
    fig, ax = plt.subplots(figsize=(6.4, 4.0), constrained_layout=True)
    ax.scatter(runs["_x"], runs[measure], s=9, color="C0", alpha=0.25, linewidths=0,
               label="runs")
    mean, ci = summary[f"{measure}_mean"], summary[f"{measure}_ci95"].fillna(0.0)
    ax.fill_between(summary["_x"], mean - ci, mean + ci, color="C0", alpha=0.2,
                    linewidth=0, label="95% confidence interval")
    ax.plot(summary["_x"], mean, color="C0", marker="o", markersize=4, label="mean")
    _, name, from_zero = next(p for p in PLOTS if p[0] == measure)
    unit = next(m["unit"] for m in study.covsim_module().measures() if m["column"] == measure)
    ax.set_xlabel(label)
    ax.set_ylabel(f"{name} [{unit}]" if unit else name)
    if from_zero and runs[measure].min() >= 0:
        ax.set_ylim(bottom=0)
    ax.set_title(f"{scenario}: {name}, mean over {len(runs) // len(summary)} runs per setting",
                 fontsize=10)
    ax.grid(True, linewidth=0.4, alpha=0.5)
    ax.legend(fontsize=8)
    study.save_svg(fig, file)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--jobs", type=int, default=os.cpu_count())
    args = ap.parse_args()
    plt = study.pyplot("covsim-study-network")
    sweeps = {}
    for s in SCENARIOS:
        for kind, grid in grids(s).items():
            name = f"{s}-{kind}"
            study.sweep(study.write_sweep(WORK / f"{name}.json", s, grid), WORK / name, args.jobs)
            sweeps[s, kind] = WORK / name
    section = []
    for s in SCENARIOS:
        robots = study.DEPLOY[s]["count"]
        section += [f"### {s}", ""]
        for kind, parameter, label, text in KINDS:
            summary = study.read_summary(sweeps[s, kind])
            section += text.splitlines() + [""]
            section += study.summary_table(summary, [(parameter, label)] + COLUMNS, robots)
            section.append("")
        for kind, parameter, label, _ in KINDS:
            out = sweeps[s, kind]
            for measure, *_ in PLOTS:
                for p in plotted_parameters(out):
                    name = f"{s}-{kind}-{measure}_vs_{p}.svg"
                    plot(plt, out, s, p, label if p == parameter else p, measure, FIGURES / name)
                    section += [f"![{s}: {measure}_vs_{p}](studies/{name})", ""]
    study.replace_section(study.DOCS / "studies.md", "network", section)
    print(f"wrote {study.DOCS / 'studies.md'}", file=sys.stderr)


if __name__ == "__main__":
    study.run(main)
