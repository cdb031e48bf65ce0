"""What every study shares: the deployments, sweep files run through `covsim.sweep` into
out/<study>/<name>, the generated sections of the docs, markdown tables from a sweep's
summary.csv, and deterministic matplotlib figures.

A study script imports this module (studies/ is its own folder on sys.path) and runs its
main through `study.run(main)`: a sweep with a failed run, a program that fails or a bad
sweep file ends the study with a message and exit code 1, before anything is written to
the docs.
"""
import json
import math
import os
import re
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
BUILD = Path(os.environ.get("COVSIM_BUILD_DIR", ROOT / "build"))
DOCS = ROOT / "docs"

# The random deployments the studies draw per seed: all robots start in one place, as in
# the paper (u_shape's 5 in a disk at the top of the left arm, office's 30 in its west
# room, dead_ends' 8 in a disk below the comb).
DEPLOY = {
    "u_shape": {"count": 5, "start": {"cluster": {"center": [0.12, 0.88], "radius": 0.1}}},
    "office": {
        "count": 30,
        "start": {"region": [[0.3, 4.2], [3.2, 4.2], [3.2, 5.8], [0.3, 5.8]]},
    },
    "dead_ends": {"count": 8, "start": {"cluster": {"center": [3, 0.45], "radius": 0.3}}},
}
SEEDS = 20


class StudyError(Exception):
    """A study that cannot produce its results: a failed run, a missing column."""


def build_of(covsim):
    """The build of a covsim program, as final.json's provenance gives it: (commit, dirty)
    from `covsim --version` ("commit 0123456789ab, dirty; ...")."""
    text = subprocess.run([str(covsim), "--version"], text=True, stdout=subprocess.PIPE,
                          check=True).stdout
    match = re.search(r"commit ([0-9a-f]+|unknown)(, dirty)?", text)
    if not match:
        raise StudyError(f"{covsim} --version: no commit in '{text.strip()}'")
    return match.group(1), match.group(2) is not None


def made_by(final, build):
    """Whether final.json is there and was written by `build` (build_of's): a run by another
    would mix builds in one table. Two dirty builds of one commit cannot be told apart."""
    if not final.exists():
        return False
    provenance = json.loads(final.read_text()).get("provenance", {})
    commit, dirty = build
    return provenance.get("commit", "")[:len(commit)] == commit and \
        provenance.get("dirty") == dirty



# ---------------------------------------------------------------------------------------
# The program and the Python package


def program():
    """The covsim program of the build (built first if missing)."""
    path = BUILD / "apps" / "covsim"
    if not path.exists():
        subprocess.run([str(ROOT / "scripts" / "build"), str(BUILD)], check=True)
    return path


def covsim_module():
    """The covsim Python package: the installed one, else the build's (built if missing)."""
    try:
        import covsim
    except ImportError:
        package = BUILD / "python"
        if not (package / "covsim").exists():
            program()
        sys.path.insert(0, str(package))
        import covsim
    return covsim


def covsim_cli(*args, quiet=False):
    """Runs the covsim program; returns its standard output. A failure raises."""
    result = subprocess.run([str(program()), *map(str, args)], check=True, text=True,
                            stdout=subprocess.PIPE)
    return "" if quiet else result.stdout


# ---------------------------------------------------------------------------------------
# Sweeps


def write_sweep(path, scenario, grid, seeds=SEEDS):
    """Writes a sweep file (docs/sweeps.md): scenario a scenario file (a Path or a name in
    scenarios/), grid a dict of dotted paths to lists of values, seeds a count or a list."""
    scenario = Path(scenario)
    if not scenario.suffix:
        scenario = ROOT / "scenarios" / f"{scenario}.json"
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps({
        "scenario": str(scenario),
        "grid": grid,
        "seeds": {"count": seeds} if isinstance(seeds, int) else list(seeds),
    }, indent=1) + "\n")
    return path


def sweep(path, out, jobs):
    """Runs the sweep file `path` into the folder `out` on `jobs` threads; returns its runs
    (runs.csv's rows, a DataFrame). A rerun into the same folder reuses every finished run
    (docs/sweeps.md). A run that failed raises StudyError naming it and its error."""
    covsim = covsim_module()
    print(f"== {Path(path).stem}", file=sys.stderr, flush=True)
    runs = covsim.sweep(str(path), jobs=jobs, out=str(out))
    check_runs(runs, Path(out))
    return runs


def check_runs(runs, out):
    """Raises StudyError if any run of a sweep's rows recorded an error."""
    if "error" not in runs.columns:
        raise StudyError(f"{out}: the sweep's rows have no column 'error'")
    failed = runs[runs["error"].notna() & (runs["error"] != "")]
    if len(failed):
        lines = [f"  run {r['run']} (setting {r['setting']}, seed {r['seed']}): {r['error']}"
                 for _, r in failed.head(10).iterrows()]
        more = len(failed) - len(lines)
        raise StudyError(f"{out}: {len(failed)} of {len(runs)} runs failed\n" + "\n".join(lines)
                         + (f"\n  ... and {more} more (runs.csv)" if more else ""))


