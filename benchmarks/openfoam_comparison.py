#!/usr/bin/env python3
"""Side by side with OpenFOAM: the tutorial multiphase/twoPhaseEulerFoam/RAS/fluidisedBed
of Debian's OpenFOAM v1912 (openfoam, openfoam-examples; installed by this script if
missing) against wetbed on the same physical set-up (prm/openfoam_fluidisedBed.prm), on
the same machine, one core each, for the same simulated time.

The tutorial is run as shipped except for what makes both codes solve the same problem:
isothermal at 300 K (its gas starts at 600 K; 0/T.* set to 300 K) with constant gas
density 1.16 kg/m^3 (rhoConst instead of perfectGas) and a laminar gas (its k-epsilon
gas turbulence has no counterpart in wetbed); no field averaging; fields written every
--write-interval s. wetbed runs the .prm on uniform meshes of --levels refinements
(12 x 80 cells at level 2).

For each run: wall time per simulated second, steps, and after --start-up the time
averages of the fluidization index FI = dP A / (V_s (rho_s - rho_g) |g|) (dP: mean
pressure over the inlet minus that over the outlet, net of the gas hydrostatic part; the
exact value of a fluidized bed without wall support is 1) and of the bed surface height
(the top of the highest of 200 horizontal slices whose mean alpha_s exceeds 0.1).
Errors: |FI - 1| and the bed-height difference against the finest wetbed run. Each run's
figures and FI(t) are stored in benchmarks/results/openfoam_comparison/<run>.json, from
which the 'openfoam_comparison' section of doc/benchmarks.md and
doc/openfoam_comparison.png are drawn.

usage: python3 benchmarks/openfoam_comparison.py [--end-time 2] [--start-up 0.5]
       [--levels 1 2 3] [--runs openfoam wetbed_1 ...] [--jobs 2] [--summarize-only]
       (build first: bash scripts/build.sh)
"""
import argparse
import glob
import json
import os
import re
import shutil
import subprocess
import time
from concurrent.futures import ThreadPoolExecutor

from benchmark_setup import bubble_diameter, replace_doc_section, repository_root, run_case, timer_seconds

root = repository_root()
parser = argparse.ArgumentParser()
parser.add_argument("--end-time", type=float, default=2.0)
parser.add_argument("--start-up", type=float, default=0.5)
parser.add_argument("--levels", type=int, nargs="+", default=[1, 2, 3], help="wetbed mesh refinements")
parser.add_argument("--runs", nargs="+", default=None, help="run only these (openfoam, wetbed_<level>)")
parser.add_argument("--write-interval", type=float, default=0.01, help="OpenFOAM field output (s): its FI samples")
parser.add_argument("--jobs", type=int, default=2, help="runs at the same time (one core each)")
parser.add_argument("--summarize-only", action="store_true", help="tabulate the stored results")
args = parser.parse_args()

work = os.path.join(root, "build", "benchmarks", "openfoam_comparison")
results = os.path.join(root, "benchmarks", "results", "openfoam_comparison")
os.makedirs(work, exist_ok=True)
os.makedirs(results, exist_ok=True)
TUTORIAL = "/usr/share/doc/openfoam-examples/examples/multiphase/twoPhaseEulerFoam/RAS/fluidisedBed"
FOAM_BASHRC = "/usr/share/openfoam/etc/bashrc"
WIDTH, HEIGHT, NX, NY = 0.15, 1.0, 30, 200  # the tutorial's blockMesh
RHO_S, RHO_G, G = 2500.0, 1.16, 9.81
SURFACE_FRACTION, SLICES = 0.1, 200  # as wetbed's bed monitors: bed_surface_height


def install_openfoam():
    if os.path.isdir(TUTORIAL) and shutil.which("twoPhaseEulerFoam"):
        return
    if os.geteuid() != 0:
        raise SystemExit("OpenFOAM is missing: run `apt-get install -y openfoam openfoam-examples` as root")
    subprocess.run(["apt-get", "update"], check=True)
    subprocess.run(["apt-get", "install", "-y", "openfoam", "openfoam-examples"], check=True,
                   env=dict(os.environ, DEBIAN_FRONTEND="noninteractive"))


