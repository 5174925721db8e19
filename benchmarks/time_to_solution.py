#!/usr/bin/env python3
"""Time to solution at equal accuracy (the accuracy guard of the time-stepping defaults).

For each case it runs, from rest:
  a          the settings before the outer-iteration and time-step work, set by parameters
             on the current build: two outer iterations with every flow solve to 1e-8
             (outer tolerance = 0) and the global Courant measure;
  b          the defaults;
  noise      b with the initial bed solids fraction changed by a relative 1e-6: the
             run-to-run yardstick of a chaotic bed;
  reference  Delta t / 4 (cfl target and maximum time step / 4), every solve to 1e-10,
             three fixed outer iterations;
and, with --variants, more time-step settings for the work-precision plot.
a and b run first and alone: side by side for a serial case (one core each), one after
the other on 2 ranks, so their ratio is measured in one invocation on the same cores;
the others follow, --jobs at a time. Each run is resumable (run the command again after
a stop).

Quantities after --start-up: time-averaged FI, bed surface height, bed height and the
dominant frequency of the pressure drop, and in 2D the mean bubble diameter. A run's
accuracy is its difference from the reference; it is "within noise" where each
difference is at most 2x the difference of the noise pair (b against noise), or 1% of
the reference's value if that is larger.

Cases: bed2d = prm/openfoam_fluidisedBed.prm at refinement level 2 (960 cells, serial,
1.5 s, statistics after 0.5 s: the level whose bubbles are within 5% of the finest in
doc/benchmarks.md "Bed work-precision"); column3d = prm/column_3d.prm (2 ranks, 0.5 s,
statistics after 0.1 s).

usage: python3 benchmarks/time_to_solution.py [--cases column3d bed2d] [--runs a b noise
       reference] [--variants] [--jobs 2] [--summarize-only]     (build first)
       python3 benchmarks/time_to_solution.py --startup   (the start-up runs only; after
       column3d's reference)
Regenerates the 'time_to_solution' section of doc/benchmarks.md and
doc/time_to_solution.png; results in benchmarks/results/time_to_solution/.
"""
import argparse
import csv
import glob
import json
import os
from concurrent.futures import ThreadPoolExecutor

from benchmark_setup import (bubble_diameter, dominant_frequency, read_case, replace_doc_section,
                             repository_root, run_resumable, time_mean, write_case)

root = repository_root()
CASES = {  # name: (prm, ranks, end time, start-up, extra sections)
    "column3d": ("column_3d", 2, 0.5, 0.1, ""),
    "bed2d": ("openfoam_fluidisedBed", 1, 1.5, 0.5, "subsection mesh\n  set initial refinement = 2\nend\n"),
}
OLD = "subsection time stepping\n  set outer tolerance = 0\n  set outer iterations = 2\n  set courant measure = global\nend\n"
SETTINGS = {  # name: (description, sections given the case's prm text)
    "a": ("2 exact outer iterations, global Courant measure", lambda prm: OLD),
    "b": ("defaults", lambda prm: ""),
    "noise": ("defaults, initial bed solids fraction x (1 + 1e-6)", lambda prm: perturbed(prm)),
    "reference": ("Δt/4, solves to 1e-10, 3 exact outer iterations", lambda prm: (
        "subsection time stepping\n  set outer tolerance = 0\n  set outer iterations = 3\n"
        f"  set cfl target = 0.125\n  set maximum time step = {value(prm, 'time stepping', 'maximum time step', 2e-3) / 4:g}\n"
        f"  set initial time step = {value(prm, 'time stepping', 'initial time step', 1e-4) / 4:g}\nend\n"
        "subsection linear solver\n  set relative tolerance = 1e-10\nend\n")),
    # the work-precision points (--variants)
    "cfl1": ("defaults, cfl target 1", lambda prm: "subsection time stepping\n  set cfl target = 1\nend\n"),
    "cfl0.25": ("defaults, cfl target 0.25", lambda prm: "subsection time stepping\n  set cfl target = 0.25\nend\n"),
    "error1e-3": ("defaults, time error tolerance 1e-3, maximum step x 4", lambda prm: (
        "subsection time stepping\n  set time error tolerance = 1e-3\n"
        f"  set maximum time step = {4 * value(prm, 'time stepping', 'maximum time step', 2e-3):g}\nend\n")),
    "error3e-4": ("defaults, time error tolerance 3e-4, maximum step x 4", lambda prm: (
        "subsection time stepping\n  set time error tolerance = 3e-4\n"
        f"  set maximum time step = {4 * value(prm, 'time stepping', 'maximum time step', 2e-3):g}\nend\n")),
    "outer1": ("defaults, 1 outer iteration", lambda prm: "subsection time stepping\n  set outer iterations = 1\nend\n"),
    "outer0.3": ("defaults, outer tolerance 0.3", lambda prm: "subsection time stepping\n  set outer iterations = 2\n"
                 "  set outer tolerance = 0.3\nend\n"),
}
MAIN = ["a", "b", "noise", "reference"]
VARIANTS = ["cfl1", "cfl0.25", "error1e-3", "error3e-4", "outer1", "outer0.3"]


