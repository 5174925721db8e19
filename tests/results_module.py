#!/usr/bin/env python3
"""Checks scripts/wetbed_results.py, the Python reader of run folders, on small synthetic
run folders written here: every reader returns the exact values written (NaN where the
file has nan, -nan or an empty cell; the run id as text), the profiles split into their
output times, the command-line summary, and scripts/plot_run.py's statistics through it.
Field readers: a VTU output of two pieces (ascii and zlib-compressed binary arrays) and
an HDF5 one, when numpy (and h5py) can be imported here or under Debian's
/usr/bin/python3; skipped otherwise.

usage: tests/results_module.py SOURCE_DIR WORK_DIR [--fields]
(--fields: the field checks alone; prints `ok ...` / `FAIL ...`, exits 1 on a failure)"""
import base64
import math
import os
import shutil
import struct
import subprocess
import sys
import zlib

source, work = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
fields_only = "--fields" in sys.argv[3:]
sys.path.insert(0, os.path.join(source, "scripts"))
import wetbed_results as wr  # noqa: E402

failures = 0


def expect(condition, message):
    global failures
    print(("ok " if condition else "FAIL ") + message)
    if not condition:
        failures += 1


def same(a, b):
    """Equal lists (or values), NaN equal to NaN."""
    if isinstance(a, list) and isinstance(b, list):
        return len(a) == len(b) and all(same(x, y) for x, y in zip(a, b))
    if isinstance(a, float) and isinstance(b, float) and math.isnan(a) and math.isnan(b):
        return True
    return type(a) is type(b) and a == b


def write(folder, name, text):
    path = os.path.join(folder, name)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(text)


nan = math.nan
run = os.path.join(work, "run")


