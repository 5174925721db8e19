#!/usr/bin/env python3
"""The start-up transient of the 3D column with adaptive refinement, localised: the
shipped column (prm/column_3d.prm) with AMR levels 0-1, as in the stress benchmark's AMR
row, run to --end-time on 2 ranks in variants that each take one suspect out: the
adaptations after the first step (field transfer, coarsening), the hanging nodes (a
uniform level-1 mesh), the Johnson-Jackson wall's energy generation (specularity 0), the
granular-energy production of the dilute nodes, and the length of the step (a fixed
0.1 ms step; the alpha_s time-error control). Prints and writes the 'amr_startup' table of
doc/benchmarks.md: peak speeds, Theta max, smallest step and FGMRES iterations per run.

usage: python3 benchmarks/amr_startup.py [--end-time 0.009] [--only NAME ...] [--no-doc]
       (build first: bash scripts/build.sh)
"""
import argparse
import csv
import os
import subprocess
import time

from benchmark_setup import read_case, replace_doc_section, repository_root, write_case

root = repository_root()
parser = argparse.ArgumentParser()
parser.add_argument("--end-time", type=float, default=0.009)
parser.add_argument("--only", nargs="*")
parser.add_argument("--no-doc", action="store_true")
args = parser.parse_args()

AMR = ("subsection adaptive refinement\n set enabled = true\n set minimum level = 0\n"
       " set maximum level = 1\nend\n")
VARIANTS = [
    ("amr", "AMR levels 0-1, Courant control (the stress row)", AMR),
    ("amr_fixed_mesh", "AMR: the initial adaptations only (the mesh fixed from the first step)",
     AMR + "subsection adaptive refinement\n set interval = 1000000\nend\n"),
    ("amr_no_coarsening", "AMR without coarsening (coarsen threshold 0)",
     AMR + "subsection adaptive refinement\n set coarsen threshold = 0\nend\n"),
    ("uniform_level_1", "uniform level 1 (6,336 cells), no AMR",
     "subsection mesh\n set initial refinement = 1\nend\n"),
    ("amr_specularity_0", "AMR, specularity coefficient 0 (no Johnson-Jackson wall heating)",
     AMR + "subsection kinetic theory\n set specularity coefficient = 0\nend\n"),
    ("amr_dilute_0_05", "AMR, dilute solids fraction 0.05 (no production below alpha_s = 0.05)",
     AMR + "subsection kinetic theory\n set dilute solids fraction = 0.05\nend\n"),
    ("amr_fixed_step", "AMR, fixed step 0.1 ms",
     AMR + "subsection time stepping\n set adaptive = false\n set initial time step = 1e-4\nend\n"),
    ("amr_time_error", "AMR, time error tolerance 1e-4",
     AMR + "subsection time stepping\n set time error tolerance = 1e-4\nend\n"),
]

work = os.path.join(root, "build", "benchmarks", "amr_startup")
os.makedirs(work, exist_ok=True)
env = dict(os.environ, OMPI_MCA_rmaps_base_oversubscribe="1")
binary = os.path.join(root, "build", "wetbed")
base = read_case("column_3d")
rows = []
for name, label, sections in VARIANTS:
    if args.only and name not in args.only:
        continue
    prm, folder, log = write_case(work, name, base, args.end_time, sections, field_interval=0,
                                  progress_interval=1)
    begin = time.time()
    with open(log, "w") as out:
        code = subprocess.call(["mpirun", "-np", "2", binary, prm, "--overwrite"], stdout=out,
                               stderr=subprocess.STDOUT, env=env)
    wall = time.time() - begin
    monitors = list(csv.DictReader(open(os.path.join(folder, "monitors.csv"))))[1:]
    peak = lambda key: max(float(r[key]) for r in monitors)  # noqa: E731
    # the last step may be cut short to land on the end time
    steps = [float(r["time_step"]) for r in monitors[:-1]] or [float(monitors[-1]["time_step"])]
    cells = [int(float(r["active_cells"])) for r in monitors]
    rows.append((label, code, len(monitors), f"{min(cells)}-{max(cells)}", peak("solids_speed_max"),
                 peak("gas_speed_max"), peak("theta_max"), min(steps),
                 int(peak("krylov_iterations")), wall))
    print(rows[-1], flush=True)

lines = [f"Command: `python3 benchmarks/amr_startup.py --end-time {args.end_time:g}` "
         "(prm/column_3d.prm, 2 ranks, from rest to the end time; each variant takes one "
         "suspect out).", "",
         "| variant | exit | steps | cells | peak solids speed (m/s) | peak gas speed (m/s) "
         "| Θ max (m²/s²) | smallest Δt (s) | most FGMRES iterations | wall s |",
         "|---|---|---|---|---|---|---|---|---|---|"]
for label, code, steps, cells, us, ug, theta, dt, krylov, wall in rows:
    lines.append(f"| {label} | {code} | {steps} | {cells} | {us:.3g} | {ug:.3g} | {theta:.3g} "
                 f"| {dt:.2e} | {krylov} | {wall:.0f} |")
print("\n".join(lines))
if not args.no_doc and not args.only:
    replace_doc_section(root, "amr_startup", "Start-up of the 3D column with adaptive refinement",
                        lines)
