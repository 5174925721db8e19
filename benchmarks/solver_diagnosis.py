#!/usr/bin/env python3
"""Where the FGMRES iterations come from: the 2D bubbling bed (prm/bubbling_bed_2d.prm)
at three uniform refinements over its first 0.01 s (serial), every flow solve to the
linear tolerance (`outer tolerance = 0`, so that the counts measure the preconditioner).
The default path (matrix-free operator, velocity p-multigrid); the assembled path with
the velocity AMG smoothed by Chebyshev (2, 4, 6 sweeps) or symmetric block Gauss-Seidel
(the 2 dim velocity components of a node as one block: the drag coupling of u_g and
u_s), and with exact inner solves (sparse direct velocity block, CG on the Schur
approximation): the exact row isolates the Schur approximation, the others the velocity
V-cycle. Prints and
writes the 'solver_diagnosis' section of doc/benchmarks.md: FGMRES iterations per solve,
their growth over two refinements, Krylov and setup time, total wall time.

usage: python3 benchmarks/solver_diagnosis.py [--end-time 0.01] [--levels 0 1 2]
(build first: bash scripts/build.sh)
"""
import argparse
import os
import re

from benchmark_setup import read_case, replace_doc_section, repository_root, solver_run

root = repository_root()
parser = argparse.ArgumentParser()
parser.add_argument("--end-time", type=float, default=0.01)
parser.add_argument("--levels", type=int, nargs="+", default=[0, 1, 2])
args = parser.parse_args()
work = os.path.join(root, "build", "benchmarks", "solver_diagnosis")
os.makedirs(work, exist_ok=True)
base = read_case("bubbling_bed_2d")
assembled = "set operator = assembled\n set velocity preconditioner = AMG\n "
configurations = [
    ("default: matrix-free, velocity p-multigrid", "set operator = automatic"),
    ("default, exact inner solves", "set operator = automatic\n set inner solves = exact"),
    ("assembled, ML: Chebyshev, 2 sweeps", assembled + "set velocity smoother = Chebyshev\n set smoother sweeps = 2"),
    ("assembled, ML: Chebyshev, 4 sweeps", assembled + "set velocity smoother = Chebyshev\n set smoother sweeps = 4"),
    ("assembled, ML: Chebyshev, 6 sweeps", assembled + "set velocity smoother = Chebyshev\n set smoother sweeps = 6"),
    ("assembled, ML: block Gauss-Seidel, 2 sweeps",
     assembled + "set velocity smoother = block Gauss-Seidel\n set smoother sweeps = 2"),
    ("assembled, exact inner solves", assembled + "set inner solves = exact"),
]


results = {}
for label, settings in configurations:
    for level in args.levels:
        name = re.sub(r"[^a-z0-9]+", "_", label.lower()) + f"_L{level}"
        sections = (f"\nsubsection mesh\n set initial refinement = {level}\nend\n"
                    f"subsection linear solver\n {settings}\nend\n"
                    "subsection time stepping\n set outer tolerance = 0\nend\n")
        results[(label, level)] = solver_run(root, work, name, base, args.end_time, sections)
        r = results[(label, level)]
        print(f"{label:30s} level {level}: {r['cells']:6d} cells, {r['its']:6.1f} its/solve, "
              f"Krylov {r['krylov']:7.2f} s, setup {r['setup']:6.2f} s, total {r['total']:7.2f} s")

levels = args.levels
lines = [f"Command: `python3 benchmarks/solver_diagnosis.py --end-time {args.end_time:g}` (first {args.end_time:g} s of the",
         "start-up, serial; every flow solve to the linear tolerance, `outer tolerance = 0`;",
         "iterations per FGMRES solve, including solves repeated after an AMG rebuild).", "",
         "| velocity preconditioner | " + " | ".join(f"its/solve L{l} ({results[(configurations[0][0], l)]['cells']} cells)" for l in levels)
         + f" | growth L{levels[0]}→L{levels[-1]} | " + " | ".join(f"Krylov + setup s L{l}" for l in levels) + " | " + f"total s L{levels[-1]} |",
         "|---|" + "---|" * (2 * len(levels) + 2)]
for label, _ in configurations:
    its = [results[(label, l)]["its"] for l in levels]
    lines.append(f"| {label} | " + " | ".join(f"{i:.1f}" for i in its) + f" | {100 * (its[-1] / its[0] - 1):.0f}% | "
                 + " | ".join(f"{results[(label, l)]['krylov'] + results[(label, l)]['setup']:.2f}" for l in levels)
                 + f" | {results[(label, levels[-1])]['total']:.1f} |")
replace_doc_section(root, "solver_diagnosis", "Where the FGMRES iterations come from (2D bed, start-up)", lines)
print("\n".join(lines))