def tables():
    shutil.rmtree(run, ignore_errors=True)
    os.makedirs(run)
    # monitors: the run ids as text, even where one reads as a number; an empty cell
    write(run, "monitors.csv",
          "step,time,pressure_drop,fluidization_index,bed_height,alpha_s_plane_0.076,run\n"
          "0,0,0,0,0.2,0.45,17c0370e71ff944d\n"
          "1,0.001,2303.31,1.01,0.21,,17c0370e71ff944d\n"
          "2,0.002,2301.5,0.99,0.22,0.44,1234e567\n")
    m = wr.monitors(run)
    expect(m is not None and list(m) == ["step", "time", "pressure_drop", "fluidization_index", "bed_height",
                                           "alpha_s_plane_0.076", "run"],
           f"monitors: the columns in the file's order {list(m) if m else None}")
    expect(same(m["time"], [0.0, 0.001, 0.002]) and same(m["pressure_drop"], [0.0, 2303.31, 2301.5])
           and same(m["alpha_s_plane_0.076"], [0.45, nan, 0.44]),
           f"monitors: the values, the empty cell NaN {m['alpha_s_plane_0.076']}")
    expect(same(m["run"], ["17c0370e71ff944d", "17c0370e71ff944d", "1234e567"]),
           f"monitors: the run ids as text {m['run']}")
    expect(wr.monitors(os.path.join(work, "nowhere")) is None, "monitors: None without the file")

    # bubbles: an empty rise velocity, text event kinds, a missing file
    write(run, "bubbles.csv",
          "step,time,track,volume,equivalent_diameter,centroid_x,centroid_y,centroid_z,lower_x,lower_y,lower_z,"
          "upper_x,upper_y,upper_z,touches_wall,cells,rise_velocity,run\n"
          "35,0.02684966027,0,0.00025,0.01784124116,0.025,0.0025,0,0,0,0,0.05,0.005,0,1,10,,17c0370e71ff944d\n"
          "40,0.03184966027,0,0.00025,0.018,0.025,0.0025,0,0,0,0,0.05,0.005,0,1,10,0.25,17c0370e71ff944d\n")
    write(run, "bubble_events.csv", "step,time,kind,tracks_before,tracks_after,run\n"
                                    "40,0.03184966027,splitting,1,2,17c0370e71ff944d\n")
    b = wr.bubbles(run)
    expect(b["summary"] is None and same(b["bubbles"]["time"], [0.02684966027, 0.03184966027])
           and same(b["bubbles"]["rise_velocity"], [nan, 0.25]) and same(b["bubbles"]["track"], [0.0, 0.0]),
           "bubbles: bubbles.csv's values (empty rise velocity NaN), no bubble_summary.csv: None")
    expect(same(b["events"]["kind"], ["splitting"]) and same(b["events"]["tracks_after"], [2.0]),
           f"bubbles: bubble_events.csv's kind as text {b['events']['kind']}")

    # spectrum: '#' lines with the dominant frequencies, then the table
    write(run, "spectrum.csv",
          "# pressure_drop: dominant frequency 3.01125 Hz (Welch: 4 segments of 160 samples at 0.002 s, from t = 1 s)\n"
          "# alpha_s_plane_0.076: dominant frequency 2.5 Hz (Welch: 4 segments of 160 samples ...)\n"
          "frequency,psd_pressure_drop,psd_alpha_s_plane_0.076\n"
          "0,489.5008374,1e-05\n"
          "3.125,1641.836646,2.5e-06\n")
    s = wr.spectrum(run)
    expect(s is not None and s["dominant"] == {"pressure_drop": 3.01125, "alpha_s_plane_0.076": 2.5},
           f"spectrum: the dominant frequencies {s['dominant'] if s else None}")
    expect(list(s["columns"]) == ["frequency", "psd_pressure_drop", "psd_alpha_s_plane_0.076"]
           and same(s["columns"]["psd_pressure_drop"], [489.5008374, 1641.836646])
           and same(s["columns"]["psd_alpha_s_plane_0.076"], [1e-05, 2.5e-06]),
           "spectrum: the '#' lines skipped, the table's values")
    expect(wr.spectrum(run, "ect_spectrum.csv") is None, "spectrum: None without the file")

    # ECT: the slab signal, 2 x 2 images (pixel_i_j, i first) with nan outside, its spectrum
    write(run, "ect.csv", "time,alpha_s_slab\n0,0.58\n0.001,0.57998783\n0.002,0.5801\n")
    write(run, "ect_images.csv", "time,pixel_0_0,pixel_1_0,pixel_0_1,pixel_1_1\n"
                                 "0,nan,0.5,0.25,0.125\n0.001,0.1,0.2,0.3,nan\n0.002,1,2,3,4\n")
    write(run, "ect_spectrum.csv", "# alpha_s_slab: dominant frequency 4.25 Hz (Welch: ...)\n"
                                   "frequency,psd_alpha_s_slab\n0,1\n")
    e = wr.ect(run)
    expect(same(e["signal"]["time"], [0.0, 0.001, 0.002])
           and same(e["signal"]["alpha_s_slab"], [0.58, 0.57998783, 0.5801]), "ect: the slab signal")
    expect(e["resolution"] == 2 and same(e["times"], [0.0, 0.001, 0.002]) and
           same(e["images"], [[[nan, 0.5], [0.25, 0.125]], [[0.1, 0.2], [0.3, nan]], [[1.0, 2.0], [3.0, 4.0]]]),
           f"ect: the images as images[k][j][i] = pixel_i_j {e['images'][0]}")
    expect(e["spectrum"]["dominant"] == {"alpha_s_slab": 4.25}, "ect: ect_spectrum.csv's dominant frequency")
    e = wr.ect(run, start=0.001, end=0.002)
    expect(same(e["times"], [0.001, 0.002]) and same(e["signal"]["alpha_s_slab"], [0.57998783, 0.5801])
           and len(e["images"]) == 2, "ect: start and end select the frames and the signal (both ends included)")
    stored = os.path.join(work, "stored_images")  # a stored copy: ect_images.csv.gz
    shutil.rmtree(stored, ignore_errors=True)
    write(stored, "ect.csv", "time,alpha_s_slab\n0,0.58\n")
    import gzip
    with open(os.path.join(run, "ect_images.csv"), "rb") as f, gzip.open(os.path.join(stored, "ect_images.csv.gz"), "wb") as g:
        g.write(f.read())
    g = wr.ect(stored)
    expect(g["resolution"] == 2 and same(g["times"], [0.0, 0.001, 0.002]) and
           same(g["images"], [[[nan, 0.5], [0.25, 0.125]], [[0.1, 0.2], [0.3, nan]], [[1.0, 2.0], [3.0, 4.0]]]),
           "ect: the images read from a gzipped ect_images.csv.gz")
    odd = os.path.join(work, "odd_images")
    shutil.rmtree(odd, ignore_errors=True)
    write(odd, "ect_images.csv", "time,pixel_0_0,pixel_1_0,pixel_0_1\n0,1,2,3\n")
    try:
        wr.ect(odd)
        refused = ""
    except ValueError as error:
        refused = str(error)
    expect("3 pixels a frame is not a square image" in refused, f"ect: 3 pixels a frame refused ({refused})")
    expect(wr.ect(os.path.join(work, "nowhere")) is None, "ect: None without the files")

    # profiles: two output times of 3 radii (nan and -nan: a point outside the domain),
    # a line with one time, a profile with no row yet
    write(run, "statistics/radial_at_0.03m.csv",
          "time,r,alpha_s_mean,alpha_s_std,u_g_axial_mean\n"
          "0.002,0.000625,0.45,0,0.3636363636\n"
          "0.002,0.001875,0.44,1e-06,nan\n"
          "0.002,0.003125,-nan,nan,-nan\n"
          "0.005,0.000625,0.4,0.01,0.35\n"
          "0.005,0.001875,0.41,0.02,0.36\n"
          "0.005,0.003125,nan,nan,nan\n")
    write(run, "statistics/line_axis.csv",
          "time,s,x,y,alpha_s,p\n0.005,0,0.025,0.01,0.45,12.5\n0.005,0.02,0.025,0.03,0.45,10\n")
    write(run, "statistics/plane_at_0.1m.csv", "time,x,y,alpha_s,p\n")
    p = wr.profiles(run)
    expect(list(p) == ["line_axis", "plane_at_0.1m", "radial_at_0.03m"], f"profiles: by name {list(p)}")
    radial = p["radial_at_0.03m"]
    expect([block.time for block in radial] == [0.002, 0.005], f"profiles: two output times {[b.time for b in radial]}")
    first, last = radial
    expect(list(first.columns) == ["r", "alpha_s_mean", "alpha_s_std", "u_g_axial_mean"],
           "profiles: the columns but time")
    expect(same(first.columns["r"], [0.000625, 0.001875, 0.003125]) and
           same(first.columns["alpha_s_mean"], [0.45, 0.44, nan]) and
           same(first.columns["u_g_axial_mean"], [0.3636363636, nan, nan]) and
           same(last.columns["alpha_s_std"], [0.01, 0.02, nan]),
           "profiles: the values of each time (nan and -nan as NaN)")
    expect(p["plane_at_0.1m"] == [] and p["line_axis"][0].columns["p"] == [12.5, 10.0],
           "profiles: a file without rows gives no block; the line's block")
    def same_block(a, b):
        return a is not None and a.time == b.time and a.columns.keys() == b.columns.keys() and \
            all(same(a.columns[k], b.columns[k]) for k in a.columns)
    expect(same_block(wr.profile(run, "radial_at_0.03m"), last)
           and same_block(wr.profile(run, "radial_at_0.03m.csv"), last),
           "profile: the last output by default (the name with or without .csv)")
    expect(same_block(wr.profile(run, "radial_at_0.03m", 0.0021), first) and
           same_block(wr.profile(run, "radial_at_0.03m", 1.0), last), "profile: the output nearest to a time")
    expect(wr.profile(run, "radial_at_9m") is None and wr.profile(run, "plane_at_0.1m") is None,
           "profile: None for a missing file or one without rows")
    expect(wr.profiles(os.path.join(work, "nowhere")) == {}, "profiles: empty without statistics/")

    # parameters.prm: subsections, comments, a continued line
    write(run, "parameters.prm",
          "# Listing of Parameters\n"
          "subsection output\n"
          "  set field interval    = 0.5    # default: 0.05\n"
          "  subsection nested level\n"
          "    set a  value = 1, \\\n      2\n"
          "  end\n"
          "end\n"
          "subsection physical properties\n"
          "  set gravity                  = 0, -9.81, 0\n"
          "  set maximum packing          = 0.61\n"
          "end\n")
    values = wr.run_parameters(run)
    expect(values == {"output/field interval": "0.5", "output/nested level/a value": "1, 2",
                      "physical properties/gravity": "0, -9.81, 0", "physical properties/maximum packing": "0.61"},
           f"run_parameters: {values}")
    expect(wr.parameter(values, "gravity") == "0, -9.81, 0" and wr.parameter(values, "output/field interval") == "0.5"
           and wr.parameter(values, "missing", "x") == "x", "parameter: by the last part of the path or the whole")

    # the command line, in this interpreter (the standard library suffices)
    summary = subprocess.run([sys.executable, os.path.join(source, "scripts", "wetbed_results.py"), run],
                             capture_output=True, text=True)
    out = summary.stdout
    wanted = ["monitors: 3 rows, t = 0 .. 0.002 s, 7 columns, 2 run ids",
              "bubbles: bubbles.csv 2 rows (1 track), bubble_events.csv 1 row",
              "spectrum.csv: dominant frequency pressure_drop 3.01125 Hz, alpha_s_plane_0.076 2.5 Hz",
              "ect_images.csv: 3 images of 2x2 pixels, t = 0 .. 0.002 s",
              "profile radial_at_0.03m: 2 times (0.002, 0.005 s), 3 rows at the last; "
              "columns r, alpha_s_mean, alpha_s_std, u_g_axial_mean",
              "profile plane_at_0.1m: no rows", "parameters.prm: 4 settings"]
    missing = [w for w in wanted if w not in out.splitlines()]
    expect(summary.returncode == 0 and not missing,
           f"scripts/wetbed_results.py RUN prints the summary (exit {summary.returncode}; missing {missing})"
           f" {summary.stderr[-300:]}")

    # scripts/plot_run.py's statistics read through the module
    import plot_run
    s = plot_run.statistics(run, start=0.0)
    expect(s["dominant_frequency_pressure_drop"] == 3.01125 and s["dominant_frequency_alpha_s_plane_0.076"] == 2.5
           and s["plane"] == 0.076 and s["end_time"] == 0.002
           and s["mean_bubble_diameter"] == (0.01784124116 + 0.018) / 2,
           "plot_run.statistics: the dominant frequencies, the probe plane, the end time, the bubble diameter")


