#!/usr/bin/env python3
"""AMR against uniform meshes on the 2D bubbling bed (prm/bubbling_bed_2d.prm): uniform
refinement levels L, L+1, L+2 and bubble-following AMR with maximum level L+2 (minimum
level L). For each: mean cell count and flow DoFs, wall time per simulated second,
time-averaged FI and bed height after the start-up, and their errors against the finest
uniform run. Regenerates the 'amr_vs_uniform' section of doc/benchmarks.md and
doc/amr_vs_uniform.png.

With --case another prm/CASE.prm (its own work folder, doc section and plot); --runs runs
only some of the four (the others are tabulated from their folders if present);
--branch-from RUN starts them from RUN's checkpoint (the same developed bed for all, a
short comparison window after it).

usage: python3 benchmarks/amr_vs_uniform.py [--case bubbling_bed_2d] [--end-time 5]
       [--start-up 1] [--level 0] [--runs uniform_<L> amr ...] [--jobs 2] [--summarize-only]
       [--until T] [--no-doc] [--work-folder DIR] [--branch-from RUN] [--batch 0.5] [--cost-from T]
       (build first: bash scripts/build.sh)

The bubble-diameter standard errors are batch means over batches of --batch seconds; the
AMR-vs-finest difference is tested by paired batch means (the batch-by-batch differences
of the two runs), which stays valid when the runs branch from one checkpoint.
"""
import argparse
import csv
import json
import os
import re
import shutil
import subprocess
from concurrent.futures import ThreadPoolExecutor

from benchmark_setup import (bubble_diameter, bubble_diameter_difference_standard_error, bubble_diameter_standard_error,
                             read_case, replace_doc_section, repository_root, summarize_run, write_case)

root = repository_root()
parser = argparse.ArgumentParser()
parser.add_argument("--end-time", type=float, default=5.0)
parser.add_argument("--start-up", type=float, default=1.0)
parser.add_argument("--level", type=int, default=0, help="L: the coarsest uniform level")
parser.add_argument("--jobs", type=int, default=2, help="runs at the same time (one core each)")
parser.add_argument("--summarize-only", action="store_true", help="tabulate the runs already in the work folder")
parser.add_argument("--case", default="bubbling_bed_2d", help="prm/CASE.prm")
parser.add_argument("--runs", nargs="+", default=None, help="run only these (uniform_<level>, amr); the others "
                    "are tabulated if their folders are in the work folder")
parser.add_argument("--amr-variants", nargs="*", default=[],
                    help="extra AMR runs, each 'PARAMETER=VALUE[,PARAMETER=VALUE...]' of the subsection "
                    "adaptive refinement, e.g. 'refine threshold=0.05' (run amr_refine_threshold_0.05); the "
                    "run 'amr' keeps the prm's values")
parser.add_argument("--until", type=float, default=None,
                    help="average over start-up < t <= UNTIL only (compare runs of which one stopped early)")
parser.add_argument("--no-doc", action="store_true",
                    help="print the table only: doc/benchmarks.md and the plot stay as they are (for partial or "
                    "exploratory summaries, e.g. with --until)")
parser.add_argument("--branch-from", default=None, metavar="RUN",
                    help="start each of --runs from the checkpoint of RUN (a finished or stopped run in the work "
                    "folder, e.g. uniform_3 run with a checkpoint at its end) instead of from t = 0: every run "
                    "then starts from the same developed bed and the comparison window (start-up < t) can begin "
                    "at the checkpoint's time")
parser.add_argument("--cost-from", type=float, default=None, metavar="T",
                    help="wall time per simulated second over T < t <= UNTIL only (default: the whole window), "
                    "e.g. the stretch that all runs covered one per core with nothing else on the machine")
parser.add_argument("--batch", type=float, default=0.5,
                    help="seconds per batch of the batch-means standard errors of the bubble diameter (longer "
                    "than the bubbling's correlation time)")
parser.add_argument("--work-folder", default=None,
                    help="the runs' folder (default build/benchmarks/amr_vs_uniform[_CASE])")
args = parser.parse_args()

suffix = "" if args.case == "bubbling_bed_2d" else "_" + args.case  # of the work folder, doc section and plot
work = os.path.abspath(args.work_folder) if args.work_folder else os.path.join(root, "build", "benchmarks", "amr_vs_uniform" + suffix)
os.makedirs(work, exist_ok=True)
base = read_case(args.case)
L = args.level
cases = {f"uniform_{level}": f"\nsubsection mesh\n  set initial refinement = {level}\nend\n" for level in (L, L + 1, L + 2)}
cases["amr"] = (f"\nsubsection mesh\n  set initial refinement = {L}\nend\n"
                f"subsection adaptive refinement\n  set enabled = true\n  set minimum level = {L}\n"
                f"  set maximum level = {L + 2}\nend\n")
for variant in args.amr_variants:
    assignments = [a.split("=") for a in variant.split(",")]
    name = "amr_" + "_".join(re.sub(r"\W+", "_", f"{k.strip()} {v.strip()}") for k, v in assignments)
    cases[name] = cases["amr"][:-len("end\n")] + "".join(f"  set {k.strip()} = {v.strip()}\n" for k, v in assignments) + "end\n"


