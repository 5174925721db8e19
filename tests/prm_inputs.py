#!/usr/bin/env python3
"""T15: every prm/*.prm runs a few steps; a corpus of bad inputs each exits with status 2,
a one-line message naming the parameter (or file) and no change to existing results.

usage: prm_inputs.py WETBED_EXECUTABLE SOURCE_DIR WORK_DIR
"""
import csv
import fcntl
import hashlib
import json
import math
import os
import re
import shutil
import signal
import subprocess
import sys
import time

wetbed, source, work = (os.path.abspath(a) for a in sys.argv[1:4])
os.makedirs(work, exist_ok=True)
# a folder a bad case must not create (an earlier run of this script may have left it)
shutil.rmtree(os.path.join(work, "never_run"), ignore_errors=True)
failures = []


env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")


def run(prm_text, name, args=(), cwd=None, ranks=1):
    path = os.path.join(work, name + ".prm")
    with open(path, "w") as f:
        f.write(prm_text)
    command = [wetbed, path] + list(args)
    if ranks > 1:
        command = ["mpirun", "--oversubscribe", "-np", str(ranks)] + command
    p = subprocess.run(command, capture_output=True, text=True, timeout=600, cwd=cwd, env=env)
    return p.returncode, p.stdout, p.stderr


def folder_digest(folder):
    """sha256 of every file under FOLDER by relative path: a byte-for-byte picture."""
    digest = {}
    for directory, _, files in os.walk(folder):
        for name in files:
            path = os.path.join(directory, name)
            digest[os.path.relpath(path, folder)] = hashlib.sha256(open(path, "rb").read()).hexdigest()
    return digest


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


# 1. every shipped case parses and runs a few steps; the seed columns (2,640 and 35,640
# cells) and the spouted bed on coarser meshes of the same geometry: their parameters are what is
# checked here
COARSER = {"seed000_large_column.prm": "subsection mesh\n set geometry parameters = radius: 0.075, height: 1.5, "
                                       "n_core: 3, n_ring: 2, n_layers: 30\nend\n",
           "seed000_small_column.prm": "subsection mesh\n set geometry parameters = radius: 0.025, height: 1.0, "
                                       "n_core: 3, n_ring: 2, n_layers: 20\nend\n",
           # the spouted bed's jet (144 m/s) takes steps of ~5 us: 60 of them on 9 x 40 cells
           "seed004_spouted_bed.prm": "subsection mesh\n set geometry parameters = n_side: 4, ny: 40\nend\n"}
for prm in sorted(os.listdir(os.path.join(source, "prm"))):
    if not prm.endswith(".prm"):
        continue
    text = with_mesh(open(os.path.join(source, "prm", prm)).read(), prm)
    folder = os.path.join(work, "good_" + prm[:-4])
    text = override(text, COARSER.get(prm, "") +
                    f"subsection time stepping\n set end time = 3e-4\n set initial time step = 1e-4\nend\n"
                          f"subsection output\n set folder = {folder}\n set field interval = 0\nend")
    code, out, err = run(text, "good_" + prm[:-4], ["--overwrite"])  # the folder may hold the last corpus run
    if code != 0 or not os.path.isfile(os.path.join(folder, "monitors.csv")):
        failures.append(f"{prm}: exit {code}: {err.strip()[-300:]}")
    else:
        print(f"ok   {prm} runs ({len(open(os.path.join(folder, 'monitors.csv')).readlines()) - 1} rows)")

# 2. bad inputs, each against a valid base that already wrote results
base = with_mesh(open(os.path.join(source, "prm", "bubbling_bed_2d.prm")).read(), "base")
results = os.path.join(work, "existing_results")
base = override(base, f"subsection output\n set folder = {results}\n set field interval = 0\nend\n"
                      "subsection bubble analysis\n set interval = 1\nend")
shutil.rmtree(results, ignore_errors=True)
code, base_out, err = run(override(base, "subsection time stepping\n set end time = 2e-4\nend"), "base_run")
# the bad inputs below may overwrite the base run's results: a refused input still must
# change nothing there (checked file by file after each case)
base = override(base, "subsection output\n set overwrite = true\nend")
if code != 0:
    failures.append("base run failed: " + err)
monitors = os.path.join(results, "monitors.csv")
digest = hashlib.sha256(open(monitors, "rb").read()).hexdigest() if os.path.isfile(monitors) else None
results_digest = folder_digest(results)
if "mesh.msh" not in results_digest:
    failures.append("the base run wrote no mesh.msh")

