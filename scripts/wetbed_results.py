#!/usr/bin/env python3
"""Reading a wetbed run folder from Python.

usage: scripts/wetbed_results.py RUN_FOLDER   (prints what the folder holds)

As a module (scripts/plot_run.py, render_fields.py and ect_stack.py use it):

    sys.path.insert(0, "scripts")
    import wetbed_results as wr
    m = wr.monitors("output/bed")                  # {"time": [...], "pressure_drop": [...]}
    last = wr.profile("output/bed", "radial_at_0.03m")  # last.time, last.columns["r"]

Tables come as {column name: list}: floats (empty cells and `nan` as NaN), strings where a
value is not a number; the column `run` (the run id, hex digits) always as strings.
Missing files give None. The tables and profiles need the standard library only; the
field readers need numpy (and h5py for HDF5) when a frame is loaded: Debian's
python3-numpy and python3-h5py, found under /usr/bin/python3 (ensure_modules re-executes
a script there).

  read_csv(path)               columns of a CSV file, '#' comment lines skipped
  monitors(folder)             monitors.csv
  bubbles(folder)              {"bubbles", "summary", "events"}: the bubble analysis files
  spectrum(folder[, file])     {"dominant": {column: Hz}, "columns"}: spectrum.csv
  ect(folder[, start, end])    the ECT sensor: slab signal, images, spectrum
  profiles(folder)             {name: [Block(time, columns), ...]} of statistics/*.csv
  profile(folder, name[, time]) the block of one profile at a time (default the last)
  read_profile(path)           the blocks of one profile file
  frames(folder)               [(time, load)] of the field outputs (HDF5, else VTU);
                               load(names) gives a Frame: points, cells, fields
  hdf5_frames, vtu_frames      the same from fields.xdmf / fields_*.pvtu alone
  vtu_array(element)           the values of a VTU DataArray (ascii or compressed binary)
  pvd_times(folder)            {pvtu file: time} from fields.pvd
  run_parameters(folder)       {"subsection/name": value} from parameters.prm
  parameter(values, name)      a value by its full path or its last part
  ensure_modules(*names)       re-executes the script under /usr/bin/python3 if one is missing
"""
import base64
import collections
import csv
import glob
import math
import os
import re
import sys
import xml.etree.ElementTree as ElementTree
import zlib

TEXT_COLUMNS = ("run",)


def ensure_modules(*names):
    """Imports the modules; where one is missing, re-executes the script under Debian's
    /usr/bin/python3 (which has python3-matplotlib, -numpy, -h5py), unless it runs there."""
    try:
        for name in names:
            __import__(name)
    except ImportError:
        debian = "/usr/bin/python3"
        if os.path.exists(debian) and os.path.realpath(sys.executable) != os.path.realpath(debian):
            os.execv(debian, [debian] + sys.argv)
        raise


# ---------------------------------------------------------------- tables


def _number(value):
    """A CSV cell as a float (empty: NaN), else the text itself."""
    if value == "":
        return math.nan
    try:
        return float(value)
    except ValueError:
        return value


def read_csv(path, text=TEXT_COLUMNS):
    """{column: list of values} of a CSV file: floats where numeric (empty cells NaN),
    else strings; the columns named in `text` kept as strings. Lines starting with '#'
    are skipped. None if the file is missing or empty."""
    if not os.path.exists(path):
        return None
    with open(path, newline="") as f:
        rows = list(csv.reader(line for line in f if not line.startswith("#")))
    if not rows:
        return None
    columns = {name: [] for name in rows[0]}
    for row in rows[1:]:
        for name, value in zip(rows[0], row):
            columns[name].append(value if name in text else _number(value))
    return columns


def monitors(folder):
    """monitors.csv: one row per monitored step (None without the file)."""
    return read_csv(os.path.join(folder, "monitors.csv"))