def run(name):
    prm, folder, log = write_case(work, name, base, args.end_time, cases[name], field_interval=0, progress_interval=100)
    command = [os.path.join(root, "build", "wetbed"), prm]
    if args.branch_from and name != args.branch_from:
        # the branch's checkpoint, its monitors and bubble files (cut back to the checkpoint
        # on resume) and its mesh: the run continues the branch's bed with its own settings
        source = os.path.join(work, args.branch_from)
        if not os.path.isfile(os.path.join(source, "checkpoint", "state")):
            raise SystemExit(f"--branch-from {args.branch_from}: no checkpoint in {source}")
        shutil.rmtree(folder, ignore_errors=True)
        shutil.copytree(os.path.join(source, "checkpoint"), os.path.join(folder, "checkpoint"))
        for f in os.listdir(source):
            if f.endswith(".csv") or f == "mesh.msh":
                shutil.copy2(os.path.join(source, f), folder)
        command.append("--resume")
    else:
        command.append("--overwrite")  # a rerun replaces the earlier results
    with open(log, "w") as out:
        subprocess.run(command, stdout=out, stderr=subprocess.STDOUT)
    return name


def window_cost(log, start, until):
    """Wall s per simulated s over the progress lines with START < t <= UNTIL (the developed
    bed only). A log may hold several pieces of a run (the logs of its resumes, concatenated:
    each piece starts at a "Resumed from" line and counts its wall time from there); the
    wall and simulated time of each piece's span are summed. None without a span."""
    wall = simulated = 0.0
    for piece in re.split(r"^(?=Resumed from)", open(log).read(), flags=re.M):
        points = [(float(t), float(w)) for t, w in
                  re.findall(r"^step\s+\d+\s+t =\s+(\S+) s.*wall (\S+) s", piece, re.M)]
        points = [p for p in points if start < p[0] <= until + 1e-12]
        if len(points) >= 2 and points[-1][0] > points[0][0]:
            wall += points[-1][1] - points[0][1]
            simulated += points[-1][0] - points[0][0]
    return wall / simulated if simulated > 0 else None


if not args.summarize_only:
    with ThreadPoolExecutor(args.jobs) as pool:  # the finest run first: it takes longest
        for name in pool.map(run, args.runs or [f"uniform_{L + 2}", "amr", f"uniform_{L + 1}", f"uniform_{L}"]):
            print("finished", name)

def last_time(name):
    path = os.path.join(work, name, "monitors.csv")
    return float(list(csv.DictReader(open(path)))[-1]["time"]) if os.path.isfile(path) else float("inf")


# every statistic over one common window: up to --until (or the end time), or to where the
# run that stopped first stopped
common_until = min([args.until or args.end_time] + [last_time(name) for name in cases])
results = {}
for name in cases:
    folder, log = os.path.join(work, name), os.path.join(work, name + ".log")
    if not os.path.isfile(os.path.join(folder, "monitors.csv")):
        continue
    summary, _ = summarize_run(folder, log, args.start_up)
    rows = list(csv.DictReader(open(os.path.join(folder, "monitors.csv"))))
    until = common_until
    rows = [r for r in rows if float(r["time"]) <= until + 1e-12]
    t = [float(r["time"]) for r in rows]
    dt = [float(r["time_step"]) for r in rows]
    after = [i for i in range(len(rows)) if t[i] > args.start_up]
    weight = sum(dt[i] for i in after) or float("nan")
    summary["mean_fi"] = sum(float(rows[i]["fluidization_index"]) * dt[i] for i in after) / weight
    summary["end"] = t[-1]
    if not summary["finished"]:  # still running or stopped: wall time from the file times
        wall = os.path.getmtime(os.path.join(folder, "monitors.csv")) - os.path.getmtime(os.path.join(work, name + ".prm"))
        summary["per_second"] = wall / t[-1]
        summary["wall"], summary["steps"] = wall, len(rows) - 1
    windowed = window_cost(log, args.start_up if args.cost_from is None else args.cost_from, until)
    if windowed is not None:
        summary["per_second"] = windowed
        if not summary["finished"]:  # resumed or branched: no whole-run wall time to show
            summary["wall"] = float("nan")
    summary["cells"] = sum(int(r["active_cells"]) * dt[i] for i, r in enumerate(rows) if i in after) / weight
    summary["bed_height"] = sum(float(rows[i]["bed_height"]) * dt[i] for i in after) / weight
    summary["bubble_diameter"] = bubble_diameter(folder, args.start_up, until)
    summary["bubble_diameter_error"] = bubble_diameter_standard_error(folder, args.start_up, until, args.batch)
    log_text = open(log).read()
    summary["flow_dofs_first"] = log_text.split("flow DoFs ")[1].split(" ")[0] if "flow DoFs " in log_text else "?"
    results[name] = summary
json.dump(results, open(os.path.join(work, "results.json"), "w"), indent=1)

