#!/usr/bin/env python3
"""Stress benchmark (issue 7): the 2D bubbling bed pushed to the edges of its parameters
and scheme options, each run short (the start-up is the hardest part: the bed lifts as
a plug and collapses) and reported as completed, stopped cleanly with a diagnostic
(exit 3 + failure_report.txt) or crashed: rejected steps, min/max alpha_s and Theta,
solids mass drift, cost. Writes the 'stress' section of doc/benchmarks.md.

Cases: restitution e = 0.5 and 0.99; U = 1.5 and 8 U_mf (Wen-Yu U_mf of the 350 um
beads); 100 um particles (stiff drag) at 8 of their U_mf; the wettest loading of the
seed-000 sweep (delta = 0.138e-2, prm/wet_column_2d.prm); AMR adapting at every step
(levels 0-2); 2 MPI ranks; and a CFL sweep: fixed time steps of 0.5, 1, 2, 4 ms with
BDF1 and BDF2 (adaptive stepping off, rejected steps still halve dt). --long adds the
20 s dry run (about 4 h here); it writes a checkpoint every 500 steps, and a later
`--long --only long` continues it from there (`wetbed --resume`), adding up the wall time
of its pieces. Every case's result is kept in build/benchmarks/stress/NAME.json and the
table lists all cases that have one, so --only reruns some without losing the others.

--3d runs the 3D columns instead, each on 2 ranks to --end-time-3d (default 3 s):
prm/column_3d.prm as shipped, with adaptive refinement (levels 0-1), and the seed's
5 cm x 1 m column (meshes/column_3d.geo with height 1 m and 80 layers, the same cell
size) dry and wet at delta = 0.055, 0.1 and 0.138e-2 (the wet particles of
prm/wet_column_2d.prm). They checkpoint every 10 minutes of wall time and continue from
there when run again; their table (the 'stress_3d' section of doc/benchmarks.md) gives
the peak speeds against the case's reference speed, rejected steps, the smallest step
and the divergence checks that fired.

usage: python3 benchmarks/stress.py [--end-time 0.2] [--jobs 2] [--long] [--only NAME ...]
       python3 benchmarks/stress.py --3d [--end-time-3d 3] [--only NAME ...] [--table]
(build first: bash scripts/build.sh)
"""
import argparse
import concurrent.futures
import csv
import json
import math
import os
import re
import sys

from benchmark_setup import read_case, replace_doc_section, repository_root, run_resumable, write_case

root = repository_root()
parser = argparse.ArgumentParser()
parser.add_argument("--end-time", type=float, default=0.2)
parser.add_argument("--jobs", type=int, default=2)
parser.add_argument("--long", action="store_true")
parser.add_argument("--only", nargs="*")
parser.add_argument("--3d", dest="three_d", action="store_true")
parser.add_argument("--end-time-3d", type=float, default=3.0)
parser.add_argument("--table", action="store_true",
                    help="with --3d: only rewrite the table from benchmarks/results/stress_3d/")
parser.add_argument("--collect", action="store_true",
                    help="only record cases run before results were kept in NAME.json")
args = parser.parse_args()
work = os.path.join(root, "build", "benchmarks", "stress")
os.makedirs(work, exist_ok=True)
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")


def minimum_fluidization_velocity(d, rho_s=2500.0, rho_g=1.2, mu=1.8e-5, g=9.81):
    """Wen and Yu (1966): Re_mf = sqrt(33.7^2 + 0.0408 Ar) - 33.7."""
    archimedes = rho_g * (rho_s - rho_g) * g * d ** 3 / mu ** 2
    return (math.sqrt(33.7 ** 2 + 0.0408 * archimedes) - 33.7) * mu / (rho_g * d)


u_mf = minimum_fluidization_velocity(350e-6)
u_mf_fine = minimum_fluidization_velocity(100e-6)
dry = read_case("bubbling_bed_2d")
cases = [
    ("default case", dry, "", 1),
    ("e = 0.5", dry, "subsection kinetic theory\n set restitution coefficient = 0.5\nend\n", 1),
    ("e = 0.99", dry, "subsection kinetic theory\n set restitution coefficient = 0.99\nend\n", 1),
    (f"U = 1.5 U_mf ({1.5 * u_mf:.3f} m/s)", dry, f"subsection boundary conditions\n set inlet superficial velocity = {1.5 * u_mf}\nend\n", 1),
    (f"U = 8 U_mf ({8 * u_mf:.3f} m/s)", dry, f"subsection boundary conditions\n set inlet superficial velocity = {8 * u_mf}\nend\n", 1),
    (f"100 um, U = 8 U_mf ({8 * u_mf_fine:.4f} m/s)", dry,
     f"subsection physical properties\n set particle diameter = 100e-6\nend\n"
     f"subsection boundary conditions\n set inlet superficial velocity = {8 * u_mf_fine}\nend\n", 1),
    ("wet, delta = 0.138e-2", read_case("wet_column_2d"), "subsection wet particles\n set liquid loading = 0.138e-2\nend\n", 1),
    ("AMR every step, levels 0-2", dry,
     "subsection adaptive refinement\n set enabled = true\n set interval = 1\n set minimum level = 0\n set maximum level = 2\nend\n", 1),
    ("2 MPI ranks", dry, "", 2),
]
for order in (1, 2):
    for dt in (0.5e-3, 1e-3, 2e-3, 4e-3, 8e-3, 16e-3):
        cases.append((f"BDF{order}, fixed dt = {1e3 * dt:g} ms", dry,
                      f"subsection time stepping\n set adaptive = false\n set bdf order = {order}\n"
                      f" set initial time step = {dt}\n set maximum time step = {dt}\nend\n", 1))