def bubbles(folder):
    """The bubble analysis: {"bubbles": bubbles.csv (one row per bubble and analysis),
    "summary": bubble_summary.csv (one row per analysis), "events": bubble_events.csv
    (splittings and coalescences)}, each None without its file."""
    return {key: read_csv(os.path.join(folder, name)) for key, name in
            (("bubbles", "bubbles.csv"), ("summary", "bubble_summary.csv"), ("events", "bubble_events.csv"))}


def spectrum(folder, file="spectrum.csv"):
    """A spectrum file (spectrum.csv, or ect_spectrum.csv): {"dominant": {column: dominant
    frequency in Hz} from its '# COLUMN: dominant frequency F Hz ...' lines, "columns":
    frequency and psd_COLUMN}. None without the file."""
    path = os.path.join(folder, file)
    if not os.path.exists(path):
        return None
    dominant = {}
    with open(path) as f:
        for line in f:
            m = re.match(r"#\s*(.+?): dominant frequency (\S+)", line)
            if m:
                dominant[m.group(1)] = float(m.group(2))
    return {"dominant": dominant, "columns": read_csv(path)}


def ect(folder, start=-math.inf, end=math.inf):
    """The ECT sensor's output between the times start and end (both included):
    {"signal": ect.csv's columns (time, alpha_s_slab), "times": the image times,
    "images": one n x n nested list per image, images[k][j][i] = pixel_i_j (NaN outside
    the column; from ect_images.csv, or its gzipped copy ect_images.csv.gz), "resolution": n, "spectrum": spectrum(folder, "ect_spectrum.csv")}.
    "signal" and "images" are None without their file; None without both. Raises
    ValueError if an image's pixels are not a square."""
    signal = read_csv(os.path.join(folder, "ect.csv"))
    if signal is not None:
        keep = [k for k, t in enumerate(signal.get("time", [])) if start <= t <= end]
        signal = {name: [values[k] for k in keep] for name, values in signal.items()}
    path = os.path.join(folder, "ect_images.csv")
    if not os.path.exists(path) and os.path.exists(path + ".gz"):  # a stored copy
        path += ".gz"
    times, images, n = [], None, None
    if os.path.exists(path):
        import gzip
        with (gzip.open(path, "rt", newline="") if path.endswith(".gz") else open(path, newline="")) as f:
            reader = csv.reader(f)
            header = next(reader, ["time"])
            pixels = len(header) - 1
            n = int(round(math.sqrt(pixels)))
            if n * n != pixels:
                raise ValueError(f"{path}: {pixels} pixels a frame is not a square image")
            # pixel_i_j, i the first axis; in the file's order without such names
            position = {name: c for c, name in enumerate(header)}
            order = [position.get(f"pixel_{i}_{j}") for j in range(n) for i in range(n)]
            if None in order:
                order = list(range(1, pixels + 1))
            images = []
            for row in reader:
                if len(row) != len(header):  # a blank line, or the row a running case writes
                    continue
                t = float(row[0])
                if start <= t <= end:
                    flat = [float(row[c]) for c in order]
                    times.append(t)
                    images.append([flat[j * n:(j + 1) * n] for j in range(n)])
    if signal is None and images is None:
        return None
    return {"signal": signal, "times": times, "images": images, "resolution": n,
            "spectrum": spectrum(folder, "ect_spectrum.csv")}


# ---------------------------------------------------------------- profiles

Block = collections.namedtuple("Block", "time columns")
Block.__doc__ = """One output time of a profile: time and {column: list of floats}, the
file's columns but `time` (positions first: r, position, x y [z], or s x y [z])."""


def read_profile(path):
    """The blocks of a profile file (rows of one time each, in the file's order); None if
    the file is missing."""
    columns = read_csv(path, text=())
    if columns is None:
        return None
    times = columns.pop("time", [])
    blocks, first = [], 0
    for k in range(1, len(times) + 1):
        if k == len(times) or times[k] != times[first]:
            blocks.append(Block(times[first], {name: values[first:k] for name, values in columns.items()}))
            first = k
    return blocks


