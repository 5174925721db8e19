#!/usr/bin/env python3
"""The ECT frames of one or more runs stacked in time, side by side (as seed 000's Fig. 4
shows dry beside wet beds).

usage: scripts/ect_stack.py RUN_FOLDER [RUN_FOLDER ...] [--labels A,B,...] [--start T]
                            [--end T] [--out FILE]

Reads each run's ect_images.csv and ect.csv (subsection ECT sensor). For every frame the
pixels along the diameter through the column's axis (the middle row of the image; the
mean of the two middle rows for an even resolution) become one column of a time-position
picture, alpha_s in grey (white: gas, black: packed). Under each picture, the slab mean
alpha_s_slab against time. Prints per run the number of frames, the mean and standard
deviation of alpha_s_slab and, if ect_spectrum.csv exists, its dominant frequency.
Writes FILE (default ect_stack.png in the first run folder).
Uses Debian's python3-matplotlib (re-executes under /usr/bin/python3 if needed)."""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from wetbed_results import ect, ensure_modules  # noqa: E402


def read_run(folder, start, end):
    """(times, diameter lines [frames x pixels], slab means, dominant frequency or None)
    of the frames in [start, end]."""
    import numpy as np
    try:
        sensor = ect(folder, start, end)
    except ValueError as error:  # not a square image
        sys.exit(str(error))
    for name, key in (("ect_images.csv", "images"), ("ect.csv", "signal")):
        if sensor is None or sensor[key] is None:
            sys.exit(f"{os.path.join(folder, name)}: not found (enable subsection ECT sensor)")
    n = sensor["resolution"]
    # [frame, second axis, first axis]
    images = np.array(sensor["images"], dtype=float).reshape(len(sensor["times"]), n, n)
    middle = images[:, n // 2, :] if n % 2 else 0.5 * (images[:, n // 2 - 1, :] + images[:, n // 2, :])
    spectrum = sensor["spectrum"]
    frequency = spectrum["dominant"].get("alpha_s_slab") if spectrum is not None else None
    return np.array(sensor["times"]), middle, np.array(sensor["signal"]["alpha_s_slab"]), frequency


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("runs", nargs="+")
    parser.add_argument("--labels", default="")
    parser.add_argument("--start", type=float, default=0.0)
    parser.add_argument("--end", type=float, default=math.inf)
    parser.add_argument("--out", default="")
    args = parser.parse_args()
    ensure_modules("matplotlib")
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    labels = args.labels.split(",") if args.labels else [os.path.basename(os.path.normpath(r)) for r in args.runs]
    if len(labels) != len(args.runs):
        sys.exit("--labels: one label per run folder")
    figure, axes = plt.subplots(2, len(args.runs), figsize=(4.5 * len(args.runs), 6), squeeze=False,
                                gridspec_kw={"height_ratios": [3, 1]})
    for k, (run, label) in enumerate(zip(args.runs, labels)):
        times, lines, slab, f = read_run(run, args.start, args.end)
        if len(times) == 0:
            sys.exit(f"{run}: no ECT frame in [{args.start}, {args.end}] s")
        top, bottom = axes[0][k], axes[1][k]
        picture = top.imshow(lines.T, aspect="auto", origin="lower", cmap="Greys", vmin=0, vmax=0.61,
                             extent=[times[0], times[-1], -1, 1], interpolation="nearest")
        top.set_title(label)
        top.set_ylabel("position across the diameter, x/R")
        bottom.plot(times, slab, lw=0.8)
        bottom.set_xlim(times[0], times[-1])
        bottom.set_xlabel("time (s)")
        bottom.set_ylabel("slab mean alpha_s")
        figure.colorbar(picture, ax=top, label="alpha_s")
        print(f"{label}: {len(times)} frames, alpha_s_slab mean {np.mean(slab):.4f}, std {np.std(slab):.4f}"
              + (f", dominant frequency {f:.3g} Hz" if f is not None else ""))
    figure.tight_layout()
    out = args.out or os.path.join(args.runs[0], "ect_stack.png")
    figure.savefig(out, dpi=120)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
