import json
import math

import numpy as np
import pytest

import covsim

PAPER = ["l_shape", "u_shape", "two_obstacles", "fig2b", "fig2c", "fig2d"]


@pytest.mark.parametrize("name", PAPER)
def test_a_run_from_python_has_the_cli_fingerprint(name, scenarios, cli, tmp_path):
    out = covsim.Simulation(covsim.Scenario.from_file(scenarios / f"{name}.json")).run()
    cli("run", scenarios / f"{name}.json", "--out", tmp_path / "run")
    final = json.loads((tmp_path / "run" / "final.json").read_text())
    assert out["fingerprint"] == final["fingerprint"]
    assert out["cost"] == final["cost"]


def test_bodies_from_python_have_the_cli_fingerprint_and_measures(scenarios, cli, tmp_path):
    s = covsim.Scenario.from_file(scenarios / "u_shape.json").set("robots.radius", 0.02)
    out = covsim.Simulation(s).run()
    cli("run", scenarios / "u_shape.json", "--set", "robots.radius=0.02", "--out", tmp_path / "run")
    final = json.loads((tmp_path / "run" / "final.json").read_text())
    assert out["fingerprint"] == final["fingerprint"]
    assert out["bodies"] == final["bodies"]
    assert out["bodies"]["radius"] == 0.02 and out["bodies"]["wall_contacts"] == 0
    assert out["fingerprint"] != covsim.Simulation(
        covsim.Scenario.from_file(scenarios / "u_shape.json")).run()["fingerprint"]
    with pytest.raises(covsim.ScenarioError, match=r"positions\[1\].*overlap"):
        covsim.Scenario.from_file(scenarios / "u_shape.json").set("robots.radius", 0.05)


def test_avoidance_and_kinematics_from_python_match_the_cli(scenarios, cli, tmp_path):
    s = (covsim.Scenario.from_file(scenarios / "u_shape.json").set("robots.radius", 0.02)
         .set("robots.avoidance", {"type": "orca"})
         .set("robots.kinematics", {"type": "differential_drive", "wheel_base": 0.053}))
    out = covsim.Simulation(s).run()
    cli("run", scenarios / "u_shape.json", "--set", "robots.radius=0.02",
        "--set", "robots.avoidance.type=orca", "--set", "robots.kinematics.type=differential_drive",
        "--out", tmp_path / "run")
    final = json.loads((tmp_path / "run" / "final.json").read_text())
    assert out["fingerprint"] == final["fingerprint"]
    assert out["bodies"] == final["bodies"]
    assert out["converged"] and out["bodies"]["contact_time"] == 0.0
    assert out["bodies"]["turn_time"] > 0.0
    with pytest.raises(covsim.ScenarioError, match=r"robots\.avoidance.*radius"):
        covsim.Scenario.from_file(scenarios / "u_shape.json").set(
            "robots.avoidance", {"type": "orca"})


def test_stepping_equals_a_whole_run(scenarios):
    s = covsim.Scenario.from_file(scenarios / "two_obstacles.json")
    s.set("network.loss", {"model": "bernoulli", "p": 0.2})
    whole = covsim.Simulation(s, seed=3).run()
    sim = covsim.Simulation(s, seed=3)
    while sim.step():
        pass
    assert sim.fingerprint == whole["fingerprint"]
    assert sim.events == whole["events"]
    chunks = covsim.Simulation(s, seed=3)
    while not chunks.finished:
        chunks.advance(0.35)
    assert chunks.fingerprint == whole["fingerprint"]
    assert chunks.outcome() == {**whole, "planner": chunks.outcome()["planner"]}


@pytest.mark.parametrize("random_phase", [True, False])
def test_stepping_with_a_simulated_radio_equals_a_whole_run(scenarios, random_phase):
    # The ns-3 peer runs ahead to the next motion step, never past a run_until's time, and
    # broadcasts at that very time wait for the next step: any stepping gives the same run.
    s = covsim.Scenario.from_file(scenarios / "u_shape.json")
    s.set("network.channel", {"type": "ns3_wifi"})
    s.set("network.random_phase", random_phase)
    try:
        whole = covsim.Simulation(s, seed=3).run()
    except RuntimeError as e:
        if "built without ns-3" in str(e) or "peer program is missing" in str(e):
            pytest.skip(f"no ns-3 peer: {e}")
        raise
    sim = covsim.Simulation(s, seed=3)
    while sim.step():
        pass
    assert sim.fingerprint == whole["fingerprint"]
    chunks = covsim.Simulation(s, seed=3)
    t = 0.0
    while not chunks.finished:
        t += 0.037 if random_phase else 0.05
        chunks.run_until(t)
    assert chunks.fingerprint == whole["fingerprint"]


