#!/usr/bin/env python3
"""Bed and bubble analytics of the dry 2D bubbling bed (prm/bubbling_bed_2d.prm) over a
long run: time-averaged FI and bed height, mean bubble diameter and count, bubble
frequency through the 7.6 cm plane, splitting and coalescence events per second, the
dominant frequencies of the plane-averaged solid fraction and of the pressure drop, and
the cost of the analysis as a fraction of the run time (timer sections `bubble
analysis` and `monitors`). Writes doc/bubbles_*.png and its section of
doc/benchmarks.md, and prints the figures.

usage: python3 benchmarks/bubble_analytics.py [--end-time 5] [--start 1]
           [--folder RUN --log LOG]   (summarize an earlier run instead of running)
(build first: bash scripts/build.sh)
"""
import argparse
import os
import re
import shutil
import subprocess
import sys

from benchmark_setup import read_case, replace_doc_section, repository_root, write_case

root = repository_root()
sys.path.insert(0, os.path.join(root, "scripts"))
import plot_run  # noqa: E402

parser = argparse.ArgumentParser()
parser.add_argument("--end-time", type=float, default=5.0)
parser.add_argument("--start", type=float, default=1.0, help="seconds of start-up left out")
parser.add_argument("--folder", help="an earlier run folder to summarize")
parser.add_argument("--log", help="its screen log (timer breakdown)")
parser.add_argument("--work", default=os.path.join(root, "build", "benchmarks", "bubble_analytics"))
args = parser.parse_args()

if args.folder:
    folder, log = args.folder, args.log
else:
    os.makedirs(args.work, exist_ok=True)
    prm, folder, log = write_case(args.work, "bubbling_bed_2d", read_case("bubbling_bed_2d"), args.end_time)
    with open(log, "w") as out:
        subprocess.run([os.path.join(root, "build", "wetbed"), prm, "--overwrite"], stdout=out, stderr=subprocess.STDOUT, check=True)

text = open(log).read() if log and os.path.exists(log) else ""


def section(name):
    """Wall seconds of a timer section (max over ranks), 0 if absent."""
    m = re.search(r"\| " + re.escape(name) + r"\s*\|\s*(\d+)\s*\|\s*[\d.e+-]+s\s+\d+\s*\|\s*[\d.e+-]+s\s*\|\s*([\d.e+-]+)s", text)
    return (float(m.group(2)), int(m.group(1))) if m else (0.0, 0)


total = re.search(r"Total wallclock time elapsed\s*\|\s*([\d.e+-]+)s", text)
total = float(total.group(1)) if total else float("nan")
bubble_time, analyses = section("bubble analysis")
monitor_time, monitor_calls = section("monitors")
finished = re.search(r"Finished: (\d+) steps \((\d+) rejected\), wall ([\d.e+-]+) s, ([\d.e+-]+) s per simulated second", text)

stats, written = plot_run.plot(folder, os.path.join(folder, "plots"), args.start, None)
for name in ("fluidization", "bubble_sizes", "bubble_count", "spectrum"):
    if name + ".png" in written:
        shutil.copy(os.path.join(folder, "plots", name + ".png"), os.path.join(root, "doc", f"bubbles_{name}.png"))

figures = {k: v for k, v in stats.items() if k != "bubble_diameters"}
for k, v in figures.items():
    print(f"{k}: {v}")
print(f"bubble analysis: {bubble_time:.2f} s in {analyses} analyses, monitors {monitor_time:.2f} s, run {total:.0f} s")

g = lambda key, fmt="{:.4g}": fmt.format(stats[key]) if key in stats else "n/a"  # noqa: E731
lines = [
    f"Command: `python3 benchmarks/bubble_analytics.py --end-time {stats['end_time']:g}` (default case: KTGF, Θ PDE,",
    "Johnson–Jackson walls, 10 × 60 cells, serial; bubbles analysed every 5 steps with a",
    "4 mm minimum diameter; statistics from t = " + f"{args.start:g} s; run it alone on the machine: its",
    "wall time is in the table).",
    "",
    "| quantity | value |",
    "|---|---|",
    f"| simulated time | {stats['end_time']:.3f} s |",
    f"| steps (rejected) | {finished.group(1) + ' (' + finished.group(2) + ')' if finished else 'n/a'} |",
    f"| time-averaged FI | {g('fluidization_index')} |",
    f"| time-averaged bed height (95% of the solids below) | {g('bed_height', '{:.4f}')} m |",
    f"| mean bubble equivalent diameter | {1000 * stats.get('mean_bubble_diameter', float('nan')):.1f} mm |",
    f"| mean bubble count | {g('bubble_count', '{:.2f}')} |",
    f"| bubble frequency (tracks born below {stats['plane']:g} m that reach into it) | {g('bubble_frequency', '{:.2f}')} /s |",
    f"| tracks whose centroid rises through {stats['plane']:g} m | {g('centroid_crossings_per_second', '{:.2f}')} /s |",
    f"| splittings per second | {g('splittings_per_second', '{:.2f}')} |",
    f"| coalescences per second | {g('coalescences_per_second', '{:.2f}')} |",
    f"| dominant frequency of α_s at {stats['plane']:g} m | {g('dominant_frequency_alpha_s_plane_' + format(stats['plane'], 'g'), '{:.2f}')} Hz |",
    f"| dominant frequency of ΔP | {g('dominant_frequency_pressure_drop', '{:.2f}')} Hz |",
    f"| run wall time | {total:.0f} s |",
    f"| bubble analysis ({analyses} analyses) | {bubble_time:.2f} s = {100 * bubble_time / total:.3f}% of the run |",
    f"| monitors incl. bed profile and planes ({monitor_calls} evaluations) | {monitor_time:.2f} s = {100 * monitor_time / total:.2f}% of the run |",
    "",
    "![FI and pressure drop](bubbles_fluidization.png)",
    "![bubble sizes](bubbles_bubble_sizes.png) ![bubble count and events](bubbles_bubble_count.png)",
    "![spectra](bubbles_spectrum.png)",
]
replace_doc_section(root, "bubble_analytics", "Bed and bubble analytics of the 2D bubbling bed", lines)
