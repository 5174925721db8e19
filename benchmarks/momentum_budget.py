#!/usr/bin/env python3
"""Momentum budget of the dry bubbling bed: where the bed weight goes.

Runs prm/bubbling_bed_2d.prm (by default on the coarse level-0 mesh, 4 s, the means over
t > 1 s) with the momentum equations in the skew-symmetric (default), the advective and
the conservative form and with free-slip (the case's) and no-slip gas walls, and writes the time means of every budget column of
monitors.csv into the 'momentum budget' section of doc/benchmarks.md:

  1 = inlet_reaction + wall_reaction + outlet_reaction + wall_support_solids
      + continuity_defect - momentum_outflow + correction_force - d(mixture_momentum)/dt

(source/postprocess/momentum_budget.cc), with the closure error of that identity step by
step (rms) and in the mean, next to the trace-based FI. One command:

  python3 benchmarks/momentum_budget.py [--refinement 0] [--end-time 4] [--jobs 2]
"""
import argparse
import concurrent.futures
import csv
import os

from benchmark_setup import read_case, replace_doc_section, repository_root, run_resumable, write_case

root = repository_root()
parser = argparse.ArgumentParser()
parser.add_argument("--refinement", type=int, default=0, help="mesh/initial refinement")
parser.add_argument("--end-time", type=float, default=4.0)
parser.add_argument("--start-up", type=float, default=1.0, help="seconds left out of the means")
parser.add_argument("--jobs", type=int, default=2)
parser.add_argument("--work", default=os.path.join(root, "build", "benchmarks", "momentum_budget"))
args = parser.parse_args()
os.makedirs(args.work, exist_ok=True)

variants = [("skew-symmetric", "free-slip"), ("skew-symmetric", "no-slip"),
            ("advective", "no-slip"), ("conservative", "no-slip"),
            ("advective", "free-slip"), ("conservative", "free-slip")]


def name(form, gas_wall):
    return f"L{args.refinement}_{form}_{gas_wall}"


def run(variant):
    form, gas_wall = variant
    base = read_case("bubbling_bed_2d")
    sections = (f"\nsubsection mesh\n  set initial refinement = {args.refinement}\nend\n"
                f"subsection momentum equations\n  set form = {form}\nend\n"
                f"subsection boundary conditions\n  set gas wall condition = {gas_wall}\nend\n")
    prm, folder, log = write_case(args.work, name(form, gas_wall), base, args.end_time, sections,
                                  field_interval=args.end_time)
    code, wall = run_resumable([os.path.join(root, "build", "wetbed"), prm], folder, log,
                               os.path.join(args.work, name(form, gas_wall) + ".wall"))
    print(f"{form}, gas {gas_wall}: exit {code}, {wall:.0f} s", flush=True)
    return folder, wall


with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
    results = list(pool.map(run, variants))

columns = ["fluidization_index", "distributor_support", "inlet_reaction", "wall_reaction",
           "outlet_reaction", "wall_support_solids", "continuity_defect", "momentum_outflow",
           "correction_force"]


def budget(folder):
    rows = list(csv.DictReader(open(os.path.join(folder, "monitors.csv"))))
    t = [float(r["time"]) for r in rows]
    value = {c: [float(r[c]) for r in rows] for c in columns + ["mixture_momentum", "time_step"]}
    mismatch = []
    for i in range(1, len(rows)):
        rate = (value["mixture_momentum"][i] - value["mixture_momentum"][i - 1]) / (t[i] - t[i - 1])
        total = (value["inlet_reaction"][i] + value["wall_reaction"][i] + value["outlet_reaction"][i]
                 + value["wall_support_solids"][i] + value["continuity_defect"][i]
                 - value["momentum_outflow"][i] + value["correction_force"][i])
        mismatch.append(total - 1 - rate)
    keep = [i for i in range(1, len(rows)) if t[i] > args.start_up]
    weight = sum(value["time_step"][i] for i in keep)
    mean = {c: sum(value[c][i] * value["time_step"][i] for i in keep) / weight for c in columns}
    closing = [mismatch[i - 1] for i in keep]
    mean["rms"] = (sum(m * m for m in closing) / len(closing)) ** 0.5
    mean["closure"] = sum(mismatch[i - 1] * value["time_step"][i] for i in keep) / weight
    mean["steps"] = len(rows) - 1
    mean["rejected"] = int(rows[-1]["rejected_steps"])
    mean["end"] = t[-1]
    return mean


lines = [f"`python3 benchmarks/momentum_budget.py --refinement {args.refinement} --end-time {args.end_time:g}`: "
         f"prm/bubbling_bed_2d.prm at mesh level {args.refinement}, time means over "
         f"{args.start_up:g} s < t ≤ {args.end_time:g} s as shares of the buoyant bed weight. "
         "FI and distributor: the trace-based monitors; R_in, R_wall, R_out: the consistent "
         "reactions of the boundary velocity rows; closure: the identity of "
         "source/postprocess/momentum_budget.cc, per step (rms) and in the mean.", "",
         "| form | gas walls | FI | distributor | R_in | R_wall | R_out | JJ friction | continuity defect | outflow | correction | closure rms | closure mean | steps (rejected) | wall s |",
         "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
for (form, gas_wall), (folder, wall) in zip(variants, results):
    try:
        m = budget(folder)
    except (OSError, KeyError, ValueError, ZeroDivisionError) as error:
        lines.append(f"| {form} | {gas_wall} | not run ({error}) |" + " |" * 12)
        continue
    lines.append(f"| {form} | {gas_wall} | {m['fluidization_index']:.4f} | {m['distributor_support']:.4f} | "
                 f"{m['inlet_reaction']:.4f} | {m['wall_reaction']:.4f} | {m['outlet_reaction']:.4f} | "
                 f"{m['wall_support_solids']:.4f} | {m['continuity_defect']:.4f} | {m['momentum_outflow']:.5f} | "
                 f"{m['correction_force']:.5f} | {m['rms']:.4f} | {m['closure']:.5f} | "
                 f"{m['steps']} ({m['rejected']}) | {wall:.0f} |")
    print(lines[-1], flush=True)
replace_doc_section(root, f"momentum-budget-L{args.refinement}",
                    f"Momentum budget of the bubbling bed (level {args.refinement})", lines)