def test_arrays_match_final_json(scenarios, cli, tmp_path):
    sim = covsim.Simulation(covsim.Scenario.from_file(scenarios / "two_obstacles.json"))
    sim.run()
    cli("run", scenarios / "two_obstacles.json", "--out", tmp_path / "run")
    final = json.loads((tmp_path / "run" / "final.json").read_text())
    n = len(final["robots"])
    for name, key in [("positions", "position"), ("virtual_generators", "virtual_generator"),
                      ("virtual_targets", "virtual_target"), ("real_targets", "real_target")]:
        a = getattr(sim, name)
        assert a.shape == (n, 2) and a.dtype == np.float64
        assert (a == np.array([r[key] for r in final["robots"]])).all()
    assert sim.projected.dtype == np.bool_ and sim.path_lengths.dtype == np.float64
    assert (sim.projected == np.array([r["projected"] for r in final["robots"]])).all()
    assert (sim.path_lengths == np.array([r["path_length"] for r in final["robots"]])).all()
    states = sim.planner_state()
    assert [p["status"] for p in states] == [r["status"] for r in final["robots"]]
    assert all(p["planner"] == "tangent_bug" and p["mode"] == "done" for p in states)
    assert sim.cost("real") == pytest.approx(final["cost"]["real"], rel=0, abs=0)
    assert sim.cost("virtual") == final["cost"]["virtual"]


def test_cells_of_a_run_cover_omega(scenarios):
    sim = covsim.Simulation(covsim.Scenario.from_file(scenarios / "u_shape.json"))
    sim.advance(10.0)
    cells = sim.cells("virtual")
    assert len(cells) == 5
    area = 0.0
    for c in cells:
        for p in c["pieces"]:
            x, y = p[:, 0], p[:, 1]
            area += 0.5 * np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y)
    assert area == pytest.approx(1 - 0.3 * 0.65, rel=1e-12)
    assert sum(c["mass"] for c in cells) == pytest.approx(area, rel=1e-12)
    assert sum(c["cost"] for c in cells) == pytest.approx(sim.cost("virtual"), rel=1e-12)


def test_observers_are_called_at_every_sample(scenarios):
    seen = []
    sim = covsim.Simulation(covsim.Scenario.from_file(scenarios / "u_shape.json"))
    sim.add_observer(lambda t, s: seen.append((t, s.cost())))
    sim.run_until(5.0)
    assert [t for t, _ in seen] == pytest.approx([0.0, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0, 3.5, 4.0,
                                                  4.5, 5.0])
    assert all(c > 0 for _, c in seen)


def test_an_observer_that_raises_stops_the_run(scenarios):
    sim = covsim.Simulation(covsim.Scenario.from_file(scenarios / "u_shape.json"))

    def broken(t, s):
        raise RuntimeError("from the observer")

    sim.add_observer(broken)
    with pytest.raises(RuntimeError, match="from the observer"):
        sim.run()


def test_cells_without_a_run_match_covsim_cells(cli, tmp_path):
    scenario = {"environment": {"outer": [[-2, -2], [2, -2], [2, 2], [-2, 2]],
                                "holes": [[[-1, -1], [1, -1], [1, 1], [-1, 1]]]},
                "density": {"type": "uniform"}}
    gens = [[-1.5, 0.0], [1.5, 0.3], [0.2, 1.7]]
    (tmp_path / "s.json").write_text(json.dumps(scenario))
    (tmp_path / "g.json").write_text(json.dumps(gens))
    expected = json.loads(cli("cells", tmp_path / "s.json", "--generators", tmp_path / "g.json"))
    cells = covsim.cells(scenario["environment"], scenario["density"], gens)
    for c, e in zip(cells, expected["cells"]):
        assert c["mass"] == e["mass"]
        assert list(c["centroid"]) == e["centroid"]
        assert c["cost"] == e["cost"]
    assert sum(c["cost"] for c in cells) == pytest.approx(expected["total_cost"], rel=1e-15)
    # The same from an Environment object and from a whole scenario.
    env = covsim.environment(scenario)
    for other in (covsim.cells(env, None, gens), covsim.cells(scenario, generators=gens)):
        assert [c["cost"] for c in other] == [c["cost"] for c in cells]
    with pytest.raises(ValueError, match="generators"):
        covsim.cells(scenario)


