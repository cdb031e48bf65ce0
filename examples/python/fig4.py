"""The paper's Fig. 4: five robots among free-standing obstacles; a virtual target inside an
obstacle is projected to the closest boundary point. The virtual generators' partition
(gold, dashed) and the last partition of the real positions (blue, filled).

    python3 examples/python/fig4.py [--out DIR]
"""
import argparse
import os
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

import covsim

ROOT = pathlib.Path(__file__).resolve().parents[2]
parser = argparse.ArgumentParser()
parser.add_argument("--out", default=".")
args = parser.parse_args()

scenario = covsim.Scenario.from_file(ROOT / "scenarios" / "two_obstacles.json")
sim = covsim.Simulation(scenario)
outcome = sim.run()

fig, ax = plt.subplots(figsize=(5.5, 5.5))
# The real partition's cells filled, the virtual one's outlined; Ω drawn over both.
for k, cell in enumerate(sim.cells("real")):
    for piece in cell["pieces"]:
        ax.fill(*piece.T, color=plt.cm.Pastel1(k % 9), lw=0.5)  # edges hide the seams
    ax.fill(*cell["cell"].T, fill=False, edgecolor="tab:blue", lw=0.8)
for cell in sim.cells("virtual"):
    ax.fill(*cell["cell"].T, fill=False, edgecolor="gold", lw=1.5, ls="--")
covsim.draw_environment(ax, scenario, color="0.3")
ax.plot(*sim.positions.T, "o", color="tab:blue", label="robots")
ax.plot(*sim.virtual_targets.T, "x", color="red", label="virtual targets")
projected = sim.projected
ax.plot(*sim.real_targets[projected].T, "x", color="gold", ms=10, mew=2, label="projected")
ax.set_aspect("equal")
ax.legend(loc="upper right", fontsize=8)
ax.set_title(f"two_obstacles: H real {outcome['cost']['real']:.4g}, "
             f"virtual {outcome['cost']['virtual']:.4g}")
os.makedirs(args.out, exist_ok=True)
out = os.path.join(args.out, "fig4.png")
fig.savefig(out, dpi=100)
print(f"wrote {out}: {int(projected.sum())} projected")
