#!/usr/bin/env python3
"""Seed 000's large column (issue 54 item 7): prm/seed000_large_column.prm (15 cm x 1.5 m,
3.5 kg of 350 um glass, U = 0.8 m/s) dry on 2 ranks from rest to --end-time (0.2 s), on
its base mesh (35,640 cells; the shipped case's adaptive refinement is switched off, as
in the small column's study: one level multiplies the cells up to 8x where it refines).
Then the strong scaling: the same span of --span s, resumed from that run's end, on 1 and
on 2 ranks one after the other, with Open MPI's message monitoring on the 2-rank span.

Reported, and written to doc/benchmarks.md ("The large column: cost, memory and
scaling") and benchmarks/results/large_column/summary.json:
  - the run: steps, rejected steps, wall time, s per simulated second, us per cell and
    per flow DoF per step, FGMRES per step, the FI and the bed-surface height at the end;
  - memory: the peak resident memory per rank and in all, per flow DoF, on 1 and 2 ranks;
  - the partition: owned cells, wall faces, owned and ghost flow DoFs per rank (the ghosts
    are what each product of the flow operator exchanges);
  - the communication of the 2-rank span: point-to-point bytes and messages per step
    between the ranks, and collective operations per step (Open MPI's pml monitoring;
    the span's resume from the checkpoint included);
  - the strong scaling over the span: wall per step on 1 and 2 ranks (the ECT sensor's
    timer taken out: its first location of the slab's points is a one-off of each run
    start), speed-up and efficiency;
  - a cost model for more ranks (model()): the 1-rank wall per step divided among the
    ranks with the 2-rank factor (imbalance and the shared memory bus), plus the measured
    messages across two interfaces per rank (the partition cuts the column into slabs
    along its axis) and the measured reductions, over a network of --bandwidth (10 GB/s)
    and --latency (2 us); memory per rank M(P) = a + b N / P from the 1- and 2-rank
    peaks. Model rows are marked as such.

Resumable: the 0.2 s run writes checkpoints every 10 min of wall time; call again to
continue it (SIGUSR2 to its ranks stops it with a checkpoint). The spans are rerun each
call; --spans-only runs them from where the run stopped, without continuing it (the
table then shows how far the run is). --report rewrites the doc section from what is
stored, without running.

usage: python3 benchmarks/large_column.py [--end-time 0.2] [--span 0.006] [--spans-only] [--report]
(build first: bash scripts/build.sh; ~1.5 h on 2 cores, nothing else running; ~5 GB)
"""
import argparse
import json
import math
import os
import re
import shutil
import subprocess
import sys

from benchmark_setup import (last_time, read_case, replace_doc_section, repository_root,
                             run_resumable, timer_seconds)

root = repository_root()
sys.path.insert(0, os.path.join(root, "scripts"))
import wetbed_results  # noqa: E402

MODEL_RANKS = (4, 8, 16, 32, 64)


CASE = "seed000_large_column"


def case_text(folder, end_time, wall_interval=600, at_end=True):
    return read_case(CASE) + f"""
subsection adaptive refinement
  set enabled = false
end
subsection time stepping
  set end time = {end_time}
end
subsection checkpoint
  set wall time interval = {wall_interval}
  set at end = {"true" if at_end else "false"}
end
subsection output
  set folder = {folder}
  set field interval = 0.1
  set progress interval = 10
end
"""


def partition(text):
    """Owned cells, wall faces, owned and ghost flow DoFs per rank from the Partition line."""
    m = re.search(r"Partition: owned cells per rank ([\d.]+)-([\d.]+), wall faces per rank ([\d.]+)-([\d.]+)"
                  r".*flow DoFs per rank ([\d.]+)-([\d.]+), ghost flow DoFs ([\d.]+)-([\d.]+) \(([\d.]+) in all\)",
                  text)
    if not m:
        return None
    v = [float(x) for x in m.groups()]
    return {"cells": v[0:2], "wall_faces": v[2:4], "owned_dofs": v[4:6], "ghost_dofs": v[6:8],
            "ghost_dofs_all": v[8]}


def cost_lines(text):
    """(flow DoFs, peak MB per rank max, MB in all) of each piece's Cost line."""
    return [(int(m.group(1)), float(m.group(2)), float(m.group(3))) for m in re.finditer(
        r"\((\d+) flow DoFs, operator [^)]*\), peak memory ([\d.e+-]+) MB per rank \(max\), ([\d.e+-]+) MB in all",
        text)]


