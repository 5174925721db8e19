#!/usr/bin/env python3
"""Cost of a case (by default the 3D column, prm/column_3d.prm; `--cases` for others, the
2D beds included) with each flow-solve path, side by side in one run on the same cores: `assembled` (the Trilinos matrix, ML on the Q2 velocity
block), `matrix-free` operator with the same ML preconditioner, and `matrix-free` with
the velocity p-multigrid; `default` sets nothing (`operator = automatic`: the
p-multigrid path in 3D). Scenes: `dry` (the shipped case), `wet` (with the wet-particle
closures of prm/wet_column_2d.prm), `amr` (adaptive refinement around the bubbles, one
level above the mesh, hanging nodes). For each refinement and path: wall time per simulated second
over the same simulated span, us per flow DoF per step, FGMRES iterations per solve,
peak memory per rank and per flow DoF, the bytes per flow DoF of the
operator, L_c and the p-multigrid (ML hierarchies not counted), the timer split, the ratio to
the assembled path and the largest relative difference of the pressure drop from the
assembled path's at the same step. Regenerates the 'cost_3d' section of doc/benchmarks.md
(another scene, other cases or --section: that section).

usage: python3 benchmarks/cost_3d.py [--end-time 5e-4] [--ranks 2] [--levels 0 1]
       [--paths assembled matrix-free p-multigrid default] [--end-time-level-1 T]
       [--scene dry|wet|amr] [--cases column_3d ...] [--section NAME]
(build first: bash scripts/build.sh)
"""
import argparse
import csv
import json
import os
import re
import subprocess

from benchmark_setup import read_case, replace_doc_section, repository_root, write_case

root = repository_root()
parser = argparse.ArgumentParser()
parser.add_argument("--end-time", type=float, default=5e-4, help="simulated span (s) at refinement 0")
parser.add_argument("--end-time-level-1", type=float, default=None, help="span at refinement 1 (default: --end-time)")
parser.add_argument("--ranks", type=int, default=2)
parser.add_argument("--levels", type=int, nargs="+", default=[0, 1])
parser.add_argument("--paths", nargs="+", default=["assembled", "matrix-free", "p-multigrid"])
parser.add_argument("--scene", choices=["dry", "wet", "amr"], default="dry")
parser.add_argument("--cases", nargs="+", default=["column_3d"],
                    help="shipped cases (prm/NAME.prm); NAME@L runs NAME at refinement L only")
parser.add_argument("--exact-solves", action="store_true",
                    help="every flow solve to the linear tolerance (`outer tolerance = 0`): the paths' pressure drops "
                         "then differ by the solver tolerance, not by the inexact outer iterations")
parser.add_argument("--section", default=None, help="doc section (default: cost_3d, or cost_3d_SCENE)")
parser.add_argument("--no-doc", action="store_true")
parser.add_argument("--replot", action="store_true", help="tabulate the cached results.json (same arguments)")
args = parser.parse_args()

settings = {
    "assembled": "subsection linear solver\n  set operator = assembled\n  set velocity preconditioner = AMG\nend\n",
    "matrix-free": "subsection linear solver\n  set operator = matrix-free\n  set velocity preconditioner = AMG\nend\n",
    "p-multigrid": "subsection linear solver\n  set operator = matrix-free\n  set velocity preconditioner = p-multigrid\nend\n",
    "default": "",
}
section = args.section or (("cost_3d" if args.cases == ["column_3d"] else "cost_paths")
                           + ("" if args.scene == "dry" else "_" + args.scene)
                           + ("_exact" if args.exact_solves else ""))
exact = "subsection time stepping\n  set outer tolerance = 0\nend\n" if args.exact_solves else ""
scene = ""
if args.scene == "wet":
    wet_case = open(os.path.join(root, "prm", "wet_column_2d.prm")).read()
    start = wet_case.index("subsection wet particles")
    scene = "\n" + wet_case[start:wet_case.index("\nend", start) + 4] + "\n"
elif args.scene == "amr":
    scene = ("subsection adaptive refinement\n  set enabled = true\n  set interval = 2\n  set initial cycles = 1\n"
             "  set maximum level = 1\n  set minimum level = 0\nend\n")
work = os.path.join(root, "build", "benchmarks", section)
os.makedirs(work, exist_ok=True)
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
results = json.load(open(os.path.join(work, "results.json"))) if args.replot else []
runs = [(spec.split("@")[0], level) for spec in args.cases
        for level in ([int(spec.split("@")[1])] if "@" in spec else args.levels)]