def vtu_binary(values, kind, block_bytes=16):
    """A DataArray's text as deal.II writes it: a base64 header of uint32 (blocks, block
    size, last block size, compressed sizes), then the base64 compressed blocks."""
    raw = struct.pack(f"<{len(values)}{kind}", *values)
    blocks = [raw[k:k + block_bytes] for k in range(0, len(raw), block_bytes)]
    compressed = [zlib.compress(b) for b in blocks]
    header = struct.pack(f"<{3 + len(blocks)}I", len(blocks), block_bytes, len(blocks[-1]),
                         *[len(c) for c in compressed])
    return (base64.b64encode(header) + base64.b64encode(b"".join(compressed))).decode()


def data_array(kind, name, values, components=1, binary=False):
    """A VTU DataArray element of values (kind: Float32, Float64, Int32 or UInt8)."""
    text = vtu_binary(values, {"Float64": "d", "Int32": "i"}[kind]) if binary else " ".join(repr(v) for v in values)
    return (f'<DataArray type="{kind}"' + (f' Name="{name}"' if name else "") + f' NumberOfComponents="{components}"'
            f' format="{"binary" if binary else "ascii"}">{text}</DataArray>\n')


def piece(points, cells, alpha_s, velocity):
    """One rank's .vtu: quadrilaterals, alpha_s in ascii, gas_velocity and the points and
    connectivity compressed."""
    return ('<?xml version="1.0" ?>\n'
            '<VTKFile type="UnstructuredGrid" version="0.1" compressor="vtkZLibDataCompressor">\n'
            f'<UnstructuredGrid>\n<Piece NumberOfPoints="{len(points)}" NumberOfCells="{len(cells)}">\n'
            '<Points>' + data_array("Float64", "", [c for p in points for c in p], 3, True) + '</Points>\n<Cells>\n'
            + data_array("Int32", "connectivity", [i for c in cells for i in c], binary=True)
            + data_array("Int32", "offsets", [4 * (k + 1) for k in range(len(cells))])
            + data_array("UInt8", "types", [9] * len(cells)) + '</Cells>\n<PointData Scalars="scalars">\n'
            + data_array("Float32", "alpha_s", alpha_s)
            + data_array("Float64", "gas_velocity", [c for v in velocity for c in v], 3, True)
            + '</PointData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n')


