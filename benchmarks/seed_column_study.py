#!/usr/bin/env python3
"""Seed 000's study on its small column (issue 54 item 4): prm/seed000_small_column.prm
(5 cm x 1 m, 350 um glass, U = 0.8 m/s), dry and at the liquid loadings
delta = 0.027, 0.055, 0.08, 0.10, 0.12, 0.138 (x 1e-2), each on 2 ranks to --end-time
(3 s), with the statistics over the last --window (2) s of each run:

  - the fluidization index from the pressure probe 1 cm above the inlet (and, beside it,
    the one from the inlet pressure);
  - the dominant frequency of the ECT slab signal at 7.6 cm (the peak of the amplitude
    spectrum of alpha_s_slab, 100 frames/s, over the window);
  - the bubble count and mean equivalent diameter, splittings and coalescences per s;
  - the bed expansion (the mean bed-surface height over the 5 cm static bed);
  - a regime label: a bed whose surface climbs by more than its static height (5 cm)
    over the window without ever dropping 2 cm below its running maximum is
    "de-fluidized (lifted plug)" (the void under it is no bubble passing through);
    otherwise no bubble in the window (mean count < 0.2) is "de-fluidized" when
    the probe FI exceeds 1.3 (the bed is lifted whole: a plug) or "channelling" when it
    is below 0.7 (the gas passes without carrying the bed's weight), else "homogeneous";
    with bubbles, "slugging" when their mean equivalent diameter is at least 0.6 of the
    column's diameter (3 cm), else "bubbling".

Each row is compared with what the seed reports (dry FI ~ 1; FI below dry at 0.027 and
0.055; FI above 1 beyond 0.1; the frequency more than doubled at 0.055; splitting bubbles
below 0.08, slugging from 0.08 to 0.12, de-fluidized above).

--levels L runs the case with L levels of adaptive refinement (the shipped case has 1);
the default 0 is the case's base mesh without refinement: in the bubbling state one level
costs about 2.7 times as much per step on 2 cores (doc/seed_column_study.md), and item 6
of the issue (AMR against uniform on two of these runs) measures what the refinement
changes.

Runs are resumable (checkpoints every 10 min of wall time): call again to continue; a
run stopped with SIGUSR2 is continued. Each piece that ends with a checkpoint (finished,
or stopped with SIGUSR2) also packs it, with the run's CSV files, log and wall time, into
benchmarks/results/seed_column_study/NAME/continue.tar.gz: a fresh clone, whose build/
has no run, continues from there. Each run's monitors.csv (gzipped), bubble summary
and events, and ECT slab signal are kept in benchmarks/results/seed_column_study/NAME/
with its summary.json; --table rewrites the table of doc/seed_column_study.md and the
picture doc/images/seed_column_fi.png without running (the runs whose folders are in
build/ summarized afresh, the others from what is stored).
A run that reaches its end time draws, from its field output in build/, the vertical
slices of alpha_s at four times of the window and the alpha_g = 0.8 iso-surface at the
end (scripts/render_fields.py) into its stored folder (the field output itself is not
kept). --pictures puts those of the dry run and of the loadings 0.055 and 0.138 into
doc/images/ (drawn afresh where build/ has the fields), with their ECT frames stacked in
time, dry beside them (scripts/ect_stack.py, from the stored ect_images.csv.gz).

--fork L1 [L2 ...] (item 6): continues each finished uniform run of --only (default dry)
from its checkpoint at --end-time to --fork-end (5 s), on its base mesh (the reference)
and with each number of AMR levels, each in its own folder fork3_<run> (its wall time
counted from the fork, its statistics over its last --window s), and writes the table
"AMR against the uniform mesh" of doc/seed_column_study.md, with the uniform run's last
window before the fork as the yardstick of what two windows of one run differ.

usage: python3 benchmarks/seed_column_study.py [--end-time 3] [--window 2] [--levels 0]
           [--only dry 0.055 ...] [--table] [--pictures] [--fork 1 2 [--fork-end 5]]
(build first: bash scripts/build.sh; 2 cores: stop other runs first)
"""
import argparse
import gzip
import json
import math
import os
import shutil
import sys

from benchmark_setup import (FIELD_OUTPUT, archive_run, dominant_frequency, read_case, replace_doc_section,
                             repository_root, restore_run, run_resumable)

root = repository_root()
sys.path.insert(0, os.path.join(root, "scripts"))
import plot_run  # noqa: E402
import wetbed_results  # noqa: E402

