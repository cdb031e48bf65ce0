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
    assert isinstance(e.value, ValueError)


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
