#!/usr/bin/env python3
"""What a cell costs, for the partition's cost model (`mesh/wall face weight`): serial
runs at the current defaults with a fixed time step, so that every run of a case takes
the same steps. Per run: the `flow assembly` time per cell and assembly, the `Krylov
solve` time per cell and FGMRES iteration (the matrix-free operator applies the wall
faces' Nitsche and friction integrals in every iteration), and the whole run per cell
and step.
- the 2D bubbling bed (prm/bubbling_bed_2d.prm) at refinements 0, 1, 2: the cost per
  cell as the share of wall faces halves with each refinement;
- the 3D column (prm/column_3d.prm) with Johnson-Jackson solids walls against no-slip
  solids walls (strong, no face integrals): the extra cost of a Johnson-Jackson wall face
  relative to a cell's, per section and for the whole step.
The runs go in turn (A B C ... A B C ...) --repeats times and each figure is the median
over the repeats, so that the machine's drifting load falls on all runs alike. Writes
the 'cell_cost' section of doc/benchmarks.md.

usage: python3 benchmarks/cell_cost.py [--steps-2d 20] [--steps-3d 24] [--repeats 3] [--no-doc]
(build first: bash scripts/build.sh)
"""
import argparse
import os
import re
import statistics

from benchmark_setup import read_case, replace_doc_section, repository_root, solver_run, timer_seconds

root = repository_root()
parser = argparse.ArgumentParser()
parser.add_argument("--steps-2d", type=int, default=20)
parser.add_argument("--steps-3d", type=int, default=24)
parser.add_argument("--repeats", type=int, default=3)
parser.add_argument("--no-doc", action="store_true", help="print the table only")
args = parser.parse_args()
work = os.path.join(root, "build", "benchmarks", "cell_cost")
os.makedirs(work, exist_ok=True)


def run(name, case, steps, dt, sections):
    """Runs CASE with STEPS fixed steps of DT (benchmark_setup.solver_run); returns its
    cost figures, read from the run's log."""
    fixed = (f"subsection time stepping\n set adaptive = false\n set initial time step = {dt}\n"
             f" set maximum time step = {dt}\nend\n"
             "subsection spectrum\n set enabled = false\nend\n")
    figures = solver_run(root, work, name, read_case(case), steps * dt * (1 + 1e-9), sections + fixed)
    text = open(os.path.join(work, name + ".log")).read()
    cells, done, iterations = figures["cells"], figures["steps"], figures["iterations"]
    walls = int(re.search(r"wall faces per rank (\d+)", text).group(1))
    assemblies = int(re.search(r"\| flow assembly\s*\|\s*(\d+)", text).group(1))
    setup = sum(timer_seconds(text, n) for n in ("setup", "output", "matrix-free setup") if timer_seconds(text, n) == timer_seconds(text, n))
    r = dict(name=name, cells=cells, walls=walls, steps=done, assemblies=assemblies, iterations=iterations,
             assembly=timer_seconds(text, "flow assembly") / assemblies / cells * 1e6,
             krylov=figures["krylov"] / max(iterations, 1) / cells * 1e6,
             step=(figures["total"] - setup) / done / cells * 1e6)
    print(f"{name}: {cells} cells, {walls} wall faces, {done} steps, {iterations / done:.1f} FGMRES per step, "
          f"assembly {r['assembly']:.1f} us per cell, Krylov {r['krylov']:.2f} us per cell and iteration, "
          f"step {r['step']:.0f} us per cell", flush=True)
    return r


plan = [(f"bubbling_bed_2d_level_{level}", "bubbling_bed_2d", args.steps_2d, 2.5e-4 / 2 ** level,
         f"subsection mesh\n set initial refinement = {level}\nend\n") for level in (0, 1, 2)]
plan += [(f"column_3d_{label}", "column_3d", args.steps_3d, 2e-4,
          f"subsection boundary conditions\n set solids wall condition = {condition}\nend\n")
         for label, condition in (("johnson_jackson", "Johnson-Jackson"), ("no_slip", "no-slip"))]
repeats = [[run(*entry) for entry in plan] for _ in range(args.repeats)]
results = []
for i in range(len(plan)):
    runs = [repeat[i] for repeat in repeats]
    r = dict(runs[0])
    for key in ("assembly", "krylov", "step"):
        r[key] = statistics.median(x[key] for x in runs)
    results.append(r)
bed, column = results[:3], results[3:]

lines = [f"Command: `python3 benchmarks/cell_cost.py --steps-2d {args.steps_2d} --steps-3d {args.steps_3d} "
         f"--repeats {args.repeats}` (medians over the repeats, the runs in turn; "
         "serial, the current defaults with a fixed time step: 2D 0.25 ms halved per refinement, 3D 0.2 ms; "
         "µs per cell: flow assembly per assembly, Krylov per FGMRES iteration, the whole step without the "
         "set-up and output).", "",
         "| run | cells | wall faces | steps | FGMRES per step | flow assembly µs per cell | "
         "Krylov µs per cell and iteration | step µs per cell |",
         "|---|---|---|---|---|---|---|---|"]
for r in bed + column:
    lines.append(f"| {r['name']} | {r['cells']} | {r['walls']} | {r['steps']} | {r['iterations'] / r['steps']:.1f} | "
                 f"{r['assembly']:.1f} | {r['krylov']:.2f} | {r['step']:.0f} |")
jj, ns = column
extra = jj["walls"] - ns["walls"] if jj["walls"] != ns["walls"] else jj["walls"]
lines.append("")
for key, label in (("assembly", "flow assembly"), ("krylov", "Krylov iteration"), ("step", "whole step")):
    face = (jj[key] - ns[key]) * jj["cells"] / extra
    lines.append(f"- {label}: a Johnson–Jackson wall face adds {face:.1f} µs, {face / ns[key]:.2f} of a cell's "
                 f"{ns[key]:.1f} µs with no-slip solids walls.")
for line in lines:
    print(line)
if not args.no_doc:
    replace_doc_section(root, "cell_cost", "What a cell costs", lines)