def monitoring(prefix, ranks):
    """Point-to-point bytes and messages between the ranks and collective messages, summed
    over the ranks' Open MPI monitoring files PREFIX.R.prof."""
    result = {"p2p_bytes": 0, "p2p_messages": 0, "collective_bytes": 0, "collective_messages": 0}
    for r in range(ranks):
        path = f"{prefix}.{r}.prof"
        if not os.path.exists(path):
            return None
        for line in open(path):
            m = re.match(r"([EC])\t(\d+)\t(\d+)\t(\d+) bytes\t(\d+) msgs sent", line)
            if m and m.group(2) != m.group(3):
                key = "p2p" if m.group(1) == "E" else "collective"
                result[key + "_bytes"] += int(m.group(4))
                result[key + "_messages"] += int(m.group(5))
    return result


def span(work, source, ranks, end_time, env):
    """Resumes a copy of SOURCE (its fields left out) to END_TIME on RANKS ranks; returns
    the span's figures."""
    name = f"span_{ranks}"
    folder = os.path.join(work, name)
    shutil.rmtree(folder, ignore_errors=True)
    shutil.copytree(source, folder, ignore=shutil.ignore_patterns("fields_*", "*.h5", "*.xdmf"))
    prm = os.path.join(work, name + ".prm")
    open(prm, "w").write(case_text(folder, end_time, wall_interval=0, at_end=False))
    prefix = os.path.join(work, name + "_mpi")
    for old in os.listdir(work):
        if old.startswith(name + "_mpi"):
            os.remove(os.path.join(work, old))
    command = ["mpirun", "-np", str(ranks)]
    if ranks > 1:
        command += ["--mca", "pml_monitoring_enable", "2", "--mca", "pml_monitoring_enable_output", "3",
                    "--mca", "pml_monitoring_filename", prefix]
    command += [os.path.join(root, "build", "wetbed"), prm, "--resume"]
    log = os.path.join(work, name + ".log")
    with open(log, "w") as out:
        code = subprocess.run(command, stdout=out, stderr=subprocess.STDOUT, env=env).returncode
    text = open(log).read()
    fin = re.search(r"Finished: (\d+) steps \((\d+) rejected\), wall ([\d.e+-]+) s", text)
    if code != 0 or not fin:
        raise SystemExit(f"{name} failed (exit {code}): see {log}")
    m = wetbed_results.monitors(folder)
    first = int(re.search(r"Resumed run \S+ from .* \(step (\d+)\)", text).group(1))
    steps = int(fin.group(1)) - first
    ect = timer_seconds(text, "ECT sensor")
    ect = 0.0 if math.isnan(ect) else ect
    wall = float(fin.group(3))
    figures = {"ranks": ranks, "steps": steps, "wall": wall, "ect": ect, "per_step": (wall - ect) / steps,
               "fgmres_per_step": sum(m["krylov_iterations"][-steps:]) / steps,
               "memory": cost_lines(text)[-1], "partition": partition(text)}
    if ranks > 1:
        figures["mpi"] = monitoring(prefix, ranks)
    return figures


def model(w1, w2, memory1, memory2, dofs, mpi, steps, bandwidth, latency):
    """Wall per step and memory per rank for MODEL_RANKS from the 1- and 2-rank figures:
    W(P) = f W1/P + n(P) (V/2 / B + M/2 L) + K ceil(log2 P) L, with f = W2 / (W1/2) the
    2-rank factor (the ranks' imbalance and their sharing of one node's memory bus, the
    shared-memory messages included), V and M the bytes and messages per step across one
    partition interface (both directions), n(P) the interfaces of a rank (1 for 2 ranks,
    2 beyond: slabs along the axis), K the collective operations per step (on 2 ranks
    each sends one message per operation), B and L the network's bandwidth and latency."""
    factor = w2 / (w1 / 2)
    volume, messages = mpi["p2p_bytes"] / steps, mpi["p2p_messages"] / steps
    collectives = mpi["collective_messages"] / steps / 2
    fixed = memory2 - memory1  # MB a rank adds: memory2 = 2 a + b N, memory1 = a + b N
    per_dof = (memory1 - fixed) / dofs
    rows = []
    for p in MODEL_RANKS:
        neighbours = 2
        communication = neighbours * (volume / 2 / bandwidth + messages / 2 * latency)
        reductions = collectives * math.ceil(math.log2(p)) * latency
        w = factor * w1 / p + communication + reductions
        rows.append({"ranks": p, "per_step": w, "efficiency": w1 / (p * w), "communication": communication,
                     "reductions": reductions, "memory_per_rank": fixed + per_dof * dofs / p})
    return {"factor": factor, "volume": volume, "messages": messages, "collectives": collectives,
            "fixed": fixed, "per_dof": per_dof, "rows": rows}


