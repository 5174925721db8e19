#!/usr/bin/env python3
"""Cost against the number of flow unknowns for both flow-solve paths and OpenFOAM:
doc/cost_vs_dofs.png from the stored results of benchmarks/cost_3d.py (3D column,
benchmarks/results/cost_3d/cost_3d.json) and benchmarks/openfoam_comparison.py (2D
fluidisedBed, benchmarks/results/openfoam_comparison/*.json). Left: wall time per
simulated second; right: µs per flow unknown per step (wall time / steps / unknowns).

Flow unknowns: wetbed's velocity and pressure DoFs (Q2^{2 dim} x Q1; on the 2D bed's
3·2^L x 20·2^L quadrilaterals 4(2 nx + 1)(2 ny + 1) + (nx + 1)(ny + 1)); OpenFOAM's cell
values of both phases' velocities and the pressure, 5 per cell in 2D.

usage: python3 benchmarks/cost_plot.py   (after the two benchmarks)
"""
import glob
import json
import os

from benchmark_setup import repository_root

root = repository_root()  # under Debian's python3, where matplotlib is

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
results = os.path.join(root, "benchmarks", "results")
series = {}  # label -> [(unknowns, s per simulated s, µs per unknown per step)]

cost_3d = json.load(open(os.path.join(results, "cost_3d", "cost_3d.json")))
names = {"assembled": "wetbed 3D, assembled + AMG", "p-multigrid": "wetbed 3D, matrix-free + p-multigrid",
         "default": "wetbed 3D, default (matrix-free + p-multigrid)",
         "matrix-free": "wetbed 3D, matrix-free + AMG"}
for r in cost_3d["results"]:
    series.setdefault(names[r["path"]], []).append(
        (r["dofs"], r["per_second"], 1e6 * r["wall"] / r["steps"] / r["dofs"]))

for path in sorted(glob.glob(os.path.join(results, "openfoam_comparison", "*.json"))):
    r = json.load(open(path))
    if r["code"] == "wetbed":
        level = {240: 1, 960: 2, 3840: 3, 60: 0, 15360: 4}[r["cells"]]
        nx, ny = 3 * 2 ** level, 20 * 2 ** level
        unknowns, label = 4 * (2 * nx + 1) * (2 * ny + 1) + (nx + 1) * (ny + 1), "wetbed 2D, assembled + AMG, 2 exact outer its"
    else:
        unknowns, label = 5 * r["cells"], "OpenFOAM twoPhaseEulerFoam 2D"
    series.setdefault(label, []).append((unknowns, r["per_second"], 1e6 * r["wall"] / r["steps"] / unknowns))

styles = {"assembled": ("tab:red", "s"), "p-multigrid": ("tab:blue", "o"), "default": ("tab:blue", "o"),
          "matrix-free + AMG": ("tab:purple", "^"), "2D": ("tab:green", "D"), "OpenFOAM": ("black", "*")}
fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
for label, points in sorted(series.items()):
    points.sort()
    key = next(k for k in ("OpenFOAM", "2D", "matrix-free + AMG", "default", "p-multigrid", "assembled") if k in label)
    color, marker = styles[key]
    for ax, i in ((axes[0], 1), (axes[1], 2)):
        ax.loglog([p[0] for p in points], [p[i] for p in points], marker=marker, color=color, label=label,
                  markersize=9 if marker == "*" else 6)
axes[0].set_ylabel("wall s per simulated s")
axes[1].set_ylabel("µs per flow unknown per step")
for ax in axes:
    ax.set_xlabel("flow unknowns (velocities + pressure)")
    ax.grid(True, which="both", alpha=0.3)
axes[1].legend(fontsize=7, loc="upper left")
fig.suptitle("Cost against unknowns: 3D column on 2 ranks (short spans, cost_3d.py); "
             "2D fluidisedBed serial over 1.5 s (openfoam_comparison.py)", fontsize=9)
fig.tight_layout()
out = os.path.join(root, "doc", "cost_vs_dofs.png")
fig.savefig(out, dpi=110)
for label, points in sorted(series.items()):
    print(label + ": " + "; ".join(f"{u} unknowns: {s:.0f} s/s, {c:.2f} µs/unknown/step" for u, s, c in points))
print("wrote", out)
