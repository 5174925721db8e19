#!/usr/bin/env python3
"""Issue 52 item 2: a seeded mutational fuzzer over the shipped case files.

usage: fuzz_inputs.py WETBED SOURCE_DIR WORK_DIR [--seed N] [--count K] [--timeout S]
                      [--only I,J,...] [--dry-run] [--memory-limit-gb G]

Mutant I (0-based) is drawn from its own RNG, seeded by (seed, I) only: the same seed gives
the same mutants, and --count 10 gives the first 10 mutants of --count 40. Each mutant is
one of the cheap 2D cases of prm/ (or its mesh .geo from meshes/) with one kind of damage,
the kinds taken in turn so that every kind is tried:
  delete / duplicate / swap lines, numbers scaled by 10^+-k, sign-flipped or zero, numbers
  made NaN / inf / 1e300, a truncated file, random bytes, Unicode, an inconsistent
  dimension (3 with a 2D mesh and vice versa), a mutated copy of the mesh .geo, and a
  stack of two or three of these.
Overrides appended afterwards make every mutant cheap (end time 3e-4, initial time step
1e-4, no field output, the output folder WORK_DIR/out/NNN); a later `set` wins, so the
mutations never touch `time stepping/end time`, `output/folder` or `output/field
interval`, and an override is left out for any other parameter the mutation touched
(the initial time step). Every other mutant writes into a folder that already holds a
previous run's results (`overwrite = true`), the others into a new folder.

Each mutant must end with
  0: it ran (monitors.csv written);
  2: exactly one line on stderr, `wetbed: error: ...`, naming a `subsection/parameter`, a
     path or a file; the output folder not created (or, if it held results, unchanged);
  3: a numerical failure, failure_report.txt in the output folder;
  slow: still computing at the timeout (at least half a core busy over its last 10 s): a
     valid case too large for the timeout, e.g. a mesh size parameter scaled by 1e3.
Anything else is a finding (a signal, 134/139, an abort trace, `terminate called`, an
assertion, a timeout with the run idle (a hang), status 1 or another code, a multi-line error, a folder left behind
or changed). One line per mutant; a failing mutant's .prm (and .geo, and its stderr) is
kept in WORK_DIR/findings/; exit status 1 if anything failed.

benchmarks/fuzz_inputs.py runs the long campaign (2,000 mutants) with this file's
configure(), prepare(), check_mutant() and finding_class().
"""
import argparse
import hashlib
import os
import random
import re
import resource
import shutil
import signal
import subprocess
import sys
import time

parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
parser.add_argument("wetbed")
parser.add_argument("source")
parser.add_argument("work")
parser.add_argument("--seed", type=int, default=1)
parser.add_argument("--count", type=int, default=40)
parser.add_argument("--timeout", type=float, default=120, help="seconds per run (a hang past it is a finding)")
parser.add_argument("--only", default="", help="comma-separated mutant numbers to run (for reproducing one)")
parser.add_argument("--dry-run", action="store_true", help="write and list the mutants, run nothing")
parser.add_argument("--memory-limit-gb", type=float, default=6,
                    help="address-space limit of each run and its gmsh (0: none)")
CASE_3D = "column_3d.prm"
args = wetbed = source = work = CASES = MESH_DIR = MUTANTS = OUT = FINDINGS = None


def configure(argv=None):
    """Parses ARGV (the command line when None) into the module's settings: args, the
    paths, the cases found in SOURCE_DIR/prm (benchmarks/fuzz_inputs.py imports this file
    and calls it with its own list). Returns args."""
    global args, wetbed, source, work, CASES, MESH_DIR, MUTANTS, OUT, FINDINGS
    args = parser.parse_args(argv)
    wetbed, source, work = (os.path.abspath(a) for a in (args.wetbed, args.source, args.work))
    # the cheap 2D cases; column_3d.prm only for the mismatched dimension (refused before a step)
    CASES = [c for c in ("quick_start_2d.prm", "bubbling_bed_2d.prm", "wet_column_2d.prm",
                         "couette_cell_2d.prm", "seed003_bed_2d.prm")
             if os.path.isfile(os.path.join(source, "prm", c))]
    MESH_DIR = os.path.join(source, "meshes")
    MUTANTS, OUT, FINDINGS = (os.path.join(work, d) for d in ("mutants", "out", "findings"))
    return args