def profiles(folder):
    """{name: [Block, ...]} of the profiles in statistics/ (the file names without .csv:
    radial_at_0.03m, lateral_at_H, plane_at_H, line_NAME); empty without any."""
    found = sorted(glob.glob(os.path.join(folder, "statistics", "*.csv")))
    return {os.path.basename(path)[:-4]: read_profile(path) for path in found}


def profile(folder, name, time=None):
    """The Block of profile `name` (statistics/NAME.csv) at the output time nearest to
    `time` (default: the last output); None without the file or any row."""
    name = name[:-4] if name.endswith(".csv") else name
    blocks = read_profile(os.path.join(folder, "statistics", name + ".csv"))
    if not blocks:
        return None
    if time is None:
        return blocks[-1]
    return min(blocks, key=lambda b: abs(b.time - time))


# ---------------------------------------------------------------- parameters


def run_parameters(folder):
    """{"subsection/.../name": value} of the `set` lines of the run's parameters.prm
    (values as text, comments left out); empty without the file."""
    path = os.path.join(folder, "parameters.prm")
    values = {}
    if not os.path.exists(path):
        return values
    sections, pending = [], ""
    for line in open(path):
        line = line.strip()
        if line.endswith("\\"):  # continued on the next line (joined as deal.II does)
            pending += line[:-1]
            continue
        line, pending = (pending + line).split("#")[0], ""
        words = line.split(None, 1)
        if not words:
            continue
        if words[0] == "subsection" and len(words) > 1:
            sections.append(words[1].strip())
        elif words[0] == "end" and len(words) == 1:
            sections = sections[:-1]
        elif words[0] == "set" and len(words) > 1 and "=" in words[1]:
            name, value = words[1].split("=", 1)
            values["/".join(sections + [" ".join(name.split())])] = value.strip()
    return values


def parameter(values, name, default=None):
    """The value of `name` in run_parameters' dict: its full path, else the last entry
    whose path ends with /name; default if none."""
    if name in values:
        return values[name]
    found = [v for k, v in values.items() if k.endswith("/" + name)]
    return found[-1] if found else default


# ---------------------------------------------------------------- fields


class Frame:
    """One field output: points (n x 3), cells (m x 2^dim vertex indices, counter-
    clockwise quadrilaterals in 2D, VTK-ordered hexahedra in 3D) and point fields (first
    component of vectors)."""

    def __init__(self, time, points, cells, fields):
        self.time, self.points, self.cells, self.fields = time, points, cells, fields


def hdf5_frames(folder):
    """(time, load) of every output listed in fields.xdmf; load(names) reads the Frame
    with those fields (numpy and h5py needed then)."""
    root = ElementTree.parse(os.path.join(folder, "fields.xdmf")).getroot()
    frames = []
    for grid in root.iter("Grid"):
        if grid.get("GridType") != "Uniform":
            continue
        time = float(grid.find("Time").get("Value"))
        geometry = grid.find("Geometry/DataItem").text.strip()
        topology = grid.find("Topology/DataItem").text.strip()
        attributes = {a.get("Name"): a.find("DataItem").text.strip() for a in grid.findall("Attribute")}

        def load(names, geometry=geometry, topology=topology, attributes=attributes, time=time):
            import numpy as np
            import h5py

            def dataset(reference):
                file, name = reference.split(":")
                with h5py.File(os.path.join(folder, file), "r") as h5:
                    return h5[name.lstrip("/")][()]

            points = np.asarray(dataset(geometry), dtype=float)
            if points.shape[1] == 2:
                points = np.column_stack([points, np.zeros(len(points))])
            fields = {}
            for n in names:
                if n in attributes:
                    fields[n] = np.asarray(dataset(attributes[n]), dtype=float).reshape(len(points), -1)[:, 0]
            return Frame(time, points, np.asarray(dataset(topology), dtype=np.int64), fields)

        frames.append((time, load))
    return frames


