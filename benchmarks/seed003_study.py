#!/usr/bin/env python3
"""Seed 003's bed, dry against wet at 2 and 3 U_mf (issue 50 item 5): prm/seed003_bed_2d.prm
run serially to --end-time (20 s, as the seed), averaged over the last half, for

  dry, U = 0.26 m/s (2 U_mf)   wet, U = 0.26 m/s   dry, U = 0.39 m/s   wet, U = 0.39 m/s

The wet arm is the seed's: the Gollwitzer restitution e_wet(St) (seed 003 Eq. 26) with a
film of 0.1 d; the seed's DEM has no liquid-bridge forces, so here neither: the wet
viscosity is capped at 1e-12 Pa s (the parameter must be > 0; the gas has 1.8e-5) and
P_wet stays out of the solids pressure. The seed gives no
liquid: water (1000 kg/m^3, 1e-3 Pa s). The liquid loading only switches the wet scene
on (the Gollwitzer law reads the film thickness): the film's mass, 0.81 of the solids'.

Prints and (--write-doc) puts into doc/examples.md ("seed003_study") the cost of each
run and, per height of the lateral profiles, the mean |wet - dry| of the time-averaged
alpha_s, vertical solids velocity and Theta across the bed, against the dry profile's
own range; draws the profiles to doc/images/seed003_profiles.png. Runs are resumable:
a second call continues them (checkpoints every 5 min of wall time).

usage: python3 benchmarks/seed003_study.py [--end-time 20] [--only NAME ...] [--write-doc]
"""
import argparse
import math
import os
import sys

from benchmark_setup import read_case, replace_doc_section, repository_root, run_resumable

root = repository_root()
sys.path.insert(0, os.path.join(root, "scripts"))
import wetbed_results  # noqa: E402

parser = argparse.ArgumentParser()
parser.add_argument("--end-time", type=float, default=20.0)
parser.add_argument("--only", nargs="*")
parser.add_argument("--write-doc", action="store_true")
args = parser.parse_args()
work = os.path.join(root, "build", "benchmarks", "seed003")
os.makedirs(work, exist_ok=True)
WET = ("subsection wet particles\n set liquid loading = 0.81\n set restitution = Gollwitzer\n"
       " set film thickness = 0.1\n set liquid density = 1000\n set liquid viscosity = 1e-3\n"
       " set maximum wet viscosity = 1e-12\n set wet pressure in solids pressure = false\nend\n")
cases = [("dry_2umf", 0.26, ""), ("wet_2umf", 0.26, WET), ("dry_3umf", 0.39, ""), ("wet_3umf", 0.39, WET)]
base = read_case("seed003_bed_2d")
start = args.end_time / 2
walls = {}
for name, U, extra in cases:
    if args.only and name not in args.only:
        continue
    folder = os.path.join(work, name)
    prm = os.path.join(work, name + ".prm")
    open(prm, "w").write(base + extra + f"\nsubsection boundary conditions\n set inlet superficial velocity = {U}\nend\n"
                         # the four arms with one scheme: a fixed two outer iterations
                         f"subsection time stepping\n set end time = {args.end_time}\n set outer tolerance = 0\n"
                         " set outer iterations = 2\nend\n"
                         f"subsection statistics\n set start time = {start}\nend\n"
                         f"subsection output\n set folder = {folder}\n set field interval = 0.5\nend\n"
                         "subsection checkpoint\n set wall time interval = 300\nend\n")
    log = os.path.join(work, name + ".log")
    code, wall = run_resumable([os.path.join(root, "build", "wetbed"), prm], folder, log,
                               os.path.join(work, name + ".wall"))
    walls[name] = (code, wall)
    print(f"{name}: exit {code}, wall {wall:.0f} s", flush=True)


def profile(name, height):
    block = wetbed_results.profile(os.path.join(work, name), f"lateral_at_{height:g}m")
    return block.columns if block is not None else None


heights = (0.01, 0.02, 0.03)
lines = [f"Command: `python3 benchmarks/seed003_study.py --end-time {args.end_time:g} --write-doc` (serial; "
         f"averages over [{start:g}, {args.end_time:g}] s).", "",
         "| run | U (m/s) | wall s | s per simulated s |", "|---|---|---|---|"]
for name, U, _ in cases:
    code, wall = walls.get(name, (None, float("nan")))
    lines.append(f"| {name} | {U} | {wall:.0f} | {wall / args.end_time:.0f} |")
lines += ["", "Mean |wet - dry| across the bed of the time-averaged profile, and (in brackets) the "
          "dry profile's own range across the bed:", "",
          "| U | height | alpha_s | u_s,y (m/s) | Theta (m^2/s^2) |", "|---|---|---|---|---|"]
curves = {}
for U, pair in ((0.26, ("dry_2umf", "wet_2umf")), (0.39, ("dry_3umf", "wet_3umf"))):
    for h in heights:
        dry, wet = profile(pair[0], h), profile(pair[1], h)
        if dry is None or wet is None:
            continue
        curves[(U, h)] = (dry, wet)
        row = [f"| {U} | {h:g} m"]
        for key in ("alpha_s_mean", "u_s_y_mean", "theta_mean"):
            pairs = [(d, w) for d, w in zip(dry[key], wet[key]) if not (math.isnan(d) or math.isnan(w))]
            difference = sum(abs(w - d) for d, w in pairs) / max(len(pairs), 1)
            spread = max(d for d, _ in pairs) - min(d for d, _ in pairs) if pairs else float("nan")
            row.append(f"{difference:.3g} ({spread:.3g})")
        lines.append(" | ".join(row) + " |")
print("\n".join(lines))
if curves:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    figure, axes = plt.subplots(2, 3, figsize=(11, 6), sharex=True)
    for r, U in enumerate((0.26, 0.39)):
        for c, (key, label) in enumerate((("alpha_s_mean", "alpha_s"), ("u_s_y_mean", "u_s,y (m/s)"),
                                          ("theta_mean", "Theta (m^2/s^2)"))):
            ax = axes[r][c]
            for h in heights:
                if (U, h) in curves:
                    dry, wet = curves[(U, h)]
                    line, = ax.plot(dry["position"], dry[key], label=f"dry {h:g} m")
                    ax.plot(wet["position"], wet[key], "--", color=line.get_color(), label=f"wet {h:g} m")
            ax.set_title(f"{label}, U = {U} m/s", fontsize=9)
            if r == 1:
                ax.set_xlabel("x (m)")
    axes[0][0].legend(fontsize=7)
    figure.tight_layout()
    picture = os.path.join(root, "doc", "images", "seed003_profiles.png")
    figure.savefig(picture, dpi=90)
    lines += ["", "![seed 003 profiles](images/seed003_profiles.png)"]
    print("wrote", picture)
if args.write_doc:
    replace_doc_section(root, "seed003_study", "Seed 003: dry and wet at 2 and 3 U_mf", lines, doc_name="examples.md")
