#!/usr/bin/env python3
"""Solver scaling of the coupled (u_g, u_s, p') solve with the default solver settings,
each flow solve to the linear solver's relative tolerance (`outer tolerance = 0`):
FGMRES iterations per solve, preconditioner setup time per build and Krylov time per
iteration against the mesh size h (three uniform refinements), the time step (fixed
dt, level 1) and the drag magnitude (particle diameter d: the Stokes drag goes as
1/d^2; level 1). The 2D bubbling bed (prm/bubbling_bed_2d.prm) over the first END_TIME
seconds of its start-up, serial. The h ladder is run twice: with the time steps of the
default start-up (the same dt on every mesh, so the Courant number grows 4x over two
refinements) and at a fixed Courant number (dt = 4e-4, 2e-4, 1e-4 s on levels 0, 1,
2, as CFL control gives in a developed flow); the second also for the wet column
(prm/wet_column_2d.prm, liquid-bridge viscosity). Prints the growth of the iterations
over two refinements (target: at most 30%) and writes the 'solver_scaling' section of
doc/benchmarks.md and doc/solver_scaling.png.

With `--path p-multigrid` the same runs use the matrix-free operator and the velocity
p-multigrid (`linear solver/operator = matrix-free`, `velocity preconditioner =
p-multigrid`) and write the 'solver_scaling_p_multigrid' section (and
doc/solver_scaling_p_multigrid.png); `--ladders` picks ladders by name.

With `--case column_3d` the h ladder at a fixed Courant number runs on the 3D column
(prm/column_3d.prm, refinements 0 and 1: 792 and 6,336 cells, dt = 2e-4 and 1e-4 s) on 2
MPI ranks, and writes the 'solver_scaling_3d' section (plus the path's suffix).

usage: python3 benchmarks/solver_scaling.py [--end-time 0.01] [--path assembled|p-multigrid]
       [--ladders h "h, fixed Courant number" ...] [--case bubbling_bed_2d|column_3d]
(build first: bash scripts/build.sh)
"""
import argparse
import os

from benchmark_setup import read_case, replace_doc_section, repository_root, solver_run

root = repository_root()
parser = argparse.ArgumentParser()
parser.add_argument("--end-time", type=float, default=0.01)
parser.add_argument("--path", choices=["assembled", "p-multigrid"], default="assembled")
parser.add_argument("--ladders", nargs="+", default=None)
parser.add_argument("--case", choices=["bubbling_bed_2d", "column_3d"], default="bubbling_bed_2d")
args = parser.parse_args()
column = args.case == "column_3d"
suffix = ("_3d" if column else "") + ("" if args.path == "assembled" else "_p_multigrid")
path_sections = ("subsection linear solver\n set operator = assembled\n set velocity preconditioner = AMG\nend\n"
                 if args.path == "assembled" else
                 "subsection linear solver\n set operator = matrix-free\n"
                 " set velocity preconditioner = p-multigrid\nend\n")
# every flow solve to the linear solver's relative tolerance (two outer iterations a
# step): the counts then measure the preconditioner, not the inexact outer iterations'
# forcing, which stops a solve after 1-2 iterations
path_sections += "subsection time stepping\n set outer tolerance = 0\nend\n"
work = os.path.join(root, "build", "benchmarks", "solver_scaling" + suffix)
os.makedirs(work, exist_ok=True)
base = read_case(args.case) + ("\nsubsection spectrum\n set enabled = false\nend\n" if column else "")
wet = read_case("wet_column_2d")
ranks = 2 if column else 1


def mesh(level):
    return f"\nsubsection mesh\n set initial refinement = {level}\nend\n"


def fixed_step(dt):
    return (f"subsection time stepping\n set adaptive = false\n set initial time step = {dt:g}\n"
            f" set maximum time step = {dt:g}\nend\n")


def courant_ladder(prefix, dt0=4e-4, levels=(0, 1, 2)):
    """dt halved per refinement: the same Courant number on every mesh"""
    return [(f"level {level}, Δt = {dt0 / 2**level:g} s", f"{prefix}_{level}", mesh(level) + fixed_step(dt0 / 2**level))
            for level in levels]


ladders = {
    "h": [(f"level {level}", f"h_{level}", mesh(level)) for level in (0, 1, 2)],
    "h, fixed Courant number": courant_ladder("courant"),
    "h, wet, same Δt": [(f"level {level}", f"wet_h_{level}", mesh(level)) for level in (0, 1, 2)],
    "h, wet, fixed Courant number": courant_ladder("wet_courant"),
    "Δt": [(f"Δt = {dt:g} s", f"dt_{dt:g}", mesh(1) + fixed_step(dt)) for dt in (1e-4, 2.5e-4, 5e-4, 1e-3)],
    "drag": [(f"d = {d * 1e6:g} µm", f"d_{d * 1e6:g}", mesh(1) + f"subsection physical properties\n"
              f" set particle diameter = {d:g}\nend\n") for d in (700e-6, 350e-6, 175e-6)],
}
if column:
    ladders = {"h, 3D column, fixed Courant number": courant_ladder("column_courant", 2e-4, (0, 1))}
