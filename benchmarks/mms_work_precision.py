#!/usr/bin/env python3
"""MMS work-precision: the error of each field against the wall time, for BDF1 and BDF2
on a ladder of meshes and of time steps, 2D (unit square) and 3D (gmsh cylinder).

The exact fields are those of the two-fluid MMS test (trigonometric velocities and
pressure, linear alpha_s, Wen-Yu drag, frictional pressure) times s(t) = 1 + sin(2 pi t)/2,
run from t = 0 to 0.3 (tests/mms_convergence.cc, kind space-time-bdfN): every (mesh level,
step count) pair is one run, so both the spatial and the temporal error are in each
error. Velocity degree 2 / pressure degree 1 (Q2/Q1, the only pair wetbed offers; no
equal-order or iso-Q1 velocity). Also run: the time discretisation alone (kind
transient-bdfN, quadratic velocities and a linear pressure that the Q2/Q1 spaces hold
exactly) and the space discretisation alone (steady, kind two-fluid).

Prints and writes the 'mms_work_precision' section of doc/benchmarks.md: the runs, the
observed rates, the cheapest run reaching each target error, and
doc/mms_work_precision.png (error against wall time). Each run's result is cached in
build/benchmarks/mms_work_precision/results.json (--fresh reruns all).

usage: python3 benchmarks/mms_work_precision.py [--dims 2 3] [--finest-2d 3] [--fresh]
(build first: bash scripts/build.sh; it builds tests/test_mms_convergence with ctest's
targets: cmake --build build --target test_mms_convergence)
"""
import argparse
import json
import math
import os
import re
import subprocess

from benchmark_setup import replace_doc_section, repository_root

root = repository_root()
parser = argparse.ArgumentParser()
parser.add_argument("--dims", type=int, nargs="+", default=[2, 3])
parser.add_argument("--fresh", action="store_true", help="ignore the cached results")
parser.add_argument("--finest-2d", type=int, default=3,
                    help="finest 2D level of the space-time and steady ladders (3: 1,024 cells; 4 for the steady ladder)")
args = parser.parse_args()
work = os.path.join(root, "build", "benchmarks", "mms_work_precision")
os.makedirs(work, exist_ok=True)
binary = os.path.join(root, "build", "tests", "test_mms_convergence")
if not os.path.exists(binary):
    raise SystemExit(f"{binary} is missing: cmake --build build --target test_mms_convergence")
cache_file = os.path.join(work, "results.json")
cache = {} if args.fresh or not os.path.exists(cache_file) else json.load(open(cache_file))
FIELDS = ["u_g L2", "grad u_g L2", "u_s L2", "grad u_s L2", "p' L2"]

# (dim, kind, level, steps) of every run
ladders = {
    2: {"space-time": (list(range(1, args.finest_2d + 1)), [3, 6, 12, 24, 48]), "transient": ([1], [12, 24, 48, 96]),
        "steady": list(range(1, args.finest_2d + 2))},
    # 3D is costly on 2 cores (192 cells: ~10 s per step): a short ladder
    3: {"space-time": ([0, 1], [3, 6]), "transient": None, "steady": [0, 1]},
}


def run(dim, kind, level, steps):
    key = f"{dim} {kind} {level} {steps}"
    if key not in cache:
        out = subprocess.run([binary, str(dim), kind, root, work, "-", str(level), str(steps)],
                             capture_output=True, text=True).stdout
        m = re.search(r"run: level (\d+) cells (\d+) steps (\d+) bdf (\d) wall ([\d.e+-]+) errors (.*)", out)
        if not m:
            raise SystemExit(f"{key}: no result\n{out[-2000:]}")
        cache[key] = {"cells": int(m.group(2)), "wall": float(m.group(5)),
                      "errors": [float(v) for v in m.group(6).split()]}
        json.dump(cache, open(cache_file, "w"), indent=1)
        print(f"{key}: {cache[key]['cells']} cells, {cache[key]['wall']:.1f} s, "
              f"u_g {cache[key]['errors'][0]:.3e}, p' {cache[key]['errors'][4]:.3e}", flush=True)
    return dict(cache[key], dim=dim, kind=kind, level=level, steps=steps)


def rate(a, b, size_a, size_b):
    return math.log(a / b) / math.log(size_a / size_b)


results = {}
for dim in args.dims:
    ladder = ladders[dim]
    space_time = [run(dim, f"space-time-bdf{order}", level, steps)
                  for order in (1, 2) for level in ladder["space-time"][0] for steps in ladder["space-time"][1]]
    time_only = ([run(dim, f"transient-bdf{order}", ladder["transient"][0][0], steps)
                  for order in (1, 2) for steps in ladder["transient"][1]] if ladder["transient"] else [])
    space_only = [run(dim, "two-fluid", level, 1) for level in ladder["steady"]]
    results[dim] = (space_time, time_only, space_only)