def vtu_array(element, appended=None):
    """The values of a deal.II VTU DataArray (ascii, or base64 zlib-compressed binary)."""
    import numpy as np

    kind = {"Float32": np.float32, "Float64": np.float64, "Int32": np.int32, "Int64": np.int64,
            "UInt8": np.uint8, "UInt32": np.uint32, "UInt64": np.uint64}[element.get("type")]
    text = (element.text or "").strip()
    if element.get("format") == "ascii":
        return np.array(text.split(), dtype=kind)
    raw = base64.b64decode(text[:24])
    header = np.frombuffer(raw[:16], dtype=np.uint32)  # blocks, block size, last size, first compressed size
    blocks = int(header[0])
    header_chars = 4 * math.ceil((3 + blocks) * 4 / 3)
    sizes = np.frombuffer(base64.b64decode(text[:header_chars])[: (3 + blocks) * 4], dtype=np.uint32)[3:]
    data = base64.b64decode(text[header_chars:])
    out, offset = [], 0
    for size in sizes:
        out.append(zlib.decompress(data[offset: offset + int(size)]))
        offset += int(size)
    return np.frombuffer(b"".join(out), dtype=kind)


def pvd_times(folder):
    """{pvtu file name: time} from the run's fields.pvd (empty without one)."""
    path = os.path.join(folder, "fields.pvd")
    if not os.path.exists(path):
        return {}
    return {d.get("file"): float(d.get("timestep")) for d in ElementTree.parse(path).getroot().iter("DataSet")}


def vtu_frames(folder):
    """(time, load) of every fields_NNN.pvtu; the time from fields.pvd, else the output's
    index times the run's field interval when parameters.prm has it (else the index);
    load(names) reads the Frame with those fields (numpy needed then)."""
    records = sorted(glob.glob(os.path.join(folder, "fields_*.pvtu")))
    times = pvd_times(folder)
    interval = parameter(run_parameters(folder), "field interval")
    interval = float(interval) if interval is not None else None
    frames = []
    for record in records:
        index = int(re.search(r"fields_(\d+)\.pvtu$", record).group(1))
        time = times.get(os.path.basename(record), index * interval if interval else float(index))

        def load(names, record=record, time=time):
            import numpy as np

            pieces = [p.get("Source") for p in ElementTree.parse(record).getroot().iter("Piece")]
            all_points, all_cells, fields, offset = [], [], {n: [] for n in names}, 0
            for piece in pieces:
                root = ElementTree.parse(os.path.join(os.path.dirname(record), piece)).getroot()
                for p in root.iter("Piece"):
                    points = vtu_array(p.find("Points/DataArray")).astype(float).reshape(-1, 3)
                    cell_data = {a.get("Name"): a for a in p.find("Cells").findall("DataArray")}
                    connectivity = vtu_array(cell_data["connectivity"]).astype(np.int64)
                    offsets = vtu_array(cell_data["offsets"]).astype(np.int64)
                    per_cell = int(offsets[0]) if len(offsets) else 4
                    all_cells.append(connectivity.reshape(-1, per_cell) + offset)
                    all_points.append(points)
                    arrays = {a.get("Name"): a for a in p.find("PointData").findall("DataArray")}
                    for n in names:
                        if n in arrays:
                            fields[n].append(vtu_array(arrays[n]).astype(float).reshape(len(points), -1)[:, 0])
                    offset += len(points)
            cells = np.vstack(all_cells)
            return Frame(time, np.vstack(all_points), cells,
                         {n: np.concatenate(v) for n, v in fields.items() if v})

        frames.append((time, load))
    return frames


def frames(folder):
    """(time, load) of the run's field outputs: those of fields.xdmf when it exists and
    h5py can be imported, else those of fields_*.pvtu; empty without either."""
    if os.path.exists(os.path.join(folder, "fields.xdmf")):
        try:
            import h5py  # noqa: F401
            return hdf5_frames(folder)
        except ImportError:
            pass
    return vtu_frames(folder)


# ---------------------------------------------------------------- command line


def _span(times):
    return f"t = {times[0]:.6g} .. {times[-1]:.6g} s" if times else "no rows"


def _count(n, word):
    return f"{n} {word}" + ("" if n == 1 else "s")


