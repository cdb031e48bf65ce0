import csv
import json

import numpy as np
import pandas
import pytest

import covsim


def test_sweep_rows_equal_runs_csv(scenarios, tmp_path):
    spec = {"scenario": str(scenarios / "two_obstacles.json"),
            "grid": {"network.loss.model": ["bernoulli"], "network.loss.p": [0.0, 0.4]},
            "seeds": [3, 4]}
    rows = covsim.sweep(spec, jobs=2, out=tmp_path / "sw")
    assert isinstance(rows, pandas.DataFrame)
    assert len(rows) == 4
    with open(tmp_path / "sw" / "runs.csv", newline="") as f:
        table = list(csv.DictReader(f))
    assert list(rows.columns) == list(table[0].keys())
    for (_, row), line in zip(rows.iterrows(), table):
        assert row["fingerprint"] == line["fingerprint"]
        assert row["sim_time"] == float(line["sim_time"])
        assert int(row["converged"]) == int(line["converged"])
    # Results do not depend on the number of threads.
    one = covsim.sweep(spec, jobs=1)
    assert list(one["fingerprint"]) == list(rows["fingerprint"])


def test_measures_name_the_sweep_columns_and_final_json_keys(scenarios, tmp_path):
    spec = {"scenario": str(scenarios / "u_shape.json"), "seeds": [1]}
    rows = covsim.sweep(spec, out=tmp_path / "sw")
    measures = covsim.measures()
    columns = [m["column"] for m in measures if m["column"] is not None]
    assert sorted(columns) == sorted(rows.columns[3:-1])  # after run, setting, seed; error
    final = covsim.Simulation(covsim.Scenario.from_file(scenarios / "u_shape.json")).run()
    in_final = [m["name"] for m in measures if m["final_json"]]
    assert in_final[:3] == list(final)[:3]
    for name in in_final:
        value = final
        for key in name.split("."):
            value = value[key]  # a KeyError names a measure final.json lacks
    units = {m["column"]: m["unit"] for m in measures if m["column"] is not None}
    assert units["time_to_10_percent"] == "s" and units["planner_step_time"] == "µs"


def test_a_sweep_resumes_into_its_folder(scenarios, tmp_path):
    spec = {"scenario": str(scenarios / "u_shape.json"),
            "grid": {"network.loss.model": ["bernoulli"], "network.loss.p": [0.0, 0.4]},
            "seeds": [1]}
    first = covsim.sweep(spec, out=tmp_path / "sw")
    # A finished run is read back, not run again; a missing one is run.
    done = tmp_path / "sw" / "runs" / "1.json"
    result = json.loads(done.read_text())
    result["wall_time"] = 12345.0
    done.write_text(json.dumps(result))
    (tmp_path / "sw" / "runs" / "0.json").unlink()
    second = covsim.sweep(dict(spec), out=tmp_path / "sw")
    assert second.loc[1, "wall_time"] == 12345.0
    assert (tmp_path / "sw" / "runs" / "0.json").exists()
    assert list(second["fingerprint"]) == list(first["fingerprint"])
    # The same from a sweep file, and another sweep into the folder is refused.
    (tmp_path / "sweep.json").write_text(json.dumps(spec))
    covsim.sweep(tmp_path / "sweep.json", out=tmp_path / "file")
    assert covsim.sweep(tmp_path / "sweep.json", out=tmp_path / "file").shape == first.shape
    spec["seeds"] = [2]
    with pytest.raises(RuntimeError, match="holds results of a different sweep"):
        covsim.sweep(spec, out=tmp_path / "sw")


