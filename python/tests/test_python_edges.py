"""The Python edge: every bad value, misuse or broken component is a Python exception naming
the call (and, for components, the robot and the component), never a crash, and a simulation
whose component raised refuses to go on."""
import threading

import numpy as np
import pytest

import covsim

ROOM = {"environment": {"outer": [[0, 0], [2, 0], [2, 1], [0, 1]]},
        "density": {"type": "uniform"},
        "robots": {"positions": [[0.1, 0.1], [0.2, 0.1], [0.1, 0.2]]}, "seed": 1}


class Straight:
    def __init__(self, environment, params):
        self.environment = environment
        self.goal = None

    def set_goal(self, goal):
        self.goal = np.array(goal)

    def step(self, reading, max_step):
        x = reading.position
        d = np.linalg.norm(self.goal - x)
        if d <= 1e-9:
            return self.goal, "reached"
        return (self.goal if d <= max_step else x + max_step * (self.goal - x) / d), "moving"


def room(planner=None, controller=None):
    s = covsim.Scenario.from_dict(ROOM)
    if planner:
        s.set("planner", {"type": planner})
    if controller:
        s.set("controller", {"type": controller})
    return s


def test_times_in_the_past_and_after_the_end_are_value_errors():
    sim = covsim.Simulation(room())
    sim.run_until(1.0)
    with pytest.raises(ValueError, match=r"run_until\(-5\): that is before now, 1 s"):
        sim.run_until(-5.0)
    with pytest.raises(ValueError, match=r"advance\(nan\)"):
        sim.advance(float("nan"))
    sim.run()
    with pytest.raises(ValueError, match=r"advance\(1\): the run has ended \(converged\)"):
        sim.advance(1.0)


def test_errors_name_the_call():
    s = room()
    with pytest.raises(covsim.ScenarioError, match=r'^set\("sensor.range", -1\): \$.sensor.range'):
        s.set("sensor.range", -1)
    spec = {"scenario": ROOM, "grid": {"sensor.rnage": [1.0]}, "seeds": [1]}
    with pytest.raises(covsim.ScenarioError) as e:
        covsim.sweep(spec)
    assert str(e.value).startswith("sweep(spec): ") and "tmp" not in str(e.value)
    assert e.value.file == "sweep(spec)"


def test_a_planner_returning_a_bad_shape_is_named_with_its_robot():
    class Shapeless(Straight):
        def step(self, reading, max_step):
            return reading.position  # not (next, status)

    covsim.register_planner("py_shapeless", Shapeless)
    with pytest.raises(TypeError, match=r"step must return \(next, status\)") as e:
        covsim.Simulation(room("py_shapeless")).run()
    assert any('robot 0\'s planner "py_shapeless" at t = 0.1 s' in n
               for n in getattr(e.value, "__notes__", []))


def test_a_law_returning_nan_stops_the_run_with_its_name_and_nothing_more():
    class Lost:
        def __init__(self, environment, params):
            pass

        def target(self, robot, knowledge):
            return [float("nan"), float("nan")]

    covsim.register_law("py_lost", Lost)
    sim = covsim.Simulation(room(controller="py_lost"))
    with pytest.raises(ValueError, match="a target must be finite") as e:
        sim.run()
    assert any("coverage law \"py_lost\"" in n for n in e.value.__notes__)
    # The simulation refuses to go on: its state stopped half-way.
    with pytest.raises(RuntimeError, match="stopped on an error"):
        sim.step()


def test_a_knowledge_kept_after_its_call_stays_readable_but_not_its_cell():
    kept = []

    class Keeper:
        def __init__(self, environment, params):
            pass

        def target(self, robot, knowledge):
            kept.append(knowledge)
            return knowledge.own_cell()["centroid"]

    covsim.register_law("py_keeper", Keeper)
    covsim.Simulation(room(controller="py_keeper")).run()
    assert kept and kept[0].points.shape == (3, 2)
    with pytest.raises(RuntimeError, match="only during the law's target call"):
        kept[0].own_cell()


def test_an_environment_kept_by_a_planner_outlives_the_run():
    kept = []

    class Keeper(Straight):
        def __init__(self, environment, params):
            super().__init__(environment, params)
            kept.append(environment)

    covsim.register_planner("py_env_keeper", Keeper)
    covsim.Simulation(room("py_env_keeper")).run()
    import gc
    gc.collect()
    assert kept[0].contains([1.0, 0.5]) and kept[0].area == pytest.approx(2.0)


def test_a_run_started_from_inside_its_own_run_is_refused():
    holder = {}

    class Reentrant(Straight):
        def step(self, reading, max_step):
            holder["sim"].run()
            return super().step(reading, max_step)

    covsim.register_planner("py_reentrant", Reentrant)
    holder["sim"] = covsim.Simulation(room("py_reentrant"))
    with pytest.raises(RuntimeError, match=r"Simulation.run\(\): called from inside"):
        holder["sim"].run()


def test_a_second_thread_cannot_read_or_drive_a_running_simulation():
    inside, release = threading.Event(), threading.Event()
    sim = covsim.Simulation(room())

    def observer(t, s):
        if t > 0 and not inside.is_set():
            inside.set()
            release.wait(10)  # the run pauses here, the GIL let go

    sim.add_observer(observer)
    runner = threading.Thread(target=sim.run)
    runner.start()
    try:
        assert inside.wait(10)
        with pytest.raises(RuntimeError, match="running in another thread"):
            sim.outcome()
        with pytest.raises(RuntimeError, match="running in another thread"):
            sim.step()
    finally:
        release.set()
        runner.join()
    assert sim.outcome()["stop_reason"] == "converged"


def test_bad_registrations_and_targets_are_refused():
    with pytest.raises(TypeError, match=r'register_planner\("py_x"\): factory must be callable'):
        covsim.register_planner("py_x", 42)
    with pytest.raises(TypeError, match=r'register_law\("py_y"\): factory must be callable'):
        covsim.register_law("py_y", "not a factory")
    with pytest.raises(ValueError, match="an int default must be 0 or more"):
        covsim.register_planner("py_z", Straight, params={"k": -1})
    s = room(controller="external")
    sim = covsim.Simulation(s)
    with pytest.raises(ValueError, match=r"set_target\(0, \(nan, 1\)\): expected a finite"):
        sim.set_target(0, [float("nan"), 1.0])


def test_the_package_exports_only_its_own_names():
    for stray in ("np", "os", "json", "tempfile", "csv", "gzip", "operator"):
        assert not hasattr(covsim, stray)
    assert all(hasattr(covsim, name) for name in covsim.__all__)


def test_cells_refuse_coincident_and_far_generators_as_the_command_does():
    cells = covsim.Cells(room())
    with pytest.raises(ValueError, match=r"cells\(generators\): .*coincide"):
        cells([[0.5, 0.5], [0.2, 0.2], [0.5, 0.5]])
    with pytest.raises(ValueError, match=r"cells\(generators\): generator 1 at \(1e\+07, 1e\+07\)"):
        cells([[0.5, 0.5], [1e7, 1e7]])
    # Outside Ω but within reach: the whole of Ω's mass, to the last bits.
    far = cells([[2.0, 2.0]])
    assert far.mass[0] == pytest.approx(cells.total_mass, rel=1e-12)


def test_sweep_jobs_out_of_range_are_value_errors():
    for jobs in (0, -1, 10**9, 2.5, True):
        with pytest.raises(ValueError, match=r"sweep\(jobs="):
            covsim.sweep({"scenario": {}, "seeds": [1]}, jobs=jobs)