def test_cells_keeps_omega_and_density_between_calls():
    environment = {"outer": [[0, 0], [4, 0], [4, 4], [0, 4]],
                   "holes": [np.array([[1.0, 1.0], [1.0, 2.0], [2.0, 2.0], [2.0, 1.0]])]}
    density = {"type": "gaussian_mixture",
               "components": [{"mean": [3, 3], "sigma": 0.5, "weight": 2.0}], "floor": 0.1}
    cells = covsim.Cells(environment, density)
    # The bump over the square less the hole (products of normal masses), and the floor.
    def normal(a, b):
        return 0.5 * (math.erf(b / math.sqrt(2)) - math.erf(a / math.sqrt(2)))
    bump = 2 * 2 * np.pi * 0.25 * (normal(-6, 2) ** 2 - normal(-4, -2) ** 2)
    assert cells.total_mass == pytest.approx(0.1 * 15 + bump, rel=1e-13)
    rng = np.random.default_rng(3)
    for n in (1, 7, 40):
        gens = rng.uniform(0, 4, (n, 2))
        p = cells(gens)
        assert isinstance(p, covsim.Partition) and len(p) == n
        assert p.mass.shape == (n,) and p.centroid.shape == (n, 2) and p.cost.shape == (n,)
        assert np.array_equal(p.generators, gens)
        # The arrays are the dicts of covsim.cells, bit for bit, and the masses add up to Ω's.
        for i, c in enumerate(covsim.cells(environment, density, gens)):
            assert c["mass"] == p.mass[i] and c["cost"] == p.cost[i]
            assert np.array_equal(c["centroid"], p.centroid[i])
            assert np.array_equal(c["cell"], p.cell(i))
            assert all(np.array_equal(a, b) for a, b in zip(c["pieces"], p.pieces(i)))
        assert p.mass.sum() == pytest.approx(cells.total_mass, rel=1e-12)
    assert np.array_equal(p.cell(-1), p.cell(n - 1))
    with pytest.raises(IndexError):
        p.cell(n)
    with pytest.raises(ValueError, match=r"\(n, 2\) array"):
        cells(np.zeros((3, 3)))


def test_the_external_law_takes_targets_from_python(scenarios):
    s = covsim.Scenario.from_file(scenarios / "two_obstacles.json")
    s.set("controller", {"type": "external"})
    sim = covsim.Simulation(s)
    sim.set_target(0, (0.9, 0.9))
    sim.advance(20.0)
    assert np.allclose(sim.positions[0], (0.9, 0.9), atol=1e-9)


def test_the_gil_is_released_while_covsim_runs(scenarios):
    # Another Python thread keeps running while the simulation computes: it records the
    # times it ran; with the GIL held through the run it could not run at all meanwhile.
    import threading
    import time

    sim = covsim.Simulation(covsim.Scenario.from_file(scenarios / "maze.json"))
    ticks, stop = [], threading.Event()

    def count():
        while not stop.is_set():
            ticks.append(time.perf_counter())

    thread = threading.Thread(target=count)
    thread.start()
    while len(ticks) < 10:  # running
        time.sleep(0.001)
    start = time.perf_counter()
    sim.run_until(400.0)
    end = time.perf_counter()
    stop.set()
    thread.join()
    assert sim.now == pytest.approx(400.0)
    inside = [t for t in ticks if start + 0.1 * (end - start) < t < end - 0.1 * (end - start)]
    assert end - start > 0.05  # long enough to tell
    assert len(inside) > 100


def test_a_seed_draws_its_own_robots_as_the_command_line_does(scenarios, cli, tmp_path):
    s = covsim.Scenario.from_file(scenarios / "u_shape.json")
    s.set("robots", {"count": 5, "start": {"cluster": {"center": [0.15, 0.85], "radius": 0.12}}})
    one, two = covsim.Simulation(s, seed=1), covsim.Simulation(s, seed=2)
    assert one.positions.shape == (5, 2)
    assert not (one.positions == two.positions).all()
    assert (np.linalg.norm(one.positions - [0.15, 0.85], axis=1) <= 0.12).all()
    (tmp_path / "drawn.json").write_text(json.dumps(s.to_dict()))
    cli("run", tmp_path / "drawn.json", "--seed", "2", "--out", tmp_path / "run")
    final = json.loads((tmp_path / "run" / "final.json").read_text())
    assert two.run()["fingerprint"] == final["fingerprint"]


def test_localization_from_python_matches_the_cli(scenarios, cli, tmp_path):
    s = covsim.Scenario.from_file(scenarios / "epuck_u_shape.json")
    out = covsim.Simulation(s).run()
    cli("run", scenarios / "epuck_u_shape.json", "--out", tmp_path / "run")
    final = json.loads((tmp_path / "run" / "final.json").read_text())
    assert out["fingerprint"] == final["fingerprint"]
    assert out["localization"] == final["localization"]
    assert out["converged"] and out["localization"]["fixes"] > 0
    assert 0.002 < out["localization"]["error_mean"] < 0.003  # 2 mm noise: 2 √(π/2) mm
    exact = covsim.Simulation(s.set("robots.localization", {"type": "exact"})).run()
    assert exact["localization"] == {"error_mean": 0.0, "error_max": 0.0, "fixes": 0}
    with pytest.raises(covsim.ScenarioError, match=r"robots\.localization.*noise"):
        covsim.Scenario.from_file(scenarios / "epuck_u_shape.json").set(
            "robots.localization", {"type": "tracking", "noise": -0.1})