if args.ladders:
    unknown = [name for name in args.ladders if name not in ladders]
    if unknown:
        raise SystemExit(f"solver_scaling.py: unknown ladder(s) {unknown}; known: {list(ladders)}")
    ladders = {name: runs for name, runs in ladders.items() if name in args.ladders}
command = f"python3 benchmarks/solver_scaling.py --end-time {args.end_time:g}"
if args.path != "assembled":
    command += f" --path {args.path}"
if column:
    command += " --case column_3d"
if args.ladders:
    command += " --ladders " + " ".join(f'"{name}"' for name in args.ladders)
settings = ("assembled operator with the ML velocity AMG, otherwise default solver settings"
            if args.path == "assembled" else
            "matrix-free operator with the velocity p-multigrid, otherwise default solver settings")
settings += ", each flow solve to the linear solver's relative tolerance (`outer tolerance = 0`)"
if column:
    settings = ("assembled operator with the ML velocity preconditioner" if args.path == "assembled" else
                "default solver settings (in 3D the matrix-free operator with the velocity p-multigrid)") + \
        ", each flow solve to the linear solver's relative tolerance (`outer tolerance = 0`)"
    description = (f"prm/column_3d.prm, first {args.end_time:g} s of the start-up, 2 MPI ranks, {settings}; "
                   "'fixed Courant number': Δt halved with h")
else:
    description = (f"prm/bubbling_bed_2d.prm, first {args.end_time:g} s of the start-up, serial, {settings}; the Δt "
                   "and drag ladders at level 1 (600 cells), the drag varied through the particle diameter, Stokes drag "
                   "∝ 1/d²; the wet ladders on prm/wet_column_2d.prm; 'same Δt': the adaptive start-up steps, identical "
                   "on every mesh; 'fixed Courant number': Δt halved with h")
lines = [f"Command: `{command}` ({description}).", "",
         "| ladder | run | cells | steps | FGMRES its/solve | setups | setup s per build | Krylov ms per iteration | total s |",
         "|---|---|---|---|---|---|---|---|---|"]
growth = {}
curves = {}  # h ladders: (cells, its/solve) per run
for ladder, runs in ladders.items():
    its = []
    curves[ladder] = []
    for label, name, sections in runs:
        r = solver_run(root, work, name, wet if "wet" in ladder else base, args.end_time, sections + path_sections,
                       ranks)
        its.append(r["its"])
        curves[ladder].append((r["cells"], r["its"]))
        row = (f"| {ladder} | {label} | {r['cells']} | {r['steps']} | {r['its']:.1f} | {r['setups']} | "
               f"{r['setup'] / max(r['setups'], 1):.3f} | {1e3 * r['krylov'] / max(r['iterations'], 1):.2f} | {r['total']:.1f} |")
        lines.append(row)
        print(row, flush=True)
    growth[ladder] = (its[0], its[-1], 100 * (its[-1] / its[0] - 1))


def over(ladder):
    first, last, percent = growth[ladder]
    return f"{first:.1f} → {last:.1f}, {percent:+.0f}%"


summary = [f"{ladder} {over(ladder)}" for ladder in ladders if ladder.startswith("h")]
others = [f"the {ladder} ladder {growth[ladder][2]:+.0f}%" for ladder in ladders if not ladder.startswith("h")]
lines += ["", "Growth of FGMRES iterations per solve over " + ("one refinement (level 0 → 1" if column else
          "two refinements (level 0 → 2") + ", target ≤ 30% over two"
          + ("" if column else "; 'fixed Courant number': Δt ∝ h, 'same Δt': Courant number × 4") + "): "
          + "; ".join(summary)
          + ("; " + ", ".join(others) if others else "") + "."]
print(lines[-1])
lines += ["", f"![iterations against cells](solver_scaling{suffix}.png)"]

import matplotlib  # noqa: E402
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
fig, ax = plt.subplots(figsize=(6.5, 4.2))
for i, ladder in enumerate(name for name in ladders if name.startswith("h")):
    cells, per_solve = zip(*curves[ladder])
    ax.plot(cells, per_solve, "o-" if "Courant" in ladder else "s--", color=f"C{i}",
            label=("3D column" if column else "dry bed" if "wet" not in ladder else "wet column")
            + (", Δt ∝ h" if "Courant" in ladder else ", same Δt"))
ax.set_xscale("log")
ax.set_xlabel("cells")
ax.set_ylabel("FGMRES iterations per solve")
ax.set_ylim(bottom=0)
ax.legend(fontsize=8)
ax.set_title("Coupled solve: iterations against refinement")
fig.tight_layout()
fig.savefig(os.path.join(root, "doc", f"solver_scaling{suffix}.png"), dpi=110)
replace_doc_section(root, "solver_scaling" + suffix,
                    ("Solver scaling: iterations against h (3D column, start-up)" if column else
                     "Solver scaling: iterations against h, Δt and drag (2D bed, start-up)")
                    + ("" if args.path == "assembled" else ", matrix-free operator with the velocity p-multigrid"), lines)
