"""Shared parts of the benchmark scripts: run under Debian's /usr/bin/python3 (where
python3-matplotlib lives) when started by another interpreter, the repository root, and
the summary of a run from its monitors.csv and screen log."""
import csv
import os
import re
import shutil
import sys


def repository_root():
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        if os.path.exists("/usr/bin/python3") and os.path.realpath(sys.executable) != "/usr/bin/python3":
            os.execv("/usr/bin/python3", ["/usr/bin/python3"] + sys.argv)
    return os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def read_case(name):
    """A shipped case, prm/NAME.prm, with its mesh paths made absolute."""
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    return open(os.path.join(root, "prm", name + ".prm")).read().replace("../meshes/", root + "/meshes/")


def write_case(work, name, base, end_time, sections="", field_interval=0.1, progress_interval=200):
    """WORK/NAME.prm: BASE with SECTIONS appended, the end time and the output into
    WORK/NAME (a later `set` wins in deal.II's ParameterHandler). Returns (prm, folder,
    log path)."""
    folder = os.path.join(work, name)
    prm = os.path.join(work, name + ".prm")
    with open(prm, "w") as f:
        f.write(base + sections + f"""
subsection time stepping
  set end time = {end_time}
end
subsection output
  set folder = {folder}
  set field interval = {field_interval}
  set progress interval = {progress_interval}
end
""")
    return prm, folder, os.path.join(work, name + ".log")


FIELD_OUTPUT = re.compile(r"^fields([._]|$)")  # the field outputs: not needed to continue a run


def archive_run(folder, sidecars, target):
    """Packs what continuing a run needs into the tar.gz TARGET: FOLDER without its field
    outputs (checkpoint, monitors and the other CSV files) and the SIDECARS beside it (its
    .log and .wall), so that a run survives the loss of build/ and continues on another
    machine (restore_run). Written beside TARGET and renamed: an interrupted archive
    leaves the previous one whole. Returns TARGET's size in bytes."""
    import tarfile
    partial = target + ".partial"
    with tarfile.open(partial, "w:gz") as archive:
        name = os.path.basename(folder)
        for entry in sorted(os.listdir(folder)):
            if not FIELD_OUTPUT.match(entry) and entry not in (".wetbed.lock", "checkpoint.partial",
                                                                       "checkpoint.previous"):
                archive.add(os.path.join(folder, entry), arcname=os.path.join(name, entry))
        for path in sidecars:
            if os.path.exists(path):
                archive.add(path, arcname=os.path.basename(path))
    os.replace(partial, target)
    return os.path.getsize(target)


def restore_run(target, folder):
    """Unpacks the archive TARGET (archive_run) beside FOLDER when FOLDER has no checkpoint
    of its own (a fresh build/): the run then continues from the archived checkpoint.
    Returns whether it did."""
    import tarfile
    if not os.path.exists(target) or os.path.isdir(os.path.join(folder, "checkpoint")):
        return False
    if os.path.isdir(folder):
        shutil.rmtree(folder)  # a piece started from rest without a checkpoint: the archive is further
    with tarfile.open(target, "r:gz") as archive:
        archive.extractall(os.path.dirname(folder))
    return True


def last_time(folder):
    """The time of the last row of FOLDER/monitors.csv (0 without one)."""
    path = os.path.join(folder, "monitors.csv")
    if not os.path.exists(path):
        return 0.0
    rows = open(path).read().split("\n")
    rows = [r for r in rows[1:] if r.strip()]
    return float(rows[-1].split(",")[1]) if rows else 0.0


