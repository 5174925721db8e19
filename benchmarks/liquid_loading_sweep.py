#!/usr/bin/env python3
"""Seed-000 liquid-loading sweep on prm/wet_column_2d.prm: delta = 0, 0.027, 0.055, 0.08,
0.1, 0.12, 0.138 x 1e-2 at U = 0.8 m/s. For each: completed or not, simulated time,
rejected steps, bounds, time-averaged FI after start-up (and its 0.5 s window range),
the dominant frequency of alpha_s averaged over the cell layer at 7.6 cm (the case's
`output/probe heights`), mean bubble count and equivalent diameter (bubble_summary.csv),
the split of the solids shear stress into kinetic/collisional/frictional/wet parts and
the mean collisional dissipation in the dense bed (alpha_s > 0.3, from the HDF5 field
outputs every 0.1 s), FGMRES iterations per step (the stiffness of mu_wet), cost. Writes
the table into doc/benchmarks.md, FI(t) into doc/liquid_loading_fi.png and the stress
split and dissipation against alpha_s (seed 000's Figs. 9-10) into
doc/liquid_loading_stress.png.

Each run writes a checkpoint every 500 steps; started again, the script continues the
unfinished runs from their checkpoints (`wetbed --resume`) and leaves finished ones, so
the study (about 7 x 4,000 s of one core) can be spread over several sittings; stop it
with SIGTERM/Ctrl-C (the runs write a checkpoint and exit).

The work folder is a build folder and does not outlive a machine, so each run's figures
are also kept in the repository, benchmarks/results/liquid_loading_sweep[_cap_X]/
delta_<d>e-2.json: its table row, FI(t) thinned to at most 2,000 points and 3,000 of its
field-output samples (4 significant digits). The table and plots are drawn from the
work folder where a run is there and from the stored file otherwise, so a sweep finished
on another machine (or with another build, --binary) keeps all its rows.

usage: python3 benchmarks/liquid_loading_sweep.py [--end-time 5] [--start-up 1]
           [--loadings 0 0.027 ...] [--jobs 2] [--summarize-only]
           [--maximum-wet-viscosity MU] [--approach-only]
(build first: bash scripts/build.sh). --jobs runs that many cases at once, one core each.
"""
import argparse
import concurrent.futures
import json
import math
import os

from benchmark_setup import read_case, replace_doc_section, repository_root, run_resumable, summarize_run, write_case
from field_samples import cell_samples, stress_split

root = repository_root()
parser = argparse.ArgumentParser()
parser.add_argument("--end-time", type=float, default=5.0)
parser.add_argument("--start-up", type=float, default=1.0, help="seconds left out of the means")
parser.add_argument("--loadings", nargs="+", type=float,
                    default=[0, 0.027, 0.055, 0.08, 0.1, 0.12, 0.138], help="delta in units of 1e-2")
parser.add_argument("--jobs", type=int, default=1)
parser.add_argument("--summarize-only", action="store_true")
parser.add_argument("--maximum-wet-viscosity", type=float,
                    help="cap of mu_wet (Pa s) instead of the case's; a sensitivity study, kept in WORK/cap_<value>")
parser.add_argument("--approach-only", action="store_true",
                    help="wet particles/lubrication stress = approach only (kept in WORK/approach_only)")
parser.add_argument("--binary", help="the wetbed executable (default: build/wetbed); to finish a sweep "
                    "with the build it was started with")
parser.add_argument("--work", default=os.path.join(root, "build", "benchmarks", "liquid_loading_sweep"))
args = parser.parse_args()
cap, suffix = "", ""
if args.maximum_wet_viscosity is not None:
    args.work = os.path.join(args.work, f"cap_{args.maximum_wet_viscosity:g}")
    cap = f"  set maximum wet viscosity = {args.maximum_wet_viscosity:g}\n"
    suffix = f"_cap_{args.maximum_wet_viscosity:g}"
if args.approach_only:
    args.work = os.path.join(args.work, "approach_only")
    cap += "  set lubrication stress = approach only\n"
    suffix += "_approach_only"
os.makedirs(args.work, exist_ok=True)
results = os.path.join(root, "benchmarks", "results", "liquid_loading_sweep" + suffix)
base = read_case("wet_column_2d")


def name(loading):
    return f"delta_{loading:g}e-2"


def case(loading):
    return write_case(args.work, name(loading), base, args.end_time,
                      f"\nsubsection wet particles\n  set liquid loading = {loading * 1e-2:.6g}\n{cap}end\n"
                      "subsection output\n  set field format = hdf5\nend\n"
                      "subsection checkpoint\n  set interval = 500\n  set at end = false\nend\n")


