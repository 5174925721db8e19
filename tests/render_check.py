#!/usr/bin/env python3
"""Runs a short 2D bubbling bed, renders one alpha_s snapshot with
scripts/render_fields.py and checks the picture.

usage: render_check.py WETBED SOURCE_DIR WORK_DIR

The case is prm/quick_start_2d.prm on its coarse mesh for 0.02 s (the bed has not yet
moved: packed below 5 cm, empty above). Checked: the PNG has the requested pixel size;
it is not blank (many distinct colours of the viridis colour map); reading the
colour-mapped pixels of the field panel back into alpha_s through the colour map, the
lowest tenth of the domain (the bed) is dense (mean above 0.45) and the highest half
(the freeboard) dilute (mean below 0.05), and the values read back match the field
output at those heights within 0.05. Uses Debian's python3-matplotlib and python3-h5py
(re-executes under /usr/bin/python3 if needed)."""
import os
import subprocess
import sys

try:
    import h5py  # noqa: F401
    import matplotlib  # noqa: F401
except ImportError:
    if os.path.realpath(sys.executable) != "/usr/bin/python3" and os.path.exists("/usr/bin/python3"):
        os.execv("/usr/bin/python3", ["/usr/bin/python3"] + sys.argv)
    raise
import matplotlib

matplotlib.use("Agg")
import matplotlib.image as mimage  # noqa: E402
import numpy as np  # noqa: E402

wetbed, source, work = (os.path.abspath(a) for a in sys.argv[1:4])
os.makedirs(work, exist_ok=True)
failures = []


def expect(condition, what):
    print(("ok   " if condition else "FAIL ") + what)
    if not condition:
        failures.append(what)


folder = os.path.join(work, "run")
text = open(os.path.join(source, "prm", "quick_start_2d.prm")).read().replace("../meshes/", source + "/meshes/")
text += (f"\nsubsection mesh\n set initial refinement = 0\nend\n"
         f"subsection time stepping\n set end time = 0.02\nend\n"
         f"subsection output\n set folder = {folder}\n set field interval = 0.01\n set field format = hdf5\nend\n")
prm = os.path.join(work, "render.prm")
open(prm, "w").write(text)
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
p = subprocess.run([wetbed, prm, "--overwrite"], capture_output=True, text=True, env=env)
if p.returncode != 0:
    print(p.stdout[-2000:], p.stderr[-2000:])
    sys.exit(f"the run failed (exit {p.returncode})")

width, height = 240, 700
out = os.path.join(work, "pictures")
p = subprocess.run([sys.executable, os.path.join(source, "scripts", "render_fields.py"), folder, "--times", "0.02",
                    "--size", f"{width}x{height}", "--no-animation", "--out", out],
                   capture_output=True, text=True)
print(p.stdout, p.stderr[-2000:])
expect(p.returncode == 0, f"render_fields.py ran (exit {p.returncode})")
png = os.path.join(out, "alpha_s_t0.020.png")
expect(os.path.exists(png), f"it wrote {png}")
if failures:
    sys.exit(1)

image = mimage.imread(png)[:, :, :3]
expect(image.shape[:2] == (height, width), f"the PNG is {image.shape[1]}x{image.shape[0]} pixels "
                                           f"({width}x{height} requested)")

# every pixel whose colour lies on the viridis map (within rounding) is a field value
lut = matplotlib.colormaps["viridis"](np.linspace(0, 1, 256))[:, :3]
unique, inverse = np.unique(np.round(image.reshape(-1, 3) * 255).astype(np.int32), axis=0, return_inverse=True)
distance = ((unique[:, None, :] / 255.0 - lut[None, :, :]) ** 2).sum(axis=2)
closest = distance.argmin(axis=1)
near = distance[np.arange(len(unique)), closest] < (3.0 / 255) ** 2
inverse = inverse.ravel()
nearest = closest[inverse]
on_map = near[inverse].reshape(image.shape[:2])
level = (nearest / 255.0).reshape(image.shape[:2])
colours = len(np.unique(nearest[on_map.ravel()]))
expect(on_map.sum() > 0.1 * width * height and colours >= 20,
       f"not blank: {on_map.sum()} colour-mapped pixels in {colours} distinct colours")

# the field panel: the first run of columns (from the left) holding colour-mapped pixels;
# the colour bar is the second
columns = on_map.sum(axis=0) > 0.3 * height
first = int(np.argmax(columns))
last = first
while last + 1 < width and columns[last + 1]:
    last += 1
panel = on_map[:, first:last + 1]
rows = np.nonzero(panel.sum(axis=1) > 0.5 * panel.shape[1])[0]
top, bottom = rows.min(), rows.max()
expect(last - first > 0.2 * width and bottom - top > 0.5 * height,
       f"the field panel: columns {first}-{last}, rows {top}-{bottom}")
packing = 0.61  # maximum packing of the case: the top of the colour scale


def band(lo, hi):
    """Mean alpha_s read from the panel's pixels between fractions lo and hi of the
    domain height (0 = bottom)."""
    r0 = int(bottom - hi * (bottom - top))
    r1 = int(bottom - lo * (bottom - top))
    values = level[r0:r1 + 1, first:last + 1][on_map[r0:r1 + 1, first:last + 1]]
    return packing * values.mean()


bed, freeboard = band(0.01, 0.1), band(0.5, 0.99)
expect(bed > 0.45, f"the bed (lowest tenth) is dense in the picture: mean alpha_s {bed:.3f}")
expect(freeboard < 0.05, f"the freeboard (upper half) is dilute in the picture: mean alpha_s {freeboard:.3f}")
expect(bed > freeboard + 0.4, f"bed denser than freeboard by {bed - freeboard:.3f}")

# the same bands from the field output the picture was made from
import xml.etree.ElementTree as ElementTree  # noqa: E402

import h5py  # noqa: E402,F811

grid = [g for g in ElementTree.parse(os.path.join(folder, "fields.xdmf")).getroot().iter("Grid")
        if g.get("GridType") == "Uniform"][-1]
with h5py.File(os.path.join(folder, grid.find("Geometry/DataItem").text.strip().split(":")[0]), "r") as h5:
    y, alpha_s = h5["nodes"][()][:, 1], h5["alpha_s"][()].ravel()
domain = 0.30
data_bed = alpha_s[(y >= 0.01 * domain) & (y <= 0.1 * domain)].mean()
data_freeboard = alpha_s[(y >= 0.5 * domain) & (y <= 0.99 * domain)].mean()
expect(abs(bed - data_bed) < 0.05 and abs(freeboard - data_freeboard) < 0.05,
       f"the picture matches the field output: bed {bed:.3f} vs {data_bed:.3f}, "
       f"freeboard {freeboard:.3f} vs {data_freeboard:.3f}")
if failures:
    print(f"{len(failures)} check(s) failed")
    sys.exit(1)
