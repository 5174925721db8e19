#!/usr/bin/env python3
"""1 against 2 MPI ranks on the 2D bubbling bed (prm/bubbling_bed_2d.prm) and the 3D
column (prm/column_3d.prm) over the same simulated start-up: wall time, speed-up,
parallel efficiency, FGMRES iterations per step (they may differ: the ML hierarchy
depends on the partition), and the time per timer section. Prints and writes the
'parallel' section of doc/benchmarks.md.

usage: python3 benchmarks/parallel_efficiency.py [--end-2d 0.05] [--end-3d 0.01]
(build first: bash scripts/build.sh; on a 2-core machine nothing else should run)
"""
import argparse
import csv
import os
import re
import subprocess

from benchmark_setup import read_case, replace_doc_section, repository_root, write_case

root = repository_root()
parser = argparse.ArgumentParser()
parser.add_argument("--end-2d", type=float, default=0.05)
parser.add_argument("--end-3d", type=float, default=0.01)
args = parser.parse_args()
work = os.path.join(root, "build", "benchmarks", "parallel")
os.makedirs(work, exist_ok=True)
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
sections = ["Krylov solve", "flow assembly", "preconditioner setup", "alpha transport",
            "solids pressure correction", "granular temperature"]


def seconds(text, name):
    m = re.search(r"\| " + re.escape(name) + r"\s*\|\s*\d+\s*\|\s*[\d.e+-]+s\s+\d+\s*\|\s*[\d.e+-]+s\s*\|\s*([\d.e+-]+)s", text)
    return float(m.group(1)) if m else 0.0


rows = []
for case, end in (("bubbling_bed_2d", args.end_2d), ("column_3d", args.end_3d)):
    result = {}
    for ranks in (1, 2):
        prm, folder, log = write_case(work, f"{case}_{ranks}", read_case(case), end,
                                      "\nsubsection checkpoint\n set at end = false\nend\n", field_interval=1000)
        command = [os.path.join(root, "build", "wetbed"), prm, "--overwrite"]
        if ranks > 1:
            command = ["mpirun", "--oversubscribe", "-np", str(ranks)] + command
        with open(log, "w") as out:
            subprocess.run(command, stdout=out, stderr=subprocess.STDOUT, check=True, env=env)
        text = open(log).read()
        monitors = list(csv.DictReader(open(os.path.join(folder, "monitors.csv"))))[1:]
        result[ranks] = {
            "wall": float(re.search(r"Total wallclock time elapsed\s*\|\s*([\d.e+-]+)s", text).group(1)),
            "cells": int(monitors[-1]["active_cells"]), "steps": len(monitors),
            "its": sum(float(r["krylov_iterations"]) for r in monitors) / len(monitors),
            "sections": {s: seconds(text, s) for s in sections},
        }
        print(f"{case} on {ranks} rank(s): {result[ranks]}")
    speedup = result[1]["wall"] / result[2]["wall"]
    rows.append((case, end, result, speedup))

lines = [f"Command: `python3 benchmarks/parallel_efficiency.py --end-2d {args.end_2d:g} --end-3d {args.end_3d:g}`",
         "(the start-up of each case; wall time of the whole run incl. set-up; section times",
         "are the maximum over the ranks).", "",
         "| case | cells | simulated | ranks | steps | FGMRES its/step | wall s | speed-up | efficiency | "
         + " | ".join(f"{s} s" for s in sections) + " |",
         "|---|---|---|---|---|---|---|---|---|" + "---|" * len(sections)]
for case, end, result, speedup in rows:
    for ranks in (1, 2):
        r = result[ranks]
        su = f"{speedup:.2f}" if ranks == 2 else "1"
        eff = f"{100 * speedup / 2:.0f}%" if ranks == 2 else "100%"
        lines.append(f"| {case} | {r['cells']} | {end:g} s | {ranks} | {r['steps']} | {r['its']:.1f} | {r['wall']:.1f} | {su} | {eff} | "
                     + " | ".join(f"{r['sections'][s]:.1f}" for s in sections) + " |")
replace_doc_section(root, "parallel", "1 against 2 MPI ranks", lines)
print("\n".join(lines))
