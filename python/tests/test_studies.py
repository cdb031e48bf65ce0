"""The studies' shared module (studies/study.py): markdown tables from a sweep's summary.csv,
the docs' generated sections, and a sweep with a failed run failing the study."""
import math
import sys

import numpy as np
import pandas
import pytest

import covsim

from conftest import SOURCE

sys.path.insert(0, str(SOURCE / "studies"))
import study  # noqa: E402


def row(**values):
    return pandas.Series(values, dtype=object)


def test_median_and_quartiles_with_the_two_modes_where_the_runs_split():
    one = row(t_median=16.25, t_q1=14.5, t_q3=23.125, t_modes=1.0, t_low_fraction=math.nan,
              t_low_median=math.nan, t_high_median=math.nan)
    assert study.median_iqr(one, "t", "%.1f") == "16.2 [14.5, 23.1]"
    two = row(t_median=40.0, t_q1=15.0, t_q3=70.0, t_modes=2.0, t_low_fraction=0.45,
              t_low_median=15.5, t_high_median=66.25)
    assert study.median_iqr(two, "t", "%.1f") == \
        "40.0 [15.0, 70.0]; 45% at 15.5, 55% at 66.2"
    none = row(t_median=math.nan, t_q1=math.nan, t_q3=math.nan, t_modes=math.nan)
    assert study.median_iqr(none, "t", "%.1f") == "–"


def test_mean_with_its_interval_percentages_and_per_robot_measures():
    r = row(cost_mean=0.011811740767354917, cost_ci95=1.996078490840063e-05,
            rate=1.0, messages_mean=4087.5, empty_mean=math.nan, empty_ci95=math.nan)
    assert study.mean_ci(r, "cost", "%.4g") == "0.01181 ± 1.996e-05"
    assert study.mean_ci(r, "empty", "%.4g") == "–"
    assert study.percent(r, "rate") == "100%"
    assert study.per_robot(r, "messages", 5) == "818"
    assert study.parameter("null") == "∞" and study.parameter("0.5") == "0.5"


def test_a_summary_table_by_column_name_from_a_sweep(scenarios, tmp_path):
    # Jittered starts: u_shape's fixed ones would give one run for every seed.
    path = study.write_sweep(tmp_path / "ranges.json", scenarios / "u_shape.json",
                             {"sensor.range": [0.5, None], "robots.jitter": [0.05]},
                             seeds=[1, 2, 3])
    runs = study.sweep(path, tmp_path / "ranges", jobs=2)
    summary = study.read_summary(tmp_path / "ranges")
    assert list(summary["sensor.range"]) == ["0.5", "null"]
    lines = study.summary_table(summary, [("sensor.range", "range [m]"), "runs", "converged",
                                          "sim_time", "cost_real"])
    assert lines[0] == ("| range [m] | runs | converged | time to converge [s] | "
                        "final cost H (real) |")
    assert lines[1] == "|---:|---:|---:|---:|---:|"
    assert len(lines) == 4
    for line, value in zip(lines[2:], [0.5, None]):
        # The same figures from the runs themselves.
        unlimited = runs["sensor.range"].isna()  # null: None, NaN in a column of numbers
        mine = (runs[unlimited] if value is None
                else runs[~unlimited & (runs["sensor.range"] == value)])
        assert len(mine) == 3
        t = np.asarray(mine["sim_time"], dtype=float)
        median, q1, q3 = np.median(t), np.quantile(t, 0.25), np.quantile(t, 0.75)
        cells = [c.strip() for c in line.strip("|").split("|")]
        assert cells[0] == ("∞" if value is None else "0.5")
        assert cells[1] == "3"
        assert cells[2] == f"{100 * mine['converged'].astype(float).mean():.0f}%"
        # Runs that all took the same time have no spread to give.
        assert cells[3] == (f"{median:.1f}" if q1 == q3 == median
                            else f"{median:.1f} [{q1:.1f}, {q3:.1f}]")
        assert cells[4].startswith(f"{np.mean(mine['cost_real']):.4g} ± ")
    with pytest.raises(study.StudyError, match="unknown table column 'colour'"):
        study.summary_table(summary, ["colour"])


def test_a_generated_section_is_replaced_or_appended(tmp_path):
    doc = tmp_path / "doc.md"
    doc.write_text("# Title\n\nprose before\n<!-- begin t -->\nold\ntable\n<!-- end t -->\n"
                   "prose after\n")
    study.replace_section(doc, "t", ["new", "", "lines"])
    assert doc.read_text() == ("# Title\n\nprose before\n<!-- begin t -->\nnew\n\nlines\n"
                               "<!-- end t -->\nprose after\n")
    study.replace_section(doc, "other", "appended\n")
    assert doc.read_text().endswith("prose after\n<!-- begin other -->\nappended\n"
                                    "<!-- end other -->\n")
    study.replace_section(doc, "t", [])
    assert "<!-- begin t -->\n<!-- end t -->\nprose after" in doc.read_text()
    broken = tmp_path / "broken.md"
    broken.write_text("<!-- begin t -->\nno end\n")
    with pytest.raises(study.StudyError, match="has no '<!-- end t -->'"):
        study.replace_section(broken, "t", ["x"])
    assert broken.read_text() == "<!-- begin t -->\nno end\n"