env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1", OMP_NUM_THREADS="1")

# parameters the overrides set (a mutation of them would always be undone) and those of
# `time stepping` that may be mutated, with their defaults (to add a line that is not there)
MASKED = {("time stepping", "end time"), ("output", "folder"), ("output", "field interval"),
          ("output", "overwrite")}
TIME_STEPPING = {"initial time step": "1e-4", "minimum time step": "1e-7", "maximum time step": "2e-3",
                 "cfl target": "0.5", "transport cfl": "0.4", "growth factor": "1.2", "bdf order": "2"}
NUMBER = re.compile(r"(?<![\w.])[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?(?![\w.])")
UNICODE = ["\u00e9", "\u00b5", "\u221e", "\u00a0", "\ufeff", "\u200b", "\uff10\uff0e\uff15", "\u0663",
           "\u202e", "\U0001d7d9", "\u00df", "\U0001f525", "\u2028", "\u0301", "\ufffd", "\u3000"]


def read(path):
    with open(path, "rb") as f:
        return f.read().decode("utf-8", "surrogateescape")


def write(path, text):
    with open(path, "wb") as f:
        f.write(text.encode("utf-8", "surrogateescape"))


def with_mesh(text):
    """Relative mesh paths (../meshes/) made absolute: the mutants live in WORK_DIR."""
    out = []
    for line in text.split("\n"):
        if line.strip().startswith("set file") and "../meshes/" in line:
            line = line.replace("../meshes/", MESH_DIR + "/")
        out.append(line)
    return "\n".join(out)


def parse(text):
    """(line index, subsection path, parameter or None) of every line."""
    stack, rows = [], []
    for i, line in enumerate(text.split("\n")):
        s = line.strip()
        key = None
        if s.startswith("subsection "):
            stack.append(s[len("subsection "):].strip())
        elif s == "end" and stack:
            stack.pop()
        elif s.startswith("set ") and "=" in s:
            key = s[4:s.index("=")].strip()
        rows.append((i, "/".join(stack), key))
    return rows


def masked(sub, key):
    return (sub, key) in MASKED


def meaningful(text):
    """Lines a line mutation may pick: not blank, no comment, not a masked parameter."""
    lines = text.split("\n")
    return [i for i, sub, key in parse(text) if lines[i].strip() and not lines[i].strip().startswith(("#", "//"))
            and not masked(sub, key)]


def short(line, n=50):
    line = line.strip()
    return ascii(line[:n] + ("..." if len(line) > n else ""))


def mutate_number(rng, token, kind):
    """A new spelling of the number TOKEN: kind scale / sign / zero / special."""
    if kind == "scale":
        k = rng.choice([-12, -6, -3, -2, -1, 1, 2, 3, 6, 12])
        if re.fullmatch(r"[-+]?\d+", token) and k > 0:
            return token + "0" * k, f"x1e{k}"
        return f"{float(token) * 10.0 ** k:.6g}", f"x1e{k}"
    if kind == "sign":
        return (token[1:] if token.startswith("-") else "-" + token.lstrip("+")), "sign flipped"
    if kind == "zero":
        return rng.choice(["0", "0.0", "-0"]), "zero"
    new = rng.choice(["nan", "NaN", "-nan", "inf", "-inf", "Infinity", "1e300", "-1e300", "1e999", "4.9e-324"])
    return new, "special"


# --- mutations of a case's text: each returns (new text, description, touched keys) -------
def number_mutation(rng, text, kinds, time_stepping_allowed=True):
    lines = text.split("\n")
    candidates = []
    for i, sub, key in parse(text):
        if key is None or masked(sub, key) or key == "file":
            continue
        if sub == "time stepping" and key not in TIME_STEPPING:
            continue
        value_start = lines[i].index("=") + 1
        for m in NUMBER.finditer(lines[i], value_start):
            candidates.append((i, sub, key, m))
    kind = rng.choice(kinds)
    # now and then a `time stepping` parameter the case leaves at its default
    if time_stepping_allowed and (not candidates or rng.random() < 0.15):
        key = rng.choice(sorted(TIME_STEPPING))
        new, how = mutate_number(rng, TIME_STEPPING[key], kind)
        for i, sub, _ in parse(text):
            if lines[i].strip() == "subsection time stepping":
                lines.insert(i + 1, f"  set {key} = {new}")
                return "\n".join(lines), f"added time stepping/{key} = {new} ({how})", {("time stepping", key)}
    if not candidates:  # a stack's earlier truncation left no number
        return text, "no number left to change", set()
    i, sub, key, m = rng.choice(candidates)
    new, how = mutate_number(rng, m.group(0), kind)
    lines[i] = lines[i][:m.start()] + new + lines[i][m.end():]
    return "\n".join(lines), f"{sub}/{key}: {m.group(0)} -> {new} ({how}, line {i + 1})", {(sub, key)}