def value(prm, subsection, name, default):
    """The last `set NAME = v` inside `subsection SUBSECTION` of a prm text (float)."""
    found, inside = default, False
    for line in prm.splitlines():
        words = line.split()
        if words[:1] == ["subsection"]:
            inside = " ".join(words[1:]) == subsection
        elif words[:1] == ["end"]:
            inside = False
        elif inside and line.strip().startswith("set ") and "=" in line:
            key, v = line.strip()[4:].split("=", 1)
            if key.strip() == name:
                found = float(v.split("#")[0])
    return found


def perturbed(prm):
    fraction = value(prm, "initial conditions", "bed solids fraction", 0.55)
    return f"subsection initial conditions\n  set bed solids fraction = {fraction * (1 + 1e-6):.12g}\nend\n"


# where the error of the default step comes from: the first 0.1 s of the 3D column (the
# bed's lift and first slug), serial, against the first 0.1 s of column3d_reference
STARTUP = {  # name: (description, sections)
    "a": ("2 exact outer iterations, global Courant measure (Δt ≤ 1e-3 s)", OLD),
    "b": ("defaults (Δt ≤ 1e-3 s)", ""),
    "outer3": ("3 exact outer iterations", "subsection time stepping\n  set outer tolerance = 0\n"
               "  set outer iterations = 3\nend\n"),
    "solves1e-10": ("2 outer iterations, solves to 1e-10", "subsection time stepping\n  set outer tolerance = 0\n"
                    "  set outer iterations = 2\nend\nsubsection linear solver\n  set relative tolerance = 1e-10\nend\n"),
    "dt4": ("defaults, Δt/4 (cfl target 0.125, Δt ≤ 2.5e-4 s)", "subsection time stepping\n  set cfl target = 0.125\n"
            "  set maximum time step = 0.00025\n  set initial time step = 2.5e-05\nend\n"),
    "a_dt4": ("2 exact outer iterations, global Courant measure, Δt/4", OLD +
              "subsection time stepping\n  set cfl target = 0.125\n  set maximum time step = 0.00025\n"
              "  set initial time step = 2.5e-05\nend\n"),
    "error1e-4": ("defaults, time error tolerance 1e-4", "subsection time stepping\n  set time error tolerance = 1e-4\nend\n"),
    "error2e-5": ("defaults, time error tolerance 2e-5", "subsection time stepping\n  set time error tolerance = 2e-5\nend\n"),
}

