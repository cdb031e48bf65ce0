"""How message loss slows coverage, in ten lines: a sweep over the Bernoulli loss rate on
the U-shaped scenario, N seeds each; the time to converge (mean and standard deviation)
and the final cost H.

    python3 examples/python/loss_study.py [--out DIR] [--seeds N]
"""
import argparse, os, pathlib
import matplotlib; matplotlib.use("Agg")
import covsim

p = argparse.ArgumentParser(); p.add_argument("--out", default="."); p.add_argument("--seeds", type=int, default=20); a = p.parse_args()
rows = covsim.sweep({"scenario": str(pathlib.Path(__file__).resolve().parents[2] / "scenarios" / "u_shape.json"),
                     "grid": {"network.loss.model": ["bernoulli"], "network.loss.p": [0.0, 0.3, 0.6, 0.9]},
                     "seeds": {"count": a.seeds}}, jobs=2)
stats = rows.groupby("network.loss.p").agg(time=("sim_time", "mean"), sd=("sim_time", "std"), H=("cost_real", "mean"))
ax = stats.plot(y="time", yerr="sd", marker="o", legend=False, xlabel="loss probability", ylabel="time to converge [s]")
os.makedirs(a.out, exist_ok=True); ax.figure.savefig(os.path.join(a.out, "loss_study.png")); print(stats.to_string())
