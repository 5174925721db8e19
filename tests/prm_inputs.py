#!/usr/bin/env python3
"""T15: every prm/*.prm runs a few steps; a corpus of bad inputs each exits with status 2,
a one-line message naming the parameter (or file) and no change to existing results.

usage: prm_inputs.py WETBED_EXECUTABLE SOURCE_DIR WORK_DIR
"""
import hashlib
import os
import shutil
import subprocess
import sys

wetbed, source, work = (os.path.abspath(a) for a in sys.argv[1:4])
os.makedirs(work, exist_ok=True)
failures = []


def run(prm_text, name):
    path = os.path.join(work, name + ".prm")
    with open(path, "w") as f:
        f.write(prm_text)
    p = subprocess.run([wetbed, path], capture_output=True, text=True, timeout=600)
    return p.returncode, p.stdout, p.stderr


def override(base, lines):
    """Appends subsection overrides (a later `set` wins in deal.II's ParameterHandler)."""
    return base + "\n" + lines + "\n"


def with_mesh(text, prm_file):
    mesh_dir = os.path.join(source, "meshes")
    # make relative mesh paths absolute (the copies live in WORK_DIR)
    out = []
    for line in text.splitlines():
        if line.strip().startswith("set file") and "../meshes/" in line:
            line = line.replace("../meshes/", mesh_dir + "/")
        out.append(line)
    return "\n".join(out) + "\n"


# 1. every shipped case parses and runs a few steps
for prm in sorted(os.listdir(os.path.join(source, "prm"))):
    if not prm.endswith(".prm"):
        continue
    text = with_mesh(open(os.path.join(source, "prm", prm)).read(), prm)
    folder = os.path.join(work, "good_" + prm[:-4])
    text = override(text, f"subsection time stepping\n set end time = 3e-4\n set initial time step = 1e-4\nend\n"
                          f"subsection output\n set folder = {folder}\n set field interval = 0\nend")
    code, out, err = run(text, "good_" + prm[:-4])
    if code != 0 or not os.path.isfile(os.path.join(folder, "monitors.csv")):
        failures.append(f"{prm}: exit {code}: {err.strip()[-300:]}")
    else:
        print(f"ok   {prm} runs ({len(open(os.path.join(folder, 'monitors.csv')).readlines()) - 1} rows)")

# 2. bad inputs, each against a valid base that already wrote results
base = with_mesh(open(os.path.join(source, "prm", "bubbling_bed_2d.prm")).read(), "base")
results = os.path.join(work, "existing_results")
base = override(base, f"subsection output\n set folder = {results}\n set field interval = 0\nend")
code, _, err = run(override(base, "subsection time stepping\n set end time = 2e-4\nend"), "base_run")
if code != 0:
    failures.append("base run failed: " + err)
monitors = os.path.join(results, "monitors.csv")
digest = hashlib.sha256(open(monitors, "rb").read()).hexdigest() if os.path.isfile(monitors) else None