def summary(folder):
    """The lines printed by the command line: what the run folder holds."""
    lines = [f"run folder: {folder}"]
    grouped = collections.Counter(re.sub(r"^fields_\d+", "fields_*", n)
                                  for n in sorted(os.listdir(folder)) if not n.startswith("."))
    lines.append("files: " + ", ".join(n + ("/" if os.path.isdir(os.path.join(folder, n)) else "")
                                       + (f" ({c})" if c > 1 else "") for n, c in grouped.items()))
    m = monitors(folder)
    if m is not None:
        t = m.get("time", [])
        runs = len(set(m.get("run", [])))
        lines.append(f"monitors: {_count(len(t), 'row')}, {_span(t)}, {_count(len(m), 'column')}"
                     + (f", {_count(runs, 'run id')}" if runs else ""))
    parts, b = [], bubbles(folder)
    for key, file in (("bubbles", "bubbles.csv"), ("summary", "bubble_summary.csv"), ("events", "bubble_events.csv")):
        table = b[key]
        if table is not None:
            parts.append(f"{file} {_count(len(table.get('time', [])), 'row')}"
                         + (f" ({_count(len(set(table.get('track', []))), 'track')})" if key == "bubbles" else ""))
    if parts:
        lines.append("bubbles: " + ", ".join(parts))
    for file in ("spectrum.csv", "ect_spectrum.csv"):
        s = spectrum(folder, file)
        if s is not None:
            found = ", ".join(f"{k} {v:.6g} Hz" for k, v in s["dominant"].items())
            lines.append(f"{file}: dominant frequency {found or 'none given'}")
    signal = read_csv(os.path.join(folder, "ect.csv"))
    if signal is not None:
        t = signal.get("time", [])
        lines.append(f"ect.csv: {_count(len(t), 'row')}, {_span(t)}")
    path = os.path.join(folder, "ect_images.csv")
    if os.path.exists(path):  # counted, not read: the images can be large
        with open(path, newline="") as f:
            reader = csv.reader(f)
            pixels = len(next(reader, ["time"])) - 1
            t = [float(row[0]) for row in reader if row]
        n = int(round(math.sqrt(pixels)))
        lines.append(f"ect_images.csv: {_count(len(t), 'image')} of {n}x{n} pixels, {_span(t)}")
    for name, blocks in profiles(folder).items():
        if not blocks:
            lines.append(f"profile {name}: no rows")
            continue
        columns = list(blocks[-1].columns)
        times = [f"{b.time:.6g}" for b in blocks]
        if len(times) > 6:
            times = times[:3] + ["..."] + times[-2:]
        rows = len(blocks[-1].columns[columns[0]]) if columns else 0
        lines.append(f"profile {name}: {_count(len(blocks), 'time')} ({', '.join(times)} s), "
                     f"{_count(rows, 'row')} at the last; columns {', '.join(columns)}")
    if os.path.exists(os.path.join(folder, "fields.xdmf")):
        t = [time for time, _ in hdf5_frames(folder)]
        lines.append(f"fields (HDF5, fields.xdmf): {_count(len(t), 'output')}, {_span(t)}")
    t = [time for time, _ in vtu_frames(folder)]
    if t:
        lines.append(f"fields (VTU, fields_*.pvtu): {_count(len(t), 'output')}, {_span(t)}"
                     + ("" if pvd_times(folder) else " (no fields.pvd: times from the output index)"))
    values = run_parameters(folder)
    if values:
        lines.append(f"parameters.prm: {_count(len(values), 'setting')}")
    return lines


def main():
    if len(sys.argv) == 2 and sys.argv[1] in ("-h", "--help"):
        print(__doc__)
        sys.exit(0)
    if len(sys.argv) != 2:
        sys.exit("usage: scripts/wetbed_results.py RUN_FOLDER   (prints what the folder holds)")
    folder = sys.argv[1]
    if not os.path.isdir(folder):
        sys.exit(f"wetbed_results: no folder {folder}")
    print("\n".join(summary(folder)))


if __name__ == "__main__":
    main()