MESHES = os.path.join(source, "tests", "meshes") + "/"
cases = [
    ("syntax error", "subsection drag\n set model Gidaspow\nend", "cannot be parsed"),
    ("unknown parameter", "subsection drag\n set colour = red\nend", "colour"),
    ("unknown subsection", "subsection nonsense\n set model = x\nend", "nonsense"),
    ("unknown drag law", "subsection drag\n set model = Stokes\nend", "model"),
    ("unknown rheology", "subsection solids stress\n set model = magic\nend", "model"),
    ("dimension 4", "set dimension = 4", "dimension"),
    ("3D case on a 2D mesh", "set dimension = 3", ("dimension", "is 2D")),
    ("2D case on a 3D mesh", "subsection mesh\n set file = " + os.path.join(source, "meshes", "column_3d.geo") + "\nend", ("dimension", "is 3D")),
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
    ("moving wall velocity through the wall", f"subsection mesh\n set file = {os.path.join(source, 'meshes', 'couette_cell_2d.geo')}\n set inlet =\n set outlet =\n set periodic boundaries = bottom, top\nend\nsubsection boundary conditions\n set moving wall = moving wall\n set moving wall velocity = 0.5, 0, 0\nend\n"
     # the bed and the probe inside the 0.6 mm tall cell: the velocity is what is wrong
     "subsection initial conditions\n set bed height = 0.0005\nend\nsubsection output\n set probe heights =\nend", "boundary conditions/moving wall velocity"),
    ("unwritable output folder", "subsection output\n set folder = /proc/wetbed-output\nend", "output/folder"),
    # every number finite (issue 30)
    ("gravity -inf", "subsection physical properties\n set gravity = 0, -inf, 0\nend", "physical properties/gravity"),
    ("gravity nan", "subsection physical properties\n set gravity = nan, -9.81, 0\nend", "physical properties/gravity"),
    ("gravity 1e999", "subsection physical properties\n set gravity = 0, -1e999, 0\nend", "physical properties/gravity"),
    ("particle diameter inf", "subsection physical properties\n set particle diameter = inf\nend", "particle diameter"),
    ("Nitsche penalty inf", "subsection boundary conditions\n set Nitsche penalty = inf\nend", "Nitsche penalty"),
    ("subnormal cfl target (fuzz finding)", "subsection time stepping\n set cfl target = 4.9e-324\nend", "time stepping/cfl target"),
    ("inlet velocity for a group that is no inlet", "subsection boundary conditions\n set inlet velocities = jet: 2\nend", "boundary conditions/inlet velocities"),
    ("inlet velocity and mass flow for one group", "subsection boundary conditions\n set inlet velocities = inlet: 2\n set inlet mass flow rates = inlet: 0.01\nend", "boundary conditions/inlet mass flow rates"),
    ("inlet velocity not an expression", "subsection boundary conditions\n set inlet velocities = inlet: 2*(x\nend", "boundary conditions/inlet velocities"),
    ("inlet velocity in z in 2D", "subsection boundary conditions\n set inlet velocities = inlet: z\nend", "boundary conditions/inlet velocities"),
    ("inlet velocity infinite at x = 0", "subsection boundary conditions\n set inlet velocities = inlet: 1/x\nend", "boundary conditions/inlet velocities"),
    ("inlet group named twice", "subsection boundary conditions\n set inlet velocities = inlet: 1; inlet: 2\nend", "boundary conditions/inlet velocities"),
    ("inlet mass flow along the inlet", "subsection boundary conditions\n set inlet mass flow rates = inlet: 0.01\n set inlet directions = inlet: 1 0\nend", "boundary conditions/inlet mass flow rates"),
    ("inlet direction out of the domain", "subsection boundary conditions\n set inlet directions = inlet: 0 -1\nend", "boundary conditions/inlet directions"),
    ("inlet direction of three components in 2D", "subsection boundary conditions\n set inlet directions = inlet: 0 1 0\nend", "boundary conditions/inlet directions"),
    ("inlet direction zero", "subsection boundary conditions\n set inlet directions = inlet: 0 0\nend", "boundary conditions/inlet directions"),
    ("inlet solids for a group that is no inlet", "subsection boundary conditions\n set inlet solids = jet: 0.1 0.1\nend", "boundary conditions/inlet solids"),
    ("inlet solids fraction at the packing", "subsection boundary conditions\n set inlet solids = inlet: 0.7 0.1\nend", "boundary conditions/inlet solids"),
    ("inlet solids fraction zero", "subsection boundary conditions\n set inlet solids = inlet: 0 0.1\nend", "boundary conditions/inlet solids"),
    ("inlet solids speed zero", "subsection boundary conditions\n set inlet solids = inlet: 0.1 0\nend", "boundary conditions/inlet solids"),
    ("inlet solids without a speed", "subsection boundary conditions\n set inlet solids = inlet: 0.1\nend", "boundary conditions/inlet solids"),
    ("profile line with a 1D point", "subsection statistics\n set lines = axis: 0.025, 0.025 0.3, 10\nend", "statistics/lines"),
    ("profile line of one point", "subsection statistics\n set lines = axis: 0.025 0, 0.025 0.3, 1\nend", "statistics/lines"),
    ("profile line without a name", "subsection statistics\n set lines = 0.025 0, 0.025 0.3, 10\nend", "statistics/lines"),
    ("radial profile in 2D", "subsection statistics\n set radial profile heights = 0.1\nend", "statistics/radial profile heights"),
    ("plane height not a number", "subsection statistics\n set plane heights = high\nend", "statistics/plane heights"),
    ("lateral profile height twice", "subsection statistics\n set lateral profile heights = 0.1, 0.1\nend", "statistics/lateral profile heights"),
    ("inlet velocity 1/0", "subsection boundary conditions\n set inlet superficial velocity = 1/0\nend", "boundary conditions/inlet superficial velocity"),
    ("inlet velocity log(t)", "subsection boundary conditions\n set inlet superficial velocity = log(t)\nend", "boundary conditions/inlet superficial velocity"),
    ("inlet velocity NaN after t = 1 s", "subsection boundary conditions\n set inlet superficial velocity = sqrt(1 - t)\nend", "boundary conditions/inlet superficial velocity"),
    ("inlet velocity 1e999*t", "subsection boundary conditions\n set inlet superficial velocity = 1e999*t\nend", "boundary conditions/inlet superficial velocity"),
    ("held solids velocity 1/0", "subsection boundary conditions\n set hold solids = true\n set held solids velocity = 0; 1/0; 0\nend", "boundary conditions/held solids velocity"),
    ("held solids velocity log(x) at the wall", "subsection boundary conditions\n set hold solids = true\n set held solids velocity = 0; log(x); 0\nend", "boundary conditions/held solids velocity"),
    ("moving wall velocity inf", "subsection boundary conditions\n set moving wall velocity = inf, 0, 0\nend", "boundary conditions/moving wall velocity"),
    ("point probe at infinity", "subsection bed monitors\n set point probes = 0.01, inf\nend", "bed monitors/point probes"),
    # consistent with the mesh (checked right after it is read, before anything is written)
    ("gravity from the inlet to the outlet", "subsection physical properties\n set gravity = 0, 9.81, 0\nend", "physical properties/gravity"),
    ("gravity across the column", "subsection physical properties\n set gravity = 9.81, 0, 0\nend", "physical properties/gravity"),
    ("bed above the domain", "subsection initial conditions\n set bed height = 0.5\nend", "initial conditions/bed height"),
    ("probe height above the domain", "subsection output\n set probe heights = 0.076, 0.5\nend", "output/probe heights"),
    ("pressure plane above the domain", "subsection bed monitors\n set pressure drop between = 0.05, 0.4\nend", "bed monitors/pressure drop between"),
    ("point probe beside the domain", "subsection bed monitors\n set point probes = 0.2, 0.1\nend", "bed monitors/point probes"),
    ("point probe below the domain", "subsection bed monitors\n set point probes = 0.01, 0.02; 0.01, -0.05\nend", "bed monitors/point probes"),
    # all-quad/hex meshes
    ("triangles (no Recombine)", "subsection mesh\n set file = " + MESHES + "column_2d_triangles.geo\nend", ("mesh/file", "Recombine")),
    ("tetrahedra (no Recombine)", "set dimension = 3\nsubsection mesh\n set file = " + MESHES + "box_3d_tetrahedra.geo\nend", ("mesh/file", "Recombine")),
    ("a .msh of triangles", "triangle msh", ("mesh/file", "Recombine")),
    ("gmsh syntax error", "syntax error geo", ("mesh/file", "gmsh failed", "syntax error")),
    # refinement against the memory
    ("initial refinement 10", "subsection mesh\n set initial refinement = 10\nend", ("mesh/initial refinement", "GB")),
    ("adaptive maximum level 12", "subsection adaptive refinement\n set enabled = true\n set maximum level = 12\nend", ("adaptive refinement/maximum level", "GB")),
    ("3D initial refinement 7", "set dimension = 3\nsubsection mesh\n set file = " + os.path.join(source, "meshes", "column_3d.geo") + "\n set initial refinement = 7\nend\nsubsection physical properties\n set gravity = 0, 0, -9.81\nend\nsubsection output\n set probe heights =\nend", ("mesh/initial refinement", "GB")),
    ("geometry parameter the .geo does not define", "subsection mesh\n set geometry parameters = radius: 0.1\nend", ("mesh/geometry parameters", "'radius'", "width")),
    ("geometry parameters without a colon", "subsection mesh\n set geometry parameters = height 0.5\nend", "mesh/geometry parameters"),
    ("geometry parameter not a number", "subsection mesh\n set geometry parameters = height: tall\nend", ("mesh/geometry parameters", "'tall'")),
    ("geometry parameter nan", "subsection mesh\n set geometry parameters = height: nan\nend", "mesh/geometry parameters"),
    ("geometry parameter given twice", "subsection mesh\n set geometry parameters = ny: 10, ny: 20\nend", ("mesh/geometry parameters", "twice")),
    ("geometry parameters for a .msh", "geometry msh", ("mesh/geometry parameters", ".msh")),
    ("pressure probe above the top", "subsection bed monitors\n set pressure probe height = 5\nend", "bed monitors/pressure probe height"),
    ("ECT slab above the top", "subsection ECT sensor\n set enabled = true\n set centre height = 0.29\nend", "ECT sensor/centre height"),
    ("ECT slab below the inlet", "subsection ECT sensor\n set enabled = true\n set centre height = 0.01\nend", "ECT sensor/centre height"),
    ("ECT frame rate 0", "subsection ECT sensor\n set enabled = true\n set frame rate = 0\nend", "ECT sensor/frame rate"),
    # resume problems exit 2
    ("resume without monitors.csv", "resume without monitors", "checkpoint/resume"),
    ("resume with a truncated monitors.csv", "resume truncated monitors", "checkpoint/resume"),
]
corrupt = os.path.join(work, "corrupt.msh")
with open(corrupt, "w") as f:
    f.write("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PhysicalNames\n3\n1 1 \"inlet\"\n1 2 \"outlet\"\n1 3 \"wall\"\n$EndPhysicalNames\n$Nodes\ngarbage\n")