for case, level in ([] if args.replot else runs):
    base = read_case(case)
    span = args.end_time_level_1 if (level >= 1 and args.end_time_level_1) else args.end_time
    for path in args.paths:
        name = f"level_{level}_{path}" if args.cases == ["column_3d"] else f"{case}_level_{level}_{path}"
        prm, folder, _ = write_case(work, name, base, span,
                                    f"\nsubsection mesh\n  set initial refinement = {level}\nend\n"
                                    "subsection spectrum\n  set enabled = false\nend\n" + scene + exact + settings[path],
                                    field_interval=0, progress_interval=100000)
        p = subprocess.run(["mpirun", "--oversubscribe", "-np", str(args.ranks), os.path.join(root, "build", "wetbed"),
                            prm, "--overwrite"], capture_output=True, text=True, env=env)
        out = p.stdout
        if p.returncode != 0:
            print(f"{name}: exit {p.returncode}\n{out[-3000:]}\n{p.stderr[-2000:]}")
            continue
        cells = int(re.search(r"Mesh: (\d+) cells", out).group(1))
        fin = re.search(r"Finished: (\d+) steps \((\d+) rejected\), wall ([\d.e+-]+) s, ([\d.e+-]+) s per simulated second", out)
        cost = re.search(r"Cost: ([\d.e+-]+) us per flow DoF per step \((\d+) flow DoFs.*peak memory ([\d.e+-]+) MB per rank", out)
        parts = re.search(r"Flow solve memory .*?: operator ([\d.e+-]+), L_c ([\d.e+-]+), p-multigrid ([\d.e+-]+)", out)
        total = re.search(r"MB in all = ([\d.e+-]+) kB per flow DoF", out)
        sections = {}
        for m in re.finditer(r"^\| ([a-zA-Z -]+?)\s+\|\s+(\d+) \|\s+[\d.e+-]+s\s+\d+ \|\s+([\d.e+-]+)s \|", out, re.M):
            sections[m.group(1).strip()] = float(m.group(3))
        rows = list(csv.DictReader(open(os.path.join(folder, "monitors.csv"))))[1:]
        solves = max(1, int(re.search(r"^\| Krylov solve\s+\|\s+(\d+)", out, re.M).group(1)))
        per_solve = sum(int(r["krylov_iterations"]) for r in rows) / solves
        r = dict(case=case, level=level, path=path, pressure_drop=[float(x["pressure_drop"]) for x in rows], cells=cells, dofs=int(cost.group(2)), steps=int(fin.group(1)),
                 rejected=int(fin.group(2)), wall=float(fin.group(3)), per_second=float(fin.group(4)),
                 per_dof=float(cost.group(1)), memory=float(cost.group(3)), per_solve=per_solve, sections=sections,
                 span=span, peak_per_dof=float(total.group(1)),
                 solver_per_dof=sum(float(parts.group(i)) for i in (1, 2, 3)))
        results.append(r)
        print(f"{name}: {cells} cells, {r['dofs']} flow DoFs, {r['steps']} steps ({r['rejected']} rejected), "
              f"wall {r['wall']:.1f} s, {r['per_second']:.0f} s per simulated s, {r['per_dof']:.1f} us/DoF/step, "
              f"FGMRES {per_solve:.1f} per solve, peak {r['memory']:.0f} MB/rank, {r['peak_per_dof']:.1f} kB/DoF peak, "
              f"{r['solver_per_dof']:.0f} B/DoF operator + L_c + multigrid", flush=True)
if not args.replot:
    json.dump(results, open(os.path.join(work, "results.json"), "w"), indent=1)

names = ["flow assembly", "matrix-free coefficients", "preconditioner setup", "Krylov solve", "alpha transport",
         "solids pressure correction"]