LOADINGS = ("dry", "0.027", "0.055", "0.08", "0.10", "0.12", "0.138")  # x 1e-2
STATIC_BED = 0.05      # m, the case's static bed height
DIAMETER = 0.05        # m, the column's diameter
NO_BUBBLES = 0.2       # mean bubble count below which a window has no bubbles
SLUG_DIAMETER = 0.6    # mean bubble diameter / column diameter from which it slugs
PLUG_FALLBACK = 0.02   # m: the most a lifted plug's surface drops below its running maximum


def run_name(loading, levels):
    return ("uniform" if levels == 0 else f"amr{levels}") + "_" + ("dry" if loading == "dry" else "wet_" + loading)


def case_text(loading, levels, end_time, window, folder, statistics_start=None):
    """The case of one run; STATISTICS_START (default end_time - window) is the time
    averages' start, which a resumed run keeps from the run it continues. Every loading
    runs with two outer iterations per step, the setting of the rows already stored, so
    that the rows compare."""
    statistics_start = end_time - window if statistics_start is None else statistics_start
    delta = 0.0 if loading == "dry" else float(loading) * 1e-2
    amr = (f"subsection adaptive refinement\n set enabled = true\n set maximum level = {levels}\nend\n"
           if levels > 0 else "subsection adaptive refinement\n set enabled = false\nend\n")
    return (read_case("seed000_small_column") + "\n" + amr +
            f"subsection wet particles\n set liquid loading = {delta:.6g}\nend\n"
            f"subsection time stepping\n set end time = {end_time}\n set outer iterations = 2\nend\n"
            f"subsection statistics\n set time averages = true\n set start time = {statistics_start}\n"
            " set radial profile heights = 0.025, 0.076\nend\n"
            "subsection checkpoint\n set wall time interval = 600\nend\n"
            f"subsection output\n set folder = {folder}\n set field interval = 0.05\n"
            " set progress interval = 100\nend\n")


def surface_motion(time, height, start):
    """(rise, fallback) of the bed surface over the window after START: how far its
    height at the end lies above that at the start, and the largest drop below its
    running maximum."""
    window = [(t, h) for t, h in zip(time, height) if t >= start]
    peak, fallback = -math.inf, 0.0
    for _, h in window:
        peak = max(peak, h)
        fallback = max(fallback, peak - h)
    return window[-1][1] - window[0][1], fallback


def regime(s):
    if s.get("surface_rise", 0.0) > STATIC_BED and s.get("surface_fallback", math.inf) < PLUG_FALLBACK:
        # the bed climbs whole, more than its own height, and never falls back: the void
        # under it (which the bubble analysis counts as one large bubble) is no bubble
        # that passes through the bed
        return "de-fluidized (lifted plug)"
    if not s["bubble_count"] >= NO_BUBBLES:
        if s["fi_probe"] > 1.3:
            return "de-fluidized (lifted plug)"
        if s["fi_probe"] < 0.7:
            return "channelling"
        return "homogeneous"
    return "slugging" if s["bubble_diameter"] >= SLUG_DIAMETER * DIAMETER else "bubbling"


def summarize(folder, end_time, window, wall, code):
    """The study's figures of one run folder over its last WINDOW s (up to where it got)."""
    m = wetbed_results.monitors(folder)
    t = m["time"]
    reached = t[-1]
    start = max(reached - window, 0.0)
    stats = plot_run.statistics(folder, start)
    signal = wetbed_results.ect(folder, start, reached)
    slab = signal["signal"] if signal is not None and signal["signal"] else None
    s = {"reached": reached, "end": end_time, "start": start, "wall": wall, "exit": code,
         "steps": int(m["step"][-1]), "rejected": int(m["rejected_steps"][-1]),
         "fi_probe": plot_run.time_average(t, m["probe_fluidization_index"], start),
         "fi_inlet": plot_run.time_average(t, m["fluidization_index"], start),
         "frequency": dominant_frequency(slab["time"], slab["alpha_s_slab"], start) if slab else math.nan,
         "slab_mean": sum(slab["alpha_s_slab"]) / len(slab["alpha_s_slab"]) if slab else math.nan,
         "bubble_count": stats.get("bubble_count", math.nan),
         "bubble_diameter": stats.get("mean_bubble_diameter", math.nan),
         "splittings": stats.get("splittings_per_second", math.nan),
         "coalescences": stats.get("coalescences_per_second", math.nan),
         "expansion": plot_run.time_average(t, m["bed_surface_height"], start) / STATIC_BED,
         "surface_end": m["bed_surface_height"][-1],
         "surface_rise": surface_motion(t, m["bed_surface_height"], start)[0],
         "surface_fallback": surface_motion(t, m["bed_surface_height"], start)[1],
         "solids_speed_max": max(m["solids_speed_max"]), "gas_speed_max": max(m["gas_speed_max"]),
         "cells": [min(m["active_cells"]), max(m["active_cells"])]}
    s["regime"] = regime(s)
    return s