triangles_msh = os.path.join(work, "triangles.msh")
with open(triangles_msh, "w") as f:  # two triangles of a unit square, gmsh 2.2
    f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n4\n1 1 \"inlet\"\n1 2 \"outlet\"\n1 3 \"wall\"\n2 10 \"fluid\"\n$EndPhysicalNames\n"
            "$Nodes\n4\n1 0 0 0\n2 0.05 0 0\n3 0.05 0.3 0\n4 0 0.3 0\n$EndNodes\n$Elements\n6\n"
            "1 1 2 1 1 1 2\n2 1 2 2 2 3 4\n3 1 2 3 3 2 3\n4 1 2 3 3 4 1\n5 2 2 10 1 1 2 3\n6 2 2 10 1 1 3 4\n$EndElements\n")
syntax_geo = os.path.join(work, "syntax_error.geo")
with open(syntax_geo, "w") as f:
    f.write(open(os.path.join(source, "meshes", "column_2d.geo")).read().replace("Plane Surface(1) = {1};", "Plane Surface(1) = {1;"))
special = {"triangle msh": f"subsection mesh\n set file = {triangles_msh}\nend",
           "geometry msh": f"subsection mesh\n set file = {triangles_msh}\n set geometry parameters = height: 1\nend",
           "syntax error geo": f"subsection mesh\n set file = {syntax_geo}\nend"}