cases = [
    ("syntax error", "subsection drag\n set model Gidaspow\nend", "cannot be parsed"),
    ("unknown parameter", "subsection drag\n set colour = red\nend", "colour"),
    ("unknown subsection", "subsection nonsense\n set model = x\nend", "nonsense"),
    ("unknown drag law", "subsection drag\n set model = Stokes\nend", "model"),
    ("unknown rheology", "subsection solids stress\n set model = magic\nend", "model"),
    ("dimension 4", "set dimension = 4", "dimension"),
    ("negative diameter", "subsection physical properties\n set particle diameter = -1e-4\nend", "physical properties/particle diameter"),
    ("zero particle density", "subsection physical properties\n set particle density = 0\nend", "physical properties/particle density"),
    ("solids lighter than gas", "subsection physical properties\n set particle density = 1.0\nend", "physical properties/particle density"),
    ("negative gas viscosity", "subsection physical properties\n set gas viscosity = -1\nend", "physical properties/gas viscosity"),
    ("maximum packing above 1", "subsection physical properties\n set maximum packing = 1.2\nend", "physical properties/maximum packing"),
    ("gravity with two numbers", "subsection physical properties\n set gravity = 0, -9.81\nend", "physical properties/gravity"),
    ("gravity not a number", "subsection physical properties\n set gravity = 0, down, 0\nend", "physical properties/gravity"),
    ("zero gravity", "subsection physical properties\n set gravity = 0, 0, 0\nend", "physical properties/gravity"),
    ("onset above packing", "subsection solids stress\n set frictional onset = 0.65\nend", "solids stress/frictional onset"),
    ("negative viscosity", "subsection solids stress\n set shear viscosity = -0.1\nend", "solids stress/shear viscosity"),
    ("packing distance too large", "subsection solids stress\n set minimum packing distance = 0.05\nend", "solids stress/minimum packing distance"),
    ("bed fraction above packing", "subsection initial conditions\n set bed solids fraction = 0.7\nend", "initial conditions/bed solids fraction"),
    ("negative bed height", "subsection initial conditions\n set bed height = -0.1\nend", "initial conditions/bed height"),
    ("bad inlet expression", "subsection boundary conditions\n set inlet superficial velocity = 0.8*)\nend", "boundary conditions/inlet superficial velocity"),
    ("partial slip without friction", "subsection boundary conditions\n set solids wall condition = partial-slip\nend", "boundary conditions/solids wall friction"),
    ("Johnson-Jackson for the gas", "subsection boundary conditions\n set gas wall condition = Johnson-Jackson\nend", "boundary conditions/gas wall condition"),
    ("unknown wall condition", "subsection boundary conditions\n set solids wall condition = sticky\nend", "boundary conditions/solids wall condition"),
    ("wall condition for the inlet", "subsection boundary conditions\n set solids wall condition = free-slip; inlet: Johnson-Jackson\nend", "boundary conditions/solids wall condition"),
    ("wall group given two conditions", "subsection boundary conditions\n set solids wall condition = wall: free-slip; wall: no-slip\nend", "boundary conditions/solids wall condition"),
    ("two default wall conditions", "subsection boundary conditions\n set gas wall condition = no-slip; free-slip\nend", "boundary conditions/gas wall condition"),
    ("gas partial slip without friction", "subsection boundary conditions\n set gas wall condition = partial-slip\nend", "boundary conditions/gas wall friction"),
    ("a wall group without a condition", f"subsection mesh\n set file = {os.path.join(source, 'tests', 'meshes', 'column_2d_split_wall.geo')}\n set wall = wall_left, wall_right\nend\nsubsection boundary conditions\n set solids wall condition = wall_left: Johnson-Jackson\nend", "boundary conditions/solids wall condition"),
    ("zero end time", "subsection time stepping\n set end time = 0\nend", "time stepping/end time"),
    ("negative time step", "subsection time stepping\n set initial time step = -1e-4\nend", "time stepping/initial time step"),
    ("time step above maximum", "subsection time stepping\n set initial time step = 1\nend", "time stepping/initial time step"),
    ("transport cfl above 1", "subsection time stepping\n set transport cfl = 2\nend", "time stepping/transport cfl"),
    ("bdf order 3", "subsection time stepping\n set bdf order = 3\nend", "bdf order"),
    ("tolerance 0", "subsection linear solver\n set relative tolerance = 0\nend", "linear solver/relative tolerance"),
    ("missing mesh", "subsection mesh\n set file = /nonexistent/column.geo\nend", "mesh/file"),
    ("mesh of wrong type", "subsection mesh\n set file = " + os.path.join(source, "README.md") + "\nend", "mesh/file"),
    ("unknown physical group", "subsection mesh\n set wall = side\nend", "mesh/wall"),
    ("cylinder in 2D", "subsection mesh\n set cylindrical wall = true\nend", "mesh/cylindrical wall"),
    ("corrupt mesh", None, "mesh/file"),
    ("wet particles without kinetic theory", "subsection solids stress\n set model = constant viscosity\nend\nsubsection boundary conditions\n set solids wall condition = free-slip\nend\nsubsection wet particles\n set liquid loading = 1e-3\nend", "wet particles/liquid loading"),
    ("wet particles with the algebraic Theta", "subsection kinetic theory\n set granular temperature = algebraic\nend\nsubsection wet particles\n set liquid loading = 1e-3\nend", "wet particles/liquid loading"),
    ("negative liquid viscosity", "subsection wet particles\n set liquid viscosity = -0.5\nend", "wet particles/liquid viscosity"),
    ("unknown rupture distance", "subsection wet particles\n set rupture distance = Newton\nend", "rupture distance"),
    ("angle of stability 90", "subsection wet particles\n set angle of stability = 90\nend", "wet particles/angle of stability"),
    ("negative checkpoint interval", "subsection checkpoint\n set interval = -5\nend", "interval"),
    ("resume without a checkpoint", f"subsection checkpoint\n set resume = true\nend\nsubsection output\n set folder = {os.path.join(work, 'never_run')}\nend", "checkpoint/resume"),
    ("resume from a damaged checkpoint", "damaged checkpoint", "checkpoint/resume"),
    ("resume from a garbage checkpoint state", "garbage checkpoint", "checkpoint/resume"),
    ("bubble gas threshold above 1", "subsection bubble analysis\n set gas fraction threshold = 1.5\nend", "gas fraction threshold"),
    ("bubble analysis every 0 steps", "subsection bubble analysis\n set interval = 0\nend", "interval"),
    ("pressure drop with one plane", "subsection bed monitors\n set pressure drop between = 0.05\nend", "bed monitors/pressure drop between"),
    ("3D point probe in a 2D case", "subsection bed monitors\n set point probes = 0.01, 0.02, 0.03\nend", "bed monitors/point probes"),
    ("point probe not a number", "subsection bed monitors\n set point probes = 0.01, high\nend", "bed monitors/point probes"),
    ("zero Welch segments", "subsection spectrum\n set segments = 0\nend", "segments"),
    ("periodic boundaries with one group", "subsection mesh\n set periodic boundaries = inlet\nend", "mesh/periodic boundaries"),
    ("periodic boundaries that are the wall", "subsection mesh\n set periodic boundaries = wall, outlet\nend", "mesh/periodic boundaries"),
    ("periodic group not in the mesh", "subsection mesh\n set periodic boundaries = front, back\nend", "mesh/periodic boundaries"),
    ("periodic faces that do not match", "subsection mesh\n set inlet =\n set outlet =\n set periodic boundaries = inlet, outlet\n set periodic direction = x\nend", "mesh/periodic boundaries"),
    ("inlet without an outlet", "subsection mesh\n set outlet =\nend", "mesh/outlet"),
    ("inlet group named twice", "subsection mesh\n set inlet = inlet, inlet\nend", "mesh/inlet"),
    ("wall group that is the outlet", "subsection mesh\n set wall = wall, outlet\nend", "mesh/wall"),
    ("one of two inlet groups not in the mesh", "subsection mesh\n set inlet = inlet, side\nend", "mesh/inlet"),
    ("empty name in a group list", "subsection mesh\n set outlet = outlet, , \nend", "mesh/outlet"),
    ("moving wall not in the mesh", "subsection boundary conditions\n set moving wall = lid\nend", "boundary conditions/moving wall"),
    ("moving wall that is the inlet", "subsection boundary conditions\n set moving wall = inlet\nend", "boundary conditions/moving wall"),
    ("moving wall velocity not a number", "subsection boundary conditions\n set moving wall velocity = 0, fast, 0\nend", "boundary conditions/moving wall velocity"),
    ("moving wall velocity through the wall", f"subsection mesh\n set file = {os.path.join(source, 'meshes', 'couette_cell_2d.geo')}\n set inlet =\n set outlet =\n set periodic boundaries = bottom, top\nend\nsubsection boundary conditions\n set moving wall = moving wall\n set moving wall velocity = 0.5, 0, 0\nend", "boundary conditions/moving wall velocity"),
    ("unwritable output folder", "subsection output\n set folder = /proc/wetbed-output\nend", "output/folder"),
]
corrupt = os.path.join(work, "corrupt.msh")
with open(corrupt, "w") as f:
    f.write("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PhysicalNames\n3\n1 1 \"inlet\"\n1 2 \"outlet\"\n1 3 \"wall\"\n$EndPhysicalNames\n$Nodes\ngarbage\n")