def edit(path, old, new, count=1):
    text = open(path).read()
    if len(re.findall(old, text)) < 1:
        raise SystemExit(f"{path}: '{old}' not found (a different OpenFOAM tutorial version?)")
    open(path, "w").write(re.sub(old, new, text, count=count))


def openfoam_case():
    """A copy of the tutorial made isothermal (300 K, constant gas density), laminar gas,
    end time and output interval set, without the field averaging."""
    case = os.path.join(work, "openfoam")
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(TUTORIAL, case)
    for phase in ("air", "particles"):  # the initial fields before setFields
        os.remove(os.path.join(case, "0", f"alpha.{phase}.gz"))
        shutil.copy(os.path.join(case, "0", f"alpha.{phase}.orig"), os.path.join(case, "0", f"alpha.{phase}"))
        edit(os.path.join(case, "0", f"T.{phase}"), r"internalField\s+uniform 600;", "internalField       uniform 300;")
    edit(os.path.join(case, "constant", "thermophysicalProperties.air"), r"equationOfState perfectGas;",
         "equationOfState rhoConst;")
    edit(os.path.join(case, "constant", "thermophysicalProperties.air"), r"(molWeight\s+28.9;\s*\})",
         r"\1\n    equationOfState\n    {\n        rho         %g;\n    }" % RHO_G)
    edit(os.path.join(case, "constant", "turbulenceProperties.air"), r"simulationType\s+RAS;", "simulationType  laminar;")
    control = os.path.join(case, "system", "controlDict")
    edit(control, r"endTime\s+[\d.]+;", f"endTime         {args.end_time:g};")
    edit(control, r"writeInterval\s+[\d.]+;", f"writeInterval   {args.write_interval:g};")
    text = open(control).read()
    open(control, "w").write(text[:text.index("functions")] + "\n")
    return case


def run_openfoam():
    install_openfoam()
    case = openfoam_case()
    script = (f". {FOAM_BASHRC} >/dev/null 2>&1; cd {case} && blockMesh > log.blockMesh 2>&1 && "
              "setFields > log.setFields 2>&1 && twoPhaseEulerFoam > log.twoPhaseEulerFoam 2>&1")
    begin = time.time()
    code = subprocess.run(["bash", "-c", script]).returncode
    wall = time.time() - begin
    if code != 0:
        raise SystemExit(f"OpenFOAM failed (exit {code}): see {case}/log.*")
    log = open(os.path.join(case, "log.twoPhaseEulerFoam")).read()
    steps = len(re.findall(r"^Time = ", log, flags=re.M))
    series = [openfoam_sample(case, d) for d in sorted(time_folders(case), key=float)]
    store("openfoam", {"code": "OpenFOAM v1912 twoPhaseEulerFoam", "cells": NX * NY, "steps": steps,
                       "rejected": 0, "wall": wall, "end": series[-1][0],
                       "execution_s": float(re.findall(r"ExecutionTime = ([\d.e+-]+) s", log)[-1])}, series)


def time_folders(case):
    return [os.path.basename(d) for d in glob.glob(os.path.join(case, "[0-9]*")) if float(os.path.basename(d)) > 0]


def foam_values(text):
    """The numbers of an OpenFOAM scalar entry 'uniform X' or 'nonuniform List<scalar> N(...)'."""
    uniform = re.match(r"\s*uniform\s+([^;\s]+)", text)
    if uniform:
        return [float(uniform.group(1))]
    listed = re.match(r"\s*nonuniform\s+List<scalar>\s*(\d+)\s*\(([^)]*)\)", text)
    values = [float(v) for v in listed.group(2).split()]
    assert len(values) == int(listed.group(1))
    return values


def foam_field(case, folder, name):
    """(cell values, {patch: face values}) of an ascii volScalarField."""
    text = open(os.path.join(case, folder, name)).read()
    internal = foam_values(text.split("internalField", 1)[1])
    patches = {}
    for patch in ("inlet", "outlet"):
        block = re.search(patch + r"\s*\{(.*?)\}", text.split("boundaryField", 1)[1], flags=re.S).group(1)
        value = re.search(r"\bvalue\s+(.*)", block, flags=re.S)
        patches[patch] = foam_values(value.group(1)) if value else None
    return internal, patches