# copies of the base run's folder (it wrote a checkpoint at its end) with one file spoilt
damaged = {}
for kind, spoil in (("damaged checkpoint", "checkpoint/triangulation_fixed.data"), ("garbage checkpoint", "checkpoint/state"),
                    ("resume without monitors", "monitors.csv"), ("resume truncated monitors", "monitors.csv")):
    folder = os.path.join(work, kind.replace(" ", "_"))
    shutil.rmtree(folder, ignore_errors=True)
    shutil.copytree(results, folder)
    if kind == "resume without monitors":
        os.remove(os.path.join(folder, spoil))
    elif kind == "resume truncated monitors":
        with open(os.path.join(folder, spoil), "r+b") as f:
            f.truncate(len(f.readline()))
    else:
        with open(os.path.join(folder, spoil), "r+b") as f:
            f.seek(40)
            f.write(b"garbage")
    damaged[kind] = (f"subsection checkpoint\n set resume = true\nend\nsubsection output\n set folder = {folder}\nend",
                     folder, folder_digest(folder))
for description, lines, expected in cases:
    if lines is None:
        lines = f"subsection mesh\n set file = {corrupt}\nend"
    lines = special.get(lines, lines)
    spoilt = damaged.get(lines)
    if spoilt:
        lines = spoilt[0]
    code, out, err = run(override(base, lines), "bad")
    message = err.strip().splitlines()[-1] if err.strip() else ""
    expected = expected if isinstance(expected, tuple) else (expected,)
    if code != 2 or not all(e in message for e in expected):
        failures.append(f"bad input '{description}': exit {code}, message '{message[:300]}'")
    elif len(err.strip().splitlines()) != 1:
        failures.append(f"bad input '{description}': {len(err.strip().splitlines())} lines on stderr, not one: {err[:300]!r}")
    else:
        print(f"ok   {description}: {message[:140]}")
    if spoilt and folder_digest(spoilt[1]) != spoilt[2]:
        failures.append(f"bad input '{description}': the run's files in {spoilt[1]} were changed")
    if folder_digest(results) != results_digest:
        failures.append(f"bad input '{description}': the previous run's files in {results} were changed")
        results_digest = folder_digest(results)
if digest and hashlib.sha256(open(monitors, "rb").read()).hexdigest() != digest:
    failures.append("an existing monitors.csv was changed by a bad-input run")

# 3. the command line
for args, expected_code in ((["--help"], 0), (["--print-parameters"], 0), (["--print-parameters", "json"], 0),
                            (["--print-parameters", "xml"], 2), ([], 1), (["/nonexistent.prm"], 2)):
    p = subprocess.run([wetbed] + args, capture_output=True, text=True)
    if p.returncode != expected_code:
        failures.append(f"wetbed {' '.join(args)}: exit {p.returncode}, expected {expected_code}")
# the JSON listing parses and every entry has its documentation and pattern
listing = json.loads(subprocess.run([wetbed, "--print-parameters", "json"], capture_output=True, text=True).stdout)


