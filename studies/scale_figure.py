#!/usr/bin/python3
"""Regenerates docs/performance/scale.svg and prints the scaling table of docs/performance.md.

BM_ScaleRun, BM_ScaleRunDecentralized and BM_DelaunayPerTick at N = 100, 1000 and 10 000
(the benchmark's counter cpu_per_sim_s: CPU time per simulated second, medians of the
repetitions, measured in one run of covsim_bench), drawn on log-log axes, with the exponent
of each series between consecutive sizes.

Usage: studies/scale_figure.py [--repetitions N] [--bench-csv FILE]
(default 3 repetitions; N = 10 000 takes minutes). The benchmark's CSV goes to
out/scale-figure/bench.csv; --bench-csv draws and tabulates an earlier one instead of
running the benchmarks.
"""
import argparse
import math
import subprocess
import sys
from pathlib import Path

import pandas as pd

import study

WORK = study.ROOT / "out" / "scale-figure"
FIGURE = study.DOCS / "performance" / "scale.svg"
# benchmark -> the series' name
SERIES = {"BM_ScaleRun": "centralized run", "BM_ScaleRunDecentralized": "decentralized run",
          "BM_DelaunayPerTick": "one Delaunay per tick"}


def run_benchmarks(repetitions, file):
    bench = study.BUILD / "bench" / "covsim_bench"
    if not bench.exists():
        study.program()
    WORK.mkdir(parents=True, exist_ok=True)
    with open(file, "w") as out:
        subprocess.run([str(bench), "--benchmark_filter=BM_ScaleRun|BM_DelaunayPerTick",
                        f"--benchmark_repetitions={repetitions}",
                        "--benchmark_report_aggregates_only=true", "--benchmark_format=csv"],
                       check=True, stdout=out)


def medians(file):
    """The medians' cpu_per_sim_s by series and robots (a table: series, robots,
    cpu_per_sim_s)."""
    bench = pd.read_csv(file)
    for column in ("name", "cpu_per_sim_s"):
        if column not in bench.columns:
            raise study.StudyError(f"{file}: no column '{column}' (a covsim_bench CSV?)")
    bench = bench[bench["name"].str.endswith("_median")]
    parts = bench["name"].str.removesuffix("_median").str.split("/")
    table = pd.DataFrame({"series": parts.str[0].map(SERIES),
                          "robots": parts.str[1].astype(int),
                          "cpu_per_sim_s": bench["cpu_per_sim_s"].astype(float)})
    if table["series"].isna().any() or table.empty:
        raise study.StudyError(f"{file}: expected the medians of {', '.join(SERIES)}")
    return table


def figure(table):
    plt = study.pyplot("covsim-scale-figure")
    fig, ax = plt.subplots(figsize=(6.4, 4.2), constrained_layout=True)
    for series in SERIES.values():
        points = table[table["series"] == series].sort_values("robots")
        ax.plot(points["robots"], points["cpu_per_sim_s"], marker="o", label=series)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("robots N")
    ax.set_ylabel("CPU time per simulated second [s]")
    ax.set_title("Time per simulated second at constant density", fontsize=10)
    ax.grid(True, which="both", linewidth=0.4, alpha=0.5)
    ax.legend(fontsize=8)
    study.save_svg(fig, FIGURE)


def report(table):
    """The table of docs/performance.md and the exponents between consecutive sizes."""
    t = table.pivot(index="robots", columns="series", values="cpu_per_sim_s")
    c, d, y = (t[SERIES[k]] for k in SERIES)
    rows = [[f"{n}", f"{c[n]:.4g}", f"{d[n]:.4g}", f"{y[n]:.4g}", f"{c[n] / y[n]:.1f}"]
            for n in t.index]
    lines = study.markdown_table(["N", "centralized [s]", "decentralized [s]",
                                  "one Delaunay per tick [s]", "centralized / Delaunay"],
                                 rows, [True] * 5)
    sizes = list(t.index)
    for a, b in zip(sizes, sizes[1:]):
        k = [math.log(s[b] / s[a]) / math.log(b / a) for s in (c, d, y)]
        lines.append(f"exponent {a} to {b}: centralized {k[0]:.2f}, decentralized {k[1]:.2f}, "
                     f"Delaunay {k[2]:.2f}")
    return lines


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repetitions", type=int, default=3)
    ap.add_argument("--bench-csv", type=Path, help="an earlier run's CSV, instead of running")
    args = ap.parse_args()
    file = args.bench_csv
    if file is None:
        file = WORK / "bench.csv"
        run_benchmarks(args.repetitions, file)
    table = medians(file)
    WORK.mkdir(parents=True, exist_ok=True)
    table.to_csv(WORK / "scale.csv", index=False)
    figure(table)
    print("\n".join(report(table)))
    print(f"wrote {FIGURE}", file=sys.stderr)


if __name__ == "__main__":
    study.run(main)
