#!/usr/bin/env python3
"""Runs a .prm case with wetbed and checks its monitors.csv against physics.

usage: case_checks.py CHECK WETBED SOURCE_DIR WORK_DIR
CHECK: ergun | split_inlet | wall_groups | hydrostatic | packed | settling | ramp | kinetic | ranks |
       monitor_interval | signals | disk_full | bubbling | hdf5 | restart | amr | amr_ranks | failure | bubbles |
       matrix_free | divergence | column_3d | seed_column | statistics | profiles
"""
import csv
import math
import os
import re
import shutil
import subprocess
import sys

check, wetbed, source, work = sys.argv[1], *(os.path.abspath(a) for a in sys.argv[2:5])
os.makedirs(work, exist_ok=True)
failures = []
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")


# a fixed two outer iterations, each solve to `linear solver/relative tolerance` (no outer
# convergence test, whose inexact solves leave differences of the order of its tolerance,
# which a bubbling bed amplifies): for comparisons of runs that must agree closely; with
# every solve to 1e-11 for those that must agree to round-off
FIXED_OUTER = "subsection time stepping\n set outer tolerance = 0\n set outer iterations = 2\nend\n"
EXACT_SOLVES = "subsection linear solver\n set relative tolerance = 1e-11\nend\n" + FIXED_OUTER

def expect(condition, what):
    print(("ok   " if condition else "FAIL ") + what)
    if not condition:
        failures.append(what)


def run(case, overrides="", ranks=1, folder=None, resume=False, expected_exit=0):
    """Copies tests/cases/CASE.prm (or prm/CASE.prm) with absolute mesh paths and the
    overrides appended, runs it (continuing its checkpoint with resume, else replacing
    the folder's earlier results with --overwrite), returns the monitors rows."""
    path = os.path.join(source, "tests", "cases", case + ".prm")
    if not os.path.isfile(path):
        path = os.path.join(source, "prm", case + ".prm")
    text = open(path).read().replace("../../meshes/", source + "/meshes/").replace("../meshes/", source + "/meshes/")
    folder = folder or os.path.join(work, case)
    text += f"\nsubsection output\n set folder = {folder}\n set field interval = 0\nend\n" + overrides
    prm = os.path.join(work, os.path.basename(folder) + ".prm")
    open(prm, "w").write(text)
    command = [wetbed, prm] if ranks == 1 else ["mpirun", "--oversubscribe", "-np", str(ranks), wetbed, prm]
    # a new run replaces what an earlier ctest run left in its folder (--overwrite); a
    # resumed one continues the checkpoint there
    p = subprocess.run(command + (["--resume"] if resume else ["--overwrite"]), capture_output=True, text=True, env=env)
    run.stdout, run.stderr = p.stdout, p.stderr
    if p.returncode != expected_exit:
        print(p.stdout[-2000:], p.stderr[-2000:])
        expect(False, f"{case} ran (exit {p.returncode})")
        sys.exit(1)
    # a failed run's monitors.csv may end in a cut row (a full disk)
    return read_monitors(folder) if expected_exit == 0 else None


def read_monitors(folder):
    # the numbers (not the text column run, the run's id)
    return [{k: float(v) for k, v in r.items() if k != "run"}
            for r in csv.DictReader(open(os.path.join(folder, "monitors.csv")))]


def same_monitors(reference, rows, what, tolerance):
    """Same steps and times (the adaptive dt follows the velocities: relative tolerance);
    pressure drop, max alpha_s and mean Theta within the relative tolerance; solids mass
    to round-off."""
    expect(len(rows) == len(reference) and all(abs(a["time"] - b["time"]) <= 1e-14 + tolerance * a["time"]
                                               for a, b in zip(reference, rows)),
           f"{what}: the same {len(reference)} monitor rows at the same times ({len(rows)} rows)")
    for name in ("pressure_drop", "alpha_s_max", "theta_mean", "bed_height"):
        worst = max(abs(a[name] - b[name]) / max(abs(a[name]), 1e-300) for a, b in zip(reference, rows))
        expect(worst <= tolerance, f"{what}: {name} agrees (max rel. difference {worst:.1e} <= {tolerance:.0e})")
    worst = max(abs(a["solids_mass"] - b["solids_mass"]) / a["solids_mass"] for a, b in zip(reference, rows))
    expect(worst <= 1e-12, f"{what}: solids mass agrees (max rel. difference {worst:.1e})")


def bounds_and_mass(rows, alpha_max, mass_tolerance=1e-12):
    expect(all(r["alpha_s_min"] >= -1e-12 for r in rows), f"alpha_s >= 0 at every step (min {min(r['alpha_s_min'] for r in rows):.3e})")
    expect(all(r["alpha_s_max"] <= alpha_max + 1e-12 for r in rows), f"alpha_s <= {alpha_max} at every step (max {max(r['alpha_s_max'] for r in rows):.12f})")
    drift = max(abs(r["solids_mass_drift"]) for r in rows)
    expect(drift <= mass_tolerance, f"solids mass constant (max relative drift {drift:.2e} <= {mass_tolerance})")
    expect(all(math.isfinite(v) for r in rows for v in r.values()), "no NaN/Inf in the monitors")


if check == "ergun":
    # T8: -dp'/dz = 150 a_s^2 mu U/(a_g^3 d^2) + 1.75 a_s rho U^2/(a_g^3 d) over H = 0.3 m
    rows = run("ergun_column")
    a_s, a_g, U, mu, d, rho, H = 0.45, 0.55, 0.2, 1.8e-5, 350e-6, 1.2, 0.3
    exact = H * (150 * a_s**2 * mu * U / (a_g**3 * d * d) + 1.75 * a_s * rho * U * U / (a_g**3 * d))
    dp = rows[-1]["pressure_drop"]
    expect(abs(dp / exact - 1) < 1e-10, f"Ergun pressure drop {dp:.12f} vs {exact:.12f} (rel. {abs(dp / exact - 1):.1e} < 1e-10)")
    # the matrix-free operator and the rhs assembled on FEValues agree to round-off, which
    # this column carries to 1.4e-10 in the gas speed (assembled path: 1.3e-12)
    speed = abs(rows[-1]["gas_speed_max"] / (U / a_g) - 1)
    expect(speed < 1e-9, f"gas at U/alpha_g (superficial inflow U; rel. {speed:.1e} < 1e-9)")
elif check == "split_inlet":
    # several groups of one type: the Ergun column with its inlet split into two physical
    # groups (tests/meshes/column_2d_split_inlet.geo, the same cells) must give the
    # single-inlet run's monitors; an inlet group without the inflow, or left out of the
    # pressure drop, changes the pressure drop at O(1)
    reference = run("ergun_column", folder=os.path.join(work, "split_inlet_reference"))
    split = (f"subsection mesh\n set file = {source}/tests/meshes/column_2d_split_inlet.geo\n"
             " set inlet = inlet_left, inlet_right\nend\n")
    rows = run("ergun_column", split, folder=os.path.join(work, "split_inlet"))
    dp, dp_ref = rows[-1]["pressure_drop"], reference[-1]["pressure_drop"]
    expect(abs(dp / dp_ref - 1) < 1e-8, f"pressure drop {dp:.12f} vs single inlet {dp_ref:.12f} (rel. {abs(dp / dp_ref - 1):.1e} < 1e-8)")
    same_monitors(reference, rows, "split inlet vs single inlet", 1e-8)
    for name in ("gas_speed_max", "distributor_support", "fluidization_index"):
        worst = max(abs(a[name] - b[name]) / max(abs(a[name]), 1e-12) for a, b in zip(reference, rows))
        expect(worst < 1e-8, f"{name} agrees (max rel. difference {worst:.1e} < 1e-8)")
    # inlets per group (issue 50). The monitored inlet velocity is the volume flow over
    # the inlet area: with 0.1 m/s through the left 2 cm and 0.3 through the right 3 cm,
    # (0.02 * 0.1 + 0.03 * 0.3) / 0.05 = 0.22 m/s. A velocity linear in x is imposed
    # exactly at the Q2 nodes (read on the inlet with a profile line), a mass flow rate
    # of rho_g U A gives the run at U, and a direction tilts the inflow.
    def inlets(text, name, lines=""):
        rows = run("ergun_column", split + "subsection boundary conditions\n" + text + "end\n"
                   + (f"subsection statistics\n set lines = {lines}\nend\n" if lines else ""),
                   folder=os.path.join(work, "split_inlet_" + name))
        profile = None
        if lines:
            profile = list(csv.DictReader(open(os.path.join(work, "split_inlet_" + name, "statistics", "line_inlet.csv"))))
            profile = [{k: float(v) for k, v in r.items()} for r in profile if float(r["time"]) == rows[-1]["time"]]
        return rows, profile
    bottom = "inlet: 0.0005 0, 0.0495 0, 50"
    rows, line = inlets(" set inlet velocities = inlet_left: 0.1; inlet_right: 0.3\n", "two_speeds", bottom)
    mean = rows[-1]["inlet_superficial_velocity"]
    expect(abs(mean - 0.22) < 1e-12, f"two inlet velocities: the inlet velocity monitored is their area mean {mean:.15f} (0.22)")
    clear = [r for r in line if r["x"] < 0.01 or r["x"] > 0.03]  # faces that do not touch x = 0.02
    worst = max(abs(r["u_g_y"] - (0.1 if r["x"] < 0.02 else 0.3) / 0.55) for r in clear)
    expect(len(clear) == 30 and worst < 1e-9, f"the gas enters at U/alpha_g of its group ({len(clear)} points, max error {worst:.1e})")
    rows, line = inlets(" set inlet velocities = inlet_left: 0.1 + 2*x; inlet_right: 0.3\n", "linear", bottom)
    mean = rows[-1]["inlet_superficial_velocity"]
    worst = max(abs(r["u_g_y"] - (0.1 + 2 * r["x"]) / 0.55) for r in line if r["x"] < 0.01)
    expect(abs(mean - 0.228) < 1e-12 and worst < 1e-9,
           f"U = 0.1 + 2x on the left: mean {mean:.15f} (0.228), at the points {worst:.1e} from (0.1 + 2x)/alpha_g")
    rows, _ = inlets(f" set inlet mass flow rates = inlet_right: {1.2 * 0.2 * 0.03!r}\n", "mass_flow")
    same_monitors(reference, rows, "a mass flow rate of rho_g U A on the right vs U", 1e-12)
    inflow, outflow, expected = rows[-1]["gas_inflow"], rows[-1]["gas_outflow"], 1.2 * 0.2 * 0.05
    expect(abs(inflow / expected - 1) < 1e-10 and abs(outflow / expected - 1) < 1e-10,
           f"the gas mass flow integrated over the inlets {inflow:.15f} kg/s/m and the outlet {outflow:.15f} "
           f"= rho_g U A = {expected:.15f} (rel. {abs(inflow / expected - 1):.1e}, {abs(outflow / expected - 1):.1e} < 1e-10)")
    rows, line = inlets(" set inlet directions = inlet_right: 0.6 0.8\n"
                        f" set inlet mass flow rates = inlet_right: {1.2 * 0.2 * 0.03 * 0.8!r}\n", "tilted", bottom)
    right = [r for r in line if 0.03 < r["x"] < 0.04]  # clear of the wall's corner node
    # the node at x = 2 cm is both groups': it takes the left group's vertical superficial
    # velocity 0.2 (not 0.16), which adds its Simpson weight h/6 of the right group's
    # first face, 1.2 * 0.01/6 * 0.04 kg/s/m, to the mass flow rates
    inflow, expected = rows[-1]["gas_inflow"], 1.2 * (0.02 * 0.2 + 0.03 * 0.8 * 0.2)
    shared = 1.2 * 0.01 / 6 * (0.2 - 0.16)
    expect(abs(inflow - expected - shared) < 1e-12 * expected,
           f"tilted: gas inflow {inflow:.15f} kg/s/m = the mass flow rates {expected:.6f} + the shared node's "
           f"{shared:.3e} (difference {abs(inflow - expected - shared):.1e})")
    worst = max(max(abs(r["u_g_x"] - 0.6 * 0.2 / 0.55), abs(r["u_g_y"] - 0.8 * 0.2 / 0.55)) for r in right)
    mean = rows[-1]["inlet_superficial_velocity"]
    expect(len(right) == 10 and worst < 1e-9 and abs(mean - 0.176) < 1e-12,
           f"tilted 0.6, 0.8 with the mass flow of 0.2 m/s along it: u_g = (0.6, 0.8) U/alpha_g on the right "
           f"(max error {worst:.1e}), inflow (0.02 * 0.2 + 0.03 * 0.8 * 0.2) / 0.05 = {mean:.15f} (0.176)")
    # a solids feed through one group (inlet solids): the quick-start bed with its inlet
    # split, 0.1 solids at 0.05 m/s through the right 3 cm. The fed mass is the feed's
    # rate rho_s alpha_in u_in A t exactly (the source integrates alpha_in u_in.(-n)
    # over the group's faces), the mass accounting closes to round-off, the solids enter
    # at the feed's velocity on the right group's nodes and rest on the left's
    rows = run("quick_start_2d", split + "subsection boundary conditions\n set inlet solids = inlet_right: 0.1 0.05\nend\n"
               "subsection time stepping\n set end time = 0.02\nend\n"
               f"subsection statistics\n set lines = {bottom}\nend\n", folder=os.path.join(work, "solids_feed"))
    fed, expected = rows[-1]["solids_fed_mass"], 2500 * 0.1 * 0.05 * 0.03 * rows[-1]["time"]
    expect(abs(fed / expected - 1) < 1e-10,
           f"fed solids mass {fed:.15f} kg/m = rho_s alpha_in u_in A t = {expected:.15f} (rel. {abs(fed / expected - 1):.1e} < 1e-10)")
    expect(rows[-1]["solids_mass"] - rows[0]["solids_mass"] > 0.99 * fed, "the bed's mass grew by the fed mass")
    bounds_and_mass(rows, 0.61)
    line = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(open(os.path.join(work, "solids_feed", "statistics", "line_inlet.csv")))]
    line = [r for r in line if r["time"] == rows[-1]["time"]]
    right = [r for r in line if r["x"] > 0.02]
    left = [r for r in line if r["x"] < 0.01]
    worst = max(max(abs(r["u_s_x"]), abs(r["u_s_y"] - 0.05)) for r in right)
    rest = max(max(abs(r["u_s_x"]), abs(r["u_s_y"])) for r in left)
    expect(len(right) == 30 and worst < 1e-9 and len(left) == 10 and rest < 1e-9,
           f"u_s = (0, 0.05) on the feeding group ({len(right)} points, max error {worst:.1e}), 0 on the other "
           f"({len(left)} points, {rest:.1e})")
    # the fed mass is in the checkpoint: a run stopped at 0.01 s and resumed to 0.02 s
    feed = split + "subsection boundary conditions\n set inlet solids = inlet_right: 0.1 0.05\nend\n"
    folder = os.path.join(work, "solids_feed_resumed")
    run("quick_start_2d", feed + "subsection time stepping\n set end time = 0.01\nend\n", folder=folder)
    rows = run("quick_start_2d", feed + "subsection time stepping\n set end time = 0.02\nend\n", folder=folder, resume=True)
    fed = rows[-1]["solids_fed_mass"]
    expect(abs(fed / expected - 1) < 1e-10 and max(abs(r["solids_mass_drift"]) for r in rows) < 1e-12,
           f"resumed at 0.01 s: fed mass {fed:.15f} kg/m at 0.02 s (rel. {abs(fed / expected - 1):.1e}), drift below 1e-12")
