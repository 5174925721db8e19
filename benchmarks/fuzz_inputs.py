#!/usr/bin/env python3
"""Issue 52: the long mutational input campaign, tabulated by mutation class.

usage: fuzz_inputs.py [--count 2000] [--seed 7] [--timeout S] [--memory-limit-gb G]
                      [--time-limit S] [--work DIR] [--wetbed PATH] [--write-doc]

Runs the mutants 0 .. COUNT-1 of tests/fuzz_inputs.py (the ctest `fuzz_inputs` runs the
first 100 of seed 1) with that file's generator and judge, imported from it: each mutant
is a cheap 2D case with one kind of damage (or a stack of them), run for a few steps,
and must end with status 0 (ran), 2 (one `wetbed: error:` line, the output folder not
created or unchanged) or 3 (numerical failure with failure_report.txt). Anything else is
a finding: its .prm (and .geo) and stderr are kept in WORK/findings, as in the test.

Prints one line per mutant, then a markdown table of the outcomes by mutation class
(mutants, allowed status 0 / 2 / 3, and the findings by kind: crash, hang, multi-line or
malformed error, partial folder, other status), the wall time, the seed and count, the
command that regenerates it, and every finding in full. --write-doc puts the table into
the `fuzz_campaign` section of doc/verification.md. --time-limit stops starting new
mutants after that many seconds (the table then states the count actually run, which is
again the first mutants of the seed). Exit status 1 if there was a finding.
"""
import argparse
import importlib.util
import json
import os
import sys
import textwrap
import time

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from benchmark_setup import replace_doc_section  # noqa: E402

parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
parser.add_argument("--count", type=int, default=2000)
parser.add_argument("--seed", type=int, default=7)
parser.add_argument("--timeout", type=float, default=120, help="seconds per run (a hang past it is a finding)")
parser.add_argument("--memory-limit-gb", type=float, default=6, help="address-space limit of each run (0: none)")
parser.add_argument("--time-limit", type=float, default=0,
                    help="start no mutant after this many seconds (0: run all COUNT)")
parser.add_argument("--work", default=os.path.join(root, "build", "benchmarks", "fuzz"))
parser.add_argument("--wetbed", default=os.path.join(root, "build", "wetbed"))
parser.add_argument("--write-doc", action="store_true", help="write the table into doc/verification.md")
args = parser.parse_args()

# tests/fuzz_inputs.py, imported by path (tests/ is no package) and set up with our arguments
spec = importlib.util.spec_from_file_location("fuzz_inputs_test", os.path.join(root, "tests", "fuzz_inputs.py"))
fuzz = importlib.util.module_from_spec(spec)
spec.loader.exec_module(fuzz)
fuzz.configure([args.wetbed, root, args.work, "--seed", str(args.seed), "--count", str(args.count),
                "--timeout", str(args.timeout), "--memory-limit-gb", str(args.memory_limit_gb)])

FINDING_COLUMNS = [("crash", "crash"), ("hang", "hang"), ("error message", "multi-line error"),
                   ("folder", "partial folder"), ("status", "other status")]


def table(results):
    head = ["mutation", "mutants", "status 0", "status 2", "status 3", "slow"] + [c[1] for c in FINDING_COLUMNS]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" + "---:|" * (len(head) - 1)]
    total = [0] * (len(head) - 1)
    for category in fuzz.CATEGORIES:
        rows = [r for r in results if r["category"] == category]
        counts = [len(rows)] + [sum(1 for r in rows if not r["why"] and r["status"] == s) for s in (0, 2, 3, None)]
        counts += [sum(1 for r in rows if r["why"] and r["class"] == c) for c, _ in FINDING_COLUMNS]
        total = [a + b for a, b in zip(total, counts)]
        lines.append(f"| {category} | " + " | ".join(str(c) for c in counts) + " |")
    lines.append("| **all** | " + " | ".join(f"**{c}**" for c in total) + " |")
    return lines, total


def command(count):
    extra = "".join(f" --{name} {value:g}" for name, value, default in
                    (("timeout", args.timeout, 120), ("memory-limit-gb", args.memory_limit_gb, 6))
                    if value != default)
    return f"python3 benchmarks/fuzz_inputs.py --count {count} --seed {args.seed}{extra} --write-doc"


def main():
    started = time.time()
    base, ok, code, err, seconds = fuzz.prepare()
    if not ok:
        print(f"the unmutated {fuzz.CASES[0]} failed (status {code}): {err.strip()[-400:]}")
        return 1
    print(f"base run of {fuzz.CASES[0]}: {seconds:.1f} s", flush=True)
    results = []
    for index in range(args.count):
        if args.time_limit > 0 and time.time() - started > args.time_limit:
            print(f"time limit of {args.time_limit:g} s reached: {index} of {args.count} mutants run", flush=True)
            break
        result = fuzz.check_mutant(index, base)
        result["class"] = fuzz.finding_class(result["status"], result["why"]) if result["why"] else ""
        if not result["why"]:
            result["stderr"] = ""  # only a finding's stderr is worth keeping
        results.append(result)
        print(result["line"], flush=True)
    wall = time.time() - started
    count = len(results)
    findings = [r for r in results if r["why"]]
    with open(os.path.join(args.work, "results.json"), "w") as f:
        json.dump({"seed": args.seed, "count": count, "wall": wall, "results": results}, f, indent=1)

    lines, total = table(results)
    minutes = f"{int(wall // 60)} min {wall % 60:.0f} s"
    allowed = total[1] + total[2] + total[3] + total[4]
    reading = (
        f"{count} mutants of the shipped 2D cases (seed {args.seed}; tests/fuzz_inputs.py's generator and judge, "
        f"the ctest `fuzz_inputs` runs the first 100 of seed 1), each a few steps long, the 12 mutation kinds "
        f"taken in turn. {allowed} ended as allowed: {total[1]} ran (status 0), {total[2]} stopped with one "
        f"`wetbed: error:` line naming the parameter or file and the output folder untouched (status 2), "
        f"{total[3]} stopped with failure_report.txt (status 3), {total[4]} were still computing at the "
        f"{args.timeout:g} s timeout (slow: a valid case too large for it, at least half a core busy over its "
        f"last 10 s). The last five columns are the findings "
        f"(a signal or abort trace, no exit within {args.timeout:g} s and idle, an error of several lines or one that "
        f"names nothing, an output folder created, changed or without its results, any other status): "
        f"{len(findings)} in all.")
    summary = textwrap.wrap(reading, 100, break_on_hyphens=False) + [""] + lines + [
        "",
        f"Wall time {minutes} ({wall / max(count, 1):.2f} s a mutant, serial, one core), "
        f"seed {args.seed}, count {count}; regenerate with `{command(count)}`.",
    ]
    print()
    print("\n".join(summary))
    if findings:
        print(f"\n{len(findings)} findings, kept in {fuzz.FINDINGS}:")
        for r in findings:
            tail = [l for l in r["stderr"].strip().split("\n") if l.strip()][-8:]
            print(f"\n{r['label']}\n  class: {r['class']}; status {r['status']}; {r['seconds']:.1f} s\n"
                  f"  why: {r['why']}\n  kept: {', '.join(r['kept'])}\n  stderr tail:\n"
                  + "\n".join("    " + l for l in tail))
    if args.write_doc:
        replace_doc_section(root, "fuzz_campaign", "Mutational input campaign", summary, "verification.md")
    return 1 if findings else 0


if __name__ == "__main__":
    sys.exit(main())
