import numpy as np
import pytest

import covsim


class Straight:
    """A planner in Python: straight at the goal, stalling at the first wall it touches."""

    def __init__(self, environment, params):
        self.environment = environment
        self.goal = None

    def set_goal(self, goal):
        self.goal = np.array(goal)

    def step(self, reading, max_step):
        x = reading.position
        # An exact sensor reads at every step: the view is from where the robot stands.
        assert np.array_equal(reading.origin, x)
        d = np.linalg.norm(self.goal - x)
        if d <= 1e-9:
            return self.goal, "reached"
        nxt = self.goal if d <= max_step else x + max_step * (self.goal - x) / d
        if not self.environment.segment_inside(x, nxt):
            return x, "stalled"
        return nxt, "moving"


class Lloyd:
    """A coverage law in Python: the paper's, via the cell covsim computes."""

    def __init__(self, environment, params):
        self.gain = params["gain"]

    def target(self, robot, knowledge):
        g = knowledge.points[knowledge.self]
        return g + self.gain * (knowledge.own_cell()["centroid"] - g)


covsim.register_planner("py_straight", Straight, "straight line, in Python")
covsim.register_law("py_lloyd", Lloyd, "Lloyd on virtual generators, in Python",
                    params={"gain": 1.0})


def test_python_components_are_registered_beside_the_builtin_ones():
    assert "py_straight" in [p["name"] for p in covsim.components("planners")]
    law = [l for l in covsim.components("laws") if l["name"] == "py_lloyd"][0]
    assert law["params"][0]["name"] == "gain" and law["params"][0]["default"] == "1"
    with pytest.raises(ValueError, match="registered already"):
        covsim.register_planner("py_straight", Straight)


def test_a_python_law_reproduces_the_paper_law_bit_for_bit(scenarios):
    s = covsim.Scenario.from_file(scenarios / "u_shape.json")
    builtin = covsim.Simulation(s).run()
    s.set("controller", {"type": "py_lloyd"})
    python = covsim.Simulation(s).run()
    assert python["stop_reason"] == "converged"
    assert python["fingerprint"] == builtin["fingerprint"]
    s.set("controller", {"type": "py_lloyd", "gain": 0.5})
    damped = covsim.Simulation(s).run()
    assert damped["converged"]
    assert damped["fingerprint"] != builtin["fingerprint"]


ROOM = {"environment": {"outer": [[0, 0], [2, 0], [2, 1], [0, 1]]},
        "density": {"type": "gaussian_mixture", "floor": 0.2,
                    "components": [{"mean": [1.5, 0.5], "sigma": 0.4, "weight": 1.0}]},
        "robots": {"positions": [[0.1, 0.1], [0.2, 0.1], [0.1, 0.2]]}, "seed": 1}


def test_a_python_planner_drives_a_run_to_convergence():
    # A convex room, where going straight always works.
    s = covsim.Scenario.from_dict(ROOM)
    s.set("planner", {"type": "py_straight"})
    sim = covsim.Simulation(s)
    out = sim.run()
    assert out["converged"]
    assert sim.planner_state()[0]["planner"] == "py_straight"
    # Deterministic: the same run twice.
    assert covsim.Simulation(s).run()["fingerprint"] == out["fingerprint"]


def test_a_python_planner_that_breaks_its_contract_fails_loudly(scenarios):
    class Liar(Straight):
        def step(self, reading, max_step):
            return reading.position, "teleported"

    covsim.register_planner("py_liar", Liar)
    s = covsim.Scenario.from_file(scenarios / "l_shape.json")
    s.set("planner", {"type": "py_liar"})
    with pytest.raises(ValueError, match="moving, reached, projected or stalled"):
        covsim.Simulation(s).run()


def test_a_python_planner_that_jumps_stops_the_run(scenarios):
    class Jumper(Straight):
        def step(self, reading, max_step):
            return self.goal, "moving"  # straight to the goal, however far

    covsim.register_planner("py_jumper", Jumper)
    s = covsim.Scenario.from_dict(ROOM)
    s.set("planner", {"type": "py_jumper"})
    with pytest.raises(RuntimeError, match="planner py_jumper proposed a step of .* the step "
                                           "length is"):
        covsim.Simulation(s).run()