class Failing:
    """A planner that gives up at its first step."""

    def __init__(self, environment, params):
        pass

    def set_goal(self, goal):
        self.goal = goal

    def step(self, reading, max_step):
        raise RuntimeError("this planner always fails")


covsim.register_planner("py_study_failing", Failing, "fails at its first step")


def test_a_sweep_with_a_failed_run_fails_the_study(scenarios, tmp_path, monkeypatch, capsys):
    path = study.write_sweep(tmp_path / "failing.json", scenarios / "u_shape.json",
                             {"planner.type": ["tangent_bug", "py_study_failing"]}, seeds=[1])
    with pytest.raises(study.StudyError, match=r"1 of 2 runs failed\n  run 1 \(setting 1, "
                                               r"seed 1\): .*this planner always fails"):
        study.sweep(path, tmp_path / "failing", jobs=1)

    def main():
        study.sweep(path, tmp_path / "failing", jobs=1)
        study.replace_section(tmp_path / "doc.md", "t", ["never written"])

    monkeypatch.setattr(sys, "argv", ["network.py"])
    with pytest.raises(SystemExit) as exit:
        study.run(main)
    assert exit.value.code == 1
    assert "network.py: " in capsys.readouterr().err
    assert not (tmp_path / "doc.md").exists()
    # A sweep file that does not validate fails the study as well.
    bad = study.write_sweep(tmp_path / "bad.json", scenarios / "u_shape.json",
                            {"sensor.range": [-1]}, seeds=[1])
    monkeypatch.setattr(sys, "argv", ["fidelity.py"])
    with pytest.raises(SystemExit) as exit:
        study.run(lambda: study.sweep(bad, tmp_path / "bad", jobs=1))
    assert exit.value.code == 1
    assert "fidelity.py: ScenarioError: " in capsys.readouterr().err


def test_the_radio_study_refuses_an_unknown_number_of_robots(monkeypatch, capsys):
    import radio

    assert [radio.grid(n)["robots"][0]["count"] for n in radio.COUNTS] == radio.COUNTS
    # The limit on 100 robots' runs is part of their sweep, and the ideal reference shares
    # every swept value but the channel's.
    assert radio.grid(100)["convergence.max_time"] == [600.0]
    assert "convergence.max_time" not in radio.grid(30)
    for n in radio.COUNTS:
        ideal = radio.ideal_grid(n)
        assert {k: v for k, v in radio.grid(n).items() if not k.startswith("network.")} == ideal
    for bad in ["7", "5,x", ""]:
        monkeypatch.setattr(sys, "argv", ["radio.py", "--counts", bad])
        with pytest.raises(SystemExit) as exit:
            study.run(radio.main)
        assert exit.value.code == 1
        assert "radio.py: " in capsys.readouterr().err


def test_compare_planners_on_ones_own_scenario(scenarios, tmp_path):
    # studies/compare_planners.py SCENARIO... --out DIR: the tables and charts for any
    # scenario, the docs left alone.
    import json
    import os
    import pathlib
    import subprocess

    from conftest import COVSIM

    room = json.loads((scenarios / "u_shape.json").read_text())
    room["robots"]["jitter"] = 0.03
    (tmp_path / "my_room.json").write_text(json.dumps(room))
    env = dict(os.environ, COVSIM_BUILD_DIR=str(pathlib.Path(COVSIM).parents[1]),
               PYTHONPATH=str(pathlib.Path(covsim.__file__).parents[1]))
    docs = (SOURCE / "docs" / "planners.md").read_text()
    script = str(SOURCE / "studies" / "compare_planners.py")
    done = subprocess.run(
        [sys.executable, script, str(tmp_path / "my_room.json"), "--out", str(tmp_path / "cmp"),
         "--seeds", "2", "--planners", "tangent_bug,visibility_graph",
         "--laws", "virtual_generators", "--jobs", "2"],
        env=env, capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    report = (tmp_path / "cmp" / "report.md").read_text()
    assert "## my_room" in report and "## Over all of them" in report
    rows = [line for line in report.splitlines() if line.startswith("| 1 ") or
            line.startswith("| 2 ")]
    assert len(rows) == 4  # 2 seeds x 2 planners, one law
    assert all("| virtual_generators |" in r for r in rows)
    for chart in ("convergence.svg", "path-ratio.svg", "step-time.svg"):
        assert (tmp_path / "cmp" / chart).stat().st_size > 1000
    assert (SOURCE / "docs" / "planners.md").read_text() == docs
    # A name that is not a registered planner, and scenarios without a folder: errors.
    bad = subprocess.run([sys.executable, script, str(tmp_path / "my_room.json"), "--out",
                          str(tmp_path / "bad"), "--planners", "tangent_bugg"],
                         env=env, capture_output=True, text=True)
    assert bad.returncode == 1 and '"tangent_bugg" is not one of' in bad.stderr
    bad = subprocess.run([sys.executable, script, str(tmp_path / "my_room.json")],
                         env=env, capture_output=True, text=True)
    assert bad.returncode == 1 and "needs --out DIR" in bad.stderr