elif check == "wall_groups":
    # a wall condition per wall group: the kinetic-theory bed (Johnson-Jackson walls,
    # algebraic Theta) with its side walls as two groups (tests/meshes/
    # column_2d_split_wall.geo, the same cells). One condition on both groups must give
    # the single-group run; Johnson-Jackson on one side and free slip on the other must
    # give the mirror image of the opposite choice, and a wall friction between the
    # free-slip and the all-Johnson-Jackson runs'
    base = ("subsection kinetic theory\n set granular temperature = algebraic\nend\n"
            "subsection time stepping\n set end time = 0.03\nend\n" + FIXED_OUTER)
    split = f"subsection mesh\n set file = {source}/tests/meshes/column_2d_split_wall.geo\n set wall = wall_left, wall_right\nend\n"
    def walls(condition):
        return f"subsection boundary conditions\n set solids wall condition = {condition}\nend\n"
    reference = run("kinetic_theory_bed", base, folder=os.path.join(work, "wall_groups_reference"))
    same = run("kinetic_theory_bed", base + split, folder=os.path.join(work, "wall_groups_same"))
    same_monitors(reference, same, "two wall groups, one condition vs one group", 1e-8)
    left = run("kinetic_theory_bed", base + split + walls("free-slip; wall_left: Johnson-Jackson"), folder=os.path.join(work, "wall_groups_left"))
    right = run("kinetic_theory_bed", base + split + walls("wall_left: free-slip; wall_right: Johnson-Jackson"), folder=os.path.join(work, "wall_groups_right"))
    free = run("kinetic_theory_bed", base + walls("free-slip"), folder=os.path.join(work, "wall_groups_free"))
    # (the bubbling start-up amplifies the 1e-11 left-right asymmetry of the discrete
    # initial state: the all-Johnson-Jackson run's own mirror probes differ by ~2e-3)
    worst = max(abs(a["pressure_drop"] - b["pressure_drop"]) / abs(a["pressure_drop"]) for a, b in zip(left[1:], right[1:]))
    expect(worst < 1e-3, f"pressure drop: Johnson-Jackson left = mirror of Johnson-Jackson right (max rel. difference {worst:.1e} < 1e-3)")
    jj, one_left, one_right, none = (sum(r["wall_support_solids"] for r in rows[1:]) for rows in (reference, left, right, free))
    expect(abs(one_left / one_right - 1) < 1e-2, f"wall support: Johnson-Jackson left = mirror of right (ratio {one_left / one_right:.4f}, 1 within 1e-2)")
    expect(abs(none) < 1e-12, f"free-slip walls carry nothing ({none:.1e})")
    expect(0.3 < one_left / jj < 0.7, f"one Johnson-Jackson wall carries about half of two walls' support ({one_left / jj:.3f})")
elif check == "packed":
    # T7b: a packed bed (JJ frictional pressure, seed values) at rest for 0.2 s
    rows = run("packed_bed_at_rest")
    speed = max(max(r["solids_speed_max"], r["gas_speed_max"]) for r in rows)
    expect(speed < 1e-5, f"spurious velocity {speed:.2e} m/s < 1e-5 at every step")
    expect(rows[-1]["time"] >= 0.2 - 1e-12, "ran to t = 0.2 s")
    expect(all(r["rejected_steps"] == 0 for r in rows), "no rejected steps")
    bounds_and_mass(rows, 0.61)
    # momentum budget: without gas flow the distributor carries the whole bed
    worst = max(abs(r["distributor_support"] - 1) + abs(r["wall_support_solids"]) + abs(r["fluidization_index"]) for r in rows[1:])
    expect(worst < 1e-3, f"the distributor carries the bed weight (|support - 1| + |walls| + |FI| <= {worst:.1e} < 1e-3)")
elif check == "hydrostatic":
    # T7a: gas only at rest; p' = p - rho_g g.x must stay zero, no velocity appears
    rows = run("hydrostatic_gas")
    expect(max(abs(r["pressure_drop"]) for r in rows) < 1e-12, "p' stays zero")
    expect(max(r["gas_speed_max"] for r in rows) < 1e-12, "gas stays at rest")
elif check == "settling":
    # T10: top interface of a settling suspension (alpha_0 = 0.1) vs the exact hindered
    # settling speed of the Wen-Yu law; zero net volume flux: u_s = -alpha_g slip,
    # beta slip = alpha_s alpha_g (rho_s - rho_g) g
    rows = run("settling_column", "subsection time stepping\n set end time = 0.16\n set maximum time step = 2e-3\nend\n")
    a_s, d, mu, rho_g, rho_s, g = 0.1, 100e-6, 1.8e-5, 1.2, 2500.0, 9.81
    a_g = 1 - a_s
    slip = 0.5
    for _ in range(200):
        re = a_g * rho_g * d * slip / mu
        beta = 18 * mu * a_s * a_g**-2.65 * (1 + 0.15 * re**0.687) / d**2
        slip = a_s * a_g * (rho_s - rho_g) * g / beta
    speed = a_g * slip
    # the 95% solids height sits 0.05 H0 (alpha_0 uniform) below the interface while the
    # suspension is intact; fit its fall between t = 0.05 and 0.15 s
    window = [r for r in rows if 0.05 <= r["time"] <= 0.15]
    t0, t1 = window[0], window[-1]
    measured = -(t1["bed_height"] - t0["bed_height"]) / (t1["time"] - t0["time"])
    expect(abs(measured / speed - 1) < 0.05, f"interface speed {measured:.4f} m/s vs hindered settling {speed:.4f} m/s (within 5%)")
    bounds_and_mass(rows, 0.61)
elif check == "ramp":
    # T9: velocity ramp through minimum fluidization (Syamlal-O'Brien, 350 um glass)
    rows = run("velocity_ramp")
    bounds_and_mass(rows, 0.61)
    expect(all(r["rejected_steps"] == 0 for r in rows), "no rejected steps")
    # fluidized plateau: time mean of FI while U is held at 0.35 m/s, after 0.2 s to settle
    held = [r for r in rows if 1.0 < r["time"] <= 1.8]
    plateau = sum(r["fluidization_index"] * r["time_step"] for r in held) / sum(r["time_step"] for r in held)
    expect(abs(plateau - 1) < 0.02, f"fluidized plateau FI {plateau:.4f} = 1 +- 2%")
    # momentum budget: gas pressure drop and distributor share the weight on the fixed-bed
    # part of the ramp; on the plateau the distributor carries almost nothing
    budget = [r["fluidization_index"] + r["distributor_support"] + r["wall_support_solids"] + r["wall_support_gas"] + r["outlet_support"]
              for r in rows if 0.05 < r["time"] < 0.4]
    expect(max(abs(b - 1) for b in budget) < 0.01, f"fixed bed: FI + supports = 1 within {max(abs(b - 1) for b in budget):.1e} < 0.01")
    carried = sum(r["distributor_support"] * r["time_step"] for r in held) / sum(r["time_step"] for r in held)
    expect(abs(carried) < 0.02, f"fluidized plateau: the distributor carries {carried:.4f} of the weight (< 2%)")

    # U_mf, the standard construction: the fixed-bed line (least squares over 0.2 <= FI
    # <= 0.8 on the rising ramp) meets FI = 1. The drag law's value: the same construction
    # on its pressure drop int beta U/alpha_g^2 dz over the bed at rest, alpha_s(z) from
    # dP_s/dz = -alpha_s (rho_s - rho_g) g (Johnson-Jackson P_s, P_s = 0 at H = 0.15 m),
    # against that bed's weight.
    def line_meets_one(points):
        n = len(points)
        sx, sy = sum(u for u, _ in points), sum(f for _, f in points)
        sxx, sxy = sum(u * u for u, _ in points), sum(u * f for u, f in points)
        slope = (n * sxy - sx * sy) / (n * sxx - sx * sx)
        return (1 - (sy - slope * sx) / n) / slope

    fixed = [(r["inlet_superficial_velocity"], r["fluidization_index"]) for r in rows if r["time"] < 0.8 and 0.2 <= r["fluidization_index"] <= 0.8]
    measured = line_meets_one(fixed)

    mu, d, rho_g, rho_s, g, H = 1.8e-5, 350e-6, 1.2, 2500.0, 9.81, 0.15

    def syamlal_obrien(a_s, slip):
        a_g = 1 - a_s
        re = rho_g * d * slip / mu
        a, b = a_g**4.14, (0.8 * a_g**1.28 if a_g <= 0.85 else a_g**2.65)
        v_r = 0.5 * (a - 0.06 * re + math.sqrt((0.06 * re) ** 2 + 0.12 * re * (2 * b - a) + a * a))
        return 0.75 * mu * a_s * a_g * (0.63 * math.sqrt(re / v_r) + 4.8) ** 2 / (v_r * d * d)

    def frictional_pressure(a):
        return 0.0 if a <= 0.58 else 0.05 * (a - 0.58) ** 2 / (0.61 - a) ** 3

    def packing_at(pressure):
        lo, hi = 0.58, 0.609
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if frictional_pressure(mid) < pressure else (lo, mid)
        return 0.5 * (lo + hi)

    layers, dz, pressure, profile = 1500, H / 1500, 0.0, []
    for _ in range(layers):  # top down, midpoint values
        a = packing_at(pressure)
        a = packing_at(pressure + 0.5 * a * (rho_s - rho_g) * g * dz)
        profile.append(a)
        pressure += a * (rho_s - rho_g) * g * dz
    weight = pressure
    law = []
    for k in range(1, 400):
        U = 0.25 * k / 400
        fi = sum(syamlal_obrien(a, U / (1 - a)) * U / (1 - a) ** 2 for a in profile) * dz / weight
        if 0.2 <= fi <= 0.8:
            law.append((U, fi))
    expected = line_meets_one(law)
    expect(abs(measured / expected - 1) < 0.05, f"U_mf {measured:.4f} m/s vs the drag law's {expected:.4f} m/s (within 5%)")
    first = next(r["inlet_superficial_velocity"] for r in rows if r["fluidization_index"] >= 1)
    print(f"     (FI first reaches 1 at U = {first:.4f} m/s; bottom packing {profile[-1]:.4f})")