def run(loading):
    prm, folder, log = case(loading)
    binary = args.binary or os.path.join(root, "build", "wetbed")
    code, wall = run_resumable([binary, prm], folder, log,
                               os.path.join(args.work, name(loading) + ".wall"))
    print(f"delta = {loading:g}e-2: exit {code}, {wall:.0f} s", flush=True)


if not args.summarize_only:
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        list(pool.map(run, args.loadings))


def bubbles(folder, start_up):
    """Time-mean bubble count and count-weighted mean equivalent diameter (mm)."""
    import csv
    path = os.path.join(folder, "bubble_summary.csv")
    rows = [r for r in csv.DictReader(open(path)) if float(r["time"]) > start_up] if os.path.exists(path) else []
    if len(rows) < 2:
        return float("nan"), float("nan")
    t = [float(r["time"]) for r in rows]
    n = [float(r["bubbles"]) for r in rows]
    d = [float(r["mean_equivalent_diameter"]) for r in rows]
    dt = [t[i + 1] - t[i] for i in range(len(t) - 1)]
    count = sum(n[i] * dt[i] for i in range(len(dt))) / sum(dt)
    weight = sum(n[i] * dt[i] for i in range(len(dt)))
    diameter = sum(n[i] * d[i] * dt[i] for i in range(len(dt))) / weight * 1e3 if weight > 0 else float("nan")
    return count, diameter


def rounded(values, digits=4):
    return [float(format(float(v), f".{digits - 1}e")) for v in values]