def parameters(out):
    """The swept parameters of a sweep folder, in the order of its summary.csv."""
    return json.loads((Path(out) / "sweep.json").read_text())["parameters"]


def _number(text):
    return math.nan if text == "" else float(text)


def read_summary(out):
    """A sweep folder's summary.csv: the parameters as written (text: JSON values, `null`
    for an unlimited one), every other column a number (NaN where the sample cannot tell)."""
    import pandas as pd

    summary = pd.read_csv(Path(out) / "summary.csv", dtype=str, keep_default_na=False)
    swept = set(parameters(out))
    for column in summary.columns:
        if column not in swept:
            summary[column] = summary[column].map(_number)
    return summary


def read_runs(out):
    """A sweep folder's runs.csv, by column: parameters and text columns as written (a
    measure of words, such as `known`: full, boundary or none), numeric measures as numbers
    (NaN where empty)."""
    import pandas as pd

    runs = pd.read_csv(Path(out) / "runs.csv", dtype=str, keep_default_na=False)
    text = set(parameters(out)) | {"stop_reason", "fingerprint", "error"}
    for column in runs.columns:
        if column in text:
            continue
        try:
            runs[column] = runs[column].map(_number)
        except ValueError:
            pass  # words: kept as written
    return runs


# ---------------------------------------------------------------------------------------
# Generated sections of the docs


def replace_section(file, name, section):
    """Replaces the generated section `name` of a markdown file with `section` (a list of
    lines, or a text whose lines they are): the lines between `<!-- begin name -->` and
    `<!-- end name -->`, which are appended (with the section) if missing. The file is
    replaced whole, never left half written."""
    file = Path(file)
    begin, end = f"<!-- begin {name} -->", f"<!-- end {name} -->"
    lines = file.read_text().splitlines() if file.exists() else []
    section = section.splitlines() if isinstance(section, str) else list(section)
    if begin in lines:
        start = lines.index(begin)
        try:
            stop = lines.index(end, start + 1)
        except ValueError:
            raise StudyError(f"{file}: '{begin}' has no '{end}' after it") from None
        lines = lines[:start + 1] + section + lines[stop:]
    else:
        lines = lines + [begin] + section + [end]
    partial = file.with_name(file.name + ".partial")
    partial.write_text("\n".join(lines) + "\n")
    partial.replace(file)


# ---------------------------------------------------------------------------------------
# Markdown tables from summary.csv


def _missing(value):
    return value is None or (isinstance(value, float) and math.isnan(value))


def median_iqr(row, measure, fmt):
    """Median [first quartile, third quartile] of a measure; where the runs split into two
    modes (docs/sweeps.md), each mode's share and median. "–" where there is no sample."""
    if _missing(row[f"{measure}_median"]):
        return "–"
    if row[f"{measure}_q1"] == row[f"{measure}_q3"] == row[f"{measure}_median"]:
        return fmt % row[f"{measure}_median"]  # one run, or all alike: no spread to give
    text = (f"{fmt % row[f'{measure}_median']} [{fmt % row[f'{measure}_q1']}, "
            f"{fmt % row[f'{measure}_q3']}]")
    if row[f"{measure}_modes"] == 2:
        low = row[f"{measure}_low_fraction"]
        text += (f"; {round(100 * low)}% at {fmt % row[f'{measure}_low_median']}, "
                 f"{round(100 * (1 - low))}% at {fmt % row[f'{measure}_high_median']}")
    return text


def mean_ci(row, measure, fmt):
    """Mean ± the half-width of its 95% confidence interval."""
    if _missing(row[f"{measure}_mean"]):
        return "–"
    if _missing(row[f"{measure}_ci95"]):
        return fmt % row[f"{measure}_mean"]  # one run: no interval
    return f"{fmt % row[f'{measure}_mean']} ± {fmt % row[f'{measure}_ci95']}"


def percent(row, column):
    """A fraction as a whole percentage."""
    return "–" if _missing(row[column]) else f"{100 * row[column]:.0f}%"


def per_robot(row, measure, robots):
    """A measure's mean divided by the number of robots, to the unit."""
    return "–" if _missing(row[f"{measure}_mean"]) else f"{row[f'{measure}_mean'] / robots:.0f}"


def milliseconds(row, measure):
    """A time measure's mean, in milliseconds."""
    return "–" if _missing(row[f"{measure}_mean"]) else f"{1000 * row[f'{measure}_mean']:.2f}"


def parameter(value):
    """A swept value as summary.csv writes it, unlimited (`null`) as ∞."""
    return "∞" if value == "null" else str(value)