elif check == "kinetic":
    # kinetic theory start-up, 0.1 s: algebraic Theta with Johnson-Jackson walls, and the
    # Theta PDE with free-slip solids walls (the PDE with JJ walls is not stable yet)
    variants = {"algebraic, Johnson-Jackson walls": "subsection kinetic theory\n set granular temperature = algebraic\nend\n",
                "PDE, free-slip walls": "subsection boundary conditions\n set solids wall condition = free-slip\nend\n"}
    for k, (name, overrides) in enumerate(variants.items()):
        rows = run("kinetic_theory_bed", overrides, 1, os.path.join(work, f"kinetic_{k}"))
        print(f"  {name}:")
        bounds_and_mass(rows, 0.61, 1e-12)
        expect(rows[-1]["time"] >= 0.1 - 1e-12, f"{name}: reached t = 0.1 s")
        expect(all(r["rejected_steps"] == 0 for r in rows), f"{name}: no rejected step")
        lo, hi = min(r["theta_min"] for r in rows[1:]), max(r["theta_max"] for r in rows[1:])
        expect(1e-10 <= lo and hi <= 1.0, f"{name}: Theta in [1e-10, 1] (min {lo:.2e}, max {hi:.2e})")
        mean = rows[-1]["theta_mean"]
        expect(1e-6 < mean < 1e-1, f"{name}: solids-weighted mean Theta {mean:.2e} m^2/s^2 in a bubbling bed's range")
elif check == "ranks":
    # T13: 1 and 2 MPI ranks give the same monitors to solver tolerance
    overrides = "subsection time stepping\n set end time = 0.02\nend\n" + FIXED_OUTER
    one = run("bubbling_bed_2d", overrides, 1, os.path.join(work, "ranks_1"))
    two = run("bubbling_bed_2d", overrides, 2, os.path.join(work, "ranks_2"))
    expect(len(one) == len(two) and all(a["time"] == b["time"] for a, b in zip(one, two)), f"same time steps ({len(one)} rows)")
    worst = max(abs(a["pressure_drop"] - b["pressure_drop"]) / abs(a["pressure_drop"]) for a, b in zip(one[1:], two[1:]))
    expect(worst < 1e-4, f"pressure drop agrees (max rel. difference {worst:.1e} < 1e-4)")
    worst = max(abs(a["alpha_s_max"] - b["alpha_s_max"]) for a, b in zip(one, two))
    expect(worst < 1e-6, f"max alpha_s agrees (max difference {worst:.1e} < 1e-6)")
    expect(all(abs(a["solids_mass"] - b["solids_mass"]) <= 1e-12 * a["solids_mass"] for a, b in zip(one, two)), "solids mass identical")
elif check == "monitor_interval":
    # `output/monitor interval` thins monitors.csv and nothing else: the rows of a run
    # with interval 3 are those of the every-step run at steps 0, 3, 6, ... and the last
    # step, identical (the time-step controller reads the fields, not the rows)
    overrides = "subsection time stepping\n set end time = 0.02\nend\n"
    every = run("bubbling_bed_2d", overrides, 1, os.path.join(work, "interval_1"))
    thin = run("bubbling_bed_2d", overrides + "subsection output\n set monitor interval = 3\nend\n",
               1, os.path.join(work, "interval_3"))
    steps = [int(r["step"]) for r in every]
    wanted = [r for r in every if int(r["step"]) % 3 == 0 or int(r["step"]) == steps[-1]]
    expect(len(every) > 10 and [int(r["step"]) for r in thin] == [int(r["step"]) for r in wanted],
           f"interval 3: rows at steps {[int(r['step']) for r in thin][:5]}... ({len(thin)} of {len(every)})")
    expect(all(a == b for a, b in zip(wanted, thin)), "the thinned rows are the every-step rows, bit for bit")
elif check == "bubbling":
    # the default case, first 0.05 s: runs, bounded, conservative, the bed lifts
    rows = run("bubbling_bed_2d", "subsection time stepping\n set end time = 0.05\nend\n"
               "subsection bed monitors\n set pressure drop between = 0.01, 0.1\n"
               " set point probes = 0.025, 0.03; 0.025, 0.2\nend\n")
    bounds_and_mass(rows, 0.61, 1e-10)
    # bed monitors: the initial bed (5 cm at 0.58) has its surface within a cell of 5 cm;
    # the probe in the bed reads 0.58, the one in the freeboard 0; the pressure drop
    # between 1 and 10 cm is most of the inlet-outlet drop (the bed starts above 1 cm)
    first, last = rows[0], rows[-1]
    expect(abs(first["bed_surface_height"] - 0.05) <= 0.006 and abs(first["expansion_ratio"] - first["bed_surface_height"] / 0.05) < 1e-12,
           f"initial bed surface {first['bed_surface_height']:.4f} m, expansion ratio {first['expansion_ratio']:.3f}")
    expect(abs(first["probe_0_alpha_s"] - 0.58) < 1e-12 and first["probe_1_alpha_s"] == 0, "point probes: 0.58 in the bed, 0 above it")
    expect(last["expansion_ratio"] > 1.05, f"the bed expands (ratio {last['expansion_ratio']:.3f})")
    ratio = last["pressure_drop_0.01_0.1"] / last["pressure_drop"]
    expect(0.7 < ratio < 1.01, f"pressure drop between 1 and 10 cm: {ratio:.3f} of the inlet-outlet drop")
    expect(rows[-1]["time"] >= 0.05 - 1e-12, "reached t = 0.05 s")
    expect(max(r["fluidization_index"] for r in rows[1:]) > 1.0, "the gas carries the bed (FI > 1 at start-up)")