def report(stored, bandwidth, latency):
    run, spans = stored["run"], stored["spans"]
    one, two = spans["1"], spans["2"]
    part = two["partition"]
    mpi = two.get("mpi") or {}
    w1, w2 = one["per_step"], two["per_step"]
    dofs = two["memory"][0]
    fit = model(w1, w2, one["memory"][2], two["memory"][2], dofs, mpi, two["steps"], bandwidth, latency)
    layers = int(re.search(r"n_layers: (\d+)", read_case(CASE)).group(1))
    planes = part["ghost_dofs_all"] / (dofs / (2 * layers + 1))  # Q2 node planes along the axis
    dt = run["simulated"] / run["steps"]
    lines = [
        f"Command: `python3 benchmarks/large_column.py --end-time {run['end_time']:g} --span {stored['span']:g}"
        f"{' --spans-only' if stored.get('spans_only') else ''}` "
        "(2 ranks, the base mesh without refinement; the spans one after the other on the same 2 cores).",
        "",
        "| run | figure |", "|---|---|",
        f"| `prm/seed000_large_column.prm` dry from rest, 2 ranks | {run['simulated']:.3f} s of {run['end_time']:g} s simulated in "
        f"{run['steps']} steps ({run['rejected']} rejected), {run['wall']:.0f} s of wall time: "
        f"**{run['wall'] / run['simulated']:.0f} s per simulated second** |",
        f"| cost per step | {run['wall'] / run['steps']:.2f} s: {1e6 * run['wall'] / run['steps'] / run['cells']:.0f} µs "
        f"per cell, {1e6 * run['wall'] / run['steps'] / dofs:.2f} µs per flow DoF ({run['cells']:,} cells, "
        f"{dofs:,} flow DoFs); FGMRES {run['fgmres_per_step']:.2f} per step; mean Δt {1e3 * dt:.2f} ms |",
        f"| state at {run['simulated']:.2f} s | FI {run['fi']:.2f} (probe {run['fi_probe']:.2f}), bed surface "
        f"{100 * run['bed_height']:.1f} cm, α_s ≤ {run['alpha_max']:.3f}, mass drift {run['mass_drift']:.1e} |",
        f"| peak memory | 1 rank {one['memory'][1]:,.0f} MB; 2 ranks {two['memory'][1]:,.0f} MB per rank (max), "
        f"{two['memory'][2]:,.0f} MB in all = {1e3 * two['memory'][2] / dofs:.2f} kB per flow DoF, "
        f"{1e3 * two['memory'][2] / run['cells']:.0f} kB per cell |",
        f"| partition (2 ranks) | owned cells {part['cells'][0]:,.0f}–{part['cells'][1]:,.0f}, wall faces "
        f"{part['wall_faces'][0]:,.0f}–{part['wall_faces'][1]:,.0f}, owned flow DoFs {part['owned_dofs'][0]:,.0f}–"
        f"{part['owned_dofs'][1]:,.0f}, ghost flow DoFs {part['ghost_dofs_all']:,.0f} in all "
        f"({100 * part['ghost_dofs_all'] / dofs:.1f}% of the flow DoFs, those of {planes:.1f} planes of Q2 nodes across "
        "the column: the partition cuts it into slabs along its axis) |",
    ]
    if mpi:
        steps = two["steps"]
        lines.append(
            f"| communication (2-rank span, per step) | point to point {mpi['p2p_bytes'] / steps / 1e6:.1f} MB in "
            f"{mpi['p2p_messages'] / steps:,.0f} messages between the ranks "
            f"({mpi['p2p_bytes'] / max(mpi['p2p_messages'], 1) / 1e3:.1f} kB each); collectives "
            f"{mpi['collective_messages'] / steps:,.0f} messages, {mpi['collective_bytes'] / steps / 1e3:.0f} kB |")
    lines += [
        "",
        f"Strong scaling over the same {stored['span'] * 1e3:g} ms resumed at t = {run['simulated']:.3f} s (wall per "
        "step with the ECT sensor's one-off location taken out; s per simulated s at the run's mean Δt so far). "
        f"Model rows: W(P) = f W1/P + 2 (V/2/B + M/2 L) + K ⌈log2 P⌉ L with the 2-rank factor f = W2/(W1/2) = "
        f"{fit['factor']:.3f}, V = {fit['volume'] / 1e6:.1f} MB and M = {fit['messages']:,.0f} messages per step across "
        f"one interface, K = {fit['collectives']:,.0f} collective operations per step (measured above), and a network "
        f"of B = {bandwidth / 1e9:g} GB/s and L = {latency * 1e6:g} µs (assumed); memory per rank "
        f"{fit['fixed']:,.0f} MB + {1e3 * fit['per_dof']:.2f} kB per flow DoF / P:",
        "",
        "| ranks | wall per step (s) | speed-up | efficiency | s per simulated s | memory per rank (MB) | source |",
        "|---|---|---|---|---|---|---|",
        f"| 1 | {w1:.2f} | 1 | 1 | {w1 / dt:,.0f} | {one['memory'][1]:,.0f} | measured ({one['steps']} steps, "
        f"FGMRES {one['fgmres_per_step']:.2f} per step) |",
        f"| 2 | {w2:.2f} | {w1 / w2:.2f} | {w1 / (2 * w2):.2f} | {w2 / dt:,.0f} | {two['memory'][1]:,.0f} | measured "
        f"({two['steps']} steps, FGMRES {two['fgmres_per_step']:.2f} per step) |",
    ]
    for r in fit["rows"]:
        lines.append(f"| {r['ranks']} | {r['per_step']:.2f} | {w1 / r['per_step']:.1f} | {r['efficiency']:.2f} | "
                     f"{r['per_step'] / dt:,.0f} | {r['memory_per_rank']:,.0f} | model (messages "
                     f"{1e3 * r['communication']:.0f} ms, reductions {1e3 * r['reductions']:.0f} ms) |")
    return lines


