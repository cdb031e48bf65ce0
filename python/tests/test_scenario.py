import json

import pytest

import covsim


def test_from_file_and_from_dict_validate_alike(scenarios):
    s = covsim.Scenario.from_file(scenarios / "u_shape.json")
    assert s.robots.shape == (5, 2)
    assert s.seed == 1
    d = json.loads((scenarios / "u_shape.json").read_text())
    t = covsim.Scenario.from_dict(d)
    assert (t.robots == s.robots).all()
    d["density"] = {"type": "uniform", "value": -1}
    with pytest.raises(covsim.ScenarioError) as e:
        covsim.Scenario.from_dict(d)
    assert e.value.path == "$.density.value"
    assert e.value.file == "<dict>"
    assert "expected a number > 0, found -1" in str(e.value)


def test_errors_name_the_file_and_json_path(scenarios, tmp_path):
    bad = tmp_path / "bad.json"
    bad.write_text('{"environment": {"outer": [[0, 0], [1, 0], [1, 1]]}, "robotz": 1}')
    with pytest.raises(covsim.ScenarioError) as e:
        covsim.Scenario.from_file(bad)
    assert e.value.file == str(bad)
    assert e.value.path == "$.robotz"
    assert e.value.line is None  # JSON values carry no place
    assert isinstance(e.value, ValueError)


def test_from_file_reads_yaml_as_its_json_twin(scenarios, tmp_path):
    y = covsim.Scenario.from_file(scenarios / "u_shape.yaml")
    j = covsim.Scenario.from_file(scenarios / "u_shape.json")
    assert y.to_dict() == j.to_dict()
    assert (y.robots == j.robots).all()
    assert covsim.Simulation(y).run()["fingerprint"] == covsim.Simulation(j).run()["fingerprint"]
    bad = tmp_path / "bad.yml"
    bad.write_text("environment:\n  outer: [[0, 0], [1, 0], [1, 1]]\nrobotz: 1\n")
    with pytest.raises(covsim.ScenarioError) as e:
        covsim.Scenario.from_file(bad)
    assert e.value.file == str(bad)
    assert e.value.path == "$.robotz"
    assert (e.value.line, e.value.column) == (3, 9)
    assert str(e.value).startswith(f"{bad}:3:9: $.robotz: unknown key")
    bad.write_text("environment: {outer: [[0, 0], [1, 0], [1, .nan]]}\n")
    with pytest.raises(covsim.ScenarioError) as e:
        covsim.Scenario.from_file(bad)
    assert str(e.value).startswith(f"{bad}:1:43: $.environment.outer[2][1]: expected a finite")


def test_set_changes_a_dotted_path_and_validates(scenarios):
    s = covsim.Scenario.from_file(scenarios / "u_shape.json")
    s.set("network.loss", {"model": "bernoulli", "p": 0.3})
    assert s.to_dict()["network"]["loss"]["p"] == 0.3
    with pytest.raises(covsim.ScenarioError) as e:
        s.set("network.loss.p", 2)
    assert e.value.path == "$.network.loss.p"
    assert s.to_dict()["network"]["loss"]["p"] == 0.3  # nothing changed
    with pytest.raises(covsim.ScenarioError) as e:
        s.set("planner.influence", 0.5)  # a parameter of another planner
    assert "potential_field" in str(e.value)
    with pytest.raises(ValueError):
        s.set("sensor.range", float("inf"))  # JSON has no infinity: null means unlimited
    s.set("sensor.range", None)