elif check == "bubbles":
    # the bubble analysis on the default case over the start-up bubble (0.06 s): bubbles.csv,
    # bubble_summary.csv and the spectrum CLI; a run resumed from a checkpoint at step 40
    # continues the bubble files and the tracks as if uninterrupted (1 rank: the same
    # rows; 1 -> 2 ranks: the same bubbles and tracks)
    import shutil
    overrides = ("subsection time stepping\n set end time = 0.06\nend\n"
                 "subsection checkpoint\n set interval = 40\n set at end = false\nend\n"
                 "subsection bubble analysis\n set interval = 5\nend\n")
    folder = os.path.join(work, "bubbles")
    rows = run("bubbling_bed_2d", overrides, 1, folder)

    def read(name, where):
        return list(csv.DictReader(open(os.path.join(where, name))))
    bubbles, summary = read("bubbles.csv", folder), read("bubble_summary.csv", folder)
    steps = int(rows[-1]["step"])
    expect(len(summary) == steps // 5 + 1, f"bubble_summary.csv: a row every 5 steps ({len(summary)} rows, {steps} steps)")
    expect(len(bubbles) >= 3 and all(int(r["cells"]) > 0 for r in bubbles), f"the start-up bubble is found ({len(bubbles)} rows)")
    last = bubbles[-1]
    expect(0.01 < float(last["equivalent_diameter"]) < 0.05 and float(last["touches_wall"]) == 1,
           f"the start-up bubble: diameter {float(last['equivalent_diameter']):.4f} m, spans the 5 cm slice")
    rising = [float(r["rise_velocity"]) for r in bubbles if r["rise_velocity"] != ""]
    expect(rising and all(0 <= v < 2 for v in rising) and max(rising) > 0, f"rise velocities in [0, 2) m/s, not all 0: {rising[:3]}...")
    p = subprocess.run([wetbed, "spectrum", os.path.join(folder, "monitors.csv"), "--start", "0.01"],
                       capture_output=True, text=True, env=env)
    expect(p.returncode == 0 and p.stdout.startswith("# pressure_drop: dominant frequency"),
           f"wetbed spectrum on monitors.csv (exit {p.returncode}): {p.stdout.splitlines()[:1]}")
    for ranks in (1, 2):
        resumed = os.path.join(work, f"bubbles_resumed_{ranks}")
        shutil.rmtree(resumed, ignore_errors=True)
        shutil.copytree(folder, resumed)
        # the files as they were at the checkpoint's end would be cut back anyway
        run("bubbling_bed_2d", overrides, ranks, resumed, resume=True)
        again = read("bubbles.csv", resumed)
        same_rows = len(again) == len(bubbles) and all(
            a["step"] == b["step"] and a["track"] == b["track"] for a, b in zip(bubbles, again))
        expect(same_rows, f"resumed on {ranks} rank(s): the same bubble rows and tracks ({len(again)} vs {len(bubbles)})")
        worst = max(abs(float(a["volume"]) - float(b["volume"])) / float(a["volume"]) for a, b in zip(bubbles, again))
        expect(worst <= (1e-9 if ranks == 1 else 0.05), f"resumed on {ranks} rank(s): bubble volumes agree (max rel. difference {worst:.1e})")
        expect(read("bubble_summary.csv", resumed)[-1]["splittings"] == summary[-1]["splittings"],
               f"resumed on {ranks} rank(s): the same splitting count")
elif check == "hdf5":
    # parallel HDF5 + XDMF output on 2 ranks: the XDMF index and the datasets agree
    try:
        import h5py
    except ImportError:  # Debian's python3-h5py lives under /usr/bin/python3
        if os.path.realpath(sys.executable) != "/usr/bin/python3":
            os.execv("/usr/bin/python3", ["/usr/bin/python3"] + sys.argv)
        raise
    import xml.etree.ElementTree as ElementTree
    folder = os.path.join(work, "hdf5")
    # with AMR (levels 0-2, a distributor band 2 cm high): the XDMF follows a changing mesh
    band = 0.02
    rows = run("bubbling_bed_2d", "subsection time stepping\n set end time = 3e-3\n set initial time step = 1e-3\nend\n"
               "subsection output\n set field interval = 1e-3\n set field format = vtu and hdf5\nend\n"
               "subsection adaptive refinement\n set enabled = true\n set interval = 1\n set maximum level = 2\n"
               f" set distributor band height = {band}\nend\n", ranks=2, folder=folder)
    xdmf = ElementTree.parse(os.path.join(folder, "fields.xdmf")).getroot()
    grids = xdmf.findall(".//Grid[@GridType='Uniform']")
    times = [float(g.find("Time").get("Value")) for g in grids]
    expect(len(grids) == 4 and times == sorted(times) and abs(times[-1] - rows[-1]["time"]) < 1e-12,
           f"fields.xdmf lists 4 outputs at increasing times {times}")
    wanted = {"alpha_s", "alpha_g", "gas_velocity", "solids_velocity", "pressure", "granular_temperature",
              "solids_pressure", "solids_shear_viscosity", "drag_coefficient", "refinement_level", "rank"}
    consistent = True
    for g in grids:
        n_nodes = int(g.find("Geometry/DataItem").get("Dimensions").split()[0])
        n_cells = int(g.find("Topology").get("NumberOfElements"))
        names = set()
        for item in g.iter("DataItem"):
            file, dataset = item.text.strip().split(":")
            dataset = dataset.lstrip("/")
            dims = tuple(int(v) for v in item.get("Dimensions").split())
            with h5py.File(os.path.join(folder, file), "r") as h5:
                shape = h5[dataset].shape
                data = h5[dataset][()]
            if shape[0] != dims[0] or (len(dims) > 1 and len(shape) > 1 and shape[1] != dims[1]):
                consistent = False
                print(f"  {file}:{dataset} has shape {shape}, the XDMF says {dims}")
            if dataset == "cells" and (shape[0] != n_cells or data.max() >= n_nodes):
                consistent = False
            if dataset == "alpha_s" and not (data.min() >= -1e-12 and data.max() <= 0.61 + 1e-12):
                consistent = False
                print(f"  alpha_s out of [0, 0.61] in {file}")
        for attribute in g.findall("Attribute"):
            names.add(attribute.get("Name"))
        consistent &= wanted <= names
    expect(consistent, "every XDMF DataItem names an HDF5 dataset of its declared shape; cells index the nodes; "
                       "alpha_s within [0, 0.61]; all fields present")
    ranks = set()
    with h5py.File(os.path.join(folder, grids[-1].find("Geometry/DataItem").text.strip().split(":")[0]), "r") as h5:
        ranks = set(h5["rank"][()].ravel().tolist())
    expect(ranks == {0.0, 1.0}, f"both ranks wrote into the one file (rank field {sorted(ranks)})")
    # every output node below the band belongs to a cell at the maximum level (each cell
    # writes its own nodes); above it the freeboard is coarser
    with h5py.File(os.path.join(folder, grids[-1].find("Geometry/DataItem").text.strip().split(":")[0]), "r") as h5:
        heights, levels = h5["nodes"][()][:, 1], h5["refinement_level"][()].ravel()
    below, above = levels[heights < band - 1e-9], levels[heights > band + 0.01]
    expect(len(below) > 0 and below.min() == 2 and above.min() < 2,
           f"distributor band: levels below {band} m in [{below.min()}, {below.max()}], above it from {above.min()}")
elif check == "restart":
    # T14: a run continued from a checkpoint equals the uninterrupted run: on the same
    # rank count, on another (1 -> 2), and after SIGTERM (issue 7)
    import shutil
    import signal
    import time as clock
    # solved to 1e-11: the restart rebuilds the velocity AMG where the uninterrupted run
    # may reuse an older one, and the runs may differ only by the solver tolerance
    overrides = ("subsection time stepping\n set end time = 0.02\nend\n"
                 + EXACT_SOLVES +
                 "subsection checkpoint\n set at end = false\n")
    reference = run("kinetic_theory_bed", overrides + "end\n", 1, os.path.join(work, "restart_reference"))
    saved = os.path.join(work, "restart_saved")
    rows = run("kinetic_theory_bed", overrides + " set interval = 20\nend\n", 1, saved)
    same_monitors(reference, rows, "run writing a checkpoint at step 20", 0.0)
    for ranks in (1, 2):
        folder = os.path.join(work, f"restart_{ranks}")
        shutil.rmtree(folder, ignore_errors=True)
        shutil.copytree(saved, folder)
        rows = run("kinetic_theory_bed", overrides + "end\n", ranks, folder, resume=True)
        # same ranks: the velocity AMG is rebuilt at the restart where the uninterrupted
        # run may reuse an older one, so the solutions agree to the FGMRES tolerance
        # (1e-8) amplified over the steps; 1 -> 2: another partition, as case_ranks
        same_monitors(reference, rows, f"resumed at step 20 on {ranks} rank(s)", 1e-6 if ranks == 1 else 1e-5)
    # SIGTERM mid-run: the run finishes its step, writes a checkpoint, exits with 4
    folder = os.path.join(work, "restart_signal")
    shutil.rmtree(folder, ignore_errors=True)
    prm = os.path.join(work, "restart_signal.prm")
    shutil.copy(os.path.join(work, "restart_1.prm"), prm)
    text = open(prm).read().replace(os.path.join(work, "restart_1"), folder)
    open(prm, "w").write(text)
    process = subprocess.Popen([wetbed, prm], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env)
    monitors = os.path.join(folder, "monitors.csv")
    while process.poll() is None and (not os.path.isfile(monitors) or len(open(monitors).readlines()) < 13):
        clock.sleep(0.02)
    process.send_signal(signal.SIGTERM)
    out, err = process.communicate()
    stopped_at = len(read_monitors(folder)) - 1
    expect(process.returncode == 4 and os.path.isfile(os.path.join(folder, "checkpoint", "state")),
           f"SIGTERM at step {stopped_at}: exit 4 (got {process.returncode}) with a checkpoint")
    rows = run("kinetic_theory_bed", overrides + "end\n", 1, folder, resume=True)
    same_monitors(reference, rows, f"stopped by SIGTERM at step {stopped_at}, resumed", 1e-6)
elif check == "signals":
    # signals under mpirun on 2 ranks (what a batch system sends): SIGUSR2 to mpirun
    # writes a checkpoint and stops, the resumed run gives the uninterrupted monitors;
    # SIGUSR1 writes a checkpoint and goes on; a wall-clock interval writes them on
    # the clock (1 rank), the results unchanged
    import shutil
    import signal
    import time as clock
    # 0.08 s (~3 s of wall time alone on 2 cores): mpirun forwards SIGTERM and SIGINT to
    # the ranks about a second after it gets them, so a shorter run may end first
    overrides = ("subsection time stepping\n set end time = 0.08\nend\n"
                 + EXACT_SOLVES +
                 "subsection checkpoint\n set at end = false\n set wall time interval = 0\nend\n")
    reference = run("kinetic_theory_bed", overrides, 2, os.path.join(work, "signals_reference"))
    mpi_env = env

    def interrupted(name, sig):
        folder = os.path.join(work, "signals_" + name)
        shutil.rmtree(folder, ignore_errors=True)
        prm = os.path.join(work, "signals_" + name + ".prm")
        text = open(os.path.join(work, "signals_reference.prm")).read()
        open(prm, "w").write(text.replace(os.path.join(work, "signals_reference"), folder))
        process = subprocess.Popen(["mpirun", "--oversubscribe", "-np", "2", wetbed, prm],
                                   stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=mpi_env)
        monitors = os.path.join(folder, "monitors.csv")
        while process.poll() is None and (not os.path.isfile(monitors) or len(open(monitors).readlines()) < 13):
            clock.sleep(0.02)
        process.send_signal(sig)
        out, err = process.communicate()
        return folder, process.returncode, out

    # SIGINT (Ctrl-C) and SIGTERM to mpirun itself: Open MPI sends SIGTERM to the ranks
    # and kills them about a second later, so the ranks abandon the step in progress
    # and checkpoint the last accepted one
    for name, sig in (("sigusr2", signal.SIGUSR2), ("sigterm", signal.SIGTERM), ("sigint", signal.SIGINT)):
        folder, code, out = interrupted(name, sig)
        stopped_at = len(read_monitors(folder)) - 1
        expect(code != 0 and "Stop requested by a signal" in out and os.path.isfile(os.path.join(folder, "checkpoint", "state")),
               f"{name.upper()} to mpirun at step {stopped_at}: stopped with a checkpoint (exit {code})"
               + "".join("; " + line for line in out.splitlines() if "Stop requested" in line))
        rows = run("kinetic_theory_bed", overrides, 2, folder, resume=True)
        same_monitors(reference, rows, f"stopped by {name.upper()} at step {stopped_at}, resumed on 2 ranks", 1e-5)
    folder, code, out = interrupted("sigusr1", signal.SIGUSR1)
    expect(code == 0 and out.count("checkpoint written") == 1 and os.path.isfile(os.path.join(folder, "checkpoint", "state")),
           f"SIGUSR1 to mpirun: one checkpoint ({out.count('checkpoint written')} written), "
           f"the run goes on to the end (exit {code})")
    same_monitors(reference, read_monitors(folder), "SIGUSR1 run vs uninterrupted", 1e-12)
    # mpirun forwards its signal to every rank, and the ranks may see it in different
    # steps: one rank at step 13, the other at step 17 is still one request
    folder = os.path.join(work, "signals_staggered")
    shutil.rmtree(folder, ignore_errors=True)
    prm = os.path.join(work, "signals_staggered.prm")
    text = open(os.path.join(work, "signals_reference.prm")).read()
    open(prm, "w").write(text.replace(os.path.join(work, "signals_reference"), folder))
    process = subprocess.Popen(["mpirun", "--oversubscribe", "-np", "2", wetbed, prm],
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=mpi_env)
    monitors = os.path.join(folder, "monitors.csv")

    def wait_for_rows(n):
        while process.poll() is None and (not os.path.isfile(monitors) or len(open(monitors).readlines()) < n):
            clock.sleep(0.02)

    wait_for_rows(13)
    ranks = subprocess.run(["pgrep", "-P", str(process.pid)], capture_output=True, text=True).stdout.split()
    if len(ranks) == 2:
        os.kill(int(ranks[0]), signal.SIGUSR1)
        wait_for_rows(17)
        os.kill(int(ranks[1]), signal.SIGUSR1)
    out, err = process.communicate()
    expect(len(ranks) == 2 and process.returncode == 0 and out.count("checkpoint written") == 1,
           f"SIGUSR1 to one rank at step 13 and to the other at step 17: one checkpoint "
           f"({out.count('checkpoint written')} written, exit {process.returncode}, {len(ranks)} ranks found)")
    # the wall clock: a checkpoint after each step that passes a multiple of 0.3 s
    rows = run("kinetic_theory_bed", overrides.replace("wall time interval = 0", "wall time interval = 0.3"), 1,
               os.path.join(work, "signals_clock"))
    written = run.stdout.count("checkpoint written")
    expect(written >= 2, f"wall time interval 0.3 s: {written} checkpoints on the clock (>= 2)")
    one_rank = run("kinetic_theory_bed", overrides, 1, os.path.join(work, "signals_clock_reference"))
    same_monitors(one_rank, rows, "checkpoints on the clock vs none", 0.0)
elif check == "disk_full":
    # a checkpoint that does not fit: status 3 with one line naming output/folder, the
    # previous checkpoint intact and resumable (the output folder on a small tmpfs: the
    # first checkpoint fits, the second does not)
    import shutil
    overrides = ("subsection time stepping\n set end time = 0.02\nend\n" + FIXED_OUTER +
                 "subsection checkpoint\n set at end = false\n set interval = 10\nend\n")
    reference = run("kinetic_theory_bed", overrides, 1, os.path.join(work, "disk_reference"))
    saved = os.path.join(work, "disk_reference", "checkpoint")
    size = sum(os.path.getsize(os.path.join(saved, f)) for f in os.listdir(saved))
    mount = os.path.join(work, "disk_small")
    os.makedirs(mount, exist_ok=True)
    subprocess.run(["umount", mount], capture_output=True)
    # room for the first (what write_checkpoint asks: 1.1 x the field data + 64 kB) and
    # for the mesh, monitors and lock, but not for a second beside it
    fixed = os.path.getsize(os.path.join(saved, "triangulation_fixed.data"))
    kb = int((1.1 * fixed + 65536 + 0.5 * size + 48 * 1024) / 1024)
    mounted = subprocess.run(["mount", "-t", "tmpfs", "-o", f"size={kb}k", "tmpfs", mount], capture_output=True)
    if mounted.returncode != 0:
        print(f"SKIP no tmpfs mount here ({mounted.stderr.strip()}): the full-disk case needs root")
    else:
        try:
            folder = os.path.join(mount, "run")
            run("kinetic_theory_bed", overrides, 1, folder, expected_exit=3)
            # wetbed's own lines (as for the field output below): a line of Open MPI's
            # about its environment is not the run's error message
            lines = [l for l in run.stderr.strip().splitlines() if l.startswith("wetbed:")]
            message = lines[-1] if lines else ""
            others = [l for l in run.stderr.strip().splitlines() if not l.startswith("wetbed:")]
            expect("output/folder" in message and "no room for a checkpoint" in message and len(lines) == 1,
                   f"a checkpoint that does not fit ({kb} kB tmpfs, checkpoints of {size // 1024} kB): exit 3, '{message[:160]}'"
                   + (f" (other stderr lines: {' | '.join(others)[:400]!r})" if others else ""))
            expect(os.path.isfile(os.path.join(folder, "checkpoint", "state")), "the previous checkpoint is kept")
            moved = os.path.join(work, "disk_moved")
            shutil.rmtree(moved, ignore_errors=True)
            shutil.copytree(folder, moved)
        finally:
            subprocess.run(["umount", mount], capture_output=True)
        rows = run("kinetic_theory_bed", overrides, 1, moved, resume=True)
        same_monitors(reference, rows, "resumed from the kept checkpoint", 1e-6)
        # a field output that does not fit (1 and 2 ranks): status 3 in one line naming
        # output/folder, none of its files left, fields.xdmf listing the outputs before,
        # the checkpoint before it intact and resumable. Room for the mesh files, the
        # first output and the checkpoint at step 5 (with the room its check asks), not
        # for the second output at t = 0.002 (step ~9) beside them
        fields = ("subsection time stepping\n set end time = 0.01\nend\n" + FIXED_OUTER +
                  "subsection checkpoint\n set at end = false\n set interval = 5\nend\n"
                  "subsection output\n set field interval = 0.002\n set field format = vtu and hdf5\nend\n")
        reference = run("kinetic_theory_bed", fields, 1, os.path.join(work, "disk_fields_reference"))
        where = os.path.join(work, "disk_fields_reference")
        def size_of(names):
            return sum(os.path.getsize(os.path.join(where, n)) for n in names)
        first = size_of([n for n in os.listdir(where) if n.startswith("fields_00000.")])
        saved = os.path.join(where, "checkpoint")
        checkpoint = sum(os.path.getsize(os.path.join(saved, f)) for f in os.listdir(saved))
        fixed = os.path.getsize(os.path.join(saved, "triangulation_fixed.data"))
        other = size_of(["mesh.msh", "gmsh.log", "parameters.prm", "monitors.csv", "bubbles.csv",
                         "bubble_summary.csv", "bubble_events.csv"])
        kb = int((other + first + max(1.1 * fixed + 65536, checkpoint) + 100 * 1024) / 1024)
        for ranks in (1, 2):
            mounted = subprocess.run(["mount", "-t", "tmpfs", "-o", f"size={kb}k", "tmpfs", mount], capture_output=True)
            try:
                folder = os.path.join(mount, "run")
                run("kinetic_theory_bed", fields, ranks, folder, expected_exit=3)
                lines = [l for l in run.stderr.strip().splitlines() if l.startswith("wetbed:")]
                message = lines[-1] if lines else ""
                expect(len(lines) == 1 and "output/folder" in message and "field output fields_00001" in message,
                       f"{ranks} rank(s): a field output that does not fit ({kb} kB tmpfs, outputs of {first // 1024} kB): exit 3, '{message[:170]}'")
                names = os.listdir(folder)
                xdmf = open(os.path.join(folder, "fields.xdmf")).read() if "fields.xdmf" in names else ""
                expect(not any(n.startswith("fields_00001") for n in names) and "fields_00000.h5" in xdmf
                       and "fields_00001" not in xdmf and xdmf.endswith("</Xdmf>\n"),
                       f"{ranks} rank(s): no file of the failed output, fields.xdmf complete with the first output only")
                moved = os.path.join(work, "disk_fields_moved")
                shutil.rmtree(moved, ignore_errors=True)
                shutil.copytree(folder, moved)
            finally:
                subprocess.run(["umount", mount], capture_output=True)
            rows = run("kinetic_theory_bed", fields, ranks, moved, resume=True)
            same_monitors(reference, rows, f"{ranks} rank(s): resumed from the checkpoint before the failed output", 1e-6)
        # monitors.csv on a full disk (2 ranks: rank 0 writes, all stop): status 3 in one
        # line naming output/folder, the rows before intact
        appended = ("subsection time stepping\n set end time = 0.5\nend\n"
                    "subsection checkpoint\n set at end = false\nend\n"
                    "subsection output\n set field interval = 0\n set field format = vtu\nend\n")
        mounted = subprocess.run(["mount", "-t", "tmpfs", "-o", "size=290k", "tmpfs", mount], capture_output=True)
        try:
            folder = os.path.join(mount, "run")
            run("kinetic_theory_bed", appended, 2, folder, expected_exit=3)
            lines = [l for l in run.stderr.strip().splitlines() if l.startswith("wetbed:")]
            message = lines[-1] if lines else ""
            written = open(os.path.join(folder, "monitors.csv")).read().split("\n")
            complete = [l for l in written[1:-1] if l.count(",") == written[0].count(",")]
            expect(len(lines) == 1 and "output/folder" in message and "monitors.csv" in message,
                   f"2 ranks: monitors.csv on a full disk (290 kB tmpfs): exit 3, '{message[:170]}'")
            expect(len(complete) == len(written) - 2 and len(complete) > 100,
                   f"2 ranks: the {len(complete)} rows before are whole")
        finally:
            subprocess.run(["umount", mount], capture_output=True)
elif check == "matrix_free":
    # linear solver/operator = matrix-free: the same bilinear form as the assembled
    # matrix (checked on a random vector after every assembly), hence the same run to
    # solver tolerance: the kinetic-theory bed (Johnson-Jackson walls, Nitsche), also
    # with the velocity p-multigrid, which the bubbling bed with AMR (hanging nodes) on 2
    # ranks and two steps of the 3D column (curved wall, MappingQ2) use as well
    matrix_free = "subsection linear solver\n set operator = matrix-free\n set check operator = true\nend\n"
    def checked(what, limit=1e-10):
        found = [float(v) for v in re.findall(r"\|A_mf x - A x\| / \(\|A\| \|x\|\) = (\S+)", run.stdout)]
        expect(len(found) > 0 and max(found) <= limit,
               f"{what}: matrix-free = assembled operator on {len(found)} assemblies (largest |A_mf x - A x| / (|A| |x|) {max(found or [1]):.1e} <= {limit:.0e})")
        lifted = [float(v) for v in re.findall(r"\|b_mf - b\| / \|b\| = (\S+)", run.stdout)]
        expect(len(lifted) == len(found) and max(lifted) <= limit,
               f"{what}: the prescribed values carried into the rhs matrix-free = by local matrices on {len(lifted)} assemblies (largest |b_mf - b| / |b| {max(lifted or [1]):.1e} <= {limit:.0e})")
    # solved to 1e-11: the two paths' iterates then agree to ~1e-9 (at the default 1e-8
    # the different preconditioners leave differences of ~1e-6)
    short = ("subsection time stepping\n set end time = 0.02\nend\n"
             + EXACT_SOLVES)
    reference = run("kinetic_theory_bed", short, folder=os.path.join(work, "matrix_free_reference"))
    rows = run("kinetic_theory_bed", short + matrix_free, folder=os.path.join(work, "matrix_free"))
    checked("kinetic-theory bed")
    same_monitors(reference, rows, "matrix-free vs assembled operator", 1e-8)
    multigrid = matrix_free.replace("end\n", " set velocity preconditioner = p-multigrid\nend\n")
    # without the check: no Q2 matrix at all (rhs, L_c and the Q1 coarse matrix only)
    rows = run("kinetic_theory_bed", short + multigrid.replace("true", "false"),
               folder=os.path.join(work, "matrix_free_multigrid"))
    expect("operator check" not in run.stdout, "p-multigrid without the check assembles no system matrix (no check printed)")
    same_monitors(reference, rows, "p-multigrid, no Q2 matrix, vs the assembled path", 1e-8)
    v_cycle_iterations = sum(float(r["krylov_iterations"]) for r in rows[1:])
    # the diagnostic inner solves on this path: the velocity block by GMRES with the
    # V-cycle to 1e-10 (fewer FGMRES iterations, each inner solve reported), and the
    # V-cycle's Q1 problem solved to 1e-10; both the same run to solver tolerance
    for mode, label in (("exact velocity", "velocity GMRES"), ("exact coarse", "coarse Q1 GMRES")):
        settings = multigrid.replace("true", "false").replace(
            "end\n", f" set inner solves = {mode}\n set verbose = true\nend\n")
        diagnosed = run("kinetic_theory_bed", short + settings,
                        folder=os.path.join(work, "matrix_free_" + mode.replace(" ", "_")))
        # the error A^-1 r of a solve to 1e-11 depends on where the residual is left: with
        # exact velocity solves the monitors differ from the reference by up to 1.5e-7
        # (true residuals checked equal to FGMRES's estimates), with the V-cycle by <= 1e-8
        same_monitors(reference, diagnosed, f"p-multigrid with inner solves = {mode}",
                      1e-6 if mode == "exact velocity" else 1e-8)
        reports = re.findall(label + r" \(.*?\): (.*)", run.stdout)
        expect(len(reports) > 0, f"inner solves = {mode}: the inner solves reported ({len(reports)} lines, e.g. '{(reports or [''])[0][:80]}')")
        if mode == "exact velocity":
            iterations = sum(float(r["krylov_iterations"]) for r in diagnosed[1:])
            expect(iterations < v_cycle_iterations,
                   f"exact velocity solves take fewer FGMRES iterations than one V-cycle ({iterations:.0f} < {v_cycle_iterations:.0f})")
    # the boundary reactions (their rows applied matrix-free, without any constraint),
    # relative to the inlet's (the bed's weight)
    for name, limit in (("inlet_reaction", 1e-7), ("wall_reaction", 1e-7), ("outlet_reaction", 1e-7)):
        worst = max(abs(a[name] - b[name]) / abs(a["inlet_reaction"]) for a, b in zip(reference[1:], rows[1:]))
        expect(worst <= limit, f"{name} (boundary rows applied matrix-free) agrees (max difference {worst:.1e} of the inlet reaction <= {limit:.0e})")
    amr = ("subsection time stepping\n set end time = 0.01\nend\n"
           "subsection adaptive refinement\n set enabled = true\n set interval = 1\n"
           " set minimum level = 0\n set maximum level = 2\nend\n")
    rows = run("bubbling_bed_2d", amr + multigrid, 2, os.path.join(work, "matrix_free_amr"))
    checked("bubbling bed, AMR, 2 ranks")
    expect(max(int(r["active_cells"]) for r in rows) > int(rows[0]["active_cells"]), "the AMR run refined (hanging nodes)")
    steps3d = ("subsection time stepping\n set end time = 2e-4\nend\n"
               "subsection spectrum\n set enabled = false\nend\n")
    run("column_3d", steps3d + multigrid, 2, os.path.join(work, "matrix_free_3d"))
    checked("3D column")
elif check in ("amr", "amr_ranks"):
    # bubble-following AMR adapting at every step (refining and coarsening) on the 2D
    # bubbling bed: solids mass to 1e-12 and bounds at every step, and a fixed-mesh run
    # continued with AMR (check amr, 1 rank); T13: 2 ranks equal 1 rank with AMR on; T14
    # with AMR: continued on 2 ranks from a 1-rank checkpoint (check amr_ranks, on the
    # 1-rank run that check amr leaves in WORK/amr_1: ctest runs it after amr)
    import shutil
    # solved to 1e-11 so that the ranks' round-off differences (~1e-7 at the default
    # 1e-8) cannot flip a refinement decision at a threshold; heavy coarsening (threshold
    # 0.06, twice the default), where deal.II's rank-local flag smoothing made 2 ranks
    # differ from 1 at step 14 before PartitionIndependentTriangulation
    overrides = ("subsection time stepping\n set end time = 0.03\nend\n"
                 + EXACT_SOLVES +
                 "subsection adaptive refinement\n set enabled = true\n set interval = 1\n"
                 " set minimum level = 0\n set maximum level = 3\n set coarsen threshold = 0.06\nend\n"
                 "subsection checkpoint\n set interval = 20\n set at end = false\nend\n")
    if check == "amr":
        one = run("bubbling_bed_2d", overrides, 1, os.path.join(work, "amr_1"))
        bounds_and_mass(one, 0.61, 1e-12)
        cells = [int(r["active_cells"]) for r in one]
        grew, shrank = sum(b > a for a, b in zip(cells, cells[1:])), sum(b < a for a, b in zip(cells, cells[1:]))
        expect(grew >= 10 and shrank >= 2, f"the mesh followed the bed: {cells[0]} -> {cells[-1]} cells, "
                                           f"{grew} adaptations with more cells, {shrank} with fewer")
        expect(max(cells) < 600 * 4 ** 2, f"AMR keeps fewer cells ({max(cells)}) than the uniform level-3 mesh (9600)")
        # a run spun up on the fixed base mesh to 0.015 s goes on with AMR from its final
        # checkpoint: the mesh adapts after the resume, the solids mass and bounds hold
        fixed = (overrides.replace(" set enabled = true\n", " set enabled = false\n")
                 .replace("set end time = 0.03", "set end time = 0.015").replace("set at end = false", "set at end = true"))
        base = run("bubbling_bed_2d", fixed, 1, os.path.join(work, "amr_spun_up"))
        folder = os.path.join(work, "amr_after_fixed")
        shutil.rmtree(folder, ignore_errors=True)
        shutil.copytree(os.path.join(work, "amr_spun_up"), folder)
        rows = run("bubbling_bed_2d", overrides, 1, folder, resume=True)
        last = int(base[-1]["step"])
        before = {int(r["active_cells"]) for r in rows if int(r["step"]) <= last}
        after = [int(r["active_cells"]) for r in rows if int(r["step"]) > last]
        expect(before == {int(base[0]["active_cells"])} and after and any(c not in before for c in after),
               f"the fixed mesh ({before} cells to step {last}) adapts after the resume: {after[:3]} ... {after[-1:]}")
        bounds_and_mass(rows, 0.61, 1e-12)
        expect(abs(float(rows[-1]["time"]) - 0.03) < 1e-9, f"the resumed run reaches 0.03 s (t = {rows[-1]['time']})")
    else:
        if not os.path.isfile(os.path.join(work, "amr_1", "monitors.csv")):
            expect(False, "check amr's 1-rank run is missing (ctest runs case_amr before case_amr_ranks)")
            sys.exit(1)
        one = read_monitors(os.path.join(work, "amr_1"))
        cells = [int(r["active_cells"]) for r in one]
        expect(abs(float(one[-1]["time"]) - 0.03) < 1e-9,
               "the 1-rank AMR run of check amr reached 0.03 s")
        # 2 ranks partitioned by cost (a wall face costs 3 cells): another partition, the
        # same mesh and monitors
        weighted = overrides + "subsection mesh\n set wall face weight = 3\nend\n"
        two = run("bubbling_bed_2d", weighted, 2, os.path.join(work, "amr_2"))
        partition = re.findall(r"Partition: owned cells per rank (\d+)-(\d+), wall faces per rank (\d+)-(\d+) "
                               r"\(mesh/wall face weight 3\)", run.stdout)
        expect(partition and partition[0][0] != partition[0][1],
               f"the cells are balanced by cost, not by count (cells and wall faces per rank: {partition[:1]})")
        expect([int(r["active_cells"]) for r in two] == cells, "2 ranks adapt the mesh exactly as 1 rank")
        same_monitors(one, two, "AMR on 2 ranks vs 1 rank", 1e-4)
        folder = os.path.join(work, "amr_resumed")
        shutil.rmtree(folder, ignore_errors=True)
        shutil.copytree(os.path.join(work, "amr_1"), folder)
        rows = run("bubbling_bed_2d", weighted, 2, folder, resume=True)  # repartitioned by cost when it adapts
        same_monitors(one, rows, "AMR run resumed at step 20 on 2 ranks", 1e-4)
elif check == "failure":
    # issue 7: a step that cannot be saved by halving dt stops the run cleanly: status 3,
    # a report naming the cause and where the failed state is extreme, the last good
    # state as fields and as a checkpoint that a corrected case resumes from
    folder = os.path.join(work, "failure")
    failing = ("subsection linear solver\n set maximum iterations = 3\nend\n" + FIXED_OUTER +
               "subsection time stepping\n set end time = 2e-3\n set minimum time step = 2e-5\nend\n")
    run("bubbling_bed_2d", failing, 1, folder, expected_exit=3)
    report = os.path.join(folder, "failure_report.txt")
    text = open(report).read() if os.path.isfile(report) else ""
    print(text)
    expect("cause of the last rejection: a linear solve did not converge" in text or
           "cause of the last rejection: FGMRES did not converge" in text, "the report names the cause")
    expect(all(k in text for k in ("alpha_s max", "Theta min", "|u_g| max", ") m", "P_s")),
           "the report locates the extremes of alpha_s, Theta, u and gives the closures there")
    # the residual history: every attempt (dt halving from the first), each FGMRES solve
    # with its 3 iterations from the initial to the final residual, marked as failed
    attempts = re.findall(r"attempt (\d+): dt ([0-9.e+-]+) s", text)
    solves = re.findall(r"flow FGMRES: (\d+) iterations, residual ([0-9.e+-]+) -> ([0-9.e+-]+) \(target ([0-9.e+-]+)\) FAILED", text)
    expect(len(attempts) >= 3 and all(abs(float(attempts[i + 1][1]) / float(attempts[i][1]) - 0.5) < 1e-9
                                      for i in range(len(attempts) - 1)),
           f"the residual history lists every attempt with dt halving ({len(attempts)} attempts)")
    expect(len(solves) == len(attempts) and all(int(n) == 3 and float(r1) < float(r0) and float(r1) > float(t)
                                                for n, r0, r1, t in solves),
           "each attempt's FGMRES: 3 iterations, residual falling but above its target")
    expect(os.path.isfile(os.path.join(folder, "checkpoint", "state")) and os.path.isfile(os.path.join(folder, "fields_00001.pvtu")),
           "the last good state was written (checkpoint and fields)")
    rows = run("bubbling_bed_2d", "subsection time stepping\n set end time = 2e-3\nend\n", 1, folder, resume=True)
    expect(rows[-1]["time"] >= 2e-3 - 1e-12, "the corrected case resumes from the checkpoint and finishes")
elif check == "divergence":
    # issue 55: a step must also be physically sane. Each check is injected by a
    # threshold the normal start-up of the quick-start bed exceeds (retries = 0: the
    # first failed check stops the run): status 3, failure_report.txt naming the check
    # (and, for the speed checks, the cells), the last good state written
    base = ("subsection time stepping\n set end time = 0.05\nend\n"
            "subsection divergence checks\n set retries = 0\n")
    injected = {
        "speed": (base + " set speed limit factor = 0.3\nend\n",
                  "speed check: |u_g| = ", "m/s; the fastest:"),
        "fluidization": (base + " set fluidization index limit = 1e-3\nend\n",
                         "fluidization index check: FI = ", "fluidization index limit = 0.001"),
        # a speed scale of 1 cm/s: the bed starting to move doubles the kinetic energy
        "energy": (base + " set reference speed = 0.01\n set speed limit factor = 1e9\n"
                   " set energy growth factor = 2\nend\n",
                   "kinetic energy check: ", "energy growth factor = 2"),
        # the Courant limit of the first step's speeds is below the smallest step allowed
        "courant": ("subsection time stepping\n set end time = 0.05\n set cfl target = 1e-3\n"
                    " set initial time step = 1e-4\n set minimum time step = 1e-4\nend\n",
                    "the next time step ", "fell below time stepping/minimum time step (Courant limit"),
        # an error tolerance no step can meet halves the step until it is below the minimum
        "time_error": ("subsection time stepping\n set end time = 0.05\n set time error tolerance = 1e-14\n"
                       " set initial time step = 1e-4\n set minimum time step = 6e-5\nend\n",
                       "the next time step ", "alpha_s time error"),
    }
    for name, (overrides, cause, detail) in injected.items():
        folder = os.path.join(work, "divergence_" + name)
        run("quick_start_2d", overrides, 1, folder, expected_exit=3)
        report = os.path.join(folder, "failure_report.txt")
        text = open(report).read() if os.path.isfile(report) else ""
        print(text[:1500])
        if not (cause in text and detail in text):
            # what the run printed, so that a failure elsewhere (CI) shows its cause
            print(run.stdout[-3000:], run.stderr[-2000:])
        expect(cause in text and detail in text, f"{name}: the report names the check ({cause.strip()})")
        expect(("diagnosis in" in run.stderr + run.stdout) and "last good state" in run.stderr + run.stdout,
               f"{name}: the one-line error points at the report and the last good state")
        expect(os.path.isfile(os.path.join(folder, "checkpoint", "state")),
               f"{name}: the last good state was written as a checkpoint")
        if name == "speed":
            cells = re.findall(r"\|u_[gs]\| = ([0-9.e+-]+) m/s in the cell at \(", text)
            expect(len(cells) >= 1 and all(float(c) > 0 for c in cells),
                   f"speed: the report lists the worst cells ({len(cells)})")
    # the defaults leave the normal start-up alone
    rows = run("quick_start_2d", "subsection time stepping\n set end time = 0.05\nend\n", 1,
               os.path.join(work, "divergence_none"))
    expect(rows[-1]["time"] >= 0.05 - 1e-12, "with the default checks the start-up runs to its end")
elif check == "column_3d":
    # issue 55: the shipped 3D column from rest past the time (0.26 s) where the
    # conservative momentum form diverged in the void under the first slug; 2 ranks,
    # default path. Speeds stay on the case's physical scales, Theta below its cap and no
    # divergence check fires.
    rows = run("column_3d", "subsection time stepping\n set end time = 0.3\nend\n"
               "subsection checkpoint\n set at end = false\nend\n", 2)
    expect(rows[-1]["time"] >= 0.3 - 1e-12, f"the column reached t = {rows[-1]['time']:.4f} s")
    expect("check:" not in run.stdout, "no divergence check rejected a step")
    solids = max(r["solids_speed_max"] for r in rows)
    gas = max(r["gas_speed_max"] for r in rows)
    theta = max(r["theta_max"] for r in rows)
    # 2.6 m/s: the terminal velocity of the 350 um beads, the case's reference speed
    expect(solids < 2 * 2.6, f"solids speed at most {solids:.2f} m/s (< 2 terminal velocities)")
    expect(gas < 10 * 2.6, f"gas speed at most {gas:.2f} m/s (< 10 terminal velocities)")
    expect(theta < 0.1, f"Theta at most {theta:.4f} m^2/s^2 (the cap is 1)")
    late = [r for r in rows if r["time"] > 0.2]
    expect(min(r["time_step"] for r in late) > 1e-4,
           f"the step stays above 1e-4 s after 0.2 s ({min(r['time_step'] for r in late):.2e} s)")
elif check == "seed_column":
    # issue 54: one .geo for every column (mesh/geometry parameters), and the seed's
    # instruments: the pressure probe with its FI and the ECT slab at a fixed frame rate,
    # on a short 3D column on 2 ranks; a resume continues the ECT files as if unbroken
    geometry = "subsection mesh\n set geometry parameters = height: 0.15, n_layers: 12, n_ring: 1\nend\n"
    instruments = ("subsection bed monitors\n set pressure probe height = 0.01\nend\n"
                   "subsection ECT sensor\n set enabled = true\n set centre height = 0.03\n set thickness = 0.02\n"
                   " set frame rate = 1000\n set resolution = 8\n set levels = 2\nend\n"
                   "subsection checkpoint\n set at end = false\n set interval = 4\nend\n"
                   "subsection statistics\n set radial profile heights = 0.03\n set plane heights = 0.03\n"
                   " set plane resolution = 8\nend\n")
    end = "subsection time stepping\n set end time = {}\nend\n"
    folder = os.path.join(work, "seed_column")
    rows = run("column_3d", geometry + instruments + end.format(0.006), 2, folder)
    # the mesh gmsh made: 0.15 m tall, (3 x 3 core + 4 x 3 x 1 ring) x 12 layers
    text = open(os.path.join(folder, "mesh.msh")).read()
    nodes = text[text.index("$Nodes"):text.index("$EndNodes")].splitlines()[2:]
    top, i = 0.0, 0
    while i < len(nodes):
        count = int(nodes[i].split()[3])
        top = max([top] + [float(line.split()[2]) for line in nodes[i + 1 + count:i + 1 + 2 * count]])
        i += 1 + 2 * count
    expect(abs(top - 0.15) < 1e-9, f"geometry parameters applied: the column is {top:.4f} m tall (0.15)")
    expect(rows[-1]["active_cells"] == 21 * 12, f"{int(rows[-1]['active_cells'])} cells (21 per layer x 12 layers)")
    # the pressure probe: below the inlet-to-outlet drop by the bed beneath the probe
    last = rows[-1]
    expect("probe_pressure_drop" in last and 0 < last["probe_pressure_drop"] < last["pressure_drop"],
           f"probe pressure drop {last.get('probe_pressure_drop', math.nan):.1f} Pa, inlet-to-outlet "
           f"{last['pressure_drop']:.1f} Pa")
    ratio = last["probe_fluidization_index"] / last["fluidization_index"]
    expect(abs(ratio - last["probe_pressure_drop"] / last["pressure_drop"]) < 1e-9 and 0.5 < ratio < 1,
           f"probe FI / FI = {ratio:.3f} (the bed above 1 cm of 5 cm)")
    # the ECT slab: a frame every 1 ms from t = 0, whatever the step
    ect = list(csv.DictReader(open(os.path.join(folder, "ect.csv"))))
    times = [float(r["time"]) for r in ect]
    expect(len(ect) == 7 and all(abs(t - 0.001 * k) < 1e-12 for k, t in enumerate(times)),
           f"{len(ect)} ECT frames at {times} (every 1 ms from 0 to 6 ms)")
    steps = [r["time"] for r in rows]
    expect(len(steps) != len(ect) or any(abs(a - b) > 1e-9 for a, b in zip(steps, times)),
           "the frames are not the steps (time steps differ from the frame interval)")
    slab = [float(r["alpha_s_slab"]) for r in ect]
    expect(abs(slab[0] - 0.58) < 1e-6, f"frame 0: the slab inside the bed at rest holds alpha_s = {slab[0]:.6f} (0.58)")
    expect(all(0 < a <= 0.61 for a in slab), f"slab alpha_s within (0, 0.61]: {min(slab):.4f} .. {max(slab):.4f}")
    images = list(csv.reader(open(os.path.join(folder, "ect_images.csv"))))
    corner, centre = images[1][1], float(images[1][1 + 3 * 8 + 3])
    expect(len(images) == 8 and len(images[1]) == 65 and corner == "nan" and abs(centre - 0.58) < 1e-6,
           f"images: 8 x 8 pixels a frame, corner outside the column ({corner}), centre {centre:.4f}")
    # resumed from the last periodic checkpoint (every 4 steps) in a copy of the folder:
    # the ECT files are cut back to it and continue as in the unbroken run
    half = os.path.join(work, "seed_column_resumed")
    shutil.rmtree(half, ignore_errors=True)
    shutil.copytree(folder, half)
    run("column_3d", geometry + instruments + end.format(0.006), 2, half, resume=True)
    restart = re.search(r"at t = ([0-9.e+-]+)", run.stdout)
    resumed = list(csv.DictReader(open(os.path.join(half, "ect.csv"))))
    expect(restart is not None and 0 < float(restart.group(1)) < 0.006 and len(resumed) == len(ect) and
           all(abs(float(a["alpha_s_slab"]) - float(b["alpha_s_slab"])) < 1e-9 for a, b in zip(resumed, ect)),
           f"resumed at t = {restart.group(1) if restart else '?'} s: {len(resumed)} frames equal to the unbroken run's")
    expect(len(list(csv.reader(open(os.path.join(half, "ect_images.csv"))))) == 8, "resumed: 7 images, no duplicate")
    # issue 50: a radial profile (20 radii, each the mean of 16 azimuths) and a plane map
    # of the bed at 3 cm, written at the end; the resumed run's files equal these
    def profile(where, name):
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(open(os.path.join(where, "statistics", name)))]
    radial_all, plane_all = profile(folder, "radial_at_0.03m.csv"), profile(folder, "plane_at_0.03m.csv")
    times = sorted(set(r["time"] for r in radial_all))
    expect(times == [0, rows[-1]["time"]], f"profiles at the field outputs t = 0 and the end: {times}")
    radial = [r for r in radial_all if r["time"] == times[-1]]
    plane = [r for r in plane_all if r["time"] == times[-1]]
    radii = [r["r"] for r in radial]
    expect(len(radial) == 20 and all(abs(r - (k + 0.5) * 0.025 / 20) < 1e-9 for k, r in enumerate(radii)),
           f"radial profile: {len(radial)} radii {radii[0]:.5f} .. {radii[-1]:.5f} m at the end")
    inside = [r["alpha_s"] for r in plane if not math.isnan(r["alpha_s"])]
    expect(all(0.5 < r["alpha_s"] < 0.61 for r in radial) and len(plane) == 64 and 40 <= len(inside) < 64 and
           all(0.5 < a < 0.61 for a in inside) and all(abs(r["z"] - 0.03) < 1e-12 for r in plane),
           f"the bed at 3 cm: alpha_s {min(r['alpha_s'] for r in radial):.4f} .. {max(r['alpha_s'] for r in radial):.4f} "
           f"across the radius, {len(inside)} of 64 map points inside the column")
    def same_rows(a, b):  # NaN (outside the domain) equal to NaN
        return len(a) == len(b) and all(x.keys() == y.keys() and all(
            (math.isnan(x[k]) and math.isnan(y[k])) or abs(x[k] - y[k]) < 1e-9 for k in x) for x, y in zip(a, b))
    expect(same_rows(profile(half, "radial_at_0.03m.csv"), radial_all) and
           same_rows(profile(half, "plane_at_0.03m.csv"), plane_all),
           "resumed: the profile files as the unbroken run's (no duplicate rows)")
    # with adaptive refinement (levels 0-1, every step) the ECT pixels are located again
    # after each mesh change: those inside the column are found in the refined cells,
    # those outside read NaN (they are not looked for again: refinement keeps the domain)
    adaptive = os.path.join(work, "seed_column_amr")
    amr = ("subsection adaptive refinement\n set enabled = true\n set minimum level = 0\n"
           " set maximum level = 1\n set interval = 1\nend\n")
    amr_rows = run("column_3d", geometry + instruments + amr + end.format(0.004), 2, adaptive)
    amr_images = list(csv.reader(open(os.path.join(adaptive, "ect_images.csv"))))[1:]
    found = [[v != "nan" for v in row[1:]] for row in amr_images]
    values = [float(v) for row in amr_images for v in row[1:] if v != "nan"]
    expect(max(r["active_cells"] for r in amr_rows) > 21 * 12 and len(amr_images) == 5 and
           all(f == [v != "nan" for v in images[1][1:]] for f in found) and all(0 < a <= 0.61 for a in values),
           f"AMR ({int(max(r['active_cells'] for r in amr_rows))} cells at most): {len(amr_images)} frames, each "
           f"with the uniform run's {sum(found[0])} pixels inside the column, alpha_s {min(values):.4f} .. {max(values):.4f}")
    # the frames stacked in time, both runs side by side (the seed's Fig. 4)
    picture = os.path.join(work, "seed_column_ect_stack.png")
    if os.path.exists(picture):
        os.remove(picture)
    stacked = subprocess.run([sys.executable, os.path.join(source, "scripts", "ect_stack.py"), folder, half,
                              "--labels", "unbroken,resumed", "--out", picture], capture_output=True, text=True)
    expect(stacked.returncode == 0 and stacked.stdout.count("7 frames") == 2 and os.path.getsize(picture) > 10000,
           f"scripts/ect_stack.py draws both runs: {stacked.stdout.strip().splitlines()[:2]} {stacked.stderr[-200:]}")
    # a name the .geo does not define is refused before anything is written
    bad = os.path.join(work, "seed_column_bad")
    shutil.rmtree(bad, ignore_errors=True)
    run("column_3d", "subsection mesh\n set geometry parameters = heigth: 1\nend\n", 1, bad, expected_exit=2)
    expect("mesh/geometry parameters" in run.stderr and "'heigth'" in run.stderr and not os.path.exists(bad),
           f"an unknown name is refused: {run.stderr.strip().splitlines()[-1][:160] if run.stderr.strip() else ''}")