lines = [f"Command: `python3 benchmarks/cost_3d.py --end-time {args.end_time}"
         + (f" --end-time-level-1 {args.end_time_level_1}" if args.end_time_level_1 else "")
         + f" --ranks {args.ranks}"
         + ("" if all("@" in c for c in args.cases) else f" --levels {' '.join(map(str, args.levels))}")
         + f" --paths {' '.join(args.paths)}"
         + (" --exact-solves" if args.exact_solves else "")
         + (f" --scene {args.scene}" if args.scene != "dry" else "")
         + (f" --cases {' '.join(args.cases)}" if args.cases != ["column_3d"] else "")
         + (f" --section {args.section}" if args.section else "") + "` "
         f"({', '.join(f'`prm/{c.split(chr(64))[0]}.prm`' for c in args.cases)}{'' if args.scene == 'dry' else ', scene ' + args.scene}, {args.ranks} MPI rank(s) on this 2-core machine, "
         "the paths run one after another in one invocation"
         + ("; every flow solve to the linear tolerance, `outer tolerance = 0`" if args.exact_solves else "")
         + "; ΔP difference: the largest relative difference of the "
         "pressure drop from the assembled path's at the same step).", "",
         "| case | refinement | cells | flow DoFs | path | simulated s | steps (rejected) | wall s | s per simulated s | "
         "speed-up vs assembled | stepping s per simulated s | stepping speed-up | µs per DoF per step | "
         "FGMRES its per solve | ΔP difference vs assembled | peak MB per rank | "
         "peak kB per DoF (all ranks) | operator + L_c + multigrid B per DoF | "
         + " | ".join(n + " s" for n in names) + " |",
         "|" + "---|" * (18 + len(names))]


def stepping(r):
    """s per simulated s without the field output and the checkpoint, which the run writes
    at its start and end and a production run every 0.05 s of simulated time and every
    15 minutes of wall time (a few steps here carry two outputs and one checkpoint)."""
    fixed = r["sections"].get("output", 0) + r["sections"].get("checkpoint", 0)
    return (r["wall"] - fixed) / r["span"]


def pressure_difference(r, reference):
    """The largest relative difference of r's pressure drop from the reference's over the
    steps both recorded ('—' without a reference or where the step counts differ)."""
    a, b = r.get("pressure_drop"), reference.get("pressure_drop") if reference else None
    if not a or not b or len(a) != len(b):
        return "—"
    scale = max(abs(x) for x in b) or 1.0
    return f"{max(abs(x - y) for x, y in zip(a, b)) / scale:.1e}"


for r in results:
    r.setdefault("case", "column_3d")
    reference = next((x for x in results if x.get("case", "column_3d") == r["case"] and x["level"] == r["level"]
                      and x["path"] == "assembled"), None)
    ratio = f"{reference['per_second'] / r['per_second']:.2f}×" if reference else "—"
    step_ratio = f"{stepping(reference) / stepping(r):.2f}×" if reference else "—"
    lines.append(f"| {r['case']} | {r['level']} | {r['cells']} | {r['dofs']} | {r['path']} | {r['span']:g} | {r['steps']} ({r['rejected']}) | "
                 f"{r['wall']:.1f} | {r['per_second']:.0f} | {ratio} | {stepping(r):.0f} | {step_ratio} | "
                 f"{r['per_dof']:.1f} | {r['per_solve']:.1f} | {pressure_difference(r, reference)} | "
                 f"{r['memory']:.0f} | {r.get('peak_per_dof', 0):.1f} | {r.get('solver_per_dof', 0):.0f} | " + " | ".join(f"{r['sections'].get(n, 0):.1f}" for n in names) + " |")
levels = sorted({r["level"] for r in results})
for case, path in [(c.split("@")[0], p) for c in args.cases for p in args.paths]:
    runs = [next((r for r in results if r["case"] == case and r["level"] == l and r["path"] == path), None)
            for l in levels]
    if len(levels) >= 2 and all(runs):
        lines.append("")
        lines.append(f"FGMRES iterations per solve, {case}, {path}: " + " → ".join(f"{r['per_solve']:.1f}" for r in runs)
                     + f" over {len(levels) - 1} refinement(s) ({100 * (runs[-1]['per_solve'] / runs[0]['per_solve'] - 1):+.0f}%).")
for line in lines:
    print(line)
if not args.no_doc:
    # kept with the repository: benchmarks/cost_plot.py draws doc/cost_vs_dofs.png from it
    stored = os.path.join(root, "benchmarks", "results", "cost_3d")
    os.makedirs(stored, exist_ok=True)
    json.dump({"command": lines[0], "results": results}, open(os.path.join(stored, section + ".json"), "w"), indent=1)
    title = ("Cost of the 3D column by flow-solve path" if args.cases == ["column_3d"] else
             "Cost by flow-solve path: " + ", ".join(c.split("@")[0] for c in args.cases)) + ("" if args.scene == "dry" else f" ({args.scene})")
    replace_doc_section(root, section, title, lines)
    print("updated doc/benchmarks.md")
