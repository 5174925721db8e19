#!/usr/bin/env python3
"""Two (or more) wetbed executables side by side on one case: the runs alternate (A B A
B ...) on the same cores, so that the machine's load drifts over all of them alike.
Prints the median wall time and TimerOutput sections of each executable, and how far
each run's monitors.csv is from the first executable's (largest relative difference
of any column, the last FGMRES counts).

usage: python3 benchmarks/compare_builds.py CASE.prm ROUNDS NAME=EXECUTABLE ...
       (NP=2 by default: mpirun -np NP; each run writes into /tmp/compare_builds/NAME)
e.g.   python3 benchmarks/compare_builds.py build/benchmarks/cost_3d/level_0_p-multigrid.prm 3 \\
           before=/tmp/old/build/wetbed after=build/wetbed
"""
import csv
import os
import re
import statistics
import subprocess
import sys

if len(sys.argv) < 4:
    sys.exit(__doc__)
prm, rounds = sys.argv[1], int(sys.argv[2])
executables = [a.split("=", 1) for a in sys.argv[3:]]
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
work = "/tmp/compare_builds"
os.makedirs(work, exist_ok=True)
text = open(prm).read()
timings = {name: [] for name, _ in executables}
monitors = {}
for _ in range(rounds):
    for name, executable in executables:
        folder = os.path.join(work, name)
        case = re.sub(r"(subsection output.*?set folder\s*=\s*)\S+", lambda m: m.group(1) + folder, text, flags=re.S)
        path = os.path.join(work, name + ".prm")
        open(path, "w").write(case)
        out = subprocess.run(["mpirun", "--oversubscribe", "-np", os.environ.get("NP", "2"), executable, path,
                              "--overwrite"], capture_output=True, text=True, env=env).stdout
        finished = re.search(r"Finished: .*wall ([\d.]+) s", out)
        if not finished:
            sys.exit(f"{name}: no 'Finished' line\n{out[-2000:]}")
        sections = {m.group(1).strip(): float(m.group(2)) for m in re.finditer(
            r"^\| ([a-zA-Z -]+?)\s+\|\s+\d+ \|\s+[\d.e+-]+s\s+\d+ \|\s+([\d.e+-]+)s \|", out, re.M)}
        sections["wall"] = float(finished.group(1))
        timings[name].append(sections)
        monitors[name] = list(csv.DictReader(open(os.path.join(folder, "monitors.csv"))))
names = ["wall", "Krylov solve", "flow assembly", "matrix-free coefficients", "preconditioner setup", "monitors",
         "solids pressure correction", "granular temperature", "alpha transport"]
print(f"median of {rounds} alternated runs, s".ljust(36) + "".join(n.rjust(12) for n, _ in executables))
for section in names:
    print(section.ljust(36) + "".join(f"{statistics.median(t.get(section, 0) for t in timings[n]):12.3f}"
                                      for n, _ in executables))
reference = monitors[executables[0][0]]
for name, _ in executables[1:]:
    worst, column = 0.0, ""
    for a, b in zip(reference, monitors[name]):
        for key in a:
            if key in ("run_id", "solids_mass_drift"):  # (drift: round-off around 0)
                continue
            try:
                u, v = float(a[key]), float(b[key])
            except ValueError:
                continue
            difference = abs(u - v) / max(abs(u), abs(v), 1e-12)
            if difference > worst:
                worst, column = difference, key
    print(f"{name} vs {executables[0][0]}: {len(monitors[name])}/{len(reference)} rows, largest relative "
          f"difference {worst:.2e} ({column}); FGMRES per step (last 8) {[r['krylov_iterations'] for r in monitors[name]][-8:]}"
           f" vs {[r['krylov_iterations'] for r in reference][-8:]}")