def run_resumable(command, folder, log, wall_file, resumable=True, env=None, end_time=None):
    """Runs COMMAND (a wetbed call, optionally under mpirun) with its screen output in LOG.
    With RESUMABLE, a run that has a checkpoint in FOLDER and a WALL_FILE from an earlier
    piece is continued (`--resume`, the log appended) and WALL_FILE keeps the wall time of
    all pieces, updated every 5 s so that an interrupted piece still counts; a run whose
    log already says `Finished:` is not started again, unless END_TIME lies beyond the
    last row of its monitors.csv (then it is continued to END_TIME from its last
    checkpoint). Returns (exit code, total wall s)."""
    import subprocess
    import time
    finished = resumable and os.path.exists(wall_file) and os.path.exists(log) and "Finished:" in open(log).read()
    if finished and (end_time is None or last_time(folder) >= end_time - 1e-9):
        return 0, float(open(wall_file).read())
    resume = resumable and os.path.isdir(os.path.join(folder, "checkpoint")) and os.path.exists(wall_file)
    earlier = float(open(wall_file).read()) if resume else 0.0
    begin = time.time()
    with open(log, "a" if resume else "w") as out:
        process = subprocess.Popen(command + (["--resume"] if resume else ["--overwrite"]),
                                   stdout=out, stderr=subprocess.STDOUT, env=env)
        while True:
            try:  # returns as the run ends, so the wall time is not rounded to the poll
                process.wait(timeout=5)
                break
            except subprocess.TimeoutExpired:
                if resumable:
                    with open(wall_file, "w") as f:
                        f.write(str(earlier + time.time() - begin))
    wall = earlier + time.time() - begin
    if resumable:
        with open(wall_file, "w") as f:
            f.write(str(wall))
    return process.returncode, wall


def summarize_run(folder, log, start_up, wall=None):
    """FI time mean after start_up and over 0.5 s windows, steps, rejected steps, wall
    time, cost per simulated second, FGMRES iterations per step, bounds, mass drift;
    returns (summary dict, (t, FI) series). WALL (all pieces of a resumed run) replaces
    the wall time of the log's last piece."""
    data = list(csv.DictReader(open(os.path.join(folder, "monitors.csv"))))
    t = [float(r["time"]) for r in data]
    dt = [float(r["time_step"]) for r in data]
    fi = [float(r["fluidization_index"]) for r in data]
    after = [i for i in range(len(t)) if t[i] > start_up]
    weight = sum(dt[i] for i in after)
    mean_fi = sum(fi[i] * dt[i] for i in after) / weight if weight > 0 else float("nan")
    windows = []
    w0 = start_up
    while w0 < t[-1] - 1e-9:
        idx = [i for i in after if w0 < t[i] <= w0 + 0.5]
        if idx:
            windows.append(sum(fi[i] * dt[i] for i in idx) / sum(dt[i] for i in idx))
        w0 += 0.5
    total_wall = wall
    text = open(log).read() if os.path.exists(log) else ""
    fin = re.search(r"Finished: (\d+) steps \((\d+) rejected\), wall ([\d.e+-]+) s, ([\d.e+-]+) s per simulated second", text)
    steps, rejected, wall, per_second = (
        (int(fin.group(1)), int(fin.group(2)), float(fin.group(3)), float(fin.group(4))) if fin
        else (len(data) - 1, int(data[-1]["rejected_steps"]), float("nan"), float("nan")))
    if total_wall is not None:
        steps, wall, per_second = int(float(data[-1]["step"])), total_wall, total_wall / max(t[-1], 1e-30)
    summary = {
        "end": t[-1], "finished": bool(fin), "mean_fi": mean_fi,
        "fi_min_window": min(windows) if windows else float("nan"),
        "fi_max_window": max(windows) if windows else float("nan"),
        "steps": steps, "rejected": rejected, "wall": wall, "per_second": per_second,
        "krylov": sum(float(r["krylov_iterations"]) for r in data[1:]) / max(len(data) - 1, 1),
        "alpha_min": min(float(r["alpha_s_min"]) for r in data),
        "alpha_max": max(float(r["alpha_s_max"]) for r in data),
        "theta_min": min(float(r["theta_min"]) for r in data),
        "theta_max": max(float(r["theta_max"]) for r in data),
        "drift": max(abs(float(r["solids_mass_drift"])) for r in data),
        "frequency": float("nan"),
    }
    probe = [k for k in data[0] if k.startswith("alpha_s_plane_")]
    if probe:
        summary["frequency"] = dominant_frequency(t, [float(r[probe[-1]]) for r in data], start_up)
    return summary, (t, fi)


