#!/usr/bin/python3
"""Regenerates the simulated-radio section of docs/studies.md and its plots (docs/studies/).

office with the ns3_wifi channel (docs/ns3.md): the broadcast period from 0.02 to 2 s ×
the number of robots (5, 30, 100) × 802.11b and 802.11g (each at its lowest rate, the
channel's defaults otherwise: log-distance path loss, 5 dB per wall). Decentralized runs
with TangentBug at infinite range and the `discover` policy, as in the communication
section, but loop 1 runs periodically every 0.5 s (the fastest office setting of that
section): with the classic loop 1 the times on office are set by the walks round its thin
walls, and 100 robots would not fit the study's budget. Each seed is a random deployment in
the west room (studies/study.py, DEPLOY); fewer seeds and periods, and for 100 robots a
limit of 600 s of simulated time, as the robots, and the cost of simulating their radios,
grow (SEEDS, PERIODS, MAX_TIME). A run stopped by the limit counts with the time it stopped
at, its final cost the cost then.

Usage: python3 studies/radio.py [--jobs N] [--counts 5,30,100]   (results are the same for
any N; --counts runs and writes up those numbers of robots alone)
Needs a build with the ns-3 peer (docs/ns3.md). The sweeps resume: a rerun into
out/study-radio/ reuses every run already there. The prose findings live in
docs/studies.md, outside the generated section.
"""
import argparse
import os
import sys

import study

WORK = study.ROOT / "out" / "study-radio"
FIGURES = study.DOCS / "studies"
COUNTS = [5, 30, 100]
SEEDS = {5: 10, 30: 3, 100: 1}
ALL_PERIODS = [0.02, 0.05, 0.1, 0.2, 0.5, 1.0, 2.0]
PERIODS = {5: ALL_PERIODS, 30: ALL_PERIODS, 100: [0.02, 0.1, 0.5, 2.0]}
# The simulated time a run may take where it is not office's own (4000 s): for 100 robots, at
# a period of 0.02 s their radios cost ns-3 about 3 wall seconds per simulated second.
MAX_TIME = {100: 600.0}
STANDARDS = ["b", "g"]
LOOP1_PERIOD = 0.5

COLUMNS = [("network.broadcast_period", "broadcast period [s]"),
           ("network.channel.standard", "802.11"),
           "runs", "converged", "time_to_1_percent", "cost_real", "delivery_ratio",
           "latency_mean", "latency_p95", "channel_occupancy", "phy_drops", "info_age_mean",
           "connected"]
# The measures plotted against the period: (column, axis name, statistic, axis from zero).
PLOTS = [("time_to_1_percent", "time to 1% of the final cost", "median", True),
         ("info_age_mean", "information age", "mean", True),
         ("delivery_ratio", "delivery ratio", "mean", True)]


def deployment(count):
    return {**study.DEPLOY["office"], "count": count}


def limit(count):
    return {"convergence.max_time": [MAX_TIME[count]]} if count in MAX_TIME else {}


def loops(count):
    return {"robots": [deployment(count)], "loops.mode": ["periodic"],
            "loops.loop1_period": [LOOP1_PERIOD]}


def ideal_grid(count):
    """The same deployments and loops with the ideal network (the centralized controller):
    the reference the radio's runs are measured against."""
    return {**loops(count), **limit(count)}


def grid(count):
    return {
        **loops(count),
        "network.channel.type": ["ns3_wifi"],
        "network.channel.standard": STANDARDS,
        "network.broadcast_period": PERIODS[count],
        **limit(count),
    }