def line_mutation(rng, text, kind):
    lines = text.split("\n")
    picks = meaningful(text)
    rows = parse(text)
    if not picks:  # a stack's earlier truncation left no line
        return text, f"no line left to {kind}", set()
    i = rng.choice(picks)
    touched = {(rows[i][1], rows[i][2])}
    if kind == "delete":
        gone = lines.pop(i)
        return "\n".join(lines), f"deleted line {i + 1} {short(gone)}", touched
    if kind == "duplicate":
        j = i + 1 if rng.random() < 0.5 else rng.randrange(len(lines) + 1)
        copy = lines[i]
        lines.insert(j, copy)
        return "\n".join(lines), f"line {i + 1} {short(copy)} duplicated at line {j + 1}", touched
    j = rng.choice([p for p in picks if p != i] or [i])
    touched.add((rows[j][1], rows[j][2]))
    lines[i], lines[j] = lines[j], lines[i]
    return "\n".join(lines), f"swapped lines {i + 1} {short(lines[j], 30)} and {j + 1} {short(lines[i], 30)}", touched


def truncate_mutation(rng, text, closing):
    """Cut the file: at any character, or at a line boundary with the open subsections closed."""
    if len(text) < 2 or "\n" not in text:  # a stack's earlier truncation left (almost) nothing
        return text, "nothing left to truncate", set()
    if not closing:
        n = rng.randrange(len(text))
        return text[:n], f"truncated at character {n} of {len(text)} (mid-line: {short(text[:n].split(chr(10))[-1], 30)})", set()
    lines = text.split("\n")
    n = rng.randrange(1, len(lines))
    depth = sum(1 if l.strip().startswith("subsection ") else -1 if l.strip() == "end" else 0 for l in lines[:n])
    cut = "\n".join(lines[:n] + ["end"] * max(depth, 0))
    # what is cut away is gone: a masked parameter after the cut is set by the overrides anyway
    return cut, f"truncated after line {n} of {len(lines)}, {max(depth, 0)} subsection(s) closed", set()


def somewhere(rng, text):
    """A character position: mostly inside a line that is not a comment (or blank)."""
    picks = meaningful(text) if rng.random() < 0.75 else []
    if not picks:
        return rng.randrange(len(text) + 1)
    i = rng.choice(picks)
    lines = text.split("\n")
    return sum(len(l) + 1 for l in lines[:i]) + rng.randint(0, len(lines[i]))


def bytes_mutation(rng, text):
    raw = bytes(rng.randrange(256) for _ in range(rng.randint(1, 8)))
    n = somewhere(rng, text)
    return (text[:n] + raw.decode("utf-8", "surrogateescape") + text[n:],
            f"{len(raw)} random bytes {raw.hex()} at character {n} (line {text.count(chr(10), 0, n) + 1})", set())


def unicode_mutation(rng, text):
    lines = text.split("\n")
    rows = parse(text)
    u = rng.choice(UNICODE)
    where = rng.choice(["value", "name", "minus", "anywhere"])
    sets = [i for i, sub, key in rows if key and not masked(sub, key)]
    if not sets:  # a stack's earlier truncation left no `set` line
        where = "anywhere"
    if where == "minus":
        minus = [i for i in sets if "-" in lines[i].split("=", 1)[1]]
        if minus:
            i = rng.choice(minus)
            head, value = lines[i].split("=", 1)
            lines[i] = head + "=" + value.replace("-", "\u2212", 1)
            return "\n".join(lines), f"U+2212 for '-' in line {i + 1} {short(lines[i])}", {(rows[i][1], rows[i][2])}
        where = "value"
    if where in ("value", "name"):
        i = rng.choice(sets)
        lo, hi = (lines[i].index("=") + 1, len(lines[i])) if where == "value" else (4, lines[i].index("="))
        n = rng.randint(lo, hi)
        lines[i] = lines[i][:n] + u + lines[i][n:]
        return "\n".join(lines), f"{ascii(u)} in the {where} of line {i + 1} {short(lines[i])}", {(rows[i][1], rows[i][2])}
    n = 0 if u == "\ufeff" else somewhere(rng, text)
    return text[:n] + u + text[n:], f"{ascii(u)} at character {n} (line {text.count(chr(10), 0, n) + 1})", set()


