#!/usr/bin/env python3
"""The momentum forms in the 3D column: prm/column_3d.prm (792 cells, 2 ranks) from rest to
--end-time (0.4 s) with each `momentum equations/form` (conservative, advective,
skew-symmetric), divergence checks on, one after the other. Per form: the outcome (a
stopped run's status and cause), steps (rejected), the start-up peaks (t <= 0.02 s: the
bed's first lift), the peak speeds and Theta, |continuity_defect| over 0.05-0.25 s as a
share of the bed weight (median, max), the FI at 0.2 s and the wall time. Writes the
table into doc/benchmarks.md ("Momentum form in the 3D column").

usage: python3 benchmarks/momentum_form_3d.py [--end-time 0.4]
(build first: bash scripts/build.sh; run it alone on the machine: the wall times are in
the table)
"""
import argparse
import csv
import os
import re
import statistics
import subprocess
import time

from benchmark_setup import read_case, replace_doc_section, repository_root, write_case

root = repository_root()
parser = argparse.ArgumentParser()
parser.add_argument("--end-time", type=float, default=0.4)
parser.add_argument("--work", default=os.path.join(root, "build", "benchmarks", "momentum_form_3d"))
args = parser.parse_args()
os.makedirs(args.work, exist_ok=True)
env = dict(os.environ, OMPI_MCA_rmaps_base_oversubscribe="1")
FORMS = ("conservative", "advective", "skew-symmetric")


def run(form):
    prm, folder, log = write_case(args.work, form, read_case("column_3d"), args.end_time,
                                  f"subsection momentum equations\n set form = {form}\nend\n",
                                  field_interval=1000, progress_interval=100)
    begin = time.time()
    with open(log, "w") as out:
        code = subprocess.run(["mpirun", "-np", "2", os.path.join(root, "build", "wetbed"), prm, "--overwrite"],
                              stdout=out, stderr=subprocess.STDOUT, env=env).returncode
    wall = time.time() - begin
    rows = [{k: (float(v) if k != "run" else v) for k, v in r.items()}
            for r in csv.DictReader(open(os.path.join(folder, "monitors.csv")))]
    text = open(log).read()
    if code == 0:
        outcome = "completed"
    else:
        cause = re.search(r"cause of the last rejection: ([^\n]{0,80})", text)
        outcome = (f"stopped at t = {rows[-1]['time']:.3f} s, status {code}"
                   + (f": {cause.group(1)}" if cause else ""))
    start = [r for r in rows if r["time"] <= 0.02]
    window = [abs(r["continuity_defect"]) for r in rows if 0.05 <= r["time"] <= 0.25]
    near = min(rows, key=lambda r: abs(r["time"] - 0.2))
    return {"form": form, "outcome": outcome, "steps": int(rows[-1]["step"]), "rejected": int(rows[-1]["rejected_steps"]),
            "start_solids": max(r["solids_speed_max"] for r in start), "start_theta": max(r["theta_max"] for r in start),
            "gas": max(r["gas_speed_max"] for r in rows), "solids": max(r["solids_speed_max"] for r in rows),
            "theta": max(r["theta_max"] for r in rows),
            "defect": (statistics.median(window), max(window)) if window else (float("nan"),) * 2,
            "fi": near["fluidization_index"] if abs(near["time"] - 0.2) < 0.01 else float("nan"), "wall": wall}


results = []
for form in FORMS:
    results.append(run(form))
    print(results[-1], flush=True)

lines = [f"Command: `python3 benchmarks/momentum_form_3d.py --end-time {args.end_time:g}` (`prm/column_3d.prm`, 792 "
         "cells, 2 ranks, the current defaults but the form, divergence checks on, one form after the other, "
         "alone on the machine). Start-up: t ≤ 0.02 s (the bed's first lift); |defect|: |`continuity_defect`| over "
         "0.05–0.25 s as a share of the bed weight (median, max).", "",
         "| form | outcome | steps (rejected) | start-up: peak u_s (m/s), Θ max | peak u_g, u_s (m/s) | Θ max (m²/s²) | "
         "\\|defect\\| | FI at 0.2 s | wall s |",
         "|---|---|---|---|---|---|---|---|---|"]
for r in results:
    label = r["form"] + (" (default)" if r["form"] == "skew-symmetric" else "")
    outcome = r["outcome"].replace("|", "\\|")
    lines.append(f"| {label} | {outcome} | {r['steps']} ({r['rejected']}) | {r['start_solids']:.3g}, {r['start_theta']:.2g} | "
                 f"{r['gas']:.3g}, {r['solids']:.3g} | {r['theta']:.2g} | {100 * r['defect'][0]:.2g}%, "
                 f"{100 * r['defect'][1]:.2g}% | {r['fi']:.3f} | {r['wall']:.0f} |")
print("\n".join(lines))
replace_doc_section(root, "momentum_form_3d", "Momentum form in the 3D column", lines)