elif check == "statistics":
    # issue 50: time averages of the fields from a start time on, weighted by the step
    # lengths, read back from the HDF5 output (single precision, hence tolerances of
    # 1e-6): the written alpha_s_mean and alpha_s_variance against the same sums over the
    # fields written at every step; a run resumed from a mid-run checkpoint ends with the
    # same averages (1e-10); with adaptive refinement the mean alpha_s keeps the solids
    # mass
    try:
        import numpy
        import h5py  # noqa: F401
    except ImportError:  # Debian's python3-numpy and python3-h5py live under /usr/bin/python3
        if os.path.realpath(sys.executable) != "/usr/bin/python3":
            os.execv("/usr/bin/python3", ["/usr/bin/python3"] + sys.argv)
        raise
    sys.path.insert(0, os.path.join(source, "scripts"))
    import render_fields
    start = 0.008
    over = ("subsection time stepping\n set end time = 0.02\nend\n"
            f"subsection statistics\n set time averages = true\n set start time = {start}\nend\n"
            "subsection checkpoint\n set interval = 7\n set at end = false\nend\n"
            "subsection output\n set field interval = 1e-9\n set monitor interval = 1\n"
            " set field format = vtu and hdf5\nend\n"
            # the resumed run must end with the unbroken run's averages to 1e-10
            + EXACT_SOLVES)
    folder = os.path.join(work, "statistics")
    rows = run("quick_start_2d", over, 1, folder)
    frames = render_fields.hdf5_frames(folder)
    expect(len(frames) == len(rows), f"{len(frames)} field outputs, one per step ({len(rows)} monitor rows)")
    # ParaView's time record of the VTU outputs: every output at its time (6 digits)
    pvd = render_fields.pvd_times(folder)
    expect(len(pvd) == len(rows) and all(abs(pvd[f"fields_{k:05d}.pvtu"] - r["time"]) <= 1e-6 * r["time"] + 1e-12
                                         for k, r in enumerate(rows)),
           f"fields.pvd lists the {len(pvd)} VTU outputs at their times")
    names = ["alpha_s", "alpha_s_mean", "alpha_s_variance", "granular_temperature", "granular_temperature_mean"]
    fields = [load(names).fields for _, load in frames]
    times = [r["time"] for r in rows]
    weights = [0.0] + [min(times[k] - times[k - 1], max(0.0, times[k] - start)) for k in range(1, len(times))]
    total = sum(weights)
    expect(abs(total - (times[-1] - start)) < 1e-12, f"averaged over {total:.6f} s = end - start")

    def weighted(name):
        mean = sum(w * f[name] for w, f in zip(weights, fields)) / total
        return mean, sum(w * (f[name] - mean) ** 2 for w, f in zip(weights, fields)) / total

    mean, variance = weighted("alpha_s")
    last = fields[-1]
    nodes = numpy.arange(len(mean)) % 9
    nodes = numpy.isin(nodes, (0, 2, 6, 8))  # the Q1 nodes: the corners of each 3 x 3 patch
    error_mean = numpy.max(numpy.abs(last["alpha_s_mean"] - mean))
    error_variance = numpy.max(numpy.abs(last["alpha_s_variance"] - variance)[nodes])
    expect(error_mean < 1e-6, f"alpha_s_mean = the step-weighted mean of the outputs (max difference {error_mean:.1e})")
    expect(error_variance < 1e-6 * numpy.max(variance) and numpy.max(variance) > 1e-6,
           f"alpha_s_variance = their weighted variance at the nodes (max difference {error_variance:.1e}, "
           f"largest variance {numpy.max(variance):.2e})")
    theta_mean, _ = weighted("granular_temperature")
    error_theta = numpy.max(numpy.abs(last["granular_temperature_mean"] - theta_mean))
    expect(error_theta < 1e-6 * numpy.max(theta_mean), f"granular_temperature_mean likewise ({error_theta:.1e})")
    before = fields[[k for k, t in enumerate(times) if t <= start][-1]]
    expect(numpy.max(numpy.abs(before["alpha_s_mean"])) == 0, "nothing is averaged before the start time")
    # resumed from the checkpoint of step 14 in a copy of the folder
    half = os.path.join(work, "statistics_resumed")
    shutil.rmtree(half, ignore_errors=True)
    shutil.copytree(folder, half)
    run("quick_start_2d", over, 1, half, resume=True)
    resumed = render_fields.hdf5_frames(half)[-1][1](names).fields
    expect(render_fields.pvd_times(half) == pvd and open(os.path.join(half, "fields.pvd")).read().count("<DataSet") == len(rows),
           "resumed: fields.pvd the unbroken run's, without duplicates")
    difference = numpy.max(numpy.abs(resumed["alpha_s_mean"] - last["alpha_s_mean"]))
    difference_variance = numpy.max(numpy.abs(resumed["alpha_s_variance"] - last["alpha_s_variance"]))
    restart = re.search(r"at t = ([0-9.e+-]+)", run.stdout)
    expect(restart is not None and start < float(restart.group(1)) < times[-1] and difference < 1e-10
           and difference_variance < 1e-10 * numpy.max(variance),
           f"resumed at t = {restart.group(1) if restart else '?'} s: the same averages "
           f"(differences {difference:.1e}, {difference_variance:.1e})")
    # adaptive refinement at every step: the mean alpha_s holds the solids mass
    amr = os.path.join(work, "statistics_amr")
    rows = run("bubbling_bed_2d", "subsection time stepping\n set end time = 0.012\nend\n"
               "subsection statistics\n set time averages = true\n set start time = 0.004\nend\n"
               "subsection adaptive refinement\n set enabled = true\n set interval = 1\n set maximum level = 2\nend\n"
               "subsection output\n set field format = hdf5\nend\n", 1, amr)
    frame = render_fields.hdf5_frames(amr)[-1][1](["alpha_s", "alpha_s_mean"])
    corners = frame.points[frame.cells][:, :, :2]
    x, y = corners[:, :, 0], corners[:, :, 1]
    area = 0.5 * numpy.abs(numpy.sum(x * numpy.roll(y, -1, axis=1) - numpy.roll(x, -1, axis=1) * y, axis=1))
    density = 2500.0
    integral = lambda name: density * numpy.sum(area * frame.fields[name][frame.cells].mean(axis=1))  # noqa: E731
    cells = [int(r["active_cells"]) for r in rows]
    changes = sum(a != b for a, b in zip(cells, cells[1:]))
    mass = rows[-1]["solids_mass"]
    expect(changes >= 3 and abs(integral("alpha_s_mean") / mass - 1) < 1e-6 and abs(integral("alpha_s") / mass - 1) < 1e-6,
           f"{changes} mesh changes: the mean alpha_s holds {integral('alpha_s_mean') / mass - 1:.1e} "
           f"of the solids mass more than it (alpha_s itself {integral('alpha_s') / mass - 1:.1e})")