def test_a_python_planner_may_keep_its_state_when_its_goal_moves():
    # Periodic loop 1 moves targets under robots on their way: move_goal when the planner
    # has one, set_goal when it has not.
    calls = {"set": 0, "move": 0}

    class Counting(Straight):
        def set_goal(self, goal):
            calls["set"] += 1
            super().set_goal(goal)

    class Keeping(Counting):
        def move_goal(self, goal):
            calls["move"] += 1
            self.goal = np.array(goal)

    s = covsim.Scenario.from_dict(ROOM)
    s.set("loops", {"mode": "periodic", "loop1_period": 0.1})
    covsim.register_planner("py_counting", Counting)
    covsim.register_planner("py_keeping", Keeping)
    s.set("planner", {"type": "py_counting"})
    assert covsim.Simulation(s).run()["converged"]
    assert calls["move"] == 0
    without = calls["set"]
    calls.update(set=0, move=0)
    s.set("planner", {"type": "py_keeping"})
    assert covsim.Simulation(s).run()["converged"]
    assert calls["move"] > 0 and calls["set"] + calls["move"] == without


class Through:
    """A planner in Python that drives through walls, as the `none` baseline does."""

    avoids_obstacles = False

    def __init__(self, environment, params):
        self.goal = None

    def set_goal(self, goal):
        self.goal = np.array(goal)

    def step(self, reading, max_step):
        x = reading.position
        d = np.linalg.norm(self.goal - x)
        if d <= max_step:
            return self.goal, "reached"
        return x + max_step * (self.goal - x) / d, "moving"


def test_a_python_planner_that_drives_through_walls_ends_the_run_where_it_leaves(scenarios):
    covsim.register_planner("py_through", Through)
    s = covsim.Scenario.from_file(scenarios / "fig2d.json")
    s.set("controller", {"type": "geodesic_lloyd"})
    s.set("planner", {"type": "py_through"})
    python = covsim.Simulation(s).run()
    s.set("planner", {"type": "none"})
    builtin = covsim.Simulation(s).run()
    assert python["stop_reason"] == "left_environment"
    assert python["left_environment"] == builtin["left_environment"]


class Feeler:
    """A planner in Python that senses: told nothing of Ω, it goes straight at the goal and
    stalls where a wall it sees is in the way; it keeps the walls its neighbours share."""

    made = []

    def __init__(self, environment, params):
        self.environment = environment
        self.goal = None
        self.heard = []
        Feeler.made.append(self)

    def set_goal(self, goal):
        self.goal = np.array(goal)

    def learn(self, walls):
        self.heard.append(walls)

    def step(self, reading, max_step):
        x = reading.position
        d = np.linalg.norm(self.goal - x)
        if d <= 1e-9:
            return self.goal, "reached"
        nxt = self.goal if d <= max_step else x + max_step * (self.goal - x) / d

        def side(p, q, r):
            return np.sign((q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]))

        for ax, ay, bx, by in reading.pieces:
            a, b = (ax, ay), (bx, by)
            if side(x, nxt, a) * side(x, nxt, b) < 0 and side(a, b, x) * side(a, b, nxt) < 0:
                return x, "stalled"
        return nxt, "moving"


def test_a_python_planner_that_senses_runs_where_omega_is_unknown_and_hears_walls(scenarios):
    covsim.register_planner("py_feeler", Feeler, "straight, on what it senses", senses=True)
    s = covsim.Scenario.from_file(scenarios / "two_obstacles.json")
    s.set("environment.known", "none")
    s.set("sensor", {"range": 0.5})
    s.set("network", {"loss": {"model": "bernoulli", "p": 0.1}})
    s.set("mapping", {"compare_known": False})
    s.set("convergence", {"max_time": 20})
    s.set("planner", {"type": "py_feeler"})
    Feeler.made.clear()
    out = covsim.Simulation(s).run()
    assert out["stop_reason"] in ("converged", "stuck", "max_time")
    # Told nothing of Ω; decentralized, the walls of readings heard, as (k, 4) rows.
    assert len(Feeler.made) == 5 and all(p.environment is None for p in Feeler.made)
    heard = [w for p in Feeler.made for w in p.heard]
    assert heard and all(w.ndim == 2 and w.shape[1] == 4 for w in heard)
    assert any(len(w) > 0 for w in heard)
    # A planner told Ω is refused where the robots do not know it.
    with pytest.raises(Exception, match="plans from what it senses"):
        s.set("planner", {"type": "py_straight"})