def store(loading, summary, fi_series, cell_data):
    """Keep the run's row, FI(t) (at most 2,000 points) and 3,000 samples in RESULTS."""
    import numpy
    t, fi = fi_series
    every = max(1, len(t) // 2000)
    pick = numpy.random.default_rng(0).permutation(len(cell_data.get("alpha_s", [])))[:3000]
    record = {"row": summary, "binary": os.path.abspath(args.binary or os.path.join(root, "build", "wetbed")),
              "fi": {"time": rounded(t[::every], 6), "value": rounded(fi[::every])},
              "samples": {key: rounded(values[pick]) for key, values in cell_data.items()}}
    os.makedirs(results, exist_ok=True)
    with open(os.path.join(results, name(loading) + ".json.part"), "w") as f:
        json.dump(record, f, separators=(",", ":"), allow_nan=True)
    os.replace(os.path.join(results, name(loading) + ".json.part"), os.path.join(results, name(loading) + ".json"))


def restore(loading):
    """(row, FI series or None, samples dict) from RESULTS, or None."""
    import numpy
    path = os.path.join(results, name(loading) + ".json")
    if not os.path.exists(path):
        return None
    record = json.load(open(path))
    fi = record.get("fi")
    return (record["row"], (fi["time"], fi["value"]) if fi else None,
            {key: numpy.asarray(values) for key, values in (record.get("samples") or {}).items()})


stored_loadings = {float(f[len("delta_"):-len("e-2.json")]) for f in os.listdir(results)
                   if f.startswith("delta_") and f.endswith("e-2.json")} if os.path.isdir(results) else set()
rows, series, samples = [], {}, {}
for loading in sorted(set(args.loadings) | stored_loadings):  # the table keeps the stored rows
    prm, folder, log = case(loading)
    if os.path.exists(os.path.join(folder, "monitors.csv")):
        wall_file = os.path.join(args.work, name(loading) + ".wall")
        wall = float(open(wall_file).read()) if os.path.exists(wall_file) else None
        summary, series[loading] = summarize_run(folder, log, args.start_up, wall)
        samples[loading] = cell_samples(folder, args.start_up)
        summary["bubbles"], summary["diameter"] = bubbles(folder, args.start_up)
        summary["split"] = stress_split(samples[loading])
        store(loading, summary, series[loading], samples[loading])
    else:
        stored = restore(loading)
        if stored is None:
            continue
        summary, fi_series, samples[loading] = stored
        if fi_series:
            series[loading] = fi_series
        print(f"delta = {loading:g}e-2: from {os.path.relpath(results, root)} (no run in {args.work})")
    rows.append(dict(summary, loading=loading))


def number(value, form):
    return "–" if value is None or (isinstance(value, float) and math.isnan(value)) else format(value, form)


lines = [f"Command: `python3 benchmarks/liquid_loading_sweep.py --end-time {args.end_time:g} --start-up {args.start_up:g} --jobs {args.jobs}"
         + (f" --maximum-wet-viscosity {args.maximum_wet_viscosity:g}" if args.maximum_wet_viscosity is not None else "")
         + (" --approach-only" if args.approach_only else "") + "`"
         " (resumable: a stopped run continues from its checkpoint; wall time summed over the pieces). Means over"
         f" t > {args.start_up:g} s; the stress split is the share of each part in the summed solids shear"
         " stress μ_i|γ̇| and the dissipation the mean collisional γ over the field outputs' cells with α_s > 0.3.", "",
         "| δ (10⁻²) | completed | simulated | rejected | α_s range | Θ range (m²/s²) | FI mean | 0.5 s windows | dominant frequency at 7.6 cm (Hz) | bubbles (mean count) | bubble d (mm) | shear stress kin/col/fr/wet (%) | γ (W/m³) | FGMRES its/step | s per simulated s |",
         "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
for r in rows:
    split = r["split"]
    shares = "/".join(number(v, ".0f") for v in split["shares"]) if split else "–"
    lines.append(
        f"| {r['loading']:g} | {'yes' if r['finished'] else 'no'} | {r['end']:.3f} s | {r['rejected']} | "
        f"[{r['alpha_min']:.1e}, {r['alpha_max']:.4f}] | [{r['theta_min']:.1e}, {r['theta_max']:.3g}] | "
        f"{number(r['mean_fi'], '.3f')} | {number(r['fi_min_window'], '.3f')}, {number(r['fi_max_window'], '.3f')} | "
        f"{number(r['frequency'], '.2f')} | {number(r['bubbles'], '.2f')} | {number(r['diameter'], '.1f')} | {shares} | "
        f"{number(split['dissipation'] if split else None, '.3g')} | {r['krylov']:.1f} | {number(r['per_second'], '.0f')} |")
print("\n".join(lines))

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
fig.savefig(os.path.join(root, "doc", f"liquid_loading_fi{suffix}.png"), dpi=110)
print(f"wrote doc/liquid_loading_fi{suffix}.png")

# seed 000's Figs. 9-10: the stress parts of one wet run (the loading nearest 0.1e-2),
# the dissipation and Theta of it and of the dry run, against alpha_s
wet = [w for w in samples if w > 0 and samples[w]]
stress_figure = bool(wet and samples.get(0))
if stress_figure:
    import numpy  # noqa: E402
    chosen = min(wet, key=lambda w: abs(w - 0.1))
    fig, axes = plt.subplots(1, 3, figsize=(12, 3.8))
    generator = numpy.random.default_rng(0)

    def thin(data, count=15000):
        pick = generator.permutation(len(data["alpha_s"]))[:count]
        return {key: values[pick] for key, values in data.items()}

    w, d = thin(samples[chosen]), thin(samples[0])
    for key, label in [("kinetic_shear_stress", "kinetic"), ("collisional_shear_stress", "collisional"),
                       ("frictional_shear_stress", "frictional"), ("wet_shear_stress", "liquid bridges")]:
        axes[0].scatter(w["alpha_s"], numpy.maximum(w[key], 1e-8), s=1, label=label)
    axes[0].set_yscale("log")
    axes[0].set_ylim(1e-6, 1e4)
    axes[0].set_title(f"solids shear stress parts, δ = {chosen:g}·10⁻²", fontsize=9)
    axes[0].set_ylabel("μ_i |γ̇| (Pa)")
    for data, label in [(d, "dry"), (w, f"δ = {chosen:g}·10⁻²")]:
        axes[1].scatter(data["alpha_s"], numpy.maximum(data["collisional_dissipation"], 1e-8), s=1, label=label)
        axes[2].scatter(data["alpha_s"], numpy.maximum(data["granular_temperature"], 1e-10), s=1, label=label)
    axes[1].set_yscale("log")
    axes[1].set_ylabel("collisional dissipation γ (W/m³)")
    axes[2].set_yscale("log")
    axes[2].set_ylabel("Θ (m²/s²)")
    for ax in axes:
        ax.set_xlabel("α_s")
        ax.legend(fontsize=7, markerscale=6)
    fig.tight_layout()
    fig.savefig(os.path.join(root, "doc", f"liquid_loading_stress{suffix}.png"), dpi=110)
    print(f"wrote doc/liquid_loading_stress{suffix}.png")

replace_doc_section(root, "liquid_loading_sweep" + suffix, "Liquid-loading sweep"
                    + (f", μ_wet capped at {args.maximum_wet_viscosity:g} Pa·s" if args.maximum_wet_viscosity is not None else "")
                    + (", lubrication stress on approach only" if args.approach_only else ""),
                    lines + ["", f"![FI(t) of the sweep](liquid_loading_fi{suffix}.png)"]
                    + (["", f"![stress split, dissipation and Θ against α_s](liquid_loading_stress{suffix}.png)"] if stress_figure
                       else ["", f"![stress split, dissipation and Θ against α_s, drawn from field outputs that are not "
                             f"stored with the results](liquid_loading_stress{suffix}.png)"]
                       if os.path.exists(os.path.join(root, "doc", f"liquid_loading_stress{suffix}.png")) else []))
