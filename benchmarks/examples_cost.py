#!/usr/bin/env python3
"""The cost and a picture of every shipped case (doc/examples.md).

usage: benchmarks/examples_cost.py [--build build] [--work build/examples] [--ranks 1]
                                   [--cases a,b,...] [--no-doc]

Runs each prm/*.prm case (serial, or on RANKS MPI ranks) for its span below (the whole
run where that is cheap, else the start of it), with field output as HDF5, and measures
the wall time of the whole run (set-up included), its CPU time (user + system of the
run's processes: on a shared machine the figure that does not grow with the other jobs,
and the wall time of a serial run on an idle core) and the load average of the machine.
The CPU time per simulated second and its extrapolation to the case's own end time are
from that span (the start-up of a bed is cheaper per simulated second than the developed
bed: then a lower bound). Renders the last output with scripts/render_fields.py into doc/images/CASE.png
(the quick start: its snapshots side by side) and rewrites the block between
<!-- examples_cost:begin --> and <!-- examples_cost:end --> of doc/examples.md
(--no-doc: print it only). Each case's row is kept in WORK/CASE.json, so a run with
--cases redoes those cases only (--cases '': the table from the kept rows)."""
import argparse
import json
import os
import re
import resource
import shutil
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from benchmark_setup import read_case, repository_root  # noqa: E402

root = repository_root()
# span (s) and field interval (s) of each case; None: the case's own end time
SPANS = {
    "quick_start_2d": (None, 0.01),
    "bubbling_bed_2d": (0.1, 0.01),
    "column_3d": (0.05, 0.01),
    "wet_column_2d": (0.05, 0.01),
    "couette_cell_2d": (None, 0.1),
    "openfoam_fluidisedBed": (0.02, 0.01),
}

parser = argparse.ArgumentParser()
parser.add_argument("--build", default=os.path.join(root, "build"))
parser.add_argument("--work", default=os.path.join(root, "build", "examples"))
parser.add_argument("--ranks", type=int, default=1)
parser.add_argument("--cases", default=",".join(SPANS))
parser.add_argument("--no-doc", action="store_true")
args = parser.parse_args()
os.makedirs(args.work, exist_ok=True)
images = os.path.join(root, "doc", "images")
os.makedirs(images, exist_ok=True)
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")


def setting(text, name):
    values = re.findall(r"^\s*set\s+" + re.escape(name) + r"\s*=\s*([^#\n]*)", text, flags=re.M)
    return values[-1].strip() if values else None


for case in [c for c in args.cases.split(",") if c]:
    span, interval = SPANS[case]
    base = read_case(case)
    end_time = float(setting(base, "end time"))
    span = span or end_time
    folder = os.path.join(args.work, case)
    prm = os.path.join(args.work, case + ".prm")
    open(prm, "w").write(base + f"""
subsection time stepping
  set end time = {span}
end
subsection output
  set folder = {folder}
  set field interval = {interval}
  set field format = hdf5
end
""")
    log = os.path.join(args.work, case + ".log")
    load_before = os.getloadavg()[0]
    command = [os.path.join(args.build, "wetbed"), prm, "--overwrite"]
    if args.ranks > 1:
        command = ["mpirun", "--oversubscribe", "-np", str(args.ranks)] + command
    used = resource.getrusage(resource.RUSAGE_CHILDREN)
    begin = time.time()
    with open(log, "w") as out:
        code = subprocess.call(command, stdout=out, stderr=subprocess.STDOUT, env=env)
    wall = time.time() - begin
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - used.ru_utime) + (after.ru_stime - used.ru_stime)
    load_after = os.getloadavg()
    if code != 0:
        sys.exit(f"{case}: exit {code}, see {log}")
    rows = open(os.path.join(folder, "monitors.csv")).read().splitlines()
    header = rows[0].split(",")
    last = dict(zip(header, rows[-1].split(",")))
    steps = int(float(last["step"]))
    cells = int(float(last["active_cells"]))
    picture_dir = os.path.join(args.work, case + "_pictures")
    shutil.rmtree(picture_dir, ignore_errors=True)
    three_d = setting(base, "dimension") == "3"
    render = [sys.executable, os.path.join(root, "scripts", "render_fields.py"), folder, "--out", picture_dir,
              "--no-animation"]
    if case == "quick_start_2d":
        render += ["--count", "6", "--size", "240x600"]
    else:
        render += ["--times", str(span), "--size", "600x260" if case == "couette_cell_2d" else "240x600"]
    subprocess.check_call(render)
    made = sorted(os.listdir(picture_dir))
    chosen = "alpha_s_snapshots.png" if case == "quick_start_2d" else [m for m in made if m.startswith("alpha_s_t")][-1]
    shutil.copy(os.path.join(picture_dir, chosen), os.path.join(images, case + ".png"))
    if three_d and "alpha_g_iso.png" in made:
        shutil.copy(os.path.join(picture_dir, "alpha_g_iso.png"), os.path.join(images, case + "_iso.png"))
    row = dict(case=case, cells=cells, ranks=args.ranks, span=span, end_time=end_time, steps=steps,
               simulated=float(last["time"]), wall=wall, cpu=cpu, load=max(load_before, load_after[0]))
    json.dump(row, open(os.path.join(args.work, case + ".json"), "w"))
    print(row, flush=True)

lines = [f"Command: `python3 benchmarks/examples_cost.py` (each case {'serial' if args.ranks == 1 else f'on {args.ranks} ranks'} for the",
         "span shown, fields as HDF5). Wall s: the whole run, set-up included; CPU s: its CPU",
         "time, the figure to compare (the wall time of a serial run on an idle core).",
         "Extrapolated: CPU s per simulated s times the case's end time.", "",
         "| case | cells | ranks | simulated | steps | wall s | CPU s | CPU s per simulated s | "
         "whole run (end time) |",
         "|---|---|---|---|---|---|---|---|---|"]
for case in SPANS:
    path = os.path.join(args.work, case + ".json")
    if not os.path.exists(path):
        continue
    r = json.load(open(path))
    per = r["cpu"] / r["simulated"]
    whole = (f"measured: {r['cpu'] / 60:.1f} min CPU ({r['end_time']:g} s)" if abs(r["span"] - r["end_time"]) < 1e-12
             else f"extrapolated: {per * r['end_time'] / 60:.0f} min CPU ({r['end_time']:g} s)")
    lines.append(f"| {case} | {r['cells']} | {r['ranks']} | {r['simulated']:.3g} s | {r['steps']} | "
                 f"{r['wall']:.0f} | {r['cpu']:.0f} | {per:.0f} | {whole} |")
table = "\n".join(lines)
print(table)
if not args.no_doc:
    path = os.path.join(root, "doc", "examples.md")
    text = open(path).read()
    begin, end = "<!-- examples_cost:begin -->", "<!-- examples_cost:end -->"
    text = re.sub(re.escape(begin) + ".*?" + re.escape(end), begin + "\n" + table + "\n" + end, text, flags=re.S)
    open(path, "w").write(text)
