"""The paper's Fig. 3: five robots spread over the U-shaped environment; their paths, the
virtual generators' paths and the final targets on the left, the cost H of the real and the
virtual generators over time on the right.

    python3 examples/python/fig3.py [--out DIR]
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

sim = covsim.Simulation(covsim.Scenario.from_file(ROOT / "scenarios" / "u_shape.json"))
t, real, virtual = [], [], []
paths, vpaths = [[] for _ in range(5)], [[] for _ in range(5)]


def sample(time, s):
    t.append(time)
    real.append(s.cost("real"))
    virtual.append(s.cost("virtual"))


sim.add_observer(sample)
while not sim.finished:
    for i, (p, v) in enumerate(zip(sim.positions, sim.virtual_generators)):
        paths[i].append(p)
        vpaths[i].append(v)
    sim.advance(0.1)

fig, (ax, bx) = plt.subplots(1, 2, figsize=(10, 4.5))
for p, v in zip(paths, vpaths):
    p, v = np.array(p), np.array(v)
    ax.plot(*p.T, color="tab:blue", lw=1)
    ax.plot(*v.T, color="tab:green", lw=0.8, ls="--")
ax.plot(*sim.scenario.robots.T, "o", mfc="white", mec="tab:blue")
ax.plot(*sim.positions.T, "o", color="tab:blue")
ax.plot(*sim.virtual_targets.T, "x", color="red")
covsim.draw_environment(ax, sim.scenario, color="0.3")
ax.set_aspect("equal")
ax.set_title(f"u_shape: {sim.stop_reason} at t = {sim.now:.1f} s")
ax.set_xlabel("x [m]")
ax.set_ylabel("y [m]")
bx.plot(t, real, label="H (real generators)")
bx.plot(t, virtual, label="H (virtual generators)")
bx.set_xlabel("time [s]")
bx.set_ylabel("cost H [m⁴·φ]")
bx.legend()
fig.tight_layout()
os.makedirs(args.out, exist_ok=True)
out = os.path.join(args.out, "fig3.png")
fig.savefig(out, dpi=100)
print(f"wrote {out}: final H real {real[-1]:.6g}, virtual {virtual[-1]:.6g}")
