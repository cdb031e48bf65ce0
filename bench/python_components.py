"""What a planner or a coverage law written in Python costs per call, against the built-in
C++ one doing the same work, measured in the same process (docs/python.md).

    PYTHONPATH=build/python python3 bench/python_components.py [--repetitions N]

Planner: straight_line against a Python straight-line planner, 12 robots in a convex room, where both
take the same steps (the runs' fingerprints are checked equal). Law: the paper's law against
a Python Lloyd law on the U-shaped scenario (bit-identical runs). Per call: the extra wall
time of the Python run over the C++ run, divided by the calls; reported as the median and the
range over the repetitions, which alternate between the two so that machine noise hits both.
"""
import argparse
import pathlib
import statistics
import time

import numpy as np

import covsim

ROOT = pathlib.Path(__file__).resolve().parents[1]


class Straight:
    def __init__(self, environment, params):
        self.environment = environment
        self.goal = None

    def set_goal(self, goal):
        self.goal = np.asarray(goal)

    def step(self, reading, max_step):
        x = reading.position
        d = float(np.hypot(*(self.goal - x)))
        if d <= 1e-12:
            return self.goal, "reached"
        if d <= max_step:
            return self.goal, "reached"
        return x + (max_step / d) * (self.goal - x), "moving"


class Lloyd:
    calls = 0

    def __init__(self, environment, params):
        pass

    def target(self, robot, knowledge):
        Lloyd.calls += 1
        return knowledge.own_cell()["centroid"]


covsim.register_planner("bench_py_straight", Straight)
covsim.register_law("bench_py_lloyd", Lloyd)


def timed(scenario):
    sim = covsim.Simulation(scenario)
    start = time.perf_counter()
    out = sim.run()
    return time.perf_counter() - start, out


def compare(label, builtin, python, calls_of, repetitions):
    extra, ratio = [], []
    for _ in range(repetitions):
        t_cpp, out_cpp = timed(builtin)
        t_py, out_py = timed(python)
        if out_cpp["fingerprint"] != out_py["fingerprint"]:
            raise SystemExit(f"{label}: the two runs differ, so the comparison is void")
        calls = calls_of(out_py)
        extra.append((t_py - t_cpp) / calls * 1e6)
        ratio.append(t_py / t_cpp)
    print(f"{label}: {calls} calls per run; Python costs {statistics.median(extra):.2f} us more "
          f"per call (range {min(extra):.2f} to {max(extra):.2f}); whole run {statistics.median(ratio):.2f}x "
          f"the C++ one (range {min(ratio):.2f} to {max(ratio):.2f}); {repetitions} repetitions")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--repetitions", type=int, default=21)
    args = parser.parse_args()

    room = covsim.Scenario.from_dict({
        "environment": {"outer": [[0, 0], [2, 0], [2, 1], [0, 1]]},
        "density": {"type": "uniform"},
        "robots": {"positions": [[0.1 + 0.1 * (k % 4), 0.1 + 0.1 * (k // 4)] for k in range(12)]},
        "seed": 1})
    room.set("planner", {"type": "straight_line"})
    py_room = room.copy()
    py_room.set("planner", {"type": "bench_py_straight"})
    compare("planner step", room, py_room, lambda out: out["planner"]["steps"], args.repetitions)

    u = covsim.Scenario.from_file(ROOT / "scenarios" / "u_shape.json")
    py_u = u.copy()
    py_u.set("controller", {"type": "bench_py_lloyd"})

    def law_calls(out):
        calls, Lloyd.calls = Lloyd.calls, 0
        return calls

    Lloyd.calls = 0
    compare("coverage law target", u, py_u, law_calls, args.repetitions)


if __name__ == "__main__":
    main()