def test_load_run_reads_a_run_folder_into_arrays(scenarios, cli, tmp_path):
    cli("run", scenarios / "u_shape.json", "--out", tmp_path / "run")
    run = covsim.load_run(tmp_path / "run")
    final = json.loads((tmp_path / "run" / "final.json").read_text())
    assert run.final == final
    assert run.robots == 5
    assert run.trajectory["t"].dtype == np.float64
    assert run.trajectory["robot"].dtype == np.int64
    path = run.path(0)
    assert path.shape[1] == 2
    assert list(path[0]) == run.scenario["robots"]["positions"][0]
    assert list(path[-1]) == final["robots"][0]["position"]
    assert run.metrics["t"][-1] == final["sim_time"]
    assert run.metrics["cost_real"][-1] == final["cost"]["real"]


def test_a_sweep_is_validated_before_it_runs_and_keeps_series(scenarios, tmp_path):
    spec = {"scenario": str(scenarios / "u_shape.json"),
            "grid": {"network.loss.model": ["bernoulli"], "network.loss.p": [0.2, 1.5]},
            "seeds": [1, 2]}
    with pytest.raises(covsim.ScenarioError, match=r"network\.loss\.p\[1\]"):
        covsim.sweep(spec, out=tmp_path / "bad")
    assert not (tmp_path / "bad" / "runs").exists()
    spec["grid"]["network.loss.p"] = [0.2]
    rows = covsim.sweep(spec, out=tmp_path / "ok", keep_series=True)
    series = tmp_path / "ok" / "runs" / "0.metrics.csv"
    assert series.exists() and series.read_text().startswith("t,cost_real")
    assert (rows["messages_delivered"] > 0).all() and (rows["info_age_mean"] > 0).all()


def test_seeds_that_give_one_run_are_said_and_counted_once(scenarios, tmp_path):
    # Without loss nothing in two_obstacles is drawn: seeds 3 and 4 run the same run.
    spec = {"scenario": str(scenarios / "two_obstacles.json"),
            "grid": {"network.loss.model": ["bernoulli"], "network.loss.p": [0.0, 0.4]},
            "seeds": [3, 4]}
    with pytest.warns(UserWarning, match=r"loss.p=0.0: 1 distinct run of 2 \(seed 4 = seed 3"):
        rows = covsim.sweep(spec, out=tmp_path / "sw")
    assert rows["fingerprint"][0] == rows["fingerprint"][1]
    assert rows["fingerprint"][2] != rows["fingerprint"][3]
    with open(tmp_path / "sw" / "summary.csv", newline="") as f:
        summary = list(csv.DictReader(f))
    assert [s["distinct_runs"] for s in summary] == ["1", "2"]
    assert summary[0]["sim_time_std"] == ""


def test_a_sweep_reports_its_progress(scenarios, tmp_path, capsys):
    spec = {"scenario": str(scenarios / "u_shape.json"),
            "grid": {"robots.jitter": [0.02], "sensor.range": [0.5, None]}, "seeds": [1, 2]}
    calls = []
    covsim.sweep(spec, jobs=2, out=tmp_path / "sw",
                 progress=lambda done, failed, total: calls.append((done, failed, total)))
    assert calls[0] == (0, 0, 4) and calls[-1] == (4, 0, 4)
    assert [c[0] for c in calls] == list(range(5))
    # Resumed: the runs found done are counted before any runs.
    calls.clear()
    covsim.sweep(spec, out=tmp_path / "sw", progress=lambda *c: calls.append(c))
    assert calls == [(4, 0, 4)]
    # True: a tqdm bar, or without tqdm a line per run on stderr.
    covsim.sweep(spec, out=tmp_path / "again", progress=True)
    err = capsys.readouterr().err
    assert "4/4" in err
    # A callback that raises ends the sweep with its exception.
    def stop(done, failed, total):
        if done == 1:
            raise KeyboardInterrupt("enough")
    with pytest.raises(KeyboardInterrupt, match="enough"):
        covsim.sweep(spec, jobs=1, out=tmp_path / "stopped", progress=stop)
    with pytest.raises(ValueError, match="progress='yes'"):
        covsim.sweep(spec, progress="yes")