def entries(node, path=""):
    for key, value in node.items():
        if isinstance(value, dict) and "value" in value and "pattern_description" in value:
            yield path + key, value
        elif isinstance(value, dict):
            yield from entries(value, path + key + "/")


described = list(entries(listing))
if len(described) < 100 or any(not e["documentation"].strip() for _, e in described):
    failures.append(f"--print-parameters json: {len(described)} entries, some without documentation: "
                    f"{[n for n, e in described if not e['documentation'].strip()][:5]}")
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

# 6. output folders, no shell, spectrum ranges (issue 30): each check is one name in
# `checks`; byte-for-byte pictures of the folders they must not change
checks = []


def check(name, condition, detail=""):
    checks.append(name)
    if condition:
        print(f"ok   {name}")
    else:
        failures.append(f"{name}: {detail}"[:600])


def last_line(err):
    return err.strip().splitlines()[-1] if err.strip() else ""


def copy_of_results(name):
    folder = os.path.join(work, name)
    shutil.rmtree(folder, ignore_errors=True)
    shutil.copytree(results, folder)
    return folder


def case_into(folder, extra=""):
    """The base case into FOLDER, a few steps, no overwrite unless EXTRA says so."""
    return override(base, f"subsection output\n set folder = {folder}\n set overwrite = false\nend\n"
                          "subsection time stepping\n set end time = 2e-4\nend\n" + extra)


def refused(name, text, where, folder=None, args=(), cwd=None, ranks=1, contains=""):
    before = folder_digest(folder) if folder and os.path.isdir(folder) else None
    code, _, err = run(text, name.replace(" ", "_").replace("/", "_")[:60], args, cwd, ranks)
    # under mpirun its notice about the exit status follows wetbed's one line
    errors = [line for line in err.splitlines() if line.startswith("wetbed: error:")]
    message = errors[-1] if ranks > 1 and len(errors) == 1 else last_line(err)
    ok = code == 2 and where in message and contains in message
    if ok and before is not None and folder_digest(folder) != before:
        ok, message = False, f"the files in {folder} were changed"
    check(name, ok, f"exit {code}, '{message}'")


# a second run into a folder in use: the lock (held here as a running wetbed holds it)
locked = copy_of_results("locked")
with open(os.path.join(locked, ".wetbed.lock"), "a") as lock:
    fcntl.flock(lock, fcntl.LOCK_EX)
    refused("folder in use (locked)", case_into(locked, "subsection output\n set overwrite = true\nend"),
            "output/folder", locked, contains="in use")
    refused("folder in use, resumed", case_into(locked, "subsection checkpoint\n set resume = true\nend"),
            "output/folder", locked, contains="in use")
    if shutil.which("mpirun"):
        refused("folder in use on 2 ranks", case_into(locked, "subsection output\n set overwrite = true\nend"),
                "output/folder", locked, ranks=2, contains="in use")
# two real runs into one folder: the second is refused, the first finishes intact
busy = os.path.join(work, "busy")
shutil.rmtree(busy, ignore_errors=True)
first_prm = os.path.join(work, "busy_first.prm")
with open(first_prm, "w") as f:
    f.write(override(base, f"subsection output\n set folder = {busy}\nend\nsubsection time stepping\n set end time = 1\nend"))
