#!/usr/bin/env python3
"""Seed-000 liquid-loading sweep on prm/wet_column_2d.prm: delta = 0, 0.027, 0.055, 0.08,
0.1, 0.12, 0.138 x 1e-2 at U = 0.8 m/s. For each: completed or not, simulated time,
rejected steps, bounds, time-averaged FI after start-up (and its 0.5 s window range),
the dominant frequency of alpha_s averaged over the cell layer at 7.6 cm (the case's
`output/probe heights`), FGMRES iterations per step (the stiffness of mu_wet), cost; a
markdown table for doc/benchmarks.md and FI(t) in doc/liquid_loading_fi.png. The bubble
and stress-split columns of the issue need the analytics of issue 6 and are not
computed here yet.

usage: python3 benchmarks/liquid_loading_sweep.py [--end-time 5] [--start-up 1]
           [--loadings 0 0.027 ...] [--jobs 2] [--summarize-only]
(build first: bash scripts/build.sh). --jobs runs that many cases at once, one core each.
"""
import argparse
import os
import subprocess
import time

from benchmark_setup import read_case, repository_root, summarize_run, write_case

root = repository_root()
parser = argparse.ArgumentParser()
parser.add_argument("--end-time", type=float, default=5.0)
parser.add_argument("--start-up", type=float, default=1.0, help="seconds left out of the FI mean")
parser.add_argument("--loadings", nargs="+", type=float,
                    default=[0, 0.027, 0.055, 0.08, 0.1, 0.12, 0.138], help="delta in units of 1e-2")
parser.add_argument("--jobs", type=int, default=1)
parser.add_argument("--summarize-only", action="store_true")
parser.add_argument("--work", default=os.path.join(root, "build", "benchmarks", "liquid_loading_sweep"))
args = parser.parse_args()
os.makedirs(args.work, exist_ok=True)
base = read_case("wet_column_2d")


def case(loading):
    return write_case(args.work, f"delta_{loading:g}e-2", base, args.end_time,
                      f"\nsubsection wet particles\n  set liquid loading = {loading * 1e-2:.6g}\nend\n")


if not args.summarize_only:
    pending, running = list(args.loadings), []
    while pending or running:
        while pending and len(running) < args.jobs:
            prm, folder, log = case(pending.pop(0))
            running.append(subprocess.Popen([os.path.join(root, "build", "wetbed"), prm],
                                            stdout=open(log, "w"), stderr=subprocess.STDOUT))
        running = [p for p in running if p.poll() is None]
        time.sleep(1)

rows, series = [], {}
for loading in args.loadings:
    prm, folder, log = case(loading)
    summary, series[loading] = summarize_run(folder, log, args.start_up)
    rows.append(dict(summary, loading=loading))

print(f"| δ (10⁻²) | completed | simulated | rejected | α_s range | Θ range (m²/s²) | FI mean (t > {args.start_up:g} s) | 0.5 s windows | dominant frequency at 7.6 cm (Hz) | FGMRES its/step | s per simulated s |")
print("|---|---|---|---|---|---|---|---|---|---|---|")
for r in rows:
    print(f"| {r['loading']:g} | {'yes' if r['finished'] else 'no'} | {r['end']:.3f} s | {r['rejected']} | "
          f"[{r['alpha_min']:.1e}, {r['alpha_max']:.4f}] | [{r['theta_min']:.1e}, {r['theta_max']:.3g}] | "
          f"{r['mean_fi']:.3f} | {r['fi_min_window']:.3f}, {r['fi_max_window']:.3f} | {r['frequency']:.2f} | {r['krylov']:.1f} | {r['per_second']:.0f} |")

import matplotlib  # noqa: E402
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

fig, ax = plt.subplots(figsize=(8, 3.5))
for loading, (t, fi) in series.items():
    ax.plot(t, fi, lw=0.6, label=f"δ = {loading:g}·10⁻²")
ax.axhline(1.0, color="k", lw=0.8)
ax.set_xlabel("t (s)")
ax.set_ylabel("FI = ΔP A / (M g)")
ax.legend(fontsize=7, ncol=2)
ax.set_title("2D wet column (seed-000 small column), liquid loading sweep")
fig.tight_layout()
fig.savefig(os.path.join(root, "doc", "liquid_loading_fi.png"), dpi=110)
print("wrote doc/liquid_loading_fi.png")