def plot(plt, sweeps, measure, file):
    """The measure against the broadcast period (log axis), a panel per number of robots,
    a line per standard: medians with the quartiles, or means with the 95% interval."""
    _, name, statistic, from_zero = next(p for p in PLOTS if p[0] == measure)
    unit = next(m["unit"] for m in study.covsim_module().measures() if m["column"] == measure)
    counts = sorted(sweeps)
    fig, axes = plt.subplots(1, len(counts), figsize=(3.2 * len(counts), 3.4),
                             constrained_layout=True, sharey=True, squeeze=False)
    axes = axes[0]
    for ax, count in zip(axes, counts):
        summary = study.read_summary(sweeps[count])
        for i, standard in enumerate(STANDARDS):
            rows = summary[summary["network.channel.standard"] == standard].assign(
                _x=lambda t: t["network.broadcast_period"].map(float)).sort_values("_x")
            if statistic == "median":
                mid, low, high = (rows[f"{measure}_median"], rows[f"{measure}_q1"],
                                  rows[f"{measure}_q3"])
            else:
                ci = rows[f"{measure}_ci95"].fillna(0.0)
                mid = rows[f"{measure}_mean"]
                low, high = mid - ci, mid + ci
            ax.fill_between(rows["_x"], low, high, color=f"C{i}", alpha=0.2, linewidth=0)
            ax.plot(rows["_x"], mid, color=f"C{i}", marker="o", markersize=4,
                    label=f"802.11{standard}")
        seeds = SEEDS[count]
        ax.set_title(f"{count} robots, {seeds} deployment{'s' if seeds > 1 else ''}",
                     fontsize=10)
        ax.set_xscale("log")
        ax.set_xlabel("broadcast period [s]")
        ax.grid(True, linewidth=0.4, alpha=0.5)
    axes[0].set_ylabel(f"{name} [{unit}]" if unit else name)
    if from_zero:
        axes[0].set_ylim(bottom=0)
    axes[0].legend(fontsize=8)
    band = "quartiles" if statistic == "median" else "95% interval"
    fig.suptitle(f"office, ns3_wifi: {name} ({statistic}, band: {band})", fontsize=10)
    study.save_svg(fig, file)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--jobs", type=int, default=os.cpu_count())
    ap.add_argument("--counts", default=",".join(map(str, COUNTS)),
                    help="the numbers of robots to run and write up, a comma list of "
                         f"{', '.join(map(str, COUNTS))} (default all)")
    args = ap.parse_args()
    counts = [int(c) for c in args.counts.split(",")]
    if not counts or any(c not in COUNTS for c in counts):
        raise study.StudyError(f"--counts: expected a comma list of {COUNTS}, found {args.counts}")
    plt = study.pyplot("covsim-study-radio")
    sweeps, ideal = {}, {}
    for count in counts:
        for name, g, out in [(f"office-{count}", grid(count), sweeps),
                             (f"office-{count}-ideal", ideal_grid(count), ideal)]:
            path = study.write_sweep(WORK / f"{name}.json", "office", g, SEEDS[count])
            study.sweep(path, WORK / name, args.jobs)
            out[count] = WORK / name
    section = []
    for count in counts:
        seeds = SEEDS[count]
        reference = study.read_summary(ideal[count]).iloc[0]
        section += [f"### {count} robots", "",
                    f"{seeds} deployment{'s' if seeds > 1 else ''} per setting. With the ideal "
                    f"network (the centralized controller, the same deployments and loops): time "
                    f"to 1% of the final cost {study.median_iqr(reference, 'time_to_1_percent', '%.1f')} s, "
                    f"final cost {study.mean_ci(reference, 'cost_real', '%.4g')}, "
                    f"{study.percent(reference, 'converged_rate')} converged.", ""]
        section += study.summary_table(study.read_summary(sweeps[count]), COLUMNS, count)
        section.append("")
    for measure, *_ in PLOTS:
        name = f"radio-{measure}.svg"
        plot(plt, sweeps, measure, FIGURES / name)
        section += [f"![office, ns3_wifi: {measure}](studies/{name})", ""]
    study.replace_section(study.DOCS / "studies.md", "radio", section)
    print(f"wrote {study.DOCS / 'studies.md'}", file=sys.stderr)


if __name__ == "__main__":
    study.run(main)
