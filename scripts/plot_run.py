#!/usr/bin/env python3
"""Turns a wetbed run folder into PNG plots and prints its bed and bubble statistics.

usage: scripts/plot_run.py RUN_FOLDER [--start T] [--out FOLDER] [--plane H]

Reads monitors.csv, bubbles.csv, bubble_summary.csv, bubble_events.csv and spectrum.csv
(those present; scripts/wetbed_results.py reads them) and writes into OUT (default
RUN_FOLDER/plots):
  fluidization.png   FI and pressure drop vs time
  bed_height.png     bed height (95% of the solids below) and plane-averaged alpha_s
  bubble_sizes.png   distribution of bubble equivalent diameters after T
  bubble_count.png   bubble count and cumulative splitting/coalescence events vs time
  spectrum.png       power spectra of the pressure drop and the plane alpha_s
Statistics from T on (default 1 s, the start-up left out): time-averaged FI, bed
height, mean bubble diameter, bubble count, bubble frequency (tracks that appear wholly
below the plane at height H and later reach into it, per second, as a measurement plane
sees bubbles; default H: the first probe plane, else 0.076 m), the tracks whose centroid
rises through H per second, splitting and coalescence events per second, dominant
frequencies.
Uses Debian's python3-matplotlib (re-executes under /usr/bin/python3 if needed)."""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from wetbed_results import bubbles, ensure_modules, monitors, spectrum  # noqa: E402


def time_average(t, y, start):
    """Trapezoidal time average of y over t >= start."""
    pairs = [(a, b) for a, b in zip(t, y) if a >= start and not math.isnan(b)]
    if len(pairs) < 2:
        return math.nan
    area = sum(0.5 * (pairs[i + 1][1] + pairs[i][1]) * (pairs[i + 1][0] - pairs[i][0]) for i in range(len(pairs) - 1))
    return area / (pairs[-1][0] - pairs[0][0])


def statistics(folder, start=1.0, plane=None):
    """The bed and bubble statistics of a run folder from `start` on, as a dict."""
    m = monitors(folder)
    if m is None:
        raise SystemExit(f"plot_run: no monitors.csv in {folder}")
    t = m["time"]
    s = {"end_time": t[-1], "start": start}
    s["fluidization_index"] = time_average(t, m["fluidization_index"], start)
    s["pressure_drop"] = time_average(t, m["pressure_drop"], start)
    s["bed_height"] = time_average(t, m["bed_height"], start)
    planes = [n for n in m if n.startswith("alpha_s_plane_")]
    if plane is None:
        plane = float(planes[0][len("alpha_s_plane_"):]) if planes else 0.076
    s["plane"] = plane
    found = bubbles(folder)
    b, summary = found["bubbles"], found["summary"]
    if summary is not None and summary["time"]:
        window = [i for i, x in enumerate(summary["time"]) if x >= start]
        duration = summary["time"][-1] - start if window else math.nan
        s["analyses"] = len(window)
        s["bubble_count"] = sum(summary["bubbles"][i] for i in window) / max(len(window), 1)
        if window and duration > 0:
            first = window[0] - 1 if window[0] > 0 else window[0]
            s["splittings_per_second"] = (summary["splittings"][-1] - summary["splittings"][first]) / duration
            s["coalescences_per_second"] = (summary["coalescences"][-1] - summary["coalescences"][first]) / duration
    if b is not None and b["time"]:
        vertical = "centroid_z" if any(abs(z) > 0 for z in b["centroid_z"]) else "centroid_y"
        diameters = [d for d, x in zip(b["equivalent_diameter"], b["time"]) if x >= start]
        s["mean_bubble_diameter"] = sum(diameters) / len(diameters) if diameters else math.nan
        s["bubble_diameters"] = diameters
        # bubble frequency: tracks that appear wholly below the plane and later reach
        # into it (as a measurement plane sees them), per second; and tracks whose
        # centroid rises through the plane (fewer: a bubble reaching the surface joins
        # the freeboard, a split starts new tracks)
        axis = vertical[-1]
        last, born_below, counted = {}, set(), set()
        crossings = 0
        for x, track, height, low, high in zip(b["time"], b["track"], b[vertical], b["lower_" + axis], b["upper_" + axis]):
            if track not in last and high < plane:
                born_below.add(track)
            if track in born_below and track not in counted and low < plane < high and x >= start:
                counted.add(track)
            if track in last and x >= start and last[track] < plane <= height:
                crossings += 1
            last[track] = height
        if summary is not None and summary["time"][-1] > start:
            s["bubble_frequency"] = len(counted) / (summary["time"][-1] - start)
            s["centroid_crossings_per_second"] = crossings / (summary["time"][-1] - start)
    found = spectrum(folder)
    for name, frequency in (found["dominant"] if found is not None else {}).items():
        s["dominant_frequency_" + name] = frequency
    return s