def openfoam_sample(case, folder):
    """(t, FI, bed surface height) of one written time of the OpenFOAM run."""
    alpha, _ = foam_field(case, folder, "alpha.particles")
    _, p = foam_field(case, folder, "p")
    solids_per_area = sum(alpha) / (NX * NY) * HEIGHT
    drop = sum(p["inlet"]) / len(p["inlet"]) - sum(p["outlet"]) / len(p["outlet"]) - RHO_G * G * HEIGHT
    rows = [sum(alpha[j * NX:(j + 1) * NX]) / NX for j in range(NY)]
    surface = max([(j + 1) * HEIGHT / NY for j in range(NY) if rows[j] > SURFACE_FRACTION], default=0.0)
    assert NY == SLICES
    return float(folder), drop / (solids_per_area * (RHO_S - RHO_G) * G), surface


def run_wetbed(level):
    name = f"wetbed_{level}"
    sections = (f"\nsubsection mesh\n  set initial refinement = {level}\nend\n"
                "subsection checkpoint\n  set interval = 400\nend\n")
    summary, rows, wall, log = run_case(root, work, name, "openfoam_fluidisedBed", args.end_time, sections,
                                        args.start_up)
    text = open(log).read()
    series = [(float(r["time"]), float(r["fluidization_index"]), float(r["bed_surface_height"])) for r in rows[1:]]
    store(name, {"code": "wetbed", "cells": int(rows[-1]["active_cells"]), "steps": summary["steps"],
                 "rejected": summary["rejected"], "wall": wall, "end": summary["end"],
                 "krylov_per_step": summary["krylov"], "frequency": summary["frequency"],
                 "bubble_diameter": bubble_diameter(os.path.dirname(log) + "/" + name, args.start_up),
                 "alpha_range": [summary["alpha_min"], summary["alpha_max"]],
                 "timers": {k: timer_seconds(text, k) for k in ("Krylov solve", "flow assembly", "preconditioner setup",
                                                              "alpha transport", "solids pressure correction",
                                                              "granular temperature", "monitors")}}, series)