# copies of the base run's folder (it wrote a checkpoint at its end) with one file spoilt
damaged = {}
for kind, spoil in (("damaged checkpoint", "triangulation_fixed.data"), ("garbage checkpoint", "state")):
    folder = os.path.join(work, kind.replace(" ", "_"))
    shutil.rmtree(folder, ignore_errors=True)
    shutil.copytree(results, folder)
    with open(os.path.join(folder, "checkpoint", spoil), "r+b") as f:
        f.seek(40)
        f.write(b"garbage")
    damaged[kind] = (f"subsection checkpoint\n set resume = true\nend\nsubsection output\n set folder = {folder}\nend",
                     os.path.join(folder, "monitors.csv"), hashlib.sha256(open(os.path.join(folder, "monitors.csv"), "rb").read()).hexdigest())
for description, lines, expected in cases:
    if lines is None:
        lines = f"subsection mesh\n set file = {corrupt}\nend"
    spoilt = damaged.get(lines)
    if spoilt:
        lines = spoilt[0]
    code, out, err = run(override(base, lines), "bad")
    message = err.strip().splitlines()[-1] if err.strip() else ""
    if code != 2 or expected not in message:
        failures.append(f"bad input '{description}': exit {code}, message '{message[:300]}'")
    else:
        print(f"ok   {description}: {message[:140]}")
    if spoilt and hashlib.sha256(open(spoilt[1], "rb").read()).hexdigest() != spoilt[2]:
        failures.append(f"bad input '{description}': the run's monitors.csv was changed")