def dominant_frequency(t, signal, start_up):
    """The frequency (Hz) of the largest peak of the amplitude spectrum of SIGNAL(t) after
    START_UP (resampled uniformly at the mean step, mean removed); nan if too short."""
    import numpy
    t = numpy.asarray(t)
    signal = numpy.asarray(signal)
    keep = t > start_up
    if keep.sum() < 16:
        return float("nan")
    times = numpy.linspace(t[keep][0], t[keep][-1], keep.sum())
    values = numpy.interp(times, t[keep], signal[keep])
    spectrum = numpy.abs(numpy.fft.rfft(values - values.mean()))
    frequencies = numpy.fft.rfftfreq(len(values), times[1] - times[0])
    return float(frequencies[1 + numpy.argmax(spectrum[1:])])


def replace_doc_section(root, key, title, lines, doc_name="benchmarks.md"):
    """Replaces the block between <!-- KEY:begin --> and <!-- KEY:end --> of
    doc/DOC_NAME (doc/benchmarks.md) with LINES (appended under `## TITLE` if absent)."""
    doc = os.path.join(root, "doc", doc_name)
    text = open(doc).read() if os.path.isfile(doc) else "# Benchmarks\n"
    begin, end = f"<!-- {key}:begin -->", f"<!-- {key}:end -->"
    section = begin + "\n" + "\n".join(lines) + "\n" + end
    if begin in text:
        text = re.sub(re.escape(begin) + ".*?" + re.escape(end), lambda _: section, text, flags=re.S)
    else:
        text += f"\n## {title}\n\n" + section + "\n"
    open(doc, "w").write(text)
    print(f"updated doc/{doc_name}")


def time_mean(rows, column, start_up):
    """The time-step-weighted mean of monitors.csv COLUMN over the ROWS after START_UP s."""
    after = [r for r in rows if float(r["time"]) > start_up]
    weight = sum(float(r["time_step"]) for r in after)
    return sum(float(r[column]) * float(r["time_step"]) for r in after) / weight


def timer_seconds(text, name):
    """Wall seconds of the TimerOutput section NAME in a screen log (nan if absent)."""
    m = re.search(r"\| " + re.escape(name) + r"\s*\|\s*\d+\s*\|\s*([\d.e+-]+)s", text)
    return float(m.group(1)) if m else float("nan")


def solver_run(root, work, name, base, end_time, sections, ranks=1):
    """Runs WORK/NAME (BASE + SECTIONS, serial or on RANKS MPI ranks, no field output, no
    checkpoint, no bubble analysis) and returns its solver figures: cells, steps, FGMRES
    iterations per solve (repeated solves after an AMG rebuild counted), Krylov,
    preconditioner-setup and total wall seconds, setups, solves and iterations."""
    import subprocess
    sections += ("\nsubsection checkpoint\n set at end = false\nend\n"
                 "subsection bubble analysis\n set enabled = false\nend\n")
    prm, folder, log = write_case(work, name, base, end_time, sections, field_interval=1000)
    command = [os.path.join(root, "build", "wetbed"), prm, "--overwrite"]
    env = None
    if ranks > 1:
        command = ["mpirun", "--oversubscribe", "-np", str(ranks)] + command
        env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    with open(log, "w") as out:
        subprocess.run(command, stdout=out, stderr=subprocess.STDOUT, check=True, env=env)
    rows = list(csv.DictReader(open(os.path.join(folder, "monitors.csv"))))[1:]
    text = open(log).read()
    solves = int(re.search(r"\| Krylov solve\s*\|\s*(\d+)", text).group(1))
    setups = re.search(r"\| preconditioner setup\s*\|\s*(\d+)", text)
    iterations = sum(float(r["krylov_iterations"]) for r in rows)
    return {"cells": int(rows[-1]["active_cells"]), "steps": len(rows), "solves": solves,
            "setups": int(setups.group(1)) if setups else 0, "iterations": iterations,
            "its": iterations / solves, "krylov": timer_seconds(text, "Krylov solve"),
            "setup": timer_seconds(text, "preconditioner setup"),
            "total": float(re.search(r"Total wallclock time elapsed\s*\|\s*([\d.e+-]+)s", text).group(1))}