def plot(folder, out, start, plane):
    ensure_modules("matplotlib")
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    m = monitors(folder)
    if m is None:
        raise SystemExit(f"plot_run: no monitors.csv in {folder}")
    os.makedirs(out, exist_ok=True)
    t = m["time"]
    written = []

    fig, ax = plt.subplots(2, 1, figsize=(8, 6), sharex=True)
    ax[0].plot(t, m["fluidization_index"], lw=0.8)
    ax[0].axhline(1.0, color="k", ls="--", lw=0.8)
    ax[0].set_ylabel("fluidization index")
    ax[1].plot(t, m["pressure_drop"], lw=0.8, color="C1")
    ax[1].set_ylabel("pressure drop (Pa)")
    ax[1].set_xlabel("time (s)")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "fluidization.png"), dpi=110)
    written.append("fluidization.png")
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(8, 4))
    ax.plot(t, m["bed_height"], lw=0.8, label="bed height (95% of the solids below), m")
    for name in [n for n in m if n.startswith("alpha_s_plane_")]:
        ax.plot(t, m[name], lw=0.8, label=f"alpha_s at {name[len('alpha_s_plane_'):]} m")
    ax.set_xlabel("time (s)")
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(out, "bed_height.png"), dpi=110)
    written.append("bed_height.png")
    plt.close(fig)

    s = statistics(folder, start, plane)
    if s.get("bubble_diameters"):
        fig, ax = plt.subplots(figsize=(6, 4))
        ax.hist([1000 * d for d in s["bubble_diameters"]], bins=30)
        ax.set_xlabel("equivalent diameter (mm)")
        ax.set_ylabel(f"bubbles x analyses (t >= {start} s)")
        fig.tight_layout()
        fig.savefig(os.path.join(out, "bubble_sizes.png"), dpi=110)
        written.append("bubble_sizes.png")
        plt.close(fig)
    summary = bubbles(folder)["summary"]
    if summary is not None and summary["time"]:
        fig, ax = plt.subplots(2, 1, figsize=(8, 6), sharex=True)
        ax[0].plot(summary["time"], summary["bubbles"], lw=0.8)
        ax[0].set_ylabel("bubbles")
        ax[1].plot(summary["time"], summary["splittings"], label="splittings")
        ax[1].plot(summary["time"], summary["coalescences"], label="coalescences")
        ax[1].set_ylabel("events (cumulative)")
        ax[1].set_xlabel("time (s)")
        ax[1].legend()
        fig.tight_layout()
        fig.savefig(os.path.join(out, "bubble_count.png"), dpi=110)
        written.append("bubble_count.png")
        plt.close(fig)
    found = spectrum(folder)
    if found is not None:
        psd = found["columns"]
        fig, ax = plt.subplots(figsize=(7, 4))
        for name in [n for n in psd if n.startswith("psd_")]:
            values = psd[name]
            peak = max(values[1:])
            ax.semilogy(psd["frequency"][1:], [v / peak for v in values[1:]], lw=0.8, label=name[4:])
        ax.set_xlim(0, 20)
        ax.set_ylim(1e-4, 2)
        ax.set_xlabel("frequency (Hz)")
        ax.set_ylabel("power spectral density / peak")
        ax.legend()
        fig.tight_layout()
        fig.savefig(os.path.join(out, "spectrum.png"), dpi=110)
        written.append("spectrum.png")
        plt.close(fig)
    return s, written


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("folder")
    parser.add_argument("--start", type=float, default=1.0, help="statistics from this time on (s)")
    parser.add_argument("--out", default=None, help="folder of the PNGs (default FOLDER/plots)")
    parser.add_argument("--plane", type=float, default=None, help="height of the bubble-frequency plane (m)")
    args = parser.parse_args()
    out = args.out or os.path.join(args.folder, "plots")
    s, written = plot(args.folder, out, args.start, args.plane)
    for key, value in s.items():
        if key != "bubble_diameters":
            print(f"{key}: {value:.6g}" if isinstance(value, float) else f"{key}: {value}")
    print("plots: " + ", ".join(os.path.join(out, w) for w in written))


if __name__ == "__main__":
    main()