if digest and hashlib.sha256(open(monitors, "rb").read()).hexdigest() != digest:
    failures.append("an existing monitors.csv was changed by a bad-input run")

# 3. the command line
for args, expected_code in ((["--help"], 0), (["--print-parameters"], 0), ([], 1), (["/nonexistent.prm"], 2)):
    p = subprocess.run([wetbed] + args, capture_output=True, text=True)
    if p.returncode != expected_code:
        failures.append(f"wetbed {' '.join(args)}: exit {p.returncode}, expected {expected_code}")
# --threads N (threads per rank): anything but an integer >= 1 exits 2 naming it
for args in (["--threads", "0"], ["--threads", "two"], ["--threads", "2.5"], ["--threads"]):
    p = subprocess.run([wetbed, os.path.join(source, "prm", "bubbling_bed_2d.prm")] + args,
                       capture_output=True, text=True)
    message = p.stderr.strip().splitlines()[-1] if p.stderr.strip() else ""
    if p.returncode != 2 or not message.startswith("wetbed: error: --threads"):
        failures.append(f"wetbed CASE {' '.join(args)}: exit {p.returncode}, message '{message}'")

# 4. wetbed closures: the wet case reports the regimes; bad options exit 2 naming them
wet_case = os.path.join(work, "wet_closures.prm")
with open(wet_case, "w") as f:
    f.write(with_mesh(open(os.path.join(source, "prm", "wet_column_2d.prm")).read(), "wet"))
p = subprocess.run([wetbed, "closures", wet_case, "--alpha-s", "0.2,0.45,0.59"], capture_output=True, text=True)
lines = p.stdout.strip().splitlines()
header = lines[0].split(",") if lines else []
regimes = [row.split(",")[header.index("regime")] for row in lines[1:]] if "regime" in header else []
if p.returncode != 0 or regimes != ["ruptured", "bridged", "contact"]:
    failures.append(f"wetbed closures (wet): exit {p.returncode}, regimes {regimes}")
for args, expected in ((["--alpha-s", "0.3,x"], "--alpha-s"), (["--theta", "-1"], "Theta"),
                       (["--colour", "red"], "--colour"), (["--points", "/nonexistent"], "/nonexistent")):
    p = subprocess.run([wetbed, "closures", wet_case] + args, capture_output=True, text=True)
    if p.returncode != 2 or expected not in p.stderr:
        failures.append(f"wetbed closures {' '.join(args)}: exit {p.returncode}, '{p.stderr.strip()}'")

# 5. wetbed spectrum: bad files and options exit 2 naming them
for args, expected in (([monitors, "--columns", "colour"], "colour"), (["/nonexistent.csv"], "/nonexistent.csv"),
                       ([monitors, "--start", "soon"], "--start"), ([monitors, "--segments", "0"], "--segments"),
                       ([monitors, "--start", "1e9"], "fewer than 16 samples")):
    p = subprocess.run([wetbed, "spectrum"] + args, capture_output=True, text=True)
    if p.returncode != 2 or expected not in p.stderr:
        failures.append(f"wetbed spectrum {' '.join(args)}: exit {p.returncode}, '{p.stderr.strip()}'")

n = len(cases)
print(f"{n} bad-input cases checked")
for f in failures:
    print("FAILED:", f)
print(f"{n + 14 - len(failures)} passed, {len(failures)} failed")
sys.exit(1 if failures else 0)
