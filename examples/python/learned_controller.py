"""A minimal "learned controller" loop: Python steps the simulation and sets every robot's
target itself (the "external" coverage law), here from a toy linear policy, as a
learning-based controller would from its network. The policy: move part of the way toward
the centroid of the robot's Voronoi cell of the current positions (covsim.cells).

    python3 examples/python/learned_controller.py [--out DIR]
"""
import argparse
import os
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import covsim

ROOT = pathlib.Path(__file__).resolve().parents[2]
parser = argparse.ArgumentParser()
parser.add_argument("--out", default=".")
args = parser.parse_args()

scenario = covsim.Scenario.from_file(ROOT / "scenarios" / "u_shape.json")
scenario.set("controller", {"type": "external"})
scenario.set("planner", {"type": "visibility_graph"})
sim = covsim.Simulation(scenario)
weights = np.array([0.8])  # the "learned" parameter: the fraction of the step


def policy(positions):
    cells = covsim.cells(scenario, generators=positions)
    centroids = np.array([c["centroid"] for c in cells])
    return positions + weights[0] * (centroids - positions)


costs = []
for iteration in range(40):
    targets = policy(sim.positions)
    env = covsim.environment(scenario)
    for i, target in enumerate(targets):
        sim.set_target(i, env.closest_point(target))  # keep targets in Ω
    sim.advance(2.0)
    costs.append(sim.cost("real"))

fig, ax = plt.subplots(figsize=(5, 3.5))
ax.plot(np.arange(1, len(costs) + 1), costs, marker=".")
ax.set_xlabel("policy step (2 s each)")
ax.set_ylabel("cost H of the real positions")
fig.tight_layout()
os.makedirs(args.out, exist_ok=True)
out = os.path.join(args.out, "learned_controller.png")
fig.savefig(out, dpi=100)
print(f"wrote {out}: H from {costs[0]:.5g} to {costs[-1]:.5g}")
