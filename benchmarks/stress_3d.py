"""The 3D rows of the stress benchmark (benchmarks/stress.py --3d): the shipped column and
the seed's 5 cm x 1 m column, dry and wet, each on 2 ranks, resumable."""
import csv
import json
import math
import os
import re

from benchmark_setup import read_case, replace_doc_section, run_resumable, write_case

WET = ("subsection wet particles\n set liquid loading = {delta}\n set liquid viscosity = 0.4945\n"
       " set liquid density = 969\n set contact angle = 0.175\n set asperity height = 2.8e-6\n"
       " set angle of stability = 30\n set approach velocity factor = 1.5\n"
       " set rupture distance = Lian\n set restitution = bridge-gated\nend\n")
AMR = ("subsection adaptive refinement\n set enabled = true\n set minimum level = 0\n"
       " set maximum level = 1\nend\n")
REFERENCE_SPEED = 2.62  # m/s: the terminal velocity of the 350 um beads (the cases' scale)


def tall_column(root, work):
    """meshes/column_3d.geo with the seed's 1 m height at the shipped cell size."""
    geo = open(os.path.join(root, "meshes", "column_3d.geo")).read()
    geo = geo.replace('height = {0.30, Name "height"}', 'height = {1.0, Name "height"}')
    geo = geo.replace('n_layers = {24, Name "n_layers"}', 'n_layers = {80, Name "n_layers"}')
    path = os.path.join(work, "column_5cm_1m.geo")
    open(path, "w").write(geo)
    return read_case("column_3d").replace(os.path.join(root, "meshes", "column_3d.geo"), path)


def cases(root, work):
    shipped, tall = read_case("column_3d"), tall_column(root, work)
    rows = [("column_3d.prm as shipped", shipped, ""),
            ("column_3d.prm with AMR (levels 0-1)", shipped, AMR),
            ("5 cm x 1 m column, dry", tall, "")]
    for delta in ("0.055e-2", "0.1e-2", "0.138e-2"):
        rows.append((f"5 cm x 1 m column, wet, delta = {delta}", tall, WET.format(delta=delta)))
    return rows


def record(label, folder, log, code, wall, end):
    rows = list(csv.DictReader(open(os.path.join(folder, "monitors.csv")))) if os.path.exists(
        os.path.join(folder, "monitors.csv")) else []
    text = open(log).read() if os.path.exists(log) else ""
    values = lambda key: [float(r[key]) for r in rows]  # noqa: E731
    # the steps the controller chose: not the start row, nor a last step cut short to
    # land on the end time
    steps = values("time_step")[1:] if rows else []
    if steps and float(rows[-1]["time"]) >= end - 1e-9 and len(steps) > 1 and steps[-1] < steps[-2]:
        steps = steps[:-1]
    result = {"label": label, "code": code, "wall": wall, "end": end,
              "reached": float(rows[-1]["time"]) if rows else 0.0,
              "steps": int(float(rows[-1]["step"])) if rows else 0,
              "rejected": int(float(rows[-1]["rejected_steps"])) if rows else 0,
              "gas": max(values("gas_speed_max")) if rows else math.nan,
              "solids": max(values("solids_speed_max")) if rows else math.nan,
              "theta": max(values("theta_max")) if rows else math.nan,
              "dt": min((v for v in steps if v > 0), default=math.nan),
              "checks": len(re.findall(r"step rejected at .*check:", text))}
    if code == 0:
        result["outcome"] = "completed"
    elif code == 3:
        cause = re.search(r"cause of the last rejection: ([^\n]{0,70})", text)
        result["outcome"] = "stopped, status 3 (" + (cause.group(1) if cause else "failure_report.txt") + ")"
    elif code == 4 or code < 0:
        result["outcome"] = "interrupted (continue: run again)"
    else:
        result["outcome"] = f"CRASHED (exit {code})"
    return result


def stored_name(label):
    return "3d_" + re.sub(r"[^a-z0-9]+", "_", label.lower()).strip("_")


def run_3d_cases(root, work, args, env):
    """Runs the selected rows (none with --table), keeps each row's result in
    benchmarks/results/stress_3d/NAME.json and rewrites the table from all stored rows."""
    results = os.path.join(root, "benchmarks", "results", "stress_3d")
    os.makedirs(results, exist_ok=True)
    selected = [c for c in cases(root, work) if not args.only or any(o in c[0] for o in args.only)]
    for label, base, sections in ([] if args.table else selected):
        name = stored_name(label)
        prm, folder, log = write_case(work, name, base, args.end_time_3d,
                                      sections + "subsection checkpoint\n set wall time interval = 600\nend\n",
                                      field_interval=1000, progress_interval=50)
        command = ["mpirun", "--oversubscribe", "-np", "2", os.path.join(root, "build", "wetbed"), prm]
        code, wall = run_resumable(command, folder, log, os.path.join(work, name + ".wall"), True, env,
                                   args.end_time_3d)
        result = record(label, folder, log, code, wall, args.end_time_3d)
        json.dump(result, open(os.path.join(results, name + ".json"), "w"), indent=1)
        print(f"{label}: {result['outcome']}, t = {result['reached']:.4g} s", flush=True)
    lines = [f"Command: `python3 benchmarks/stress.py --3d [--end-time-3d T] [--only NAME]` (2 ranks each, "
             "resumable within a checkout: run it again to continue; default path; each row's end time is in its "
             "'simulated' column; `--table` rewrites this table from benchmarks/results/stress_3d/). Reference speed V = 2.62 m/s (the terminal "
             "velocity of the 350 µm beads, the cases' largest scale); the speed check fires above 20 V = 52 m/s.", "",
             "| case | outcome | simulated | steps | rejected | peak gas speed (m/s, /V) | peak solids speed (m/s, /V) | "
             "Θ max (m²/s²) | smallest Δt (s) | checks fired | wall s |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for label, _, _ in cases(root, work):
        stored = os.path.join(results, stored_name(label) + ".json")
        if not os.path.exists(stored):
            lines.append(f"| {label} | not run yet | | | | | | | | | |")
            continue
        r = json.load(open(stored))
        lines.append(f"| {r['label']} | {r['outcome']} | {r['reached']:.3g} / {r['end']:g} s | {r['steps']} | "
                     f"{r['rejected']} | {r['gas']:.2f} ({r['gas'] / REFERENCE_SPEED:.1f}) | "
                     f"{r['solids']:.2f} ({r['solids'] / REFERENCE_SPEED:.1f}) | {r['theta']:.3g} | {r['dt']:.2e} | "
                     f"{r['checks']} | {r['wall']:.0f} |")
    replace_doc_section(root, "stress_3d", "Stress benchmark: 3D columns", lines)
    print("\n".join(lines))
