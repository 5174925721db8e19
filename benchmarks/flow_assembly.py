#!/usr/bin/env python3
"""Cost of the flow assembly: the TimerOutput 'flow assembly' time per assembly of a
short run, for several thread counts (`wetbed CASE.prm --threads N`) and optionally a
second build (--reference, e.g. a build of an earlier commit), run in turn (A B A B ...)
so that the ratios are measured side by side on the same cores. Also checks that every
configuration gives the same monitors (pressure drop to 1e-6 relative).

usage: python3 benchmarks/flow_assembly.py [--case bubbling_bed_2d] [--end-time 0.02]
           [--threads 1 2] [--repeats 3] [--reference OTHER/build/wetbed]
(build first: bash scripts/build.sh)
"""
import argparse
import csv
import os
import re
import statistics
import subprocess

from benchmark_setup import read_case, repository_root, write_case

root = repository_root()
parser = argparse.ArgumentParser()
parser.add_argument("--case", default="bubbling_bed_2d")
parser.add_argument("--end-time", type=float, default=0.02)
parser.add_argument("--threads", type=int, nargs="+", default=[1, 2])
parser.add_argument("--repeats", type=int, default=3)
parser.add_argument("--reference", help="a second wetbed executable, run with 1 thread")
args = parser.parse_args()

work = os.path.join(root, "build", "benchmarks", "flow_assembly")
os.makedirs(work, exist_ok=True)
wetbed = os.path.join(root, "build", "wetbed")
configurations = [(f"this build, {n} thread{'s' if n > 1 else ''}", [wetbed], n) for n in args.threads]
if args.reference:
    # an older build may not know --threads: it runs on one thread
    configurations.insert(0, ("reference build, 1 thread", [os.path.abspath(args.reference)], None))

timer_row = re.compile(r"^\| flow assembly\s+\|\s+(\d+) \|\s+([0-9.e+-]+)s")
results = {name: [] for name, _, _ in configurations}
monitors = {}
for repeat in range(args.repeats):
    for index, (name, command, threads) in enumerate(configurations):
        prm, folder, log = write_case(work, f"run_{index}", read_case(args.case), args.end_time,
                                      field_interval=0, progress_interval=1000)
        full = command + [prm, "--overwrite"] + (["--threads", str(threads)] if threads else [])
        out = subprocess.run(full, capture_output=True, text=True)
        if out.returncode != 0:
            raise SystemExit(f"{' '.join(full)} failed ({out.returncode}):\n{out.stdout[-2000:]}{out.stderr[-2000:]}")
        for line in out.stdout.splitlines():
            m = timer_row.match(line)
            if m:
                calls, seconds = int(m.group(1)), float(m.group(2))
                results[name].append(1000 * seconds / calls)
        monitors[name] = [float(r["pressure_drop"]) for r in csv.DictReader(open(os.path.join(folder, "monitors.csv")))]

first = configurations[0][0]
print(f"{args.case}, end time {args.end_time} s, {args.repeats} runs each, in turn")
print("| configuration | ms per flow assembly (median, min-max) | ratio to the first (median of run-by-run ratios) |")
print("|---|---|---|")
for name, _, _ in configurations:
    times = results[name]
    ratios = [a / b for a, b in zip(results[first], times)]
    print(f"| {name} | {statistics.median(times):.2f} ({min(times):.2f}-{max(times):.2f}) | "
          f"{statistics.median(ratios):.2f}x |")
for name, _, _ in configurations[1:]:
    a, b = monitors[first], monitors[name]
    worst = max(abs(x - y) / max(abs(x), 1e-300) for x, y in zip(a[1:], b[1:])) if len(a) == len(b) else float("inf")
    print(f"pressure drop, {name} vs {first}: {len(b)} rows, max rel. difference {worst:.1e}")
    if not worst < 1e-6:
        raise SystemExit("the configurations disagree")
