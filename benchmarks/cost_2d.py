#!/usr/bin/env python3
"""Cost per simulated second of the 2D bubbling bed at three mesh sizes (2 MPI ranks):
wall time, the TimerOutput breakdown, FGMRES iterations per linear solve and their growth
under refinement. Regenerates the 'cost' section of doc/benchmarks.md and
doc/cost_2d.png.

usage: python3 benchmarks/cost_2d.py [--end-time 0.05] [--ranks 2] [--levels 0 1 2]
(build first: bash scripts/build.sh)
"""
import argparse
import csv
import json
import os
import re
import subprocess

from benchmark_setup import read_case, repository_root, write_case

root = repository_root()
parser = argparse.ArgumentParser()
parser.add_argument("--end-time", type=float, default=0.05)
parser.add_argument("--ranks", type=int, default=2)
parser.add_argument("--levels", type=int, nargs="+", default=[0, 1, 2])
parser.add_argument("--replot", action="store_true", help="redraw from the cached results.json")
args = parser.parse_args()

work = os.path.join(root, "build", "benchmarks", "cost_2d")
os.makedirs(work, exist_ok=True)
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
base = read_case("bubbling_bed_2d")
cache = os.path.join(work, "results.json")
results = []
for level in ([] if args.replot else args.levels):
    prm, folder, _ = write_case(work, f"level_{level}", base, args.end_time,
                                f"\nsubsection mesh\n  set initial refinement = {level}\nend\n",
                                field_interval=0, progress_interval=100000)
    out = subprocess.run(["mpirun", "--oversubscribe", "-np", str(args.ranks), os.path.join(root, "build", "wetbed"), prm, "--overwrite"],
                         capture_output=True, text=True, env=env).stdout
    cells = int(re.search(r"Mesh: (\d+) cells; flow DoFs (\d+) \(u_g, u_s\) \+ (\d+)", out).group(1))
    dofs = [int(x) for x in re.search(r"flow DoFs (\d+) \(u_g, u_s\) \+ (\d+)", out).groups()]
    fin = re.search(r"Finished: (\d+) steps \((\d+) rejected\), wall ([\d.e+-]+) s, ([\d.e+-]+) s per simulated second, ([\d.e+-]+) us per cell per step", out)
    steps, rejected, wall, per_second, per_cell = int(fin.group(1)), int(fin.group(2)), float(fin.group(3)), float(fin.group(4)), float(fin.group(5))
    sections = {}
    for m in re.finditer(r"^\| ([a-zA-Z ]+?)\s+\|\s+(\d+) \|\s+[\d.e+-]+s\s+\d+ \|\s+([\d.e+-]+)s \|", out, re.M):
        sections[m.group(1).strip()] = (int(m.group(2)), float(m.group(3)))
    rows = list(csv.DictReader(open(os.path.join(folder, "monitors.csv"))))[1:]
    solves = sections.get("Krylov solve", (1, 0))[0]
    krylov = [int(r["krylov_iterations"]) for r in rows]
    per_solve = sum(krylov) / max(solves, 1)
    results.append(dict(level=level, cells=cells, dofs=dofs, steps=steps, rejected=rejected, wall=wall,
                        per_second=per_second, per_cell=per_cell, sections=sections, per_solve=per_solve,
                        max_step=max(krylov)))
    print(f"level {level}: {cells} cells, {dofs[0]}+{dofs[1]} flow DoFs, {steps} steps ({rejected} rejected), "
          f"wall {wall:.1f} s, {per_second:.0f} s per simulated s, {per_cell:.0f} us/cell/step, "
          f"FGMRES {per_solve:.1f} iterations per solve")

if args.replot:
    saved = json.load(open(cache))
    results, args.end_time, args.ranks = saved["results"], saved["end_time"], saved["ranks"]
else:
    json.dump({"results": results, "end_time": args.end_time, "ranks": args.ranks}, open(cache, "w"))

names = ["flow assembly", "preconditioner setup", "Krylov solve", "alpha transport", "solids pressure correction", "monitors", "output"]
lines = [f"Command: `python3 benchmarks/cost_2d.py --end-time {args.end_time} --ranks {args.ranks}` "
         f"(`prm/bubbling_bed_2d.prm` at three uniform refinements, first {args.end_time} s simulated, "
         f"{args.ranks} MPI ranks on this 2-core machine).", "",
         "| cells | flow DoFs (u + p) | steps (rejected) | wall s | s per simulated s | µs per cell per step | FGMRES its per solve | " +
         " | ".join(n + " s" for n in names) + " |",
         "|" + "---|" * (7 + len(names))]
for r in results:
    lines.append(f"| {r['cells']} | {r['dofs'][0]} + {r['dofs'][1]} | {r['steps']} ({r['rejected']}) | {r['wall']:.1f} | {r['per_second']:.0f} | "
                 f"{r['per_cell']:.0f} | {r['per_solve']:.1f} | " + " | ".join(f"{r['sections'].get(n, (0, 0))[1]:.1f}" for n in names) + " |")
if len(results) >= 3:
    growth = results[-1]["per_solve"] / results[-3]["per_solve"] - 1
    lines += ["", f"FGMRES iterations per solve grow by {100 * growth:.0f}% over two refinements (target ≤ 30%)."]
lines += ["", "![time per section](cost_2d.png)"]

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 4))
    cells = [r["cells"] for r in results]
    ax.plot(cells, [r["per_second"] for r in results], "k-o", label="total")
    for n in names:
        values = [r["sections"].get(n, (0, 0))[1] / max(r["wall"], 1e-9) * r["per_second"] for r in results]
        if max(values) > 0:
            ax.plot(cells, [max(v, 1e-3) for v in values], "-o", label=n)
    ax.set_xscale("log")
    ax.set_xlabel("cells")
    ax.set_ylabel("wall s per simulated s")
    ax.set_yscale("log")
    ax.legend(fontsize=7)
    ax.set_title("2D bubbling bed: cost by section")
    fig.tight_layout()
    fig.savefig(os.path.join(root, "doc", "cost_2d.png"), dpi=110)
except ImportError:
    lines.append("(matplotlib missing: no plot)")

doc = os.path.join(root, "doc", "benchmarks.md")
text = open(doc).read() if os.path.isfile(doc) else "# Benchmarks\n"
begin, end = "<!-- cost_2d:begin -->", "<!-- cost_2d:end -->"
section = begin + "\n" + "\n".join(lines) + "\n" + end
text = re.sub(re.escape(begin) + ".*?" + re.escape(end), section, text, flags=re.S) if begin in text else text + "\n## Cost per simulated second (2D)\n\n" + section + "\n"
open(doc, "w").write(text)
print("updated doc/benchmarks.md")