def fields():
    try:
        import numpy as np
    except ImportError:
        debian = "/usr/bin/python3"
        if not fields_only and os.path.exists(debian) and os.path.realpath(sys.executable) != os.path.realpath(debian):
            print(f"(the field checks under {debian}: numpy is missing here)")
            sys.stdout.flush()
            return subprocess.run([debian, os.path.abspath(__file__), source, work, "--fields"]).returncode == 0
        print("skip fields: numpy is missing")
        return True
    folder = os.path.join(work, "vtu")
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    # two pieces (ranks), one quadrilateral each, side by side
    left = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
    right = [(1, 0, 0), (2, 0, 0), (2, 1, 0), (1, 1, 0)]
    for k in (0, 1):
        write(folder, f"fields_0000{k}.0.vtu", piece(left, [(0, 1, 2, 3)], [0.5, 0.25, 0.125, 0.0], [(1, 9, 9)] * 4))
        write(folder, f"fields_0000{k}.1.vtu", piece(right, [(0, 1, 2, 3)], [0.25, 0.75, 1.5, 0.125],
                                                     [(2, 9, 9), (3, 9, 9), (4, 9, 9), (5, 9, 9)]))
        write(folder, f"fields_0000{k}.pvtu", '<?xml version="1.0"?>\n<VTKFile type="PUnstructuredGrid">\n'
              f'<PUnstructuredGrid><Piece Source="fields_0000{k}.0.vtu"/><Piece Source="fields_0000{k}.1.vtu"/>'
              '</PUnstructuredGrid>\n</VTKFile>\n')
    write(folder, "parameters.prm", "subsection output\n  set field interval = 0.5\nend\n")
    found = wr.frames(folder)
    expect([t for t, _ in found] == [0.0, 0.5], f"VTU without fields.pvd: the times from the index x field interval "
                                                f"{[t for t, _ in found]}")
    write(folder, "fields.pvd", '<?xml version="1.0"?>\n<VTKFile type="Collection"><Collection>\n'
                                '<DataSet timestep="0.125" group="" part="0" file="fields_00000.pvtu"/>\n'
                                '<DataSet timestep="0.375" group="" part="0" file="fields_00001.pvtu"/>\n'
                                '</Collection></VTKFile>\n')
    expect(wr.pvd_times(folder) == {"fields_00000.pvtu": 0.125, "fields_00001.pvtu": 0.375}, "pvd_times")
    found = wr.frames(folder)
    frame = found[-1][1](["alpha_s", "gas_velocity", "absent"])
    expect(frame.time == 0.375 and [t for t, _ in found] == [0.125, 0.375], "VTU: the times from fields.pvd")
    expect(np.array_equal(frame.points, np.array(left + right, dtype=float)) and
           np.array_equal(frame.cells, np.array([[0, 1, 2, 3], [4, 5, 6, 7]])),
           f"VTU: the points and cells of both pieces (the second's indices shifted) {frame.cells.tolist()}")
    expect(sorted(frame.fields) == ["alpha_s", "gas_velocity"] and
           np.array_equal(frame.fields["alpha_s"], [0.5, 0.25, 0.125, 0.0, 0.25, 0.75, 1.5, 0.125]) and
           np.array_equal(frame.fields["gas_velocity"], [1, 1, 1, 1, 2, 3, 4, 5]),
           f"VTU: ascii and compressed binary arrays, vectors' first component {frame.fields.get('gas_velocity')}")
    try:
        import h5py
    except ImportError:
        print("skip HDF5: h5py is missing")
        return True
    with h5py.File(os.path.join(folder, "fields_00000.h5"), "w") as h5:
        h5["nodes"] = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], dtype=float)
        h5["cells"] = np.array([[0, 1, 2, 3]], dtype=np.uint32)
        h5["alpha_s"] = np.array([[0.5], [0.25], [0.125], [0.0625]])
    write(folder, "fields.xdmf",
          '<?xml version="1.0" ?>\n<Xdmf Version="2.0"><Domain>\n'
          '<Grid Name="CellTime" GridType="Collection" CollectionType="Temporal">\n'
          '<Grid Name="mesh" GridType="Uniform"><Time Value="0.0625"/>\n'
          '<Geometry GeometryType="XY"><DataItem Format="HDF">fields_00000.h5:/nodes</DataItem></Geometry>\n'
          '<Topology TopologyType="Quadrilateral"><DataItem Format="HDF">fields_00000.h5:/cells</DataItem></Topology>\n'
          '<Attribute Name="alpha_s"><DataItem Format="HDF">fields_00000.h5:/alpha_s</DataItem></Attribute>\n'
          '</Grid></Grid></Domain></Xdmf>\n')
    found = wr.frames(folder)
    frame = found[0][1](["alpha_s"])
    expect([t for t, _ in found] == [0.0625] and frame.points.shape == (4, 3)
           and frame.points[2].tolist() == [1, 1, 0] and frame.cells.tolist() == [[0, 1, 2, 3]]
           and frame.fields["alpha_s"].tolist() == [0.5, 0.25, 0.125, 0.0625],
           "HDF5 before VTU: fields.xdmf's output, 2D points padded with z = 0")
    return True


for part in ([] if fields_only else [tables]) + [fields]:
    try:
        if part() is False:
            failures += 1
    except Exception:  # a reader that raises fails the check, the others still run
        import traceback
        traceback.print_exc(file=sys.stdout)
        expect(False, f"{part.__name__}: ran to the end")
print(f"{'the field checks' if fields_only else 'results_module'}: {failures} failure{'s' if failures != 1 else ''}")
sys.exit(1 if failures else 0)