elif check == "profiles":
    # issue 50: profiles and maps of the time averages, on the steady Ergun column (solids
    # held at alpha_s = 0.45, gas at U/alpha_g, p' linear): the means are the fields in
    # closed form and every standard deviation 0. Written at each field output (every
    # 2 ms) and at the end; a run resumed from its mid-run checkpoint rewrites nothing
    # twice.
    over = ("subsection time stepping\n set end time = 5e-3\nend\n"
            "subsection statistics\n set time averages = true\n set start time = 1e-3\n"
            " set lateral profile heights = 0.15\n set plane heights = 0.1, 0.2\n set plane resolution = 10\n"
            " set lines = axis: 0.025 0.01, 0.025 0.29, 15\nend\n"
            "subsection output\n set field interval = 2e-3\nend\n"
            "subsection checkpoint\n set interval = 3\n set at end = false\nend\n")
    folder = os.path.join(work, "profiles")
    rows = run("ergun_column", over, 1, folder)

    def profile(where, name):
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(open(os.path.join(where, "statistics", name)))]
    axis = profile(folder, "line_axis.csv")
    times = sorted(set(r["time"] for r in axis))
    expect(len(axis) == 3 * 15 and all(abs(a - b) < 1e-12 for a, b in zip(times, (0.002, 0.004, 0.005))),
           f"the axis line: {len(axis)} rows at t = {times} (the outputs at 2 and 4 ms and the end; none before the start)")
    U, a_g = 0.2, 0.55
    worst = max(max(abs(r["alpha_s_mean"] - 0.45), abs(r["u_g_y_mean"] - U / a_g), abs(r["u_g_x_mean"]),
                    abs(r["u_s_x_mean"]), abs(r["u_s_y_mean"])) for r in axis)
    deviation = max(r[k] for r in axis for k in r if k.endswith("_std"))
    expect(worst < 1e-9 and deviation < 1e-6,
           f"means = the steady fields (alpha_s 0.45, u_g = U/alpha_g, u_s = 0; max error {worst:.1e}), "
           f"standard deviations at most {deviation:.1e}")
    last = [r for r in axis if r["time"] == times[-1]]
    slope = (last[-1]["p_mean"] - last[0]["p_mean"]) / (last[-1]["s"] - last[0]["s"])
    expected = -rows[-1]["pressure_drop"] / 0.3
    linear = max(abs(r["p_mean"] - (last[0]["p_mean"] + slope * r["s"])) for r in last)
    expect(abs(slope / expected - 1) < 1e-8 and linear < 1e-8 * abs(expected),
           f"p' along the axis: slope {slope:.6f} Pa/m = -pressure drop / H ({expected:.6f}), linear to {linear:.1e}")
    lateral = [r for r in profile(folder, "lateral_at_0.15m.csv") if r["time"] == times[-1]]
    positions = [r["position"] for r in lateral]
    expect(len(lateral) == 20 and all(abs(x - (k + 0.5) * 0.05 / 20) < 1e-12 for k, x in enumerate(positions)) and
           max(abs(r["alpha_s_mean"] - 0.45) for r in lateral) < 1e-9,
           f"lateral profile at 15 cm: 20 points {positions[0]:.5f} .. {positions[-1]:.5f} m, alpha_s_mean 0.45")
    plane = [r for r in profile(folder, "plane_at_0.2m.csv") if r["time"] == times[-1]]
    expect(len(plane) == 10 and all(abs(r["y"] - 0.2) < 1e-12 and abs(r["u_g_y_mean"] - U / a_g) < 1e-9 for r in plane),
           f"plane at 20 cm (a line in 2D): {len(plane)} points, u_g_y_mean = U/alpha_g")
    # a prescribed periodic signal: U(t) = U0 (1 + A sin(2 pi t / 4 ms)) moves the gas of
    # the fixed bed at U(t)/alpha_g; averaged over two periods (steps of 1 ms from 1 ms on)
    # the mean is U0/alpha_g and the standard deviation A U0/alpha_g/sqrt(2), exactly
    periodic = os.path.join(work, "profiles_periodic")
    run("ergun_column", "subsection time stepping\n set end time = 9e-3\nend\n"
        "subsection boundary conditions\n set inlet superficial velocity = 0.2*(1 + 0.5*sin(2*pi*t/0.004))\nend\n"
        "subsection statistics\n set time averages = true\n set start time = 1e-3\n"
        " set lines = axis: 0.025 0.01, 0.025 0.29, 15\nend\n", 1, periodic)
    ends = [r for r in profile(periodic, "line_axis.csv") if abs(r["time"] - 9e-3) < 1e-12]
    mean_error = max(abs(r["u_g_y_mean"] - U / a_g) for r in ends)
    std_error = max(abs(r["u_g_y_std"] - 0.5 * U / a_g / math.sqrt(2)) for r in ends)
    expect(len(ends) == 15 and mean_error < 1e-9 and std_error < 1e-9,
           f"periodic inflow: u_g_y mean {ends[0]['u_g_y_mean']:.10f} (U0/alpha_g {U / a_g:.10f}), standard deviation "
           f"{ends[0]['u_g_y_std']:.10f} (A U0/alpha_g/sqrt 2 {0.5 * U / a_g / math.sqrt(2):.10f}); errors {mean_error:.1e}, {std_error:.1e}")
    # resumed from the checkpoint of step 3 in a copy of the folder
    half = os.path.join(work, "profiles_resumed")
    shutil.rmtree(half, ignore_errors=True)
    shutil.copytree(folder, half)
    run("ergun_column", over, 1, half, resume=True)
    restart = re.search(r"at t = ([0-9.e+-]+)", run.stdout)
    resumed = profile(half, "line_axis.csv")
    difference = max(abs(a[k] - b[k]) for a, b in zip(axis, resumed) for k in a)
    expect(restart is not None and abs(float(restart.group(1)) - 0.003) < 1e-9 and len(resumed) == len(axis)
           and difference < 1e-9,
           f"resumed at t = {restart.group(1) if restart else '?'} s: {len(resumed)} rows as the unbroken run's "
           f"(difference {difference:.1e})")
else:
    sys.exit(f"unknown check {check}")

print(f"{check}: {'all checks passed' if not failures else 'checks failed'}")
sys.exit(1 if failures else 0)