finest = results.get(f"uniform_{L + 2}")
lines = [f"Command: `python3 benchmarks/amr_vs_uniform.py --case {args.case} --end-time {args.end_time} --start-up {args.start_up} "
         f"--level {L} --jobs {args.jobs}"
         + "".join(" --amr-variants " + " ".join(f"'{v}'" for v in args.amr_variants) for _ in args.amr_variants[:1])
         + (f" --branch-from {args.branch_from}" if args.branch_from else "")
         + (f" --until {args.until}" if args.until else "") + f" --batch {args.batch}"
         + (f" --cost-from {args.cost_from}" if args.cost_from is not None else "")
         + f"` (serial runs, {args.jobs} at a time on this 2-core machine). "
         + (f"Every run but {args.branch_from} continues {args.branch_from}'s checkpoint. " if args.branch_from else "")
         + f"Means over {args.start_up} s < t ≤ {common_until:.4g} s; differences to the finest uniform run "
         f"(level {L + 2}); s per simulated s from the progress lines over "
         + (f"{args.cost_from} s < t ≤ {common_until:.4g} s" if args.cost_from is not None else "that window")
         + " (the developed bed; "
         "from the file times where a log has no two such lines).", "",
         "| run | cells (mean) | steps (rejected) | wall s | s per simulated s | FI mean | FI difference | bed height (m) | "
         "height difference | bubble diameter (mm) ± standard error | diameter difference ± standard error | α_s range | mass drift |",
         "|" + "---|" * 13]
for name, s in results.items():
    # signed relative differences to the finest run (the plot takes their magnitudes)
    fi_error = s["mean_fi"] / finest["mean_fi"] - 1 if finest else float("nan")
    h_error = s["bed_height"] / finest["bed_height"] - 1 if finest else float("nan")
    d_error = s["bubble_diameter"] / finest["bubble_diameter"] - 1 if finest else float("nan")
    # paired batch means: valid for independent runs and for runs branched from one state
    d_sigma = (bubble_diameter_difference_standard_error(os.path.join(work, name), os.path.join(work, f"uniform_{L + 2}"),
                                                         args.start_up, common_until, args.batch)
               if finest and s is not finest else float("nan"))
    s["diameter_error_sigma"] = d_sigma
    s["fi_error"], s["height_error"], s["diameter_error"] = fi_error, h_error, d_error
    label = name if s["finished"] else f"{name} (to {s['end']:.3f} s)"
    lines.append(f"| {label} | {s['cells']:.0f} | {s['steps']} ({s['rejected']}) | {'–' if s['wall'] != s['wall'] else format(s['wall'], '.0f')} | {s['per_second']:.0f} | "
                 f"{s['mean_fi']:.4f} | {100 * fi_error:+.2f}% | {s['bed_height']:.4f} | {100 * h_error:+.2f}% | "
                 f"{1000 * s['bubble_diameter']:.1f} ± {1000 * s['bubble_diameter_error']:.1f} | "
                 f"{100 * d_error:+.1f}% ± {100 * d_sigma:.1f}% | [{s['alpha_min']:.1e}, {s['alpha_max']:.4f}] | {s['drift']:.1e} |")
for name in [n for n in results if n.startswith("amr")] if finest else []:
    s = results[name]
    speed_up = finest["per_second"] / s["per_second"]
    lines += ["", f"{name} (max level {L + 2}) vs uniform level {L + 2}: {speed_up:.2f}× less wall time per simulated "
                  f"second, FI {100 * s['fi_error']:+.2f}%, bed height "
                  f"{100 * s['height_error']:+.2f}%, mean bubble diameter "
                  f"{100 * s['diameter_error']:+.1f}% ± {100 * s['diameter_error_sigma']:.1f}% "
                  f"(differences to uniform level {L + 2}; ± one standard error, paired batch means of {args.batch} s; goal: within 5% for at least 3× less wall time)."]
lines += ["", f"![error vs cost](amr_vs_uniform{suffix}.png)"]
for name, s in results.items():
    print(name, {k: s[k] for k in ("cells", "per_second", "mean_fi", "fi_error", "bed_height", "height_error",
                                   "bubble_diameter", "diameter_error", "diameter_error_sigma")})

if args.no_doc:
    print("\n".join(lines))
    raise SystemExit(0)

import matplotlib  # noqa: E402
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
fig, ax = plt.subplots(figsize=(6, 4))
for name, s in results.items():
    if name == f"uniform_{L + 2}":
        continue
    for key, marker in (("fi_error", "o"), ("height_error", "s")):
        ax.plot(s["per_second"], max(100 * abs(s[key]), 1e-3), marker, color="C1" if name.startswith("amr") else "C0",
                label=f"{name}: {'FI' if key == 'fi_error' else 'bed height'}")
ax.set_xscale("log")
ax.set_yscale("log")
ax.set_xlabel("wall s per simulated s")
ax.set_ylabel(f"error vs uniform level {L + 2} (%)")
ax.legend(fontsize=7)
ax.set_title(f"{args.case}: AMR vs uniform meshes")
fig.tight_layout()
fig.savefig(os.path.join(root, "doc", f"amr_vs_uniform{suffix}.png"), dpi=110)
replace_doc_section(root, "amr_vs_uniform" + suffix, f"AMR against uniform meshes (prm/{args.case}.prm)", lines)