cases.append(("long dry run, 20 s", dry, "", 1))
all_labels = [c[0] for c in cases]
if not args.long:
    cases = cases[:-1]
if args.collect:
    cases = []
if args.only:
    cases = [c for c in cases if any(o in c[0] for o in args.only)]


def run(case):
    label, base, sections, ranks = case
    name = re.sub(r"[^a-z0-9]+", "_", label.lower()).strip("_")
    long = label.startswith("long")
    end = 20.0 if long else args.end_time
    checkpoints = " set interval = 500\n" if long else ""
    prm, folder, log = write_case(work, name, base, end,
                                  sections + f"subsection checkpoint\n set at end = false\n{checkpoints}end\n",
                                  field_interval=1000)
    command = [os.path.join(root, "build", "wetbed"), prm]
    if ranks > 1:
        command = ["mpirun", "--oversubscribe", "-np", str(ranks)] + command
    code, wall = run_resumable(command, folder, log, os.path.join(work, name + ".wall"), long, env)
    record(label, name, folder, code, wall)


def record(label, name, folder, code, wall):
    """The result of one case from its folder, kept in NAME.json and printed."""
    end = 20.0 if label.startswith("long") else args.end_time
    rows = list(csv.DictReader(open(os.path.join(folder, "monitors.csv")))) if os.path.exists(os.path.join(folder, "monitors.csv")) else []
    values = lambda key: [float(r[key]) for r in rows]  # noqa: E731
    result = {"label": label, "code": code, "wall": wall, "end": end,
              "reached": float(rows[-1]["time"]) if rows else 0.0,
              "steps": int(float(rows[-1]["step"])) if rows else 0,
              "rejected": int(float(rows[-1]["rejected_steps"])) if rows else 0,
              "alpha": (min(values("alpha_s_min")), max(values("alpha_s_max"))) if rows else (math.nan, math.nan),
              "theta": (min(values("theta_min")), max(values("theta_max"))) if rows else (math.nan, math.nan),
              "drift": max(abs(v) for v in values("solids_mass_drift")) if rows else math.nan,
              "finite": all(math.isfinite(float(v)) for r in rows for k, v in r.items() if v != "" and k != "run"),
              "report": os.path.exists(os.path.join(folder, "failure_report.txt"))}
    if code == 0:
        result["outcome"] = "completed"
    elif code == 3 and result["report"]:
        reason = open(os.path.join(folder, "failure_report.txt")).read().splitlines()
        result["outcome"] = "stopped cleanly (" + (reason[0][:60] if reason else "report") + ")"
    elif code == 4 or (code < 0 and label.startswith("long")):
        result["outcome"] = "interrupted (continue it with --long --only long)"
    else:
        result["outcome"] = f"CRASHED (exit {code})"
    with open(os.path.join(work, name + ".json"), "w") as f:
        json.dump(result, f)
    print(f"{label}: {result['outcome']}, t = {result['reached']:.4g} s, {result['steps']} steps, "
          f"{result['rejected']} rejected, alpha_s [{result['alpha'][0]:.2e}, {result['alpha'][1]:.4f}], "
          f"drift {result['drift']:.1e}, {wall:.0f} s", flush=True)
    return result


if args.three_d:
    from stress_3d import run_3d_cases
    run_3d_cases(root, work, args, env)
    sys.exit(0)
with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
    list(pool.map(run, cases))
if args.collect:
    for label in all_labels:
        name = re.sub(r"[^a-z0-9]+", "_", label.lower()).strip("_")
        folder, log = os.path.join(work, name), os.path.join(work, name + ".log")
        if os.path.exists(os.path.join(folder, "monitors.csv")) and not os.path.exists(os.path.join(work, name + ".json")):
            finished = re.search(r"Finished: .* wall ([\d.e+-]+) s", open(log).read())
            record(label, name, folder, 0 if finished else 3, float(finished.group(1)) if finished else math.nan)
results = []
for label in all_labels:
    stored = os.path.join(work, re.sub(r"[^a-z0-9]+", "_", label.lower()).strip("_") + ".json")
    if os.path.exists(stored):
        results.append(json.load(open(stored)))

lines = [f"Command: `python3 benchmarks/stress.py --end-time {args.end_time:g} --jobs {args.jobs}`"
         " (the 20 s row: `--long --only long`, resumable from its checkpoints; `prm/bubbling_bed_2d.prm`, 600 cells, unless the case says otherwise;",
         f"U_mf by Wen–Yu: {u_mf:.3f} m/s for 350 µm, {u_mf_fine:.4f} m/s for 100 µm; runs two at a time on the",
         "2-core machine, so the wall times are upper bounds).", "",
         "| case | outcome | simulated | steps | rejected | α_s range | Θ range (m²/s²) | mass drift | NaN-free | wall s |",
         "|---|---|---|---|---|---|---|---|---|---|"]
for r in results:
    lines.append(f"| {r['label']} | {r['outcome']} | {r['reached']:.3g} / {r['end']:g} s | {r['steps']} | {r['rejected']} | "
                 f"[{r['alpha'][0]:.1e}, {r['alpha'][1]:.4f}] | [{r['theta'][0]:.1e}, {r['theta'][1]:.3g}] | {r['drift']:.1e} | "
                 f"{'yes' if r['finite'] else 'NO'} | {r['wall']:.0f} |")
replace_doc_section(root, "stress", "Stress benchmark", lines)
print("\n".join(lines))