# The measures of summary.csv a table can show: name -> (header, cell(row, robots)).
MEASURES = {
    "runs": ("runs", lambda row, _r: f"{row['runs']:.0f}"),
    # The statistics count these: runs with one fingerprint count once.
    "distinct_runs": ("distinct runs", lambda row, _r: f"{row['distinct_runs']:.0f}"),
    "converged": ("converged", lambda row, _r: percent(row, "converged_rate")),
    "sim_time": ("time to converge [s]", lambda row, _r: median_iqr(row, "sim_time", "%.1f")),
    "time_to_1_percent": ("time to 1% of the final cost [s]",
                          lambda row, _r: median_iqr(row, "time_to_1_percent", "%.1f")),
    "cost_real": ("final cost H (real)", lambda row, _r: mean_ci(row, "cost_real", "%.4g")),
    "path_length": ("path, all robots [m]", lambda row, _r: mean_ci(row, "path_length", "%.4g")),
    "messages_delivered": ("delivered per robot",
                           lambda row, r: per_robot(row, "messages_delivered", r)),
    "info_age_mean": ("information age [s]", lambda row, _r: mean_ci(row, "info_age_mean", "%.2f")),
    "area_claimed_by_several": ("claimed by several [m²]",
                                lambda row, _r: mean_ci(row, "area_claimed_by_several", "%.3g")),
    "connected": ("connected", lambda row, _r: percent(row, "connected_fraction_mean")),
    "delivery_ratio": ("delivery ratio",
                       lambda row, _r: mean_ci(row, "delivery_ratio", "%.3f")),
    "latency_mean": ("latency [ms]", lambda row, _r: milliseconds(row, "latency_mean")),
    "latency_p95": ("latency, 95th percentile [ms]",
                    lambda row, _r: milliseconds(row, "latency_p95")),
    "channel_occupancy": ("air busy",
                          lambda row, _r: mean_ci(row, "channel_occupancy", "%.3f")),
    "phy_drops": ("PHY drops per robot", lambda row, r: per_robot(row, "phy_drops", r)),
}


def markdown_table(headers, rows, right):
    """A markdown table: headers, rows of cell texts, and per column whether it is
    right-aligned (numbers)."""
    lines = ["| " + " | ".join(headers) + " |",
             "|" + "|".join("---:" if r else "---" for r in right) + "|"]
    lines += ["| " + " | ".join(row) + " |" for row in rows]
    return lines


def summary_table(summary, columns, robots=1):
    """A markdown table (a list of lines) of a summary.csv read by read_summary, a row per
    setting. columns: a swept parameter as (path, label), or a name of MEASURES; robots
    divides the per-robot measures."""
    headers, cells, right = [], [], []
    for c in columns:
        if isinstance(c, tuple):
            path, label = c
            if path not in summary.columns:
                raise StudyError(f"summary.csv has no parameter column '{path}'")
            headers.append(label)
            cells.append(lambda row, p=path: parameter(row[p]))
            right.append(path != "planner.type")
        elif c in MEASURES:
            header, cell = MEASURES[c]
            headers.append(header)
            cells.append(lambda row, cell=cell: cell(row, robots))
            right.append(True)
        else:
            raise StudyError(f"unknown table column '{c}' (a (path, label) or one of "
                             f"{', '.join(MEASURES)})")
    rows = [[cell(row) for cell in cells] for _, row in summary.iterrows()]
    return markdown_table(headers, rows, right)


# ---------------------------------------------------------------------------------------
# Figures


def pyplot(salt):
    """matplotlib's pyplot, headless, drawing the same SVG for the same data: element ids
    hashed from `salt`, and (see save_svg) no date."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    plt.rcParams["svg.hashsalt"] = salt
    return plt


def save_svg(fig, file):
    """Writes a figure as SVG without a date, and closes it."""
    import matplotlib.pyplot as plt

    Path(file).parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(file, format="svg", metadata={"Date": None})
    plt.close(fig)


# ---------------------------------------------------------------------------------------
# Running a study


def run(main):
    """Runs a study's main; a failure is one message on stderr and exit code 1."""
    name = Path(sys.argv[0]).name
    try:
        code = main()
    except StudyError as e:
        print(f"{name}: {e}", file=sys.stderr)
        sys.exit(1)
    except subprocess.CalledProcessError as e:
        print(f"{name}: {' '.join(map(str, e.cmd))} failed with exit code {e.returncode}",
              file=sys.stderr)
        sys.exit(1)
    except (RuntimeError, ValueError, OSError) as e:
        # covsim.ScenarioError is a ValueError; a sweep folder holding another sweep, a
        # RuntimeError.
        print(f"{name}: {type(e).__name__}: {e}", file=sys.stderr)
        sys.exit(1)
    sys.exit(code or 0)