def geo_mutation(rng, geo):
    """One damage to a .geo (gmsh's language): lines, numbers, bytes, Unicode, truncation."""
    kind = rng.choice(["delete", "duplicate", "swap", "scale", "sign", "zero", "special", "truncate", "bytes", "unicode"])
    lines = geo.split("\n")
    code = [i for i, l in enumerate(lines) if l.strip() and not l.strip().startswith("//")]
    if kind in ("delete", "duplicate", "swap"):
        if not code:  # the first of two damages truncated the file
            return geo, f"no .geo line left to {kind}"
        i = rng.choice(code)
        if kind == "delete":
            gone = lines.pop(i)
            return "\n".join(lines), f"deleted .geo line {i + 1} {short(gone)}"
        if kind == "duplicate":
            lines.insert(i + 1, lines[i])
            return "\n".join(lines), f"duplicated .geo line {i + 1} {short(lines[i])}"
        j = rng.choice(code)
        lines[i], lines[j] = lines[j], lines[i]
        return "\n".join(lines), f"swapped .geo lines {i + 1} and {j + 1}"
    if kind in ("scale", "sign", "zero", "special"):
        spots = [(i, m) for i in code for m in NUMBER.finditer(lines[i])]
        if not spots:
            return geo, "no .geo number left to change"
        i, m = rng.choice(spots)
        new, how = mutate_number(rng, m.group(0), kind)
        lines[i] = lines[i][:m.start()] + new + lines[i][m.end():]
        return "\n".join(lines), f".geo line {i + 1}: {m.group(0)} -> {new} ({how}) in {short(lines[i], 40)}"
    if kind == "truncate":
        if not geo:
            return geo, "nothing of the .geo left to truncate"
        n = rng.randrange(len(geo))
        return geo[:n], f".geo truncated at character {n} of {len(geo)}"
    if kind == "bytes":
        text, what, _ = bytes_mutation(rng, geo)
        return text, ".geo: " + what
    u = rng.choice(UNICODE)
    n = rng.randrange(len(geo) + 1)
    return geo[:n] + u + geo[n:], f".geo: {ascii(u)} at character {n}"


CATEGORIES = ["delete line", "duplicate line", "swap lines", "number scaled", "number sign/zero",
              "number NaN/inf/huge", "truncated", "random bytes", "unicode", "dimension", "mesh .geo", "stack"]


def one_mutation(rng, text, category):
    if category == "delete line":
        return line_mutation(rng, text, "delete")
    if category == "duplicate line":
        return line_mutation(rng, text, "duplicate")
    if category == "swap lines":
        return line_mutation(rng, text, "swap")
    if category == "number scaled":
        return number_mutation(rng, text, ["scale"])
    if category == "number sign/zero":
        return number_mutation(rng, text, ["sign", "zero"])
    if category == "number NaN/inf/huge":
        return number_mutation(rng, text, ["special"])
    if category == "truncated":
        return truncate_mutation(rng, text, rng.random() < 0.5)
    if category == "random bytes":
        return bytes_mutation(rng, text)
    return unicode_mutation(rng, text)


DIMENSION_VARIANTS = ["3 with a 2D mesh", "2 with the 3D mesh", "2D case on the 3D mesh", "3D case on a 2D mesh"]