def run_case(root, work, name, case, end_time, sections, start_up):
    """Runs prm/CASE.prm + SECTIONS as WORK/NAME (serial, resumable, no field output) to
    END_TIME; returns (summary of summarize_run, all monitor rows, total wall s, log path).
    Stops the script with the log's name if the run fails."""
    prm, folder, log = write_case(work, name, read_case(case), end_time, sections,
                                  field_interval=0, progress_interval=500)
    code, wall = run_resumable([os.path.join(root, "build", "wetbed"), prm], folder, log,
                               os.path.join(work, name + ".wall"))
    if code != 0:
        raise SystemExit(f"{name} failed (exit {code}): see {log}")
    summary, _ = summarize_run(folder, log, start_up, wall)
    return summary, list(csv.DictReader(open(os.path.join(folder, "monitors.csv")))), wall, log


def bubble_diameter(folder, start_up, until=float("inf")):
    """Mean equivalent bubble diameter (m) over the bubble analyses of FOLDER's
    bubble_summary.csv with start_up < t <= until that found bubbles, weighted by the
    number of bubbles; nan if none."""
    path = os.path.join(folder, "bubble_summary.csv")
    found = [r for r in (csv.DictReader(open(path)) if os.path.isfile(path) else [])
             if start_up < float(r["time"]) <= until + 1e-12 and int(r["bubbles"]) > 0]
    if not found:
        return float("nan")
    return sum(int(r["bubbles"]) * float(r["mean_equivalent_diameter"]) for r in found) / sum(int(r["bubbles"]) for r in found)


def bubble_diameter_batch_means(folder, start_up, until, batch):
    """bubble_diameter() over consecutive batches of BATCH seconds of start_up < t <= until
    (nan for a batch without bubbles)."""
    count = int(round((until - start_up) / batch))
    return [bubble_diameter(folder, start_up + k * batch, start_up + (k + 1) * batch) for k in range(count)]


def _standard_error_of_mean(values):
    """Standard deviation of VALUES over the square root of their number; nan with fewer than 3."""
    if len(values) < 3:
        return float("nan")
    mean = sum(values) / len(values)
    return (sum((v - mean) ** 2 for v in values) / (len(values) - 1) / len(values)) ** 0.5


def bubble_diameter_standard_error(folder, start_up, until, batch=0.5):
    """Standard error (m) of the mean bubble diameter of bubble_diameter(), by batch means:
    the window start_up < t <= until cut into batches of BATCH seconds, the error being the
    standard deviation of the batch means over the square root of their number; nan with
    fewer than 3 batches that found bubbles. Batches must be longer than the correlation
    time of the bubbling: on the fluidisedBed case (pressure-drop period ~0.9 s) the error
    still grows from 0.1 s to 0.5 s batches (x1.4-1.6), hence the default of 0.5 s."""
    return _standard_error_of_mean([m for m in bubble_diameter_batch_means(folder, start_up, until, batch) if m == m])


def bubble_diameter_difference_standard_error(folder, reference, start_up, until, batch=0.5):
    """Standard error of the relative difference bubble_diameter(FOLDER) / bubble_diameter(REFERENCE) - 1
    by paired batch means: the batch-by-batch differences of the two runs' batch means (both
    over the same batches), their standard error divided by the reference's mean. Valid for
    independent runs and for runs branched from the same state (whose early batches are
    correlated, which the pairing accounts for); nan with fewer than 3 batches where both
    found bubbles."""
    pairs = zip(bubble_diameter_batch_means(folder, start_up, until, batch),
                bubble_diameter_batch_means(reference, start_up, until, batch))
    differences = [a - b for a, b in pairs if a == a and b == b]
    return _standard_error_of_mean(differences) / bubble_diameter(reference, start_up, until)
