#!/usr/bin/env python3
"""Cost of the flow assembly: the TimerOutput 'flow assembly' time per assembly of a
short run, for each flow-solve path (`default`: the matrix-free path, whose assembly is
the rhs, L_c and the quadrature-point coefficients; `assembled`: the Trilinos matrix as
well) and several thread counts (`wetbed CASE.prm --threads N`), and optionally a second
build (--reference, e.g. a build of an earlier commit), run in turn (A B A B ...) so that
the ratios are measured side by side on the same cores. Every flow solve runs to the
linear tolerance (`outer tolerance = 0`), so that all configurations assemble equally
often. Checks that the thread counts of one path give the same monitors (pressure drop
to 1e-6 relative) and prints how far the paths' pressure drops differ. --write-doc:
the 'flow_assembly_CASE' section of doc/benchmarks.md.

usage: python3 benchmarks/flow_assembly.py [--case bubbling_bed_2d] [--end-time 0.02]
           [--threads 1 2] [--paths default assembled] [--repeats 3]
           [--reference OTHER/build/wetbed] [--write-doc]
(build first: bash scripts/build.sh)
"""
import argparse
import csv
import os
import re
import statistics
import subprocess

from benchmark_setup import read_case, replace_doc_section, repository_root, write_case

root = repository_root()
parser = argparse.ArgumentParser()
parser.add_argument("--case", default="bubbling_bed_2d")
parser.add_argument("--end-time", type=float, default=0.02)
parser.add_argument("--threads", type=int, nargs="+", default=[1, 2])
parser.add_argument("--repeats", type=int, default=3)
parser.add_argument("--paths", nargs="+", choices=["default", "assembled"], default=["default", "assembled"])
parser.add_argument("--reference", help="a second wetbed executable, run with 1 thread")
parser.add_argument("--write-doc", action="store_true")
args = parser.parse_args()

work = os.path.join(root, "build", "benchmarks", "flow_assembly")
os.makedirs(work, exist_ok=True)
wetbed = os.path.join(root, "build", "wetbed")
path_settings = {"default": "",
                 "assembled": "subsection linear solver\n  set operator = assembled\n"
                              "  set velocity preconditioner = AMG\nend\n"}
configurations = [(f"{path}, {n} thread{'s' if n > 1 else ''}", [wetbed], n, path)
                  for path in args.paths for n in args.threads]
if args.reference:
    # an older build may not know --threads: it runs on one thread
    configurations.insert(0, ("reference build, 1 thread", [os.path.abspath(args.reference)], None, args.paths[-1]))

timer_row = re.compile(r"^\| flow assembly\s+\|\s+(\d+) \|\s+([0-9.e+-]+)s")
results = {name: [] for name, _, _, _ in configurations}
calls_per_run = {}
monitors = {}
for repeat in range(args.repeats):
    for index, (name, command, threads, path) in enumerate(configurations):
        prm, folder, log = write_case(work, f"run_{index}", read_case(args.case), args.end_time,
                                      "subsection time stepping\n  set outer tolerance = 0\nend\n"
                                      + path_settings[path], field_interval=0, progress_interval=1000)
        full = command + [prm, "--overwrite"] + (["--threads", str(threads)] if threads else [])
        out = subprocess.run(full, capture_output=True, text=True)
        if out.returncode != 0:
            raise SystemExit(f"{' '.join(full)} failed ({out.returncode}):\n{out.stdout[-2000:]}{out.stderr[-2000:]}")
        for line in out.stdout.splitlines():
            m = timer_row.match(line)
            if m:
                calls, seconds = int(m.group(1)), float(m.group(2))
                results[name].append(1000 * seconds / calls)
                calls_per_run[name] = calls
        monitors[name] = [float(r["pressure_drop"]) for r in csv.DictReader(open(os.path.join(folder, "monitors.csv")))]

first = configurations[0][0]
cells = re.search(r"Mesh: (\d+) cells", out.stdout).group(1)
lines = [f"Command: `python3 benchmarks/flow_assembly.py --case {args.case} --end-time {args.end_time:g} "
         f"--repeats {args.repeats} --threads {' '.join(map(str, args.threads))} --paths {' '.join(args.paths)}"
         + (" --reference OTHER/build/wetbed" if args.reference else "") + " --write-doc` "
         f"(`prm/{args.case}.prm`, {cells} cells, 1 MPI rank, every flow solve to the linear tolerance; "
         f"the configurations run in turn, {args.repeats} times each, on the same 2 cores).", "",
         "| configuration | assemblies per run | ms per flow assembly (median, min–max) | ratio to the first "
         "(median of run-by-run ratios) |",
         "|---|---|---|---|"]
for name, _, _, _ in configurations:
    times = results[name]
    ratios = [a / b for a, b in zip(results[first], times)]
    lines.append(f"| {name} | {calls_per_run[name]} | {statistics.median(times):.2f} ({min(times):.2f}–{max(times):.2f}) | "
                 f"{statistics.median(ratios):.2f}× |")
lines.append("")
disagree = []
for name, _, _, path in configurations[1:]:
    reference = next(c for c in configurations if c[3] == path)[0]
    if reference == name:
        reference = first
    a, b = monitors[reference], monitors[name]
    worst = max(abs(x - y) / max(abs(x), 1e-300) for x, y in zip(a[1:], b[1:])) if len(a) == len(b) else float("inf")
    lines.append(f"Pressure drop, {name} against {reference}: {len(b)} rows, largest relative difference {worst:.1e}.")
    same_path = next(c for c in configurations if c[0] == reference)[3] == path
    if same_path and not worst < 1e-6:
        disagree.append(name)
for line in lines:
    print(line)
if disagree:
    raise SystemExit("the thread counts disagree: " + ", ".join(disagree))
if args.write_doc:
    replace_doc_section(root, "flow_assembly_" + args.case, f"Flow assembly ({args.case})", lines)