parser = argparse.ArgumentParser()
parser.add_argument("--cases", nargs="+", default=list(CASES), choices=list(CASES))
parser.add_argument("--runs", nargs="+", default=MAIN, choices=list(SETTINGS))
parser.add_argument("--variants", action="store_true", help="also the work-precision variants")
parser.add_argument("--jobs", type=int, default=2)
parser.add_argument("--summarize-only", action="store_true")
parser.add_argument("--startup", action="store_true", help="the start-up runs of the 3D column (serial, 0.1 s)")
args = parser.parse_args()
work = os.path.join(root, "build", "benchmarks", "time_to_solution")
results = os.path.join(root, "benchmarks", "results", "time_to_solution")
os.makedirs(work, exist_ok=True)
os.makedirs(results, exist_ok=True)


def run(job):
    case, setting = job
    prm_name, ranks, end_time, start_up, extra = CASES[case]
    base = read_case(prm_name)
    name = f"{case}_{setting}"
    sections = extra + SETTINGS[setting][1](base + extra)
    prm, folder, log = write_case(work, name, base, end_time, sections, field_interval=0, progress_interval=500)
    command = [os.path.join(root, "build", "wetbed"), prm]
    if ranks > 1:
        command = ["mpirun", "--oversubscribe", "-np", str(ranks)] + command
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    code, wall = run_resumable(command, folder, log, os.path.join(work, name + ".wall"), env=env)
    if code != 0:
        raise SystemExit(f"{name} failed (exit {code}): see {log}")
    rows = list(csv.DictReader(open(os.path.join(folder, "monitors.csv"))))[1:]
    text = open(log).read()
    fgmres = [line for line in text.splitlines() if line.startswith("Finished:")]
    t = [float(r["time"]) for r in rows]
    record = {
        "case": case, "setting": setting, "description": SETTINGS[setting][0], "ranks": ranks,
        "end": t[-1], "steps": int(rows[-1]["step"]), "rejected": int(rows[-1]["rejected_steps"]),
        "wall": wall, "per_second": wall / t[-1],
        "krylov_per_step": sum(float(r["krylov_iterations"]) for r in rows) / len(rows),
        "mean_dt": t[-1] / int(rows[-1]["step"]),
        "fi": time_mean(rows, "fluidization_index", start_up),
        "surface": time_mean(rows, "bed_surface_height", start_up),
        "bed_height": time_mean(rows, "bed_height", start_up),
        "frequency": dominant_frequency(t, [float(r["pressure_drop"]) for r in rows], start_up),
        "bubble_diameter": bubble_diameter(folder, start_up),
        "finished_line": fgmres[-1] if fgmres else "",
    }
    with open(os.path.join(results, name + ".json"), "w") as f:
        json.dump(record, f, indent=1)
    print(f"{name}: {record['per_second']:.0f} s per simulated s, FI {record['fi']:.4f}, "
          f"surface {record['surface']:.4f} m", flush=True)
    return name


def run_startup(name):
    base = read_case("column_3d")
    prm, folder, log = write_case(os.path.join(work, "startup"), name, base, 0.1, STARTUP[name][1],
                                  field_interval=0, progress_interval=500)
    code, wall = run_resumable([os.path.join(root, "build", "wetbed"), prm], folder, log,
                               os.path.join(work, "startup", name + ".wall"))
    if code != 0:
        raise SystemExit(f"startup {name} failed (exit {code}): see {log}")
    return name


