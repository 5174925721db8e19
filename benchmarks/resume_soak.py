#!/usr/bin/env python3
"""Resume soak (issue 52): a run with adaptive refinement and bubble tracking on 2 MPI
ranks, interrupted again and again at random steps — SIGTERM to mpirun, SIGUSR2
(forwarded to the ranks: checkpoint and stop), SIGKILL of one rank — and resumed each
time, on 2 ranks or (every third cycle) on 1. The result must equal the uninterrupted
2-rank run's, and the files a resume continues must be whole: monitors.csv with every
step once, bubbles.csv without repeated rows, fields.xdmf listing each output once.

usage: python3 benchmarks/resume_soak.py [--cycles 20] [--end-time 0.1] [--seed 1]
           [--work DIR] [--wetbed PATH] [--write-doc]
The ctest variant (`resume_soak`): --cycles 5 --end-time 0.04. --write-doc puts the
table into doc/benchmarks.md ("Resume soak").
"""
import argparse
import csv
import os
import random
import re
import shutil
import signal
import subprocess
import sys
import time

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(root, "benchmarks"))
parser = argparse.ArgumentParser()
parser.add_argument("--cycles", type=int, default=20)
parser.add_argument("--end-time", type=float, default=0.1)
parser.add_argument("--seed", type=int, default=1)
parser.add_argument("--work", default=os.path.join(root, "build", "benchmarks", "resume_soak"))
parser.add_argument("--wetbed", default=os.path.join(root, "build", "wetbed"))
parser.add_argument("--write-doc", action="store_true")
args = parser.parse_args()
os.makedirs(args.work, exist_ok=True)
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_mpi_yield_when_idle="1")
failures = []


def expect(condition, what):
    print(("ok   " if condition else "FAIL ") + what, flush=True)
    if not condition:
        failures.append(what)


def case(name):
    text = open(os.path.join(root, "prm", "bubbling_bed_2d.prm")).read().replace("../meshes/", root + "/meshes/")
    folder = os.path.join(args.work, name)
    # outer tolerance 0: every solve to 1e-8, so a resumed run (whose preconditioners are
    # rebuilt) follows the uninterrupted one (doc/theory.md "Outer iterations")
    text += (f"\nsubsection time stepping\n set end time = {args.end_time}\n set outer tolerance = 0\nend\n"
             f"subsection output\n set folder = {folder}\n set field interval = 0.005\n set field format = hdf5\n"
             " set progress interval = 1\nend\n"
             "subsection adaptive refinement\n set enabled = true\n set interval = 5\n set minimum level = 0\n"
             " set maximum level = 1\nend\n"
             "subsection bubble analysis\n set interval = 2\nend\n"
             "subsection checkpoint\n set interval = 7\n set wall time interval = 0\nend\n")
    prm = os.path.join(args.work, name + ".prm")
    open(prm, "w").write(text)
    return prm, folder


def command(prm, ranks, resume):
    run = [args.wetbed, prm, "--resume" if resume else "--overwrite"]
    return run if ranks == 1 else ["mpirun", "--oversubscribe", "-np", str(ranks)] + run


def monitor_rows(folder):
    try:
        return list(csv.DictReader(open(os.path.join(folder, "monitors.csv"))))
    except (OSError, csv.Error):
        return []


def xdmf_times(folder):
    text = open(os.path.join(folder, "fields.xdmf")).read()
    return [float(t) for t in re.findall(r'<Time Value="([^"]+)"', text)]