def store(name, record, series):
    """Time averages after the start-up (step-weighted for wetbed, the written times for
    OpenFOAM), the series thinned to 2,000 points, into results/NAME.json."""
    t = [s[0] for s in series]
    weights = [t[i] - (t[i - 1] if i else 0.0) for i in range(len(t))]
    after = [i for i in range(len(t)) if t[i] > args.start_up]
    total = sum(weights[i] for i in after)
    record["mean_fi"] = sum(series[i][1] * weights[i] for i in after) / total
    record["mean_surface"] = sum(series[i][2] * weights[i] for i in after) / total
    record["per_second"] = record["wall"] / record["end"]
    record["start_up"], record["end_time"] = args.start_up, args.end_time
    stride = max(1, len(series) // 2000)
    record["series"] = [[round(v, 5) for v in s] for s in series[::stride]]
    with open(os.path.join(results, name + ".json.part"), "w") as f:
        json.dump(record, f, separators=(",", ":"))
    os.replace(os.path.join(results, name + ".json.part"), os.path.join(results, name + ".json"))
    print(f"{name}: {record['per_second']:.0f} s per simulated s, FI {record['mean_fi']:.4f}, "
          f"surface {record['mean_surface']:.4f} m")


def run(name):
    run_openfoam() if name == "openfoam" else run_wetbed(int(name.split("_")[1]))
    return name


if not args.summarize_only:
    names = args.runs or ["openfoam"] + [f"wetbed_{level}" for level in sorted(args.levels, reverse=True)]
    with ThreadPoolExecutor(args.jobs) as pool:
        for finished in pool.map(run, names):
            print("finished", finished)

records = {os.path.basename(p)[:-5]: json.load(open(p)) for p in sorted(glob.glob(os.path.join(results, "*.json")))}
ours = sorted((int(n.split("_")[1]), n) for n in records if n.startswith("wetbed_"))
finest = records[ours[-1][1]] if ours else None
order = (["openfoam"] if "openfoam" in records else []) + [n for _, n in ours]
for name in order:
    r = records[name]
    r["fi_error"] = abs(r["mean_fi"] - 1)
    r["surface_error"] = abs(r["mean_surface"] / finest["mean_surface"] - 1) if finest else float("nan")
first = records[order[0]] if order else {}
lines = [f"Command: `python3 benchmarks/openfoam_comparison.py --end-time {first.get('end_time', args.end_time):g} "
         f"--start-up {first.get('start_up', args.start_up):g} --levels {' '.join(str(l) for l, _ in ours)}` "
         "(every run serial, two at a time on this 2-core machine). OpenFOAM: the tutorial's 30 × 200 cells and fixed "
         "Δt = 2·10⁻⁴ s, isothermal 300 K, constant gas density, laminar gas; wetbed: prm/openfoam_fluidisedBed.prm "
         "(Q2/Q1, BDF2, CFL 0.5 adaptive Δt ≤ 10⁻³ s). Means after the start-up; FI error against the exact 1, "
         f"bed-surface error against the finest wetbed run ({ours[-1][1] if ours else '-'}).", "",
         "| run | cells | steps | wall s | s per simulated s | FI mean | FI error | bed surface (m) | surface error vs finest |",
         "|" + "---|" * 9]
for name in order:
    r = records[name]
    lines.append(f"| {name} | {r['cells']} | {r['steps']} | {r['wall']:.0f} | {r['per_second']:.0f} | {r['mean_fi']:.4f} | "
                 f"{100 * r['fi_error']:.2f}% | {r['mean_surface']:.4f} | {100 * r['surface_error']:.2f}% |")
if "openfoam" in records and ours:
    of = records["openfoam"]
    matching = [n for _, n in ours if records[n]["fi_error"] <= of["fi_error"]]
    lines.append("")
    if matching:
        best = min(matching, key=lambda n: records[n]["per_second"])
        lines.append(f"Cheapest wetbed run at least as close to FI = 1 as OpenFOAM ({100 * of['fi_error']:.2f}%): {best}, "
                     f"{records[best]['per_second']:.0f} s per simulated s = {records[best]['per_second'] / of['per_second']:.2f}× "
                     "OpenFOAM's wall time (goal: below 1/3).")
    else:
        lines.append(f"No wetbed run is as close to FI = 1 as OpenFOAM ({100 * of['fi_error']:.2f}%).")
    for _, n in ours:
        timers = records[n].get("timers", {})
        lines.append(f"- {n}: {records[n]['per_second'] / of['per_second']:.2f}× OpenFOAM per simulated second; "
                     f"{records[n]['krylov_per_step']:.0f} FGMRES iterations per step; time split " +
                     ", ".join(f"{k} {v:.0f} s" for k, v in timers.items() if v == v) + ".")
lines += ["", "![FI and cost](openfoam_comparison.png)"]

import matplotlib  # noqa: E402
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4))
for i, name in enumerate(order):
    t, fi, _ = zip(*records[name]["series"])
    left.plot(t, fi, lw=0.8, color=f"C{i}", label=f"{name} ({records[name]['cells']} cells)")
    right.plot(records[name]["per_second"], max(100 * records[name]["fi_error"], 1e-3), "o", color=f"C{i}",
               label=f"{name}: |FI - 1|")
    if records[name]["surface_error"] > 0:
        right.plot(records[name]["per_second"], 100 * records[name]["surface_error"], "s", mfc="none", color=f"C{i}",
                   label=f"{name}: bed surface vs finest")
left.axhline(1, color="k", lw=0.5)
left.set_xlabel("t (s)")
left.set_ylabel("FI")
left.legend(fontsize=7)
left.set_title("fluidization index")
right.set_xscale("log")
right.set_yscale("log")
right.set_xlabel("wall s per simulated s (one core)")
right.set_ylabel("error (%)")
right.legend(fontsize=7)
right.set_title("error against cost")
fig.tight_layout()
fig.savefig(os.path.join(root, "doc", "openfoam_comparison.png"), dpi=110)
for name in order:
    print(name, {k: records[name][k] for k in ("cells", "per_second", "mean_fi", "fi_error", "mean_surface", "surface_error")})
replace_doc_section(root, "openfoam_comparison", "Side by side with OpenFOAM's twoPhaseEulerFoam (fluidisedBed tutorial)", lines)