def startup_lines():
    """The start-up table: FI and bed surface means over 0-0.05 and 0.05-0.1 s against
    the first 0.1 s of column3d_reference."""
    def windows(path):
        rows = list(csv.DictReader(open(path)))[1:]
        out = []
        for lo, hi in ((0.0, 0.05), (0.05, 0.1)):
            part = [r for r in rows if lo < float(r["time"]) <= hi + 1e-12]
            w = sum(float(r["time_step"]) for r in part)
            out += [sum(float(r[k]) * float(r["time_step"]) for r in part) / w
                    for k in ("fluidization_index", "bed_surface_height")]
        errors = sorted(float(r["time_error"]) for r in rows if float(r["time"]) <= 0.1 + 1e-12)
        return out, errors[len(errors) // 2], sum(1 for r in rows if float(r["time"]) <= 0.1 + 1e-12)
    reference_path = os.path.join(work, "column3d_reference", "monitors.csv")
    if not os.path.isfile(reference_path):
        return []
    ref, ref_error, ref_steps = windows(reference_path)
    stored = {"reference": {"steps": ref_steps, "windows": ref, "median_time_error": ref_error}}
    lines = ["**Start-up of the 3D column** (`--startup`: prm/column_3d.prm, serial, the first 0.1 s: the bed's lift "
             "and first slug; means over 0–0.05 s and 0.05–0.1 s; the reference is the first 0.1 s of column3d's, "
             "on 2 ranks)", "",
             "| run | settings | steps | wall s | FI 0–0.05 s | surface 0–0.05 s (m) | FI 0.05–0.1 s | surface 0.05–0.1 s (m) | "
             "largest difference vs reference | median time_error |", "|" + "---|" * 10,
             f"| reference | Δt/4, solves to 1e-10, 3 exact outer iterations | {ref_steps} | | " +
             " | ".join(f"{v:.4f}" for v in ref) + f" | | {ref_error:.1e} |"]
    for name in STARTUP:
        folder = os.path.join(work, "startup", name)
        log = os.path.join(work, "startup", name + ".log")
        if not os.path.isfile(os.path.join(folder, "monitors.csv")) or "Finished:" not in open(log).read():
            continue
        values, error, steps = windows(os.path.join(folder, "monitors.csv"))
        wall = float(open(os.path.join(work, "startup", name + ".wall")).read())
        worst = max(abs(v / r - 1) for v, r in zip(values, ref))
        lines.append(f"| {name} | {STARTUP[name][0]} | {steps} | {wall:.0f} | " + " | ".join(f"{v:.4f}" for v in values)
                     + f" | {100 * worst:.1f}% | {error:.1e} |")
        stored[name] = {"settings": STARTUP[name][0], "steps": steps, "wall": wall, "windows": values,
                        "largest_difference": worst, "median_time_error": error}
    with open(os.path.join(results, "startup.json"), "w") as f:
        json.dump(stored, f, indent=1)
    return lines + [""]


if args.startup and not args.summarize_only:
    os.makedirs(os.path.join(work, "startup"), exist_ok=True)
    for finished in map(run_startup, STARTUP):  # one at a time: the wall times compare
        print("finished startup", finished, flush=True)

if not args.summarize_only and not args.startup:
    settings = args.runs + (VARIANTS if args.variants else [])
    for case in args.cases:
        # the timed pair first and alone: side by side when serial (one core each), one
        # after the other on 2 ranks (two 2-rank jobs on 2 cores shared them unevenly:
        # the fixed-cost parts of one ran 1.9x slower per call than the other's)
        timed = [(case, s) for s in ("a", "b") if s in settings]
        with ThreadPoolExecutor(args.jobs if CASES[case][1] == 1 else 1) as pool:
            for finished in pool.map(run, timed):
                print("finished", finished, flush=True)
    jobs = [(case, s) for case in args.cases for s in settings if s not in ("a", "b")]
    with ThreadPoolExecutor(args.jobs) as pool:
        for finished in pool.map(run, jobs):
            print("finished", finished, flush=True)

QUANTITIES = [("fi", "FI mean", "{:.4f}"), ("surface", "bed surface (m)", "{:.4f}"),
              ("bed_height", "bed height (m)", "{:.4f}"), ("frequency", "ΔP frequency (Hz)", "{:.2f}"),
              ("bubble_diameter", "bubble d (mm)", "{:.1f}")]
records = {os.path.basename(p)[:-5]: json.load(open(p)) for p in sorted(glob.glob(os.path.join(results, "*.json")))}
lines = ["Command: `python3 benchmarks/time_to_solution.py --variants` (a and b first and alone: side by side "
         "when serial, one after the other on 2 ranks; then the others two at a time; `--cases column3d` or "
         "`bed2d` for one). Differences are relative to the "
         "reference run (Δt/4, solves to 1e-10); the noise row is b against b with the initial bed perturbed by 1e-6; "
         "a row is within noise (✓) where every difference is at most twice the noise pair's or 1%.", ""]
points = []
for case in CASES:
    ref, b, noise = (records.get(f"{case}_{s}") for s in ("reference", "b", "noise"))
    if not any(k.startswith(case + "_") for k in records):
        continue
    lines += [f"**{case}** ({CASES[case][0]}.prm, {CASES[case][1]} rank(s), {CASES[case][2]:g} s, statistics after "
              f"{CASES[case][3]:g} s)", "",
              "| run | settings | steps | mean Δt (s) | rejected | FGMRES per step | s per simulated s | cost vs a | "
              + " | ".join(q[1] for q in QUANTITIES) + " | largest difference vs reference | within noise |",
              "|" + "---|" * (10 + len(QUANTITIES))]

    def difference(r, key):
        if ref is None or r.get(key) != r.get(key) or ref.get(key) != ref.get(key):
            return float("nan")
        return abs(r[key] / ref[key] - 1)

    tolerance, pairs = {}, {}
    for key, _, _ in QUANTITIES:
        pair = abs(b[key] / noise[key] - 1) if b and noise and b[key] == b[key] and noise[key] == noise[key] else float("nan")
        pairs[key] = pair
        tolerance[key] = max(2 * pair, 0.01) if pair == pair else float("nan")
    a = records.get(f"{case}_a")
    for setting in ["a", "b", "noise", "reference"] + VARIANTS:
        r = records.get(f"{case}_{setting}")
        if r is None:
            continue
        diffs = {k: difference(r, k) for k, _, _ in QUANTITIES}
        finite = {k: d for k, d in diffs.items() if d == d}
        worst = max(finite, key=finite.get) if finite else None
        within = all(finite[k] <= tolerance[k] for k in finite if tolerance[k] == tolerance[k]) if finite else None
        if setting not in ("reference", "noise") and worst:  # noise and reference: not timed
            points.append((case, setting, r["per_second"], finite[worst]))
        cells = [(fmt.format(1000 * r[k]) if k == "bubble_diameter" else fmt.format(r[k])) for k, _, fmt in QUANTITIES]
        lines.append(f"| {setting} | {r['description']} | {r['steps']} | {r['mean_dt']:.2e} | {r['rejected']} | "
                     f"{r['krylov_per_step']:.0f} | " +
                     # the noise and reference runs share the cores with others: not timed
                     (f"{r['per_second']:.0f} | {(r['per_second'] / a['per_second']) if a else float('nan'):.2f} | "
                      if setting not in ("noise", "reference") else "(not timed) | | ") + " | ".join(cells) +
                     f" | {'' if worst is None or setting == 'reference' else f'{100 * finite[worst]:.1f}% ({worst})'} | "
                     f"{'' if setting == 'reference' or within is None else ('✓' if within else '✗')} |")
    lines.append("")
    lines.append("Noise yardstick (b against noise): " + ", ".join(
        f"{q[1]} {100 * pairs[q[0]]:.2g}%" for q in QUANTITIES if pairs[q[0]] == pairs[q[0]]) + ".")
    lines.append("")
lines += startup_lines()
if points:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    figure, axes = plt.subplots(1, len({p[0] for p in points}), figsize=(10, 4), squeeze=False)
    for axis, case in zip(axes[0], sorted({p[0] for p in points})):
        for c, setting, cost, error in points:
            if c == case:
                axis.loglog(cost, max(error, 1e-4), "o")
                axis.annotate(setting, (cost, max(error, 1e-4)))
        axis.set_xlabel("wall s per simulated s")
        axis.set_ylabel("largest relative difference from the reference")
        axis.set_title(case)
    figure.tight_layout()
    figure.savefig(os.path.join(root, "doc", "time_to_solution.png"), dpi=90)
    lines.append("![error against cost](time_to_solution.png)")
replace_doc_section(root, "time_to_solution", "Time to solution", lines)
