#!/usr/bin/env python3
"""The dry bubbling bed (prm/bubbling_bed_2d.prm, kinetic theory, Johnson-Jackson walls)
over a long run with the granular temperature PDE and the algebraic model: time-averaged
fluidization index after start-up, bounds of alpha_s and Theta at every step, rejected
steps, mass drift, cost per simulated second and FGMRES iterations. Prints a markdown
table for doc/benchmarks.md and draws doc/bubbling_bed_fi.png.

usage: python3 benchmarks/bubbling_bed_fi.py [--end-time 5] [--start-up 1]
           [--models PDE algebraic] [--parallel] [--summarize-only]
(build first: bash scripts/build.sh). --parallel runs the models at the same time, one
core each; --summarize-only re-reads the monitors of an earlier run. Started again, an
unfinished run continues from its checkpoint (every 500 steps and on SIGTERM) and a
finished one is left alone; the wall time sums over the pieces (WORK/MODEL.wall).
"""
import argparse
import concurrent.futures
import os

from benchmark_setup import read_case, repository_root, run_resumable, summarize_run, write_case

root = repository_root()
parser = argparse.ArgumentParser()
parser.add_argument("--end-time", type=float, default=5.0)
parser.add_argument("--start-up", type=float, default=1.0, help="seconds left out of the FI mean")
parser.add_argument("--models", nargs="+", default=["PDE", "algebraic"])
parser.add_argument("--parallel", action="store_true")
parser.add_argument("--summarize-only", action="store_true")
parser.add_argument("--work", default=os.path.join(root, "build", "benchmarks", "bubbling_bed_fi"))
args = parser.parse_args()
os.makedirs(args.work, exist_ok=True)

base = read_case("bubbling_bed_2d")


def case(model):
    return write_case(args.work, model, base, args.end_time,
                      f"\nsubsection kinetic theory\n  set granular temperature = {model}\nend\n"
                      "subsection checkpoint\n  set interval = 500\n  set at end = false\nend\n")


def run(model):
    prm, folder, log = case(model)
    code, wall = run_resumable([os.path.join(root, "build", "wetbed"), prm], folder, log,
                               os.path.join(args.work, model + ".wall"))
    print(f"{model}: exit {code}, {wall:.0f} s", flush=True)


if not args.summarize_only:
    with concurrent.futures.ThreadPoolExecutor(len(args.models) if args.parallel else 1) as pool:
        list(pool.map(run, args.models))

rows, series = [], {}
for model in args.models:
    prm, folder, log = case(model)
    wall_file = os.path.join(args.work, model + ".wall")
    summary, series[model] = summarize_run(
        folder, log, args.start_up, float(open(wall_file).read()) if os.path.exists(wall_file) else None)
    rows.append(dict(summary, model=model))

print(f"| model | simulated | FI mean (t > {args.start_up:g} s) | 0.5 s windows (min, max) | steps | rejected | alpha_s range | Theta range (m²/s²) | mass drift | FGMRES its/step | wall (s) | s per simulated s |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|")
for r in rows:
    print(f"| {r['model']} | {r['end']:.2f} s | {r['mean_fi']:.4f} | {r['fi_min_window']:.3f}, {r['fi_max_window']:.3f} | {r['steps']} | {r['rejected']} | "
          f"[{r['alpha_min']:.1e}, {r['alpha_max']:.4f}] | [{r['theta_min']:.1e}, {r['theta_max']:.3g}] | {r['drift']:.1e} | {r['krylov']:.1f} | {r['wall']:.0f} | {r['per_second']:.0f} |")

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

fig, ax = plt.subplots(figsize=(8, 3.5))
for model, (t, fi) in series.items():
    ax.plot(t, fi, lw=0.6, label=f"{model}")
ax.axhline(1.0, color="k", lw=0.8)
ax.axvline(args.start_up, color="gray", ls="--", lw=0.8)
ax.set_xlabel("t (s)")
ax.set_ylabel("FI = ΔP A / (M g)")
ax.set_ylim(0, 2.5)
ax.legend()
ax.set_title("2D bubbling bed, kinetic theory + Johnson–Jackson walls")
fig.tight_layout()
fig.savefig(os.path.join(root, "doc", "bubbling_bed_fi.png"), dpi=110)
print("wrote doc/bubbling_bed_fi.png")