first = subprocess.Popen([wetbed, first_prm], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
for _ in range(600):
    if os.path.isfile(os.path.join(busy, "monitors.csv")) or first.poll() is not None:
        break
    time.sleep(0.1)
code, _, err = run(case_into(busy, "subsection output\n set overwrite = true\nend"), "busy_second")
first.send_signal(signal.SIGTERM)
first_code = first.wait(timeout=300)
rows = open(os.path.join(busy, "monitors.csv"), "rb").read() if os.path.isfile(os.path.join(busy, "monitors.csv")) else b""
n_lines = rows.count(b"\n")
check("two runs into one folder", code == 2 and "in use" in last_line(err) and first_code in (0, 4)
      and b"\0" not in rows and n_lines >= 2,
      f"second exit {code} '{last_line(err)}', first exit {first_code}, {n_lines} lines")
# a previous run's results: refused unless overwrite
refused("previous results without overwrite", case_into(copy_of_results("previous")), "output/folder",
        os.path.join(work, "previous"), contains="--overwrite")
# a bad input found only once the mesh is read, pointed at such a folder: refused for
# the input (the whole input is checked before the folder's verdict), the folder as it was
refused("bad inlet group into previous results", case_into(copy_of_results("previous_bad_input"),
        "subsection boundary conditions\n set inlet velocities = inlet: 1/x\nend"),
        "boundary conditions/inlet velocities", os.path.join(work, "previous_bad_input"))
refused("bed above the domain into previous results", case_into(copy_of_results("previous_bad_bed"),
        "subsection initial conditions\n set bed height = 0.5\nend"),
        "initial conditions/bed height", os.path.join(work, "previous_bad_bed"))
refused("previous results on 2 ranks", case_into(copy_of_results("previous_2_ranks")), "output/folder",
        os.path.join(work, "previous_2_ranks"), ranks=2, contains="--overwrite")
only_checkpoint = copy_of_results("previous_checkpoint")
os.remove(os.path.join(only_checkpoint, "monitors.csv"))
refused("previous checkpoint without overwrite", case_into(only_checkpoint), "output/folder", only_checkpoint)
for name, extra, args in (("overwrite = true", "subsection output\n set overwrite = true\nend", []),
                          ("--overwrite", "", ["--overwrite"])):
    folder = copy_of_results("overwritten")
    open(os.path.join(folder, "fields_00007.pvtu"), "w").write("stale")
    code, _, err = run(case_into(folder, extra), "overwritten", args)
    check(f"{name} replaces a previous run", code == 0 and not os.path.exists(os.path.join(folder, "fields_00007.pvtu"))
          and os.path.isfile(os.path.join(folder, "monitors.csv")), f"exit {code} '{last_line(err)}'")
# nothing is created before the input is checked
empty_cwd = os.path.join(work, "empty_cwd")
shutil.rmtree(empty_cwd, ignore_errors=True)
os.makedirs(empty_cwd)
code, _, err = run("", "empty", cwd=empty_cwd)
check("an empty .prm creates nothing", code == 2 and os.listdir(empty_cwd) == [], f"exit {code}, left {os.listdir(empty_cwd)}")
new_top = os.path.join(work, "never_created")
shutil.rmtree(new_top, ignore_errors=True)
for name, extra in (("missing mesh", f"subsection mesh\n set file = {os.path.join(work, 'missing.geo')}\nend"),
                    ("unknown physical group", "subsection mesh\n set wall = side\nend"),
                    ("bed above the domain", "subsection initial conditions\n set bed height = 0.5\nend"),
                    ("triangles", f"subsection mesh\n set file = {MESHES}column_2d_triangles.geo\nend"),
                    # refused after the mesh was read and accepted (the pending mesh goes too)
                    ("moving wall velocity through the wall", [c for c in cases if c[0] == "moving wall velocity through the wall"][0][1])):
    code, _, err = run(case_into(os.path.join(new_top, "a", "b"), extra), "never_created")
    check(f"{name} into a new folder creates nothing", code == 2 and not os.path.exists(new_top),
          f"exit {code} '{last_line(err)}', exists: {os.path.exists(new_top)}")
check("resume into a missing folder creates nothing", not os.path.exists(os.path.join(work, "never_run")))
a_file = os.path.join(work, "a_file")
open(a_file, "w").write("not a folder")
refused("output folder is a file", case_into(a_file), "output/folder")
if shutil.which("mpirun"):
    refused("triangles on 2 ranks", override(base, f"subsection mesh\n set file = {MESHES}column_2d_triangles.geo\nend"),
            "mesh/file", results, ranks=2, contains="Recombine")
# checkpoint identity: a resume refuses a checkpoint that is not this case's, naming
# what differs, and changes nothing; what may change on resume does not stop it
def resume_of(folder, extra=""):
    return override(base, f"subsection output\n set folder = {folder}\nend\n"
                          "subsection checkpoint\n set resume = true\nend\n"
                          "subsection time stepping\n set end time = 2e-4\nend\n" + extra)


for name, extra, contains in (
        ("another particle density", "subsection physical properties\n set particle density = 2600\nend", "physical properties/particle density"),
        ("another initial refinement", "subsection mesh\n set initial refinement = 0\nend", "mesh/initial refinement"),
        ("another drag law", "subsection drag\n set model = Wen-Yu\nend", "drag/model")):
    folder = copy_of_results("identity")
    refused(f"resume with {name}", resume_of(folder, extra), "checkpoint/resume", folder, contains=contains)
folder = copy_of_results("identity")
state = open(os.path.join(folder, "checkpoint", "state")).read()
digit = next(i for i in range(len(state) // 2, len(state)) if state[i].isdigit() and state[i] != "9")
open(os.path.join(folder, "checkpoint", "state"), "w").write(state[:digit] + str(int(state[digit]) + 1) + state[digit + 1:])
refused("resume from a state with one digit changed", resume_of(folder), "checkpoint/resume", folder, contains="checksum")
folder = copy_of_results("identity")
os.remove(os.path.join(folder, "checkpoint", "state.checksum"))
refused("resume from a state without its checksum", resume_of(folder), "checkpoint/resume", folder, contains="checksum")
folder = copy_of_results("identity")
rows = open(os.path.join(folder, "monitors.csv")).read().split("\n")
rows[1] = rows[1].replace("0", "1", 1)
open(os.path.join(folder, "monitors.csv"), "w").write("\n".join(rows))
refused("resume onto another run's monitors.csv", resume_of(folder), "checkpoint/resume", folder, contains="monitors.csv")
for name in ("bubbles.csv", "bubble_summary.csv"):
    folder = copy_of_results("identity")
    rows = open(os.path.join(folder, name)).read().split("\n")
    line = 1 if rows[1] else 0  # a data row, or the header of a file without rows
    rows[line] = rows[line].replace("0", "1", 1) if line else rows[line].replace("step", "Step")
    open(os.path.join(folder, name), "w").write("\n".join(rows))
    refused(f"resume onto another run's {name}", resume_of(folder), "checkpoint/resume", folder, contains=name)


# the same refusals on 2 ranks (rank 0 checks, every rank stops with the same line)
if shutil.which("mpirun"):
    folder = copy_of_results("identity")
    refused("resume with another particle density on 2 ranks",
            resume_of(folder, "subsection physical properties\n set particle density = 2600\nend"),
            "checkpoint/resume", folder, ranks=2, contains="physical properties/particle density")
    state = open(os.path.join(folder, "checkpoint", "state")).read()
    digit = next(i for i in range(len(state) // 2, len(state)) if state[i].isdigit() and state[i] != "9")
    open(os.path.join(folder, "checkpoint", "state"), "w").write(state[:digit] + str(int(state[digit]) + 1) + state[digit + 1:])
    refused("resume from a state with one digit changed on 2 ranks", resume_of(folder), "checkpoint/resume", folder,
            ranks=2, contains="checksum")
    refused("previous results without overwrite on 2 ranks", case_into(copy_of_results("previous")), "output/folder",
            os.path.join(work, "previous"), ranks=2, contains="--overwrite")
    refused("gravity from the inlet to the outlet on 2 ranks",
            case_into(copy_of_results("previous"), "subsection output\n set overwrite = true\nend\n"
                                                  "subsection physical properties\n set gravity = 0, 9.81, 0\nend"),
            "physical properties/gravity", os.path.join(work, "previous"), ranks=2)
    refused("inlet velocity log(t) on 2 ranks",
            case_into(copy_of_results("previous"), "subsection output\n set overwrite = true\nend\n"
                                                  "subsection boundary conditions\n set inlet superficial velocity = log(t)\nend"),
            "boundary conditions/inlet superficial velocity", os.path.join(work, "previous"), ranks=2)
# a later run that overwrote the folder without writing a checkpoint: the earlier run's
# checkpoint went with its results, so a resume finds none instead of resuming it onto
# the later run's monitors.csv
folder = copy_of_results("stale")
code, _, err = run(case_into(folder, "subsection output\n set overwrite = true\nend\n"
                                     "subsection checkpoint\n set at end = false\nend"), "stale_later")
check("an overwriting run removes the earlier run's checkpoint", code == 0 and not os.path.exists(os.path.join(folder, "checkpoint")),
      f"exit {code} '{last_line(err)}'")
refused("resume after a later run without a checkpoint", resume_of(folder), "checkpoint/resume", folder)


def run_ids(folder, name):
    path = os.path.join(folder, name)
    return [r["run"] for r in csv.DictReader(open(path))] if os.path.isfile(path) else []


# every row of monitors.csv and bubble_summary.csv carries the id the run printed (the
# base run is too short for bubbles: bubbles.csv is checked by the test bubble_analysis)
printed = re.findall(r"^Run ([0-9a-f]{16})$", base_out, re.M)
for name in ("monitors.csv", "bubble_summary.csv"):
    ids = run_ids(results, name)
    check(f"{name} rows carry the run id", len(printed) == 1 and ids and set(ids) == set(printed),
          f"printed {printed}, in {name}: {sorted(set(ids))[:3]} ({len(ids)} rows)")
# the mesh file changed under the checkpoint (a copy of the .geo, one more column)
mesh_copy = os.path.join(work, "identity_mesh.geo")
shutil.copy(os.path.join(source, "meshes", "column_2d.geo"), mesh_copy)
mesh_folder = os.path.join(work, "identity_mesh")
shutil.rmtree(mesh_folder, ignore_errors=True)
code, _, err = run(case_into(mesh_folder, f"subsection mesh\n set file = {mesh_copy}\nend"), "identity_mesh")
open(mesh_copy, "w").write(open(mesh_copy).read().replace('nx = {5', 'nx = {6'))
refused("resume after the mesh file changed", resume_of(mesh_folder, f"subsection mesh\n set file = {mesh_copy}\nend"),
        "checkpoint/resume", mesh_folder, contains="mesh/file")
# the same numbers written differently are the same case (2500 and 2.5e3; 0, -9.81, 0
# without blanks and with trailing zeros); another number is not
folder = copy_of_results("identity")
code, _, err = run(resume_of(folder, "subsection physical properties\n set particle density = 2.5e3\n"
                                     " set gravity = 0.0,-9.810,0\nend\n"), "identity_rewritten")
check("resume with the same numbers written differently continues the run", code == 0, f"exit {code} '{last_line(err)}'")
folder = copy_of_results("identity")
refused("resume with gravity -9.8", resume_of(folder, "subsection physical properties\n set gravity = 0, -9.8, 0\nend"),
        "checkpoint/resume", folder, contains="physical properties/gravity")
# what may change: the end time and the solver tolerance; rows the run wrote after the
# checkpoint are its own and are replaced
folder = copy_of_results("identity")
lines_before = open(os.path.join(folder, "monitors.csv")).read().count("\n")
with open(os.path.join(folder, "monitors.csv"), "a") as f:
    f.write(open(os.path.join(folder, "monitors.csv")).read().split("\n")[-2] + "\n")
code, _, err = run(resume_of(folder, "subsection time stepping\n set end time = 4e-4\nend\n"
                                     "subsection linear solver\n set relative tolerance = 1e-9\nend"), "identity_resume")
lines_after = open(os.path.join(folder, "monitors.csv")).read().count("\n")
check("resume with a new end time and tolerance continues the run", code == 0 and lines_after > lines_before,
      f"exit {code} '{last_line(err)}', {lines_before} -> {lines_after} lines")
check("the resumed rows carry the run's id", set(run_ids(folder, "monitors.csv")) == set(printed),
      f"{sorted(set(run_ids(folder, 'monitors.csv')))}, printed {printed}")
# no shell: a mesh path and an output folder holding $(...), quotes and ; run as names
pwned = os.path.join("/tmp", f"wetbed_pwned_{os.getpid()}")
shell_dir = os.path.join(work, f"shell $(touch {pwned}) `touch {pwned}` \"; touch {pwned}; '")
shutil.rmtree(os.path.join(work, "shell $(touch "), ignore_errors=True)
os.makedirs(shell_dir, exist_ok=True)
geo = os.path.join(shell_dir, "column $(touch x).geo")
shutil.copy(os.path.join(source, "meshes", "column_2d.geo"), geo)
code, _, err = run(case_into(os.path.join(shell_dir, "out $(touch y)"), f"subsection mesh\n set file = {geo}\nend"), "shell")
check("no shell: $(...) in the mesh and folder names", code == 0 and not os.path.exists(pwned)
      and not os.path.exists(os.path.join(work, "x")) and os.path.isfile(os.path.join(shell_dir, "out $(touch y)", "mesh.msh")),
      f"exit {code} '{last_line(err)}', {pwned} exists: {os.path.exists(pwned)}")
shutil.rmtree(os.path.join(work, "shell $(touch "), ignore_errors=True)
# fuzz campaign finding #879 (gravity x 1e12): the alpha_s transport asked for ~1e8
# explicit sub-steps and ran on for ever, deaf to SIGTERM. A step that needs more than
# 1000 is rejected; the halved steps end the run with status 3 and its report in seconds
folder = os.path.join(work, "huge_gravity")
shutil.rmtree(folder, ignore_errors=True)
started = time.time()
code, _, err = run(case_into(folder, "subsection physical properties\n set gravity = 0, -9.81e12, 0\nend"), "huge_gravity")
took = time.time() - started
report = os.path.join(folder, "failure_report.txt")
report_text = open(report).read() if os.path.isfile(report) else ""
check("gravity x 1e12 (fuzz #879): status 3 within 60 s, the transport's sub-steps named",
      code == 3 and took < 60 and "sub-steps (at most 1000)" in report_text,
      f"exit {code} after {took:.0f} s '{last_line(err)}', report {'with' if report_text else 'without'} the sub-steps")
# the spectrum CLI: every option range-checked, non-finite samples refused naming the file
series = os.path.join(work, "series.csv")
with open(series, "w") as f:
    f.write("time,pressure_drop\n" + "".join(f"{i * 0.01},{math.sin(i)}\n" for i in range(64)))
p = subprocess.run([wetbed, "spectrum", series], capture_output=True, text=True)
check("spectrum of a clean series", p.returncode == 0, p.stderr)
for values, name in ((("nan", 1), "NaN in pressure_drop"), (("inf", 0), "inf in time")):
    spoilt = os.path.join(work, name.replace(" ", "_") + ".csv")
    lines = open(series).read().splitlines()
    row = lines[20].split(",")
    row[values[1]] = values[0]
    lines[20] = ",".join(row)
    open(spoilt, "w").write("\n".join(lines) + "\n")
    p = subprocess.run([wetbed, "spectrum", spoilt], capture_output=True, text=True)
    check(f"spectrum: {name}", p.returncode == 2 and spoilt in last_line(p.stderr) and "finite" in last_line(p.stderr),
          f"exit {p.returncode} '{last_line(p.stderr)}'")
for args, expected in ((["--segments", "-1"], "--segments"), (["--segments", "5000"], "--segments"),
                       (["--segments", "2.5"], "--segments"), (["--start", "-1"], "--start"),
                       (["--start", "nan"], "--start"), (["--start", "inf"], "--start"),
                       (["--columns", ","], "--columns"), (["--segments"], "--segments")):
    p = subprocess.run([wetbed, "spectrum", series] + args, capture_output=True, text=True)
    check(f"spectrum {' '.join(args)}", p.returncode == 2 and expected in last_line(p.stderr)
          and len(p.stderr.strip().splitlines()) == 1, f"exit {p.returncode} '{p.stderr.strip()}'")

n = len(cases)
print(f"{n} bad-input cases and {len(checks)} folder, shell and spectrum checks")
for f in failures:
    print("FAILED:", f)
print(f"{n + 14 + len(checks) - len(failures)} passed, {len(failures)} failed")
sys.exit(1 if failures else 0)