def store(folder, name, summary):
    """Keeps the run's monitors (gzipped), bubble summary and events, slab signal and figures."""
    kept = os.path.join(root, "benchmarks", "results", "seed_column_study", name)
    os.makedirs(kept, exist_ok=True)
    with open(os.path.join(folder, "monitors.csv"), "rb") as f, gzip.open(os.path.join(kept, "monitors.csv.gz"), "wb") as g:
        shutil.copyfileobj(f, g)
    for file in ("bubble_summary.csv", "bubble_events.csv", "ect.csv"):
        if os.path.exists(os.path.join(folder, file)):
            shutil.copy(os.path.join(folder, file), kept)
    if os.path.exists(os.path.join(folder, "ect_images.csv")):  # the frames of the ECT stacks
        with open(os.path.join(folder, "ect_images.csv"), "rb") as f, \
                gzip.open(os.path.join(kept, "ect_images.csv.gz"), "wb") as g:
            shutil.copyfileobj(f, g)
    json.dump(summary, open(os.path.join(kept, "summary.json"), "w"), indent=1)


def seed_statements(loading, s, dry):
    """What the seed reports for this loading, each with whether this run agrees."""
    out = []
    verdict = lambda ok: "agrees" if ok else "differs"  # noqa: E731
    if loading == "dry":
        out.append(f"FI ≈ 1: {verdict(0.85 <= s['fi_inlet'] <= 1.15)}")
        out.append(f"splitting bubbles: {verdict(s['regime'] == 'bubbling' and s['splittings'] > 0)}")
        return "; ".join(out)
    delta = float(loading)
    if dry is not None and delta <= 0.055:
        out.append(f"FI below dry: {verdict(s['fi_probe'] < dry['fi_probe'])}")
    if delta > 0.1:
        out.append(f"FI > 1: {verdict(s['fi_probe'] > 1)}")
    if dry is not None and loading == "0.055":
        out.append(f"frequency > 2× dry: {verdict(s['frequency'] > 2 * dry['frequency'])}")
    if delta < 0.08:
        out.append(f"splitting bubbles: {verdict(s['regime'] == 'bubbling' and s['splittings'] > 0)}")
    elif delta <= 0.12:
        out.append(f"slugging: {verdict(s['regime'] == 'slugging')}")
    else:
        out.append(f"de-fluidized: {verdict(s['regime'].startswith('de-fluidized'))}")
    return "; ".join(out)


def with_surface_motion(summary, kept):
    """A stored summary with the bed surface's rise and fallback over its window (from
    the stored monitors.csv.gz where the summary predates them) and its regime again."""
    if "surface_rise" not in summary and os.path.exists(os.path.join(kept, "monitors.csv.gz")):
        import csv
        with gzip.open(os.path.join(kept, "monitors.csv.gz"), "rt") as f:
            rows = [r for r in csv.DictReader(f) if float(r["time"]) <= summary["reached"] + 1e-12]
        summary["surface_rise"], summary["surface_fallback"] = surface_motion(
            [float(r["time"]) for r in rows], [float(r["bed_surface_height"]) for r in rows], summary["start"])
        summary["regime"] = regime(summary)
    return summary