def make_mutant(index):
    """(description, prm text before the overrides, geo text or None, touched keys)."""
    rng = random.Random(f"wetbed-fuzz:{args.seed}:{index}")
    category = CATEGORIES[index % len(CATEGORIES)]
    case = rng.choice(CASES)
    text = read(os.path.join(source, "prm", case))
    geo = None
    if category == "dimension":
        # the four variants in turn (every 12th mutant is one of them)
        variant = DIMENSION_VARIANTS[index // len(CATEGORIES) % len(DIMENSION_VARIANTS)]
        if variant in ("2 with the 3D mesh", "3D case on a 2D mesh"):
            if os.path.isfile(os.path.join(source, "prm", CASE_3D)):
                case = CASE_3D
                text = read(os.path.join(source, "prm", case))
            else:
                variant = "3 with a 2D mesh" if variant.startswith("2") else "2D case on the 3D mesh"
        if variant in ("3 with a 2D mesh", "2 with the 3D mesh"):
            new = "3" if variant.startswith("3") else "2"
            text, n = re.subn(r"(?m)^(\s*set\s+dimension\s*=\s*)\S+", lambda m: m.group(1) + new, text)
            if not n:
                text = f"set dimension = {new}\n" + text
        else:
            mesh = "column_3d.geo" if variant.startswith("2D") else "column_2d.geo"
            text = re.sub(r"(?m)^(\s*set\s+file\s*=\s*).*$", lambda m: m.group(1) + "../meshes/" + mesh, text)
        return f"{case}: dimension: {variant}", text, None, set()
    if category == "mesh .geo":
        m = re.search(r"(?m)^\s*set\s+file\s*=\s*(\S+\.geo)\s*$", text)
        geo_name = os.path.basename(m.group(1))
        geo = read(os.path.join(MESH_DIR, geo_name))
        what = []
        for _ in range(rng.choice([1, 1, 2])):
            geo, w = geo_mutation(rng, geo)
            what.append(w)
        return f"{case} on a mutated {geo_name}: " + "; ".join(what), text, geo, set()
    if category == "stack":
        what, touched = [], set()
        for _ in range(rng.choice([2, 3])):
            text, w, t = one_mutation(rng, text, rng.choice(CATEGORIES[:9]))
            what.append(w)
            touched |= t
        return f"{case}: " + "; ".join(what), text, None, touched
    text, w, touched = one_mutation(rng, text, category)
    return f"{case}: {category}: {w}", text, None, touched


def overrides(folder, touched, existing):
    ts = "subsection time stepping\n  set end time = 3e-4\n"
    if ("time stepping", "initial time step") not in touched:
        ts += "  set initial time step = 1e-4\n"
    out = f"subsection output\n  set folder = {folder}\n  set field interval = 0\n"
    if existing:
        out += "  set overwrite = true\n"
    return "\n# --- fuzz_inputs.py overrides: a few steps, output in WORK_DIR ---\n" + ts + "end\n" + out + "end\n"


def folder_digest(folder):
    digest = {}
    for directory, _, files in os.walk(folder):
        for name in files:
            path = os.path.join(directory, name)
            with open(path, "rb") as f:
                digest[os.path.relpath(path, folder)] = hashlib.sha256(f.read()).hexdigest()
    return digest


def limits():
    if args.memory_limit_gb > 0:
        n = int(args.memory_limit_gb * 2 ** 30)
        resource.setrlimit(resource.RLIMIT_AS, (n, n))


def group_cpu_seconds(session):
    """CPU seconds used so far by the live processes of SESSION (wetbed and its gmsh)."""
    total = 0
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            fields = open(f"/proc/{entry}/stat").read().rsplit(")", 1)[1].split()
        except (OSError, IndexError):
            continue
        if int(fields[3]) == session:  # field 6 of stat: the session id
            total += int(fields[11]) + int(fields[12])  # utime + stime
    return total / os.sysconf("SC_CLK_TCK")


BUSY_WINDOW = 10.0  # s: how long before the timeout the CPU use is measured


def run(prm):
    """(status or None on a timeout, stdout, stderr, seconds, busy); the whole process
    group (wetbed and the gmsh it starts) goes on a timeout. BUSY: on a timeout, the share
    of a core the group used in the last BUSY_WINDOW seconds (a run still computing, e.g.
    a valid but huge mesh, is not a hang: a hang waits, idle)."""
    start = time.time()
    p = subprocess.Popen([wetbed, prm], stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=env,
                         cwd=work, start_new_session=True, preexec_fn=limits)
    busy = 0.0
    window = min(BUSY_WINDOW, args.timeout / 2)
    try:
        out, err = p.communicate(timeout=args.timeout - window)
        code = p.returncode
    except subprocess.TimeoutExpired:
        cpu = group_cpu_seconds(p.pid)
        try:
            out, err = p.communicate(timeout=window)
            code = p.returncode
        except subprocess.TimeoutExpired:
            busy = (group_cpu_seconds(p.pid) - cpu) / window
            os.killpg(p.pid, signal.SIGKILL)
            out, err = p.communicate()
            code = None
    try:  # a gmsh left behind by wetbed
        os.killpg(p.pid, signal.SIGKILL)
    except (ProcessLookupError, PermissionError):
        pass
    dec = lambda b: b.decode("utf-8", "replace")
    return code, dec(out), dec(err), time.time() - start, busy


CRASH = ("terminate called", "Assertion", "An error occurred in line", "Segmentation fault", "Aborted",
         "Process received signal", "core dumped", "Stacktrace", "stack trace", "Backtrace", "Traceback",
         "MPI_ABORT", "double free", "malloc(): ", "Floating point exception")
NAMES_SOMETHING = re.compile(r"/|\b[\w.\-]+\.(?:prm|geo|msh)\b")


def judge(code, err, folder, before, prm_path, busy=0.0):
    """'' if the outcome is one of the allowed, else why not. A timeout is allowed only
    while the run still computes (BUSY >= 0.5 of a core): a valid case too large for the
    timeout (a mesh parameter scaled by 1e3), reported as `slow`."""
    lines = [l for l in err.strip().split("\n") if l.strip()]
    tail = " | ".join(lines[-3:])[-400:]
    crash = [c for c in CRASH if c in err]
    if code is None:
        return "" if busy >= 0.5 else f"hang: no exit within {args.timeout:g} s, idle ({busy:.0%} of a core)"
    if code < 0:
        return f"killed by signal {signal.Signals(-code).name} ({code}): {tail}"
    if crash:
        return f"status {code} with {crash[0]!r} on stderr: {tail}"
    if code == 0:
        if not os.path.isfile(os.path.join(folder, "monitors.csv")):
            return "status 0 without monitors.csv"
        return ""
    if code == 2:
        if len(lines) != 1:
            return f"status 2 with {len(lines)} lines on stderr, not one: {tail}"
        if not lines[0].startswith("wetbed: error:"):
            return f"status 2, the line does not start with 'wetbed: error:': {tail}"
        if not NAMES_SOMETHING.search(lines[0][len("wetbed: error:"):]):
            return f"status 2, the line names no subsection/parameter or file: {tail}"
        if before is None and os.path.exists(folder):
            return f"status 2 created the output folder ({sorted(os.listdir(folder))[:6]}): {tail}"
        if before is not None and folder_digest(folder) != before:
            after = folder_digest(folder)
            changed = sorted(k for k in set(before) | set(after) if before.get(k) != after.get(k))
            return f"status 2 changed the existing output folder ({changed[:6]}): {tail}"
        return ""
    if code == 3:
        if not os.path.isfile(os.path.join(folder, "failure_report.txt")):
            return f"status 3 without failure_report.txt: {tail}"
        return ""
    return f"status {code}: {tail}"


def finding_class(code, why):
    """The class of a finding (WHY from judge() non-empty): crash, hang, error message
    (several lines, or one that is not `wetbed: error: ...` naming something), folder (an
    output folder created, changed or incomplete) or status (1, 4, 5, ...)."""
    if code is None:
        return "hang"
    if code < 0 or why.startswith(f"status {code} with '"):
        return "crash"
    if why.startswith(("status 2 with", "status 2, the line")):
        return "error message"
    if why.startswith(("status 0 without", "status 3 without", "status 2 created", "status 2 changed")):
        return "folder"
    return "status"


def prepare():
    """Empties WORK_DIR's mutants/, out/ and findings/ and (unless --dry-run) runs the
    unmutated first case into WORK_DIR/base_results, the previous run's results of the
    mutants that write into an existing folder. Returns (base folder, ok, status, stderr,
    seconds): ok unless that run failed (a status other than 0, or no monitors.csv)."""
    for d in (MUTANTS, OUT, FINDINGS):
        shutil.rmtree(d, ignore_errors=True)
        os.makedirs(d)
    base = os.path.join(work, "base_results")
    if args.dry_run:
        return base, True, 0, "", 0.0
    shutil.rmtree(base, ignore_errors=True)
    prm = os.path.join(MUTANTS, "base.prm")
    write(prm, with_mesh(read(os.path.join(source, "prm", CASES[0]))) + overrides(base, set(), False))
    code, _, err, seconds, _ = run(prm)
    return base, code == 0 and os.path.isfile(os.path.join(base, "monitors.csv")), code, err, seconds


def check_mutant(index, base):
    """Writes mutant INDEX into WORK_DIR/mutants and (unless --dry-run) runs and judges it;
    a finding's .prm (and .geo) and its stderr are kept in WORK_DIR/findings, an allowed
    outcome's output folder is removed. Returns a dict: index, category, label, ran,
    status (None on a hang), why ('' if allowed), seconds, kept (the finding's files),
    stderr, and line (main's line for it)."""
    description, text, geo, touched = make_mutant(index)
    label = f"#{index:03d} {description}"
    name = f"{index:03d}"
    result = {"index": index, "category": CATEGORIES[index % len(CATEGORIES)], "label": label,
              "ran": False, "status": None, "why": "", "seconds": 0.0, "kept": [], "stderr": ""}
    folder = os.path.join(OUT, name)
    existing = index % 2 == 1
    geo_path = None
    if geo is not None:
        geo_path = os.path.join(MUTANTS, name + ".geo")
        write(geo_path, geo)
        text = re.sub(r"(?m)^(\s*set\s+file\s*=\s*).*$", lambda m: m.group(1) + geo_path, text)
    prm_path = os.path.join(MUTANTS, name + ".prm")
    write(prm_path, with_mesh(text) + overrides(folder, touched, existing))
    if args.dry_run:
        result["line"] = f"dry  {label}"
        return result
    before = None
    if existing:
        shutil.copytree(base, folder)
        before = folder_digest(folder)
    code, out, err, seconds, busy = run(prm_path)
    why = judge(code, err, folder, before, prm_path, busy)
    result.update(ran=True, status=code, why=why, seconds=seconds, stderr=err)
    if why:
        kept = [os.path.join(FINDINGS, name + ".prm")]
        shutil.copy(prm_path, kept[0])
        if geo_path:
            kept.append(os.path.join(FINDINGS, name + ".geo"))
            shutil.copy(geo_path, kept[-1])
        kept.append(os.path.join(FINDINGS, name + ".txt"))
        with open(kept[-1], "w") as f:
            f.write(f"{label}\n{why}\nstatus {code}, {seconds:.1f} s, output folder {folder}"
                    f"{' (held results, overwrite = true)' if existing else ''}\n"
                    f"--- stderr ---\n{err[-4000:]}\n--- stdout (tail) ---\n{out[-4000:]}\n")
        result["kept"] = kept
        result["line"] = f"FAIL {label}: {why} [{seconds:.1f} s]"
    else:
        first = err.strip().split("\n")[-1][:160] if code else ""
        outcome = f"status {code}" if code is not None else f"slow: still computing at the timeout ({busy:.0%} of a core)"
        result["line"] = f"ok   {label} -> {outcome} [{seconds:.1f} s]{'  ' + first if first else ''}"
        shutil.rmtree(folder, ignore_errors=True)  # keep WORK_DIR small: a finding's folder stays
    return result


def main():
    started = time.time()
    base, ok, code, err, seconds = prepare()
    if not args.dry_run:
        if not ok:
            print(f"the unmutated {CASES[0]} failed (status {code}): {err.strip()[-400:]}")
            return 1
        print(f"base run of {CASES[0]}: {seconds:.1f} s")
    only = {int(s) for s in args.only.split(",") if s.strip()}
    failures = []
    for index in range(args.count):
        if only and index not in only:
            continue
        result = check_mutant(index, base)
        print(result["line"], flush=result["ran"])
        if result["why"]:
            failures.append(result["label"])
    n = len(only) if only else args.count
    print(f"{n} mutants (seed {args.seed}) in {time.time() - started:.0f} s: {len(failures)} findings"
          + (f", kept in {FINDINGS}" if failures else ""))
    return 1 if failures else 0


if __name__ == "__main__":
    configure()
    sys.exit(main())