lines = ["Command: `python3 benchmarks/mms_work_precision.py --dims " + " ".join(map(str, args.dims))
         + (f" --finest-2d {args.finest_2d}" if args.finest_2d != 3 else "") + "` "
         "(serial; tests/mms_convergence.cc runs; wall time of the solver, mesh set-up included). "
         "Q2/Q1 (u_g, u_s / p′) is the only velocity-pressure pair wetbed offers.", ""]
for dim, (space_time, time_only, space_only) in results.items():
    lines += [f"### {dim}D" + (" (unit square)" if dim == 2 else " (gmsh cylinder, curved wall, MappingQ2)"), ""]
    # space alone
    lines += ["Space alone (steady two-fluid fields): errors and rates h → h/2.", "",
              "| cells | wall s | " + " | ".join(FIELDS) + " |", "|---|---|" + "---|" * len(FIELDS)]
    for i, r in enumerate(space_only):
        cells = [f"{e:.2e}" + (f" ({rate(space_only[i - 1]['errors'][k], e, space_only[i - 1]['cells'] ** (-1 / dim), r['cells'] ** (-1 / dim)):.2f})" if i else "")
                 for k, e in enumerate(r["errors"])]
        lines.append(f"| {r['cells']} | {r['wall']:.1f} | " + " | ".join(cells) + " |")
    lines.append("")
    if time_only:
        lines += [f"Time alone (quadratic velocities, linear pressure: no spatial error on {time_only[0]['cells']} cells; "
                  "frictional pressure off): errors and rates Δt → Δt/2 to t = 0.3.", "",
                  "| BDF | steps | wall s | " + " | ".join(FIELDS) + " |", "|---|---|---|" + "---|" * len(FIELDS)]
        for i, r in enumerate(time_only):
            previous = time_only[i - 1] if i and time_only[i - 1]["kind"] == r["kind"] else None
            cells = [f"{e:.2e}" + (f" ({rate(previous['errors'][k], e, 1 / previous['steps'], 1 / r['steps']):.2f})" if previous else "")
                     for k, e in enumerate(r["errors"])]
            lines.append(f"| {r['kind'][-1]} | {r['steps']} | {r['wall']:.1f} | " + " | ".join(cells) + " |")
        lines.append("")
    # space and time together
    lines += ["Space and time together (trigonometric fields × s(t), t = 0.3): every run.", "",
              "| BDF | cells | steps | wall s | " + " | ".join(FIELDS) + " |", "|---|---|---|---|" + "---|" * len(FIELDS)]
    for r in space_time:
        lines.append(f"| {r['kind'][-1]} | {r['cells']} | {r['steps']} | {r['wall']:.1f} | "
                     + " | ".join(f"{e:.2e}" for e in r["errors"]) + " |")
    lines.append("")
    lines += ["Cheapest run reaching a target error (space and time together):", "",
              "| field | target | BDF1: cells, steps, wall s | BDF2: cells, steps, wall s |", "|---|---|---|---|"]
    for k in (0, 4):
        best = min(r["errors"][k] for r in space_time)
        targets = sorted({10 ** math.ceil(math.log10(best) + 0.5 * j) for j in range(4)})
        for target in targets:
            row = [FIELDS[k], f"{target:.0e}"]
            for order in ("1", "2"):
                ok = [r for r in space_time if r["kind"][-1] == order and r["errors"][k] <= target]
                cheapest = min(ok, key=lambda r: r["wall"]) if ok else None
                row.append(f"{cheapest['cells']}, {cheapest['steps']}, {cheapest['wall']:.1f}" if cheapest else "not reached")
            lines.append("| " + " | ".join(row) + " |")
    lines.append("")
print("\n".join(lines))

import matplotlib  # noqa: E402
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

fig, axes = plt.subplots(len(results), 2, figsize=(10, 3.8 * len(results)), squeeze=False)
for row, (dim, (space_time, _, _)) in enumerate(results.items()):
    for column, k in enumerate((0, 4)):
        ax = axes[row][column]
        for order, style in (("1", "--"), ("2", "-")):
            for level in sorted({r["level"] for r in space_time}):
                runs = [r for r in space_time if r["kind"][-1] == order and r["level"] == level]
                ax.loglog([r["wall"] for r in runs], [r["errors"][k] for r in runs], style, marker="o", ms=3,
                          label=f"BDF{order}, {runs[0]['cells']} cells")
        ax.set_xlabel("wall time (s)")
        ax.set_ylabel(f"{FIELDS[k]} error at t = 0.3")
        ax.set_title(f"{dim}D, {FIELDS[k]} (points: 3, 6, 12, ... steps)", fontsize=9)
        ax.legend(fontsize=7)
fig.tight_layout()
fig.savefig(os.path.join(root, "doc", "mms_work_precision.png"), dpi=110)
print("wrote doc/mms_work_precision.png")
replace_doc_section(root, "mms_work_precision", "MMS work-precision (BDF1 and BDF2, Q2/Q1)",
                    lines + ["![error against wall time](mms_work_precision.png)"])