def main():
    global CASE
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--end-time", type=float, default=0.2)
    parser.add_argument("--span", type=float, default=0.006)
    parser.add_argument("--report", action="store_true", help="rewrite the doc section from what is stored")
    parser.add_argument("--bandwidth", type=float, default=10e9, help="the model's network bandwidth, B/s")
    parser.add_argument("--latency", type=float, default=2e-6, help="the model's network latency, s")
    parser.add_argument("--spans-only", action="store_true",
                        help="the spans from where the run stopped (its checkpoint), the run not continued")
    parser.add_argument("--case", default=CASE, help=argparse.SUPPRESS)  # the script's own check, on a small case
    args = parser.parse_args()
    CASE = args.case
    tag = "large_column" if CASE == "seed000_large_column" else "large_column_" + CASE
    work = os.path.join(root, "build", "benchmarks", tag)
    results = os.path.join(root, "build", "benchmarks", tag, "results") if tag != "large_column" else \
        os.path.join(root, "benchmarks", "results", "large_column")
    os.makedirs(work, exist_ok=True)
    os.makedirs(results, exist_ok=True)
    stored_path = os.path.join(results, "summary.json")
    if not args.report:
        env = dict(os.environ, OMPI_MCA_rmaps_base_oversubscribe="1")
        folder, prm = os.path.join(work, "run_2"), os.path.join(work, "run_2.prm")
        wall_file = os.path.join(work, "run_2.wall")
        if args.spans_only:
            if not os.path.isdir(os.path.join(folder, "checkpoint")):
                sys.exit("--spans-only: the run has no checkpoint yet")
            wall = float(open(wall_file).read())
        else:
            open(prm, "w").write(case_text(folder, args.end_time))
            code, wall = run_resumable(["mpirun", "-np", "2", os.path.join(root, "build", "wetbed"), prm], folder,
                                       os.path.join(work, "run_2.log"), wall_file, True, env, args.end_time)
            if code == 4:
                sys.exit("the run stopped with a checkpoint: call again to continue it")
            if code != 0:
                sys.exit(f"the run failed (exit {code}): see {work}/run_2.log")
        m = wetbed_results.monitors(folder)
        text = open(os.path.join(work, "run_2.log")).read()
        run = {"end_time": args.end_time, "simulated": m["time"][-1], "steps": int(m["step"][-1]),
               "rejected": int(m["rejected_steps"][-1]), "wall": wall,
               "cells": int(m["active_cells"][-1]), "fgmres_per_step": sum(m["krylov_iterations"]) / max(m["step"][-1], 1),
               "fi": m["fluidization_index"][-1], "fi_probe": (m.get("probe_fluidization_index") or [float("nan")])[-1],
               "bed_height": m["bed_surface_height"][-1], "alpha_max": m["alpha_s_max"][-1],
               "mass_drift": m["solids_mass_drift"][-1], "memory": cost_lines(text)}
        spans = {}
        for ranks in (1, 2):
            spans[str(ranks)] = span(work, folder, ranks, last_time(folder) + args.span, env)
            print(f"span on {ranks} rank(s): {spans[str(ranks)]['per_step']:.2f} s per step", flush=True)
        json.dump({"run": run, "spans": spans, "span": args.span, "spans_only": args.spans_only},
                  open(stored_path, "w"), indent=1)
    lines = report(json.load(open(stored_path)), args.bandwidth, args.latency)
    print("\n".join(lines))
    if tag == "large_column":
        replace_doc_section(root, "large_column", "The large column: cost, memory and scaling", lines)


if __name__ == "__main__":
    main()