start = time.time()
prm, reference = case("reference")
shutil.rmtree(reference, ignore_errors=True)
p = subprocess.run(command(prm, 2, False), capture_output=True, text=True, env=env)
expect(p.returncode == 0, f"the uninterrupted run on 2 ranks (exit {p.returncode}) {p.stderr[-300:]}")
reference_wall = time.time() - start
prm, folder = case("soak")
shutil.rmtree(folder, ignore_errors=True)
generator = random.Random(args.seed)
interrupts = []
resumed = False
cycle = 0
while True:
    ranks = 1 if resumed and cycle % 3 == 2 else 2
    process = subprocess.Popen(command(prm, ranks, resumed), stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                               text=True, env=env)
    if cycle >= args.cycles:  # the last piece runs to the end
        out, err = process.communicate()
        expect(process.returncode == 0, f"the last piece on {ranks} rank(s) finished (exit {process.returncode}) {err[-300:]}")
        break
    # wait for a random number of new steps, then interrupt
    # (the first interruption after the first checkpoint: a resume needs one)
    before = len(monitor_rows(folder))
    wanted = before + generator.randint(3, 12)
    checkpoint = os.path.join(folder, "checkpoint")
    while process.poll() is None and (len(monitor_rows(folder)) < wanted or not os.path.isdir(checkpoint)):
        time.sleep(0.05)
    if process.poll() is not None:  # it finished before the interrupt
        out, err = process.communicate()
        expect(process.returncode == 0, f"cycle {cycle + 1}: finished early (exit {process.returncode}) "
                                        f"{[l for l in err.splitlines() if 'wetbed' in l][-1:]}")
        break
    how = ("SIGTERM to mpirun", "SIGUSR2", "SIGKILL of a rank")[generator.randrange(3)] if ranks == 2 else \
        ("SIGTERM", "SIGUSR2", "SIGKILL")[generator.randrange(3)]
    children = [int(c) for c in subprocess.run(["pgrep", "-P", str(process.pid)], capture_output=True,
                                               text=True).stdout.split()] if ranks == 2 else [process.pid]
    if how.startswith("SIGTERM"):
        process.send_signal(signal.SIGTERM)
    elif how.startswith("SIGUSR2"):
        for child in children:
            os.kill(child, signal.SIGUSR2)
    else:
        os.kill(generator.choice(children), signal.SIGKILL)
    try:
        process.communicate(timeout=120)
    except subprocess.TimeoutExpired:
        process.kill()
        process.communicate()
    rows = monitor_rows(folder)
    interrupts.append((cycle + 1, ranks, how, len(rows) - 1, process.returncode))
    print(f"cycle {cycle + 1}: {how} on {ranks} rank(s) at step {len(rows) - 1} (exit {process.returncode})", flush=True)
    resumed = True
    cycle += 1

# the results and the files
rows, reference_rows = monitor_rows(folder), monitor_rows(reference)
steps = [int(r["step"]) for r in rows]
expect(steps == list(range(len(steps))), f"monitors.csv: steps 0..{steps[-1] if steps else '?'} once each")
expect(len(rows) == len(reference_rows), f"{len(rows)} monitor rows, the uninterrupted run {len(reference_rows)}")
names = ("time", "solids_mass", "bed_height", "pressure_drop", "alpha_s_max", "theta_mean", "active_cells")
worst = {k: max((abs(float(a[k]) - float(b[k])) / max(abs(float(b[k])), 1e-12) for a, b in zip(rows, reference_rows)),
                default=float("nan")) for k in names}
changed_ranks = any(r == 1 for _, r, _, _, _ in interrupts) or False
expect(max(worst.values()) < 1e-6, "every monitor row equals the uninterrupted run's: max rel. differences " +
       ", ".join(f"{k} {v:.1e}" for k, v in worst.items()))
bubbles = open(os.path.join(folder, "bubbles.csv")).read().splitlines()
expect(len(bubbles) == len(set(bubbles)), f"bubbles.csv: {len(bubbles)} rows, none repeated")
times, reference_times = xdmf_times(folder), xdmf_times(reference)
expect(times == sorted(set(times)) and len(times) == len(reference_times),
       f"fields.xdmf: {len(times)} outputs, each once (the uninterrupted run: {len(reference_times)})")
wall = time.time() - start
print(f"{len(interrupts)} interruptions, {sum(1 for i in interrupts if i[1] == 1)} pieces on 1 rank; wall {wall:.0f} s "
      f"(the uninterrupted run {reference_wall:.0f} s)")
if args.write_doc:
    from benchmark_setup import replace_doc_section
    lines = [f"Command: `python3 benchmarks/resume_soak.py --cycles {args.cycles} --end-time {args.end_time} "
             f"--seed {args.seed} --write-doc` (prm/bubbling_bed_2d.prm with adaptive refinement every 5 steps, "
             "levels 0-1, bubble tracking every 2 steps, HDF5 fields every 5 ms, a checkpoint every 7 steps; "
             f"2 MPI ranks, each third piece on 1). Wall time {wall:.0f} s.", "",
             "| cycle | ranks | interrupt | at step | exit |", "|---|---|---|---|---|"]
    lines += [f"| {c} | {r} | {h} | {s} | {e} |" for c, r, h, s, e in interrupts]
    lines += ["", "| compared with the uninterrupted run | result |", "|---|---|",
              f"| monitor rows | {len(rows)} (uninterrupted {len(reference_rows)}), steps once each: "
              f"{steps == list(range(len(steps)))} |"]
    lines += [f"| max rel. difference of {k} over all rows | {v:.1e} |" for k, v in worst.items()]
    lines += [f"| bubbles.csv rows repeated | {len(bubbles) - len(set(bubbles))} |",
              f"| fields.xdmf outputs | {len(times)} (uninterrupted {len(reference_times)}) |"]
    replace_doc_section(root, "resume_soak", "Resume soak", lines)
if failures:
    sys.exit("resume soak: checks failed")