def table(levels, end_time):
    results = os.path.join(root, "benchmarks", "results", "seed_column_study")
    stored = {}
    for loading in LOADINGS:
        path = os.path.join(results, run_name(loading, levels), "summary.json")
        if os.path.exists(path):
            stored[loading] = with_surface_motion(json.load(open(path)), os.path.dirname(path))
    dry = stored.get("dry")
    if dry is not None and dry["reached"] < dry["end"] - 1e-9:
        dry = None  # compare only with a finished dry run
    mesh = "the base mesh (2,640 cells), no refinement" if levels == 0 else f"{levels} level(s) of AMR"
    lines = [f"Command: `python3 benchmarks/seed_column_study.py --end-time {end_time:g} --levels {levels}` "
             f"(2 ranks a run, {mesh}; resumable: run it again to continue; `--table` rewrites this from "
             "benchmarks/results/seed_column_study/). Statistics over each run's last 2 s; a run that has not "
             "reached its end time shows its last 2 s so far.", "",
             "| δ (10⁻²) | simulated | FI probe (inlet) | f at 7.6 cm (Hz) | bubbles | mean d_b (cm) | "
             "splits, coalescences per s | expansion | regime | seed 000 | wall s (s per simulated s) |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for loading in LOADINGS:
        s = stored.get(loading)
        if s is None:
            lines.append(f"| {loading} | not run yet | | | | | | | | | |")
            continue
        finished = s["reached"] >= s["end"] - 1e-9
        verdicts = seed_statements(loading, s, dry) if finished else "not compared before the run ends"
        lines.append(
            f"| {loading} | {s['reached']:.2f} / {s['end']:g} s | {s['fi_probe']:.2f} ({s['fi_inlet']:.2f}) | "
            f"{s['frequency']:.2f} | {s['bubble_count']:.2f} | {100 * s['bubble_diameter']:.2f} | "
            f"{s['splittings']:.2f}, {s['coalescences']:.2f} | {s['expansion']:.2f} | {s['regime']} | "
            f"{verdicts} | {s['wall']:.0f} ({s['wall'] / max(s['reached'], 1e-9):.0f}) |")
    figure_lines = picture({k: v for k, v in stored.items() if v["reached"] >= v["end"] - 1e-9}, levels)
    return lines + figure_lines


def picture(stored, levels):
    """FI and the slab frequency against the loading, the seed's trend marked."""
    points = [(0.0 if k == "dry" else float(k), s) for k, s in stored.items()]
    if len(points) < 2:
        return []
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    points.sort(key=lambda p: p[0])
    x = [p[0] for p in points]
    figure, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
    left.plot(x, [p[1]["fi_probe"] for p in points], "o-", label="wetbed, probe at 1 cm")
    left.plot(x, [p[1]["fi_inlet"] for p in points], "s--", label="wetbed, inlet")
    left.axhline(1, color="grey", lw=0.8)
    left.axvspan(0.0, 0.055, color="tab:blue", alpha=0.08, label="seed: FI below dry")
    left.axvspan(0.1, 0.14, color="tab:red", alpha=0.08, label="seed: FI > 1")
    left.set_xlabel("liquid loading δ (10⁻²)")
    left.set_ylabel("fluidization index")
    left.legend(fontsize=8)
    right.plot(x, [p[1]["frequency"] for p in points], "o-", label="wetbed, ECT slab at 7.6 cm")
    if points[0][0] == 0.0:
        right.plot([0.055], [2 * points[0][1]["frequency"]], "v", color="tab:red",
                   label="seed: > 2× dry at 0.055")
    right.set_xlabel("liquid loading δ (10⁻²)")
    right.set_ylabel("dominant frequency (Hz)")
    right.legend(fontsize=8)
    figure.tight_layout()
    name = "seed_column_fi.png" if levels == 0 else f"seed_column_fi_amr{levels}.png"
    figure.savefig(os.path.join(root, "doc", "images", name), dpi=90)
    return ["", f"![FI and frequency against the loading](images/{name})"]


ARCHIVE = "continue.tar.gz"  # what continuing a run needs: its checkpoint, CSV files, log and wall time
PICTURED = ("dry", "0.055", "0.138")  # the seed's three regimes


def render(name, work, window):
    """Draws a run's alpha_s slices at four times of its last WINDOW s and its alpha_g = 0.8
    iso-surface at the end (scripts/render_fields.py) from its field output in WORK, into
    its stored folder (the pictures outlive build/, whose field output is not kept).
    Returns whether the fields were there."""
    import subprocess
    folder = os.path.join(work, name)
    if not os.path.exists(os.path.join(folder, "monitors.csv")) or not os.path.exists(os.path.join(folder, "fields.pvd")):
        return False
    python = "/usr/bin/python3" if os.path.exists("/usr/bin/python3") else sys.executable
    m = wetbed_results.monitors(folder)
    end = m["time"][-1]
    start = max(end - window, 0.0)
    top = max(0.3, 0.05 + max(h for t, h in zip(m["time"], m["bed_surface_height"]) if t >= start))
    times = ",".join(f"{start + k * (end - start) / 3:.3f}" for k in range(4))
    out = os.path.join(work, "pictures", name)
    subprocess.run([python, os.path.join(root, "scripts", "render_fields.py"), folder, "--times", times,
                    "--no-animation", "--height", f"0,{min(top, 1.0):.2f}", "--size", "300x700", "--out", out],
                   check=True, stdout=subprocess.DEVNULL)
    kept = os.path.join(root, "benchmarks", "results", "seed_column_study", name)
    os.makedirs(kept, exist_ok=True)
    for picture in ("alpha_s_snapshots.png", "alpha_g_iso.png"):
        if os.path.exists(os.path.join(out, picture)):
            shutil.copy(os.path.join(out, picture), kept)
    return True


def pictures(levels, work, window):
    """The slices and iso-surfaces of the pictured runs (drawn afresh where build/ has
    their fields, else as stored by render()), and their ECT frames stacked in time from
    the stored ect_images.csv.gz."""
    import subprocess
    python = "/usr/bin/python3" if os.path.exists("/usr/bin/python3") else sys.executable
    images = os.path.join(root, "doc", "images")
    tag = "" if levels == 0 else f"_amr{levels}"
    lines, stacked, labels = [], [], []
    for loading in PICTURED:
        name = run_name(loading, levels)
        render(name, work, window)
        kept = os.path.join(root, "benchmarks", "results", "seed_column_study", name)
        label = "dry" if loading == "dry" else f"δ = {loading}·10⁻²"
        for source, kind in (("alpha_s_snapshots.png", "slices"), ("alpha_g_iso.png", "iso")):
            if os.path.exists(os.path.join(kept, source)):
                target = f"seed_column_{name.replace('.', '_')}_{kind}.png"  # name: uniform_... or amrL_...
                shutil.copy(os.path.join(kept, source), os.path.join(images, target))
                what = "α_s on the vertical slice through the axis" if kind == "slices" else "the α_g = 0.8 iso-surface"
                lines.append(f"![{label}: {what}](images/{target})")
        if os.path.exists(os.path.join(kept, "ect_images.csv.gz")) and os.path.exists(os.path.join(kept, "ect.csv")):
            stacked.append(kept)
            labels.append(label)
    if len(stacked) > 1:
        target = f"seed_column_ect{tag}.png"
        ends = [json.load(open(os.path.join(k, "summary.json")))["reached"] for k in stacked]
        subprocess.run([python, os.path.join(root, "scripts", "ect_stack.py"), *stacked, "--labels", ",".join(labels),
                        "--start", f"{max(0.0, min(ends) - window):.3f}",
                        "--out", os.path.join(images, target)], check=True, stdout=subprocess.DEVNULL)
        lines.append(f"![ECT frames stacked in time, dry beside wet](images/{target})")
    return lines


def run_piece(name, work, case, end_time, window, env, extra=None):
    """Writes WORK/NAME.prm (CASE), runs it on 2 ranks (continued from its checkpoint, or
    from its stored continue.tar.gz in a build/ without it) to END_TIME, and keeps what it
    reached: the stored results (the summary with EXTRA added) and, when the piece ended
    with a checkpoint, continue.tar.gz. Returns (exit code, summary or None without a
    monitors.csv)."""
    folder, prm = os.path.join(work, name), os.path.join(work, name + ".prm")
    sidecars = [os.path.join(work, name + ".log"), os.path.join(work, name + ".wall")]
    archive = os.path.join(root, "benchmarks", "results", "seed_column_study", name, ARCHIVE)
    if restore_run(archive, folder):
        print(f"{name}: continues from {os.path.relpath(archive, root)}", flush=True)
    open(prm, "w").write(case)
    command = ["mpirun", "-np", "2", os.path.join(root, "build", "wetbed"), prm]
    code, wall = run_resumable(command, folder, *sidecars, True, env, end_time)
    if not os.path.exists(os.path.join(folder, "monitors.csv")):
        print(f"{name}: exit {code}, no monitors.csv (see {name}.log)", flush=True)
        return code, None
    summary = dict(summarize(folder, end_time, window, wall, code), **(extra or {}))
    store(folder, name, summary)
    if code == 0 and summary["reached"] >= end_time - 1e-9:  # its pictures, while its fields are here
        render(name, work, window)
    if code in (0, 4) and os.path.isdir(os.path.join(folder, "checkpoint")):
        size = archive_run(folder, sidecars, archive)
        print(f"{name}: checkpoint kept in {os.path.relpath(archive, root)} ({size / 1e6:.1f} MB)", flush=True)
    print(f"{name}: exit {code}, t = {summary['reached']:.3f} s, wall {wall:.0f} s, {summary['regime']}", flush=True)
    return code, summary


def fork_name(loading, levels, fork_time):
    """The run that continues uniform_<loading> from its end FORK_TIME with LEVELS levels
    of AMR (0: on the base mesh, the reference)."""
    return f"fork{fork_time:g}_" + run_name(loading, levels)


def fork(loading, levels, args, work, env):
    """Item 6: continues the finished uniform run of LOADING (its checkpoint at
    args.end_time, from build/ or its stored continue.tar.gz) to args.fork_end with
    LEVELS levels of adaptive refinement (0: on the base mesh, the reference the AMR run
    is compared with), in a copy of its folder; the statistics over the last
    args.window s, the wall time counted from the fork. Returns the stored summary or
    None."""
    source = run_name(loading, 0)
    results = os.path.join(root, "benchmarks", "results", "seed_column_study")
    source_folder = os.path.join(work, source)
    if restore_run(os.path.join(results, source, ARCHIVE), source_folder):
        print(f"{source}: restored from its stored checkpoint", flush=True)
    name = fork_name(loading, levels, args.end_time)
    folder = os.path.join(work, name)
    restore_run(os.path.join(results, name, ARCHIVE), folder)
    if not os.path.isdir(os.path.join(folder, "checkpoint")):
        if not os.path.isdir(os.path.join(source_folder, "checkpoint")) or \
                wetbed_results.monitors(source_folder)["time"][-1] < args.end_time - 1e-9:
            print(f"{name}: {source} has not reached {args.end_time:g} s with a checkpoint; run it first", flush=True)
            return None
        if os.path.isdir(folder):
            shutil.rmtree(folder)
        shutil.copytree(source_folder, folder, ignore=lambda d, names: [
            n for n in names if FIELD_OUTPUT.match(n) or n in (".wetbed.lock", "checkpoint.previous", "checkpoint.partial")])
        with open(os.path.join(work, name + ".wall"), "w") as f:  # the fork's own wall time: continued from here
            f.write("0")
    case = case_text(loading, levels, args.fork_end, args.window, folder, statistics_start=args.end_time - args.window)
    code, summary = run_piece(name, work, case, args.fork_end, args.window, env, {"fork": args.end_time})
    return summary if code in (0, 4) else None


def fork_table(loadings, levels, fork_time, fork_end, window):
    """The AMR forks against the uniform mesh continued over the same span, and the
    uniform run's previous window as the yardstick of what a window's statistics vary."""
    results = os.path.join(root, "benchmarks", "results", "seed_column_study")
    lines = [f"Command: `python3 benchmarks/seed_column_study.py --end-time {fork_time:g} --fork "
             f"{' '.join(map(str, levels))} --fork-end {fork_end:g} --only {' '.join(loadings)}` (each uniform run's "
             f"checkpoint at {fork_time:g} s continued to {fork_end:g} s on 2 ranks, on its base mesh and with each "
             f"number of AMR levels; statistics over each run's last {window:g} s). The uniform run's own last "
             f"{window:g} s before the fork are the yardstick of how much two windows of one run differ.", "",
             "| δ (10⁻²) | mesh | window | cells | FI probe (inlet) | f at 7.6 cm (Hz) | bubbles | mean d_b (cm) | "
             "splits, coalescences per s | expansion | regime | wall s per simulated s | cost against uniform |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for loading in loadings:
        rows = []
        path = os.path.join(results, run_name(loading, 0), "summary.json")
        if os.path.exists(path):
            rows.append(("base mesh", json.load(open(path)), None))
        for level in [0] + list(levels):
            path = os.path.join(results, fork_name(loading, level, fork_time), "summary.json")
            if os.path.exists(path):
                rows.append(("base mesh" if level == 0 else f"AMR, {level} level(s)", json.load(open(path)), fork_time))
        reference = next((s for mesh, s, f in rows if f is not None and mesh == "base mesh"), None)
        for mesh, s, start in rows:
            span = s["reached"] - (start or 0.0)
            cost = s["wall"] / max(span, 1e-9)
            ratio = ""
            if start is not None and reference is not None:
                ratio = f"{cost / (reference['wall'] / max(reference['reached'] - start, 1e-9)):.2f}×"
            lines.append(
                f"| {loading} | {mesh} | {s['start']:.2f}–{s['reached']:.2f} s | {int(s['cells'][0])}–{int(s['cells'][1])} | "
                f"{s['fi_probe']:.2f} ({s['fi_inlet']:.2f}) | {s['frequency']:.2f} | {s['bubble_count']:.2f} | "
                f"{100 * s['bubble_diameter']:.2f} | {s['splittings']:.2f}, {s['coalescences']:.2f} | "
                f"{s['expansion']:.2f} | {s['regime']} | {cost:.0f} | {ratio} |")
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--end-time", type=float, default=3.0)
    parser.add_argument("--window", type=float, default=2.0)
    parser.add_argument("--levels", type=int, default=0)
    parser.add_argument("--only", nargs="*", help="loadings to run, in this order (dry, 0.027, ...)")
    parser.add_argument("--table", action="store_true", help="rewrite the table only")
    parser.add_argument("--pictures", action="store_true", help="also draw slices, iso-surfaces and ECT stacks")
    parser.add_argument("--fork", type=int, nargs="+", metavar="LEVELS",
                        help="continue the finished uniform runs (--only, default dry) from --end-time to "
                             "--fork-end with each number of AMR levels, and on the base mesh")
    parser.add_argument("--fork-end", type=float, default=5.0)
    args = parser.parse_args()
    unknown = [o for o in (args.only or []) if o not in LOADINGS]
    if unknown:
        sys.exit(f"--only: unknown loading(s) {unknown}; choose from {LOADINGS}")
    if args.fork is not None and (min(args.fork) < 1 or args.fork_end <= args.end_time + args.window / 2):
        sys.exit("--fork: levels >= 1, and --fork-end beyond --end-time by at least half the --window")
    work = os.path.join(root, "build", "benchmarks", "seed_column_study")
    os.makedirs(work, exist_ok=True)
    env = dict(os.environ, OMPI_MCA_rmaps_base_oversubscribe="1")
    if args.fork is not None:
        loadings = args.only or ["dry"]
        stopped = False
        for loading in ([] if args.table else loadings):
            for level in [0] + args.fork:  # the reference first: it is the cheaper
                summary = fork(loading, level, args, work, env)
                if summary is None:  # no uniform run to fork, or a failed run: the next loading
                    break
                if summary["reached"] < args.fork_end - 1e-9:  # SIGUSR2: the rest waits for the next call
                    print("stopped with a checkpoint; run the same command again to continue", flush=True)
                    stopped = True
                    break
            if stopped:
                break
        lines = fork_table(loadings, args.fork, args.end_time, args.fork_end, args.window)
        replace_doc_section(root, "seed_column_amr", "AMR against the uniform mesh", lines,
                            doc_name="seed_column_study.md")
        print("\n".join(lines))
        return
    for loading in ([] if args.table else args.only or LOADINGS):  # in the order given
        name = run_name(loading, args.levels)
        case = case_text(loading, args.levels, args.end_time, args.window, os.path.join(work, name))
        code, summary = run_piece(name, work, case, args.end_time, args.window, env)
        if summary is None:
            continue
        if code == 4:  # stopped with a checkpoint (SIGUSR2): the later runs wait for the next call
            print(f"{name}: stopped with a checkpoint; run the same command again to continue", flush=True)
            break
        if code != 0:
            print(f"{name}: stopped with status {code}; see {name}.log and failure_report.txt", flush=True)
    if args.table:  # the runs present in build/ summarized afresh (a run stopped by hand included)
        for loading in args.only or LOADINGS:
            name = run_name(loading, args.levels)
            folder, wall_file = os.path.join(work, name), os.path.join(work, name + ".wall")
            if os.path.exists(os.path.join(folder, "monitors.csv")) and os.path.exists(wall_file):
                store(folder, name, summarize(folder, args.end_time, args.window,
                                              float(open(wall_file).read()), None))
    lines = table(args.levels, args.end_time)
    if args.pictures:
        lines += [""] + pictures(args.levels, work, args.window)
    key = "seed_column_study" if args.levels == 0 else f"seed_column_study_amr{args.levels}"
    replace_doc_section(root, key, "The study: dry and six loadings" +
                        ("" if args.levels == 0 else f" ({args.levels} level(s) of AMR)"), lines,
                        doc_name="seed_column_study.md")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
